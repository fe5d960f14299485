// Another program run as a child process, the way a shell runs it.
//
// posix_spawn, with the child's standard input a given text (or /dev/null),
// its standard output a pipe that is read to the end and thrown away (only
// counted), and its standard error a pipe whose first kilobytes are kept for
// the report. The wall-clock time from the spawn to the exit is what a user
// waits; the child's own processor time comes from wait4. A child that runs
// past the time limit is killed (by its process id, SIGKILL).
//
// The benchmark uses it for `build/gas` (section 5 of the report) and for
// gnuplot (its pictures).
#pragma once

#include <string>
#include <vector>

namespace gas::benchmark {

struct ChildRun {
  bool started = false;        // false: it could not be started (see `error`)
  bool timed_out = false;      // killed when the time limit ran out
  int exit_status = -1;        // its exit status, if it exited
  int signal = 0;              // the signal that ended it, if one did
  double wall_seconds = 0;     // from the spawn to its exit
  double cpu_seconds = 0;      // its user and system time
  long long max_rss_kb = 0;    // the most memory it held at once (kB, VmHWM seen
                               // every 20 ms while it ran)
  long long output_bytes = 0;  // what it wrote to standard output
  std::string error;           // its standard error (the start), or why it did not start

  bool succeeded() const {
    return started && !timed_out && signal == 0 && exit_status == 0;
  }
  // Why it did not succeed, in one line (the first line of its standard error).
  std::string failure() const;
};

// Runs `program` (looked up in PATH if it has no '/') with `arguments`
// (without the program's own name), feeding it `input` on standard input,
// for at most `time_limit` seconds of wall-clock time.
ChildRun run_child(const std::string& program, const std::vector<std::string>& arguments,
                   const std::string& input, double time_limit);

// Whether an executable named `name` is in PATH.
bool on_path(const std::string& name);

}  // namespace gas::benchmark
