// A child process, timed. See child_process.hpp.
#include "child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

extern char** environ;

namespace gas::benchmark {
namespace {

using Clock = std::chrono::steady_clock;

// How much of the child's standard error the report keeps.
constexpr std::size_t kept_error_bytes = 4096;

// A file descriptor closed when it goes out of scope.
class Descriptor {
 public:
  Descriptor() = default;
  explicit Descriptor(int fd) : fd_(fd) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() { close(); }
  int get() const { return fd_; }
  bool open() const { return fd_ >= 0; }
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  void reset(int fd) {
    close();
    fd_ = fd;
  }

 private:
  int fd_ = -1;
};

// A pipe whose two ends close on exec: the child gets only the copies that
// posix_spawn puts on its 0, 1 and 2.
bool make_pipe(Descriptor& read_end, Descriptor& write_end) {
  int ends[2];
  if (pipe2(ends, O_CLOEXEC) != 0) return false;
  read_end.reset(ends[0]);
  write_end.reset(ends[1]);
  return true;
}

// SIGPIPE ignored while the child runs (a child that exits before reading
// all its input must not end the benchmark), restored after.
class IgnoreBrokenPipes {
 public:
  IgnoreBrokenPipes() {
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGPIPE, &ignore, &saved_);
  }
  ~IgnoreBrokenPipes() { sigaction(SIGPIPE, &saved_, nullptr); }
  IgnoreBrokenPipes(const IgnoreBrokenPipes&) = delete;
  IgnoreBrokenPipes& operator=(const IgnoreBrokenPipes&) = delete;

 private:
  struct sigaction saved_ {};
};

double seconds_between(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

// The most memory the running child has held so far: VmHWM in
// /proc/PID/status, its own since it started its program (0 if unknown).
// (wait4's ru_maxrss will not do: a child started by posix_spawn shares this
// process's memory until its exec, and counts that as its own peak.)
long long resident_peak_kb(pid_t child) {
  std::ifstream status(fmt::format("/proc/{}/status", child));
  for (std::string line; std::getline(status, line);)
    if (line.rfind("VmHWM:", 0) == 0) return std::atoll(line.c_str() + 6);
  return 0;
}

}  // namespace

std::string ChildRun::failure() const {
  if (succeeded()) return "";
  std::string first_line = error.substr(0, error.find('\n'));
  std::string how;
  if (!started) {
    how = "could not start";
  } else if (timed_out) {
    how = fmt::format("stopped after {:.0f} s", wall_seconds);
  } else if (signal != 0) {
    how = fmt::format("killed by signal {} ({})", signal, strsignal(signal));
  } else {
    how = fmt::format("exit status {}", exit_status);
  }
  return first_line.empty() ? how : fmt::format("{}: {}", how, first_line);
}

bool on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream folders(path ? path : "/usr/bin:/bin");
  for (std::string folder; std::getline(folders, folder, ':');) {
    const std::string candidate = (folder.empty() ? "." : folder) + "/" + name;
    if (access(candidate.c_str(), X_OK) == 0) return true;
  }
  return false;
}

namespace {

// The child's three standard streams, as this process sees them: the write
// end of its input (closed at once if there is no input), the read ends of
// its output and error.
struct Streams {
  Descriptor input, output, error;
};

// Starts `program` with its standard streams on pipes (its input on
// /dev/null if `input` is empty) and every signal at its default, none
// blocked, whatever the benchmark ignores (SIGPIPE). Returns its process id,
// or 0 with `run.error` saying why not.
pid_t spawn(const std::string& program, const std::vector<std::string>& arguments,
            bool with_input, Streams& streams, ChildRun& run) {
  Descriptor input_read, output_write, error_write;
  if (!make_pipe(streams.output, output_write) ||
      !make_pipe(streams.error, error_write) ||
      (with_input && !make_pipe(input_read, streams.input))) {
    run.error = fmt::format("cannot make a pipe: {}", std::strerror(errno));
    return 0;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (with_input) {
    posix_spawn_file_actions_adddup2(&actions, input_read.get(), 0);
  } else {
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  }
  posix_spawn_file_actions_adddup2(&actions, output_write.get(), 1);
  posix_spawn_file_actions_adddup2(&actions, error_write.get(), 2);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t all, none;
  sigfillset(&all);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attributes, &all);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(program.c_str()));
  for (const std::string& argument : arguments)
    argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  pid_t child = 0;
  const int spawned =
      posix_spawnp(&child, program.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) {
    run.error = fmt::format("{}: {}", program, std::strerror(spawned));
    return 0;
  }
  run.started = true;
  if (streams.input.open()) fcntl(streams.input.get(), F_SETFL, O_NONBLOCK);
  return child;  // (its ends of the pipes close here: they are the child's now)
}

