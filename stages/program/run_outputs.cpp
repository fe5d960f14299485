// What a run leaves behind besides its frames. See run_outputs.hpp.
#include "program/run_outputs.hpp"

#include <fmt/format.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "beyond/lyapunov_screen.hpp"
#include "program/event_lines.hpp"
#include "stage2_input.hpp"

namespace gas {

bool bell_may_ring(std::chrono::steady_clock::time_point last,
                   std::chrono::steady_clock::time_point now) {
  return now - last >= std::chrono::duration<double>(bell_interval_seconds);
}

namespace {

// "FILE: cannot be written (errno's reason)".
std::string cannot_write(const std::string& path) {
  return fmt::format("{}: cannot be written ({})", path, std::strerror(errno));
}

// A new file beside `path` (a rename stays within one file system), named in
// `name`, with the permissions fopen would give it (0666 less the umask:
// mkstemp makes it for its owner alone). Its descriptor, or -1 (errno set).
int new_file_beside(const std::string& path, std::string& name) {
  name = path + ".XXXXXX";
  const int descriptor = mkstemp(name.data());
  if (descriptor >= 0) {
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(descriptor, 0666 & ~mask);
  }
  return descriptor;
}

}  // namespace

OutputFile::OutputFile(const std::optional<std::string>& path) {
  if (!path) return;
  path_ = *path;
  file_.reset(std::fopen(path->c_str(), "w"));
  if (!file_) throw std::runtime_error(fmt::format("{}: cannot write this file", *path));
}

void OutputFile::fail() {
  if (!failure_) failure_ = cannot_write(path_);
}

void OutputFile::write(std::string_view text) {
  // (Nothing to write may come as a null pointer, which fwrite may not get.)
  if (!file_ || failure_ || text.empty()) return;
  if (std::fwrite(text.data(), 1, text.size(), file_.get()) != text.size()) fail();
}

void OutputFile::close() {
  if (!file_) return;
  if (!failure_ && (std::fflush(file_.get()) != 0 || std::ferror(file_.get()) != 0))
    fail();
  if (std::fclose(file_.release()) != 0) fail();
}

std::optional<std::string> write_whole(const std::string& path,
                                       const PieceByPiece& pieces) {
  std::string temporary;
  const int descriptor = new_file_beside(path, temporary);
  if (descriptor < 0) return cannot_write(path);
  // All of it, and on the disk, before it takes the old file's name; each
  // failure is described by the errno of the call that failed (the pieces
  // after a failure are not written).
  std::optional<std::string> failure;
  pieces([&](std::string_view piece) {
    for (std::size_t done = 0; !failure && done < piece.size();) {
      const ssize_t wrote = ::write(descriptor, piece.data() + done, piece.size() - done);
      if (wrote > 0) {
        done += static_cast<std::size_t>(wrote);
      } else if (!(wrote < 0 && errno == EINTR)) {  // a signal: the flag is seen later
        failure = cannot_write(path);
      }
    }
  });
  if (!failure && fsync(descriptor) != 0) failure = cannot_write(path);
  if (::close(descriptor) != 0 && !failure) failure = cannot_write(path);
  if (!failure && std::rename(temporary.c_str(), path.c_str()) != 0)
    failure = cannot_write(path);
  if (failure) std::remove(temporary.c_str());
  return failure;
}

std::optional<std::string> write_whole(const std::string& path, const std::string& text) {
  return write_whole(path, [&](const auto& write) { write(text); });
}

RunOutputs::RunOutputs(const Options& options, Display& display)
    : events_(options.events_path),
      csv_(options.csv_path),
      dump_path_(options.dump_path),
      structure_path_(options.structure_path),
      vacf_path_(options.vacf_path),
      bell_(options.bell),
      display_(display) {
  // A dump, the structure and the VACF are written at the end; whether they
  // can be is asked now, so that a bad path fails before the run, not after it.
  for (const auto* path : {&dump_path_, &structure_path_, &vacf_path_}) {
    if (!*path) continue;
    std::string probe;
    const int descriptor = new_file_beside(**path, probe);
    if (descriptor < 0)
      throw std::runtime_error(fmt::format("{}: cannot write this file", **path));
    ::close(descriptor);
    std::remove(probe.c_str());
  }
  events_.write("T,K,N1,N2\n");
  if (csv_) csv_.write(csv_header() + lyapunov_csv_header() + "\n");
}

// --events: its lines are written to the file in blocks (and at the end),
// of 64 kB at first, so that the first lines of a slow run soon show, then
// twice as large each time up to 1 MB: a system call a block, not one every
// 4 kB (the kernel's work then took some 5 % of a run at N = 10^3, against 2
// to 3 %).
constexpr std::size_t first_event_block = std::size_t{1} << 16;
constexpr std::size_t largest_event_block = std::size_t{1} << 20;

void RunOutputs::record(const Step& step) {
  if (events_ && !step.collisions.empty()) {
    // Each line put straight into the buffer (event_lines.hpp: T in the
    // fewest digits that read back to the same double, the integers digit
    // pair by digit pair: about 430 instructions a line, 150 of them fmt's
    // shortest digits, against some 710 by fmt's compiled "{},{},{},{}"),
    // the buffer written whenever a block is full.
    if (event_lines_.empty()) event_lines_.resize(first_event_block + longest_event_line);
    for (const Collision& c : step.collisions) {
      char* const buffer = event_lines_.data();
      event_lines_used_ = static_cast<std::size_t>(
          write_event_line(buffer + event_lines_used_, c) - buffer);
      if (event_lines_used_ + longest_event_line >= event_lines_.size()) {
        write_event_lines();
        const std::size_t block = event_lines_.size() - longest_event_line;
        if (block < largest_event_block)  // the next block twice as large
          event_lines_.resize(2 * block + longest_event_line);
      }
    }
  }
  if (bell_ && !step.collisions.empty()) ring_bell();
}

void RunOutputs::write_event_lines() {
  events_.write({event_lines_.data(), event_lines_used_});
  event_lines_used_ = 0;
}

void RunOutputs::write_csv(const Figures& figures, const KineticFigures& kinetic,
                           const std::string& more) {
  csv_.write(csv_row(figures, kinetic) + more + "\n");
}

void RunOutputs::finish(const Gas& gas, const GasStatistics* statistics,
                        const VelocityAutocorrelation* vacf) {
  write_event_lines();
  events_.close();
  csv_.close();
  if (dump_path_) {
    dump_failure_ = write_whole(*dump_path_,
                                [&](const auto& write) { write_scene_text(gas, write); });
  }
  if (structure_path_ && statistics)
    structure_failure_ =
        write_whole(*structure_path_, structure_csv(statistics->structure()));
  if (vacf_path_ && vacf) vacf_failure_ = write_whole(*vacf_path_, vacf_csv(*vacf));
}

std::optional<std::string> RunOutputs::failure() const {
  if (events_.failure()) return events_.failure();
  if (csv_.failure()) return csv_.failure();
  if (dump_failure_) return dump_failure_;
  if (structure_failure_) return structure_failure_;
  return vacf_failure_;
}

std::vector<std::string> RunOutputs::written() const {
  std::vector<std::string> files;
  for (const OutputFile* file : {&events_, &csv_})
    if (*file) files.push_back(file->path());
  if (dump_path_) files.push_back(*dump_path_);
  if (structure_path_) files.push_back(*structure_path_);
  if (vacf_path_) files.push_back(*vacf_path_);
  return files;
}

void RunOutputs::ring_bell() {
  const auto now = std::chrono::steady_clock::now();
  if (bell_may_ring(last_bell_, now)) {
    display_.bell();
    last_bell_ = now;
  }
}

}  // namespace gas
