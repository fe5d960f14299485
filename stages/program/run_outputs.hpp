// What a run leaves behind besides its frames: the --events and --csv files,
// the --dump at the end, and the --bell on collisions.
//
// Beyond the article: its program only drew (stage 6) and sounded a note at
// each collision (stage 7's "sound"); these outputs let a run be studied
// afterwards. Their formats are fixed (README.md, "The program"), and tests
// read them.
// Lesson: lessons/7-model-control.md; the formats: README.md.
#pragma once

#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "beyond/kinetic_screen.hpp"
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
class OutputFile {
 public:
  // Opens `path` for writing, if there is one. Throws std::runtime_error if
  // the file cannot be written.
  explicit OutputFile(const std::optional<std::string>& path);
  explicit operator bool() const { return file_ != nullptr; }
  std::FILE* get() const { return file_.get(); }

 private:
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_{nullptr, std::fclose};
};

// The outputs the options ask for, from the start of a run to its end.
class RunOutputs {
 public:
  // Opens the --events and --csv files and writes their header lines, so that
  // a path that cannot be written fails before the first frame (throws
  // std::runtime_error). The bell, if asked for, rings through `display`.
  RunOutputs(const Options& options, Display& display);

  // After a display step: every collision of the step to --events (T,K,N1,N2),
  // and a ring of the bell if anything collided.
  void record(const Step& step);

  // Is --csv written? (Its figures take a pass over every ball: the caller
  // works them out only then.)
  bool writes_csv() const { return static_cast<bool>(csv_); }
  // After a display step: the figures to --csv, one row.
  void write_csv(const Figures& figures, const KineticFigures& kinetic);

  // At the end of the run: --dump writes the gas as a scene file.
  void finish(const Gas& gas) const;

 private:
  // --bell: rings now, if bell_may_ring.
  void ring_bell();

  OutputFile events_;                                  // --events
  OutputFile csv_;                                     // --csv
  std::optional<std::string> dump_path_;               // --dump
  bool bell_ = false;                                  // --bell
  Display& display_;                                   // where the bell rings
  std::chrono::steady_clock::time_point last_bell_{};  // when it last rang
};

}  // namespace gas