// Feeds the child its input and reads its output (counted) and error (the
// first kilobytes kept) until both end, or until the deadline (then it is
// killed); meanwhile its largest resident memory is read every 20 ms.
void talk(pid_t child, const std::string& input, Streams& streams,
          Clock::time_point deadline, ChildRun& run) {
  std::size_t written = 0;
  char buffer[1 << 16];
  while (streams.output.open() || streams.error.open()) {
    const Clock::time_point now = Clock::now();
    if (now >= deadline) {
      kill(child, SIGKILL);
      run.timed_out = true;
      return;
    }
    pollfd watched[3];
    Descriptor* owners[3];
    nfds_t count = 0;
    for (Descriptor* d : {&streams.output, &streams.error}) {
      if (!d->open()) continue;
      watched[count] = {d->get(), POLLIN, 0};
      owners[count++] = d;
    }
    if (streams.input.open()) {
      watched[count] = {streams.input.get(), POLLOUT, 0};
      owners[count++] = &streams.input;
    }
    const auto wait_ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now);
    const int ready = poll(
        watched, count, static_cast<int>(std::min<long long>(wait_ms.count() + 1, 20)));
    if (ready < 0 && errno != EINTR) return;
    run.max_rss_kb = std::max(run.max_rss_kb, resident_peak_kb(child));
    for (nfds_t i = 0; i < count; ++i) {
      if (watched[i].revents == 0) continue;
      Descriptor& d = *owners[i];
      if (&d == &streams.input) {
        const ssize_t n = write(d.get(), input.data() + written, input.size() - written);
        if (n > 0) written += static_cast<std::size_t>(n);
        if ((n < 0 && errno != EAGAIN) || written == input.size()) d.close();
        continue;
      }
      const ssize_t n = read(d.get(), buffer, sizeof buffer);
      if (n <= 0) {
        if (n == 0 || (errno != EINTR && errno != EAGAIN)) d.close();
      } else if (&d == &streams.output) {
        run.output_bytes += n;
      } else if (run.error.size() < kept_error_bytes) {
        run.error.append(buffer,
                         std::min<std::size_t>(static_cast<std::size_t>(n),
                                               kept_error_bytes - run.error.size()));
      }
    }
  }
}

// Waits for the child's exit (it may have closed its output before
// exiting), killing it at the deadline; its status and processor time.
void await_exit(pid_t child, const std::string& program, Clock::time_point deadline,
                ChildRun& run) {
  int status = 0;
  rusage usage{};
  while (true) {
    const pid_t done = wait4(child, &status, run.timed_out ? 0 : WNOHANG, &usage);
    if (done == child) break;
    if (done < 0 && errno != EINTR) {
      run.error = fmt::format("waiting for {}: {}", program, std::strerror(errno));
      return;
    }
    if (Clock::now() >= deadline) {
      kill(child, SIGKILL);
      run.timed_out = true;
    } else if (done == 0) {
      std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
  }
  run.cpu_seconds =
      static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
      1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  if (WIFEXITED(status)) run.exit_status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.signal = WTERMSIG(status);
}

}  // namespace

ChildRun run_child(const std::string& program, const std::vector<std::string>& arguments,
                   const std::string& input, double time_limit) {
  ChildRun run;
  const IgnoreBrokenPipes ignore_broken_pipes;
  Streams streams;
  const Clock::time_point began = Clock::now();
  const pid_t child = spawn(program, arguments, !input.empty(), streams, run);
  if (child == 0) return run;
  const Clock::time_point deadline =
      began + std::chrono::duration_cast<Clock::duration>(
                  std::chrono::duration<double>(time_limit));
  talk(child, input, streams, deadline, run);
  streams.input.close();
  streams.output.close();
  streams.error.close();
  await_exit(child, program, deadline, run);
  run.wall_seconds = seconds_between(began, Clock::now());
  return run;
}

}  // namespace gas::benchmark
