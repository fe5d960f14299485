// What a run leaves behind besides its frames: the --events and --csv files,
// the --dump, --structure and --vacf at the end, and the --bell on collisions.
//
// Beyond the article: its program only drew (stage 6) and sounded a note at
// each collision (stage 7's "sound"); these outputs let a run be studied
// afterwards. Their formats are fixed (README.md, "The program"), and tests
// read them.
// Lesson: lessons/7-model-control.md; the formats: README.md.
#pragma once

#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "beyond/kinetic_csv.hpp"
#include "beyond/velocity_autocorrelation.hpp"
#include "program/options.hpp"
#include "stage1_data.hpp"
#include "stage6_output.hpp"
#include "stage7_control.hpp"

namespace gas {

// --bell: the bell rings at most once in this many seconds (about seven times
// a second), so that a crowd does not buzz.
inline constexpr double bell_interval_seconds = 0.15;

// --bell: may the bell ring at `now`, when it last rang at `last`? Only once
// bell_interval_seconds have passed since.
bool bell_may_ring(std::chrono::steady_clock::time_point last,
                   std::chrono::steady_clock::time_point now);

// A file to write, closed when the object dies; none if no path was given.
// It is written in whole lines, and a line that cannot be written (a full
// disk, say) is remembered as a failure: nothing more is written to it, and
// the run ends with a message naming the file.
class OutputFile {
 public:
  // Opens `path` for writing, if there is one. Throws std::runtime_error if
  // the file cannot be written.
  explicit OutputFile(const std::optional<std::string>& path);
  // Was a file asked for (its name: path())?
  explicit operator bool() const { return !path_.empty(); }
  const std::string& path() const { return path_; }

  // Writes `text`, whole lines.
  void write(std::string_view text);
  // Sends what is buffered to the file and closes it.
  void close();
  // "FILE: what went wrong", once a write or the close has failed.
  const std::optional<std::string>& failure() const { return failure_; }

 private:
  void fail();  // remembers errno's reason

  std::string path_;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_{nullptr, std::fclose};
  std::optional<std::string> failure_;
};

// A text made a piece at a time, each piece handed to `write` as it is made
// (stage 2's write_scene_text is one).
using PieceByPiece =
    std::function<void(const std::function<void(std::string_view piece)>& write)>;

// Writes the text `pieces` makes to `path` whole or not at all: into a new
// file beside it, each piece as it comes (so a --dump of 10^6 balls never
// holds its 96 MB of text), then renamed over `path`, so that a run that
// dies while writing never leaves half a scene. Returns "FILE: what went
// wrong" on failure.
std::optional<std::string> write_whole(const std::string& path,
                                       const PieceByPiece& pieces);
// The same for a text made already.
std::optional<std::string> write_whole(const std::string& path, const std::string& text);

// The outputs the options ask for, from the start of a run to its end.
class RunOutputs {
 public:
  // Opens the --events and --csv files and writes their header lines, so that
  // a path that cannot be written fails before the first frame (throws
  // std::runtime_error). The bell, if asked for, rings through `display`.
  RunOutputs(const Options& options, Display& display);

  // After a display step: every collision of the step to --events (T,K,N1,N2),
  // and a ring of the bell if anything collided. The lines gather in a
  // buffer, written to the file a block at a time (and at the end).
  void record(const Step& step);

  // Is --csv written? (Its figures take a pass over every ball: the caller
  // works them out only then.)
  bool writes_csv() const { return static_cast<bool>(csv_); }
  // After a display step: the figures to --csv, one row; `more`, the
  // Lyapunov exponent's block (beyond/lyapunov_screen.hpp), at its end.
  void write_csv(const Figures& figures, const KineticFigures& kinetic,
                 const std::string& more);

  // At the end of the run, however it ends: --events and --csv closed on a
  // whole line, and --dump written whole, the gas at its time T (every
  // collision up to T is in --events); --structure written whole from the
  // statistics (which a run that asks for it has); --vacf written whole from
  // the velocity autocorrelation (likewise).
  void finish(const Gas& gas, const GasStatistics* statistics,
              const VelocityAutocorrelation* vacf = nullptr);

  // The first output that could not be written, "FILE: why", if any.
  std::optional<std::string> failure() const;
  // The files written, for the message of an interrupted run.
  std::vector<std::string> written() const;

 private:
  // --bell: rings now, if bell_may_ring.
  void ring_bell();
  // --events: the lines gathered so far to the file.
  void write_event_lines();

  OutputFile events_;                                  // --events
  std::vector<char> event_lines_;                      // its lines not yet written
  std::size_t event_lines_used_ = 0;                   // their characters
  OutputFile csv_;                                     // --csv
  std::optional<std::string> dump_path_;               // --dump
  std::optional<std::string> dump_failure_;            // why --dump was not written
  std::optional<std::string> structure_path_;          // --structure
  std::optional<std::string> structure_failure_;       // why it was not written
  std::optional<std::string> vacf_path_;               // --vacf
  std::optional<std::string> vacf_failure_;            // why it was not written
  bool bell_ = false;                                  // --bell
  Display& display_;                                   // where the bell rings
  std::chrono::steady_clock::time_point last_bell_{};  // when it last rang
};

}  // namespace gas
