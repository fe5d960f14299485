// Interrupted runs lose nothing (issue 17): a `gas` run stopped by SIGINT,
// SIGTERM or SIGHUP ends as E would — its --events and --csv files end on a
// whole line, its --dump is a whole scene that reads back, its exit status is
// 128 + the signal's number, and stderr says what happened. An output that
// cannot be written (a full disk) ends the run with exit 1 and a message
// naming the file. The program runs here as a child process, as a user's
// shell or job scheduler would start and stop it.
#include <doctest/doctest.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "beyond/random_placement.hpp"
#include "program/run_outputs.hpp"
#include "program/terminal.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;
using gas::testing::read_file;
using gas::testing::source_path;

using gas::testing::Scratch;

// The lines of a text; the text must end with '\n' (whole lines only).
std::vector<std::string> whole_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    REQUIRE_MESSAGE(end != std::string::npos,
                    "the last line is cut: '" << text.substr(start) << "'");
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

std::size_t fields(const std::string& line) {
  return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
}

// Starts build/gas with `arguments`, its stdout to /dev/null and its stderr
// to `err`; returns its process id.
pid_t start_gas(const std::vector<std::string>& arguments, const std::string& err) {
  const pid_t child = fork();
  if (child == 0) {
    // (A stream that cannot be reopened: no run, status 126.)
    if (!std::freopen("/dev/null", "r", stdin) ||
        !std::freopen("/dev/null", "w", stdout) ||
        !std::freopen(err.c_str(), "w", stderr))
      std::_Exit(126);
    std::vector<char*> argv{const_cast<char*>(GAS_PROGRAM)};
    for (const std::string& argument : arguments)
      argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    execv(GAS_PROGRAM, argv.data());
    std::_Exit(127);
  }
  return child;
}

// Waits for the child at most `seconds`; kills it if it does not end.
// Returns the raw status from waitpid.
int wait_for(pid_t child, double seconds) {
  const auto until =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(child, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > until) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      FAIL("gas did not end within " << seconds << " s of the signal");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return status;
}

// Waits until `path` holds more than `lines` lines (the run is under way).
void wait_for_lines(const std::string& path, std::size_t lines) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < until) {
    std::ifstream file(path);
    std::size_t count = 0;
    for (std::string line; std::getline(file, line);) ++count;
    if (count > lines) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace

TEST_SUITE("console") {
  TEST_CASE("interrupted by SIGINT or SIGTERM or SIGHUP a run leaves whole files") {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
      CAPTURE(signal);
      const Scratch scratch;
      const std::string events = scratch.file("events.csv"),
                        csv = scratch.file("figures.csv"),
                        dump = scratch.file("end.scene"), err = scratch.file("err");
      // The crowd for ever, every file asked for; the signal comes once the
      // events file has passed its first buffer (so the run is mid-stride).
      const pid_t child = start_gas({source_path("data/crowd.scene"), "--until", "1e9",
                                     "--events", events, "--csv", csv, "--dump", dump},
                                    err);
      wait_for_lines(events, 200);
      kill(child, signal);
      const int status = wait_for(child, 20);
      // It ended by itself, with 128 + the signal's number.
      REQUIRE(WIFEXITED(status));
      CHECK(WEXITSTATUS(status) == 128 + signal);
      CHECK(read_file(err).find("interrupted by") != std::string::npos);
      CHECK(read_file(err).find("written whole: " + events) != std::string::npos);
      // --events: whole lines T,K,N1,N2, in time order.
      const std::vector<std::string> event_lines = whole_lines(read_file(events));
      REQUIRE(event_lines.size() > 200);
      CHECK(event_lines[0] == "T,K,N1,N2");
      double last = 0;
      for (std::size_t i = 1; i < event_lines.size(); ++i) {
        REQUIRE(fields(event_lines[i]) == 4);
        const double time = std::stod(event_lines[i]);
        CHECK(time >= last);
        last = time;
      }
      // --csv: whole rows, each with as many figures as the header names.
      const std::vector<std::string> csv_lines = whole_lines(read_file(csv));
      REQUIRE(csv_lines.size() > 1);
      for (const std::string& row : csv_lines) CHECK(fields(row) == fields(csv_lines[0]));
      CHECK(fields(csv_lines[0]) > 30);
      // --dump: a scene that reads back, at a time no earlier than the last
      // collision written (every collision up to its T is in --events).
      const gas::Gas end = gas::read_scene_file(dump);
      CHECK(end.balls.size() ==
            gas::read_scene_file(source_path("data/crowd.scene")).balls.size());
      const std::string dumped = read_file(dump);
      const double dump_time = std::stod(dumped.substr(dumped.find("T = ") + 4));
      CHECK(dump_time >= last);
      // Nothing else left beside them (no temporary file of the dump).
      CHECK(std::distance(fs::directory_iterator(scratch.path),
                          fs::directory_iterator()) == 4);
    }
  }

  TEST_CASE("of two signals in a row the first decides, whichever two they are") {
    // Ctrl-C, then SIGTERM from a scheduler (or the terminal closing: SIGHUP)
    // before the loop has looked: the run ends for the first, and says so.
    // Each pair in a child process of its own, as the program would get
    // them: the flag installed, the two signals raised one after the other
    // (raise returns after the handler has run), the signal read back as the
    // exit status.
    const int signals[] = {SIGINT, SIGTERM, SIGHUP};
    for (const int first : signals) {
      for (const int second : signals) {
        const std::string names =
            std::string(gas::signal_name(first)) + ", then " + gas::signal_name(second);
        INFO(names);
        const pid_t child = fork();
        REQUIRE(child >= 0);
        if (child == 0) {
          gas::install_interrupt_flag();
          if (gas::interrupted()) std::_Exit(100);  // a flag raised by nothing
          raise(first);
          raise(second);
          std::_Exit(gas::interrupted() ? gas::interrupting_signal() : 101);
        }
        int status = 0;
        REQUIRE(waitpid(child, &status, 0) == child);
        REQUIRE(WIFEXITED(status));  // not killed: both signals only raised the flag
        CHECK(WEXITSTATUS(status) == first);
      }
    }
  }

  TEST_CASE("the program: SIGINT then SIGTERM at once, the run ends for SIGINT") {
    // The two signals sent back to back to a run under way: the exit status
    // and the message are the first one's (130, "SIGINT"), not the last's.
    // Often both are still pending when the program next runs; the kernel
    // then hands over SIGINT first (the lower number) and, with the other
    // two signals blocked while its handler runs, SIGINT's handler sets the
    // flag first. So the outcome does not depend on timing. (Without that
    // blocking SIGTERM's handler would run on top of SIGINT's before it,
    // and the run would end for SIGTERM.)
    const Scratch scratch;
    const std::string events = scratch.file("events.csv"), err = scratch.file("err");
    const pid_t child = start_gas(
        {source_path("data/crowd.scene"), "--until", "1e9", "--events", events}, err);
    wait_for_lines(events, 200);
    kill(child, SIGINT);
    kill(child, SIGTERM);
    const int status = wait_for(child, 20);
    REQUIRE(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 128 + SIGINT);
    CHECK(read_file(err).rfind("gas: interrupted by SIGINT at T = ", 0) == 0);
  }

  TEST_CASE("an output that cannot be written ends the run with exit 1 naming the file") {
    // /dev/full: every write fails with "No space left on device".
    const gas::testing::ProgramRun full = gas::testing::run_program(
        {"data/crowd.scene", "--until", "2000", "--events", "/dev/full"});
    CHECK(full.status == 1);
    CHECK(full.err.rfind("gas: /dev/full: cannot be written (", 0) == 0);
    // A dump that cannot be written is refused before the run.
    const gas::testing::ProgramRun nowhere = gas::testing::run_program(
        {"data/crowd.scene", "--until", "1e9", "--dump", "/nonexistent/end.scene"});
    CHECK(nowhere.status == 1);
    CHECK(nowhere.err == "gas: /nonexistent/end.scene: cannot write this file\n");
    CHECK(nowhere.out.empty());
  }

  TEST_CASE("write_whole replaces a file whole and leaves no temporary file") {
    const Scratch scratch;
    const std::string path = scratch.file("d.scene");
    std::ofstream(path) << "an old scene\n";
    CHECK_FALSE(gas::write_whole(path, "a new scene\n").has_value());
    CHECK(read_file(path) == "a new scene\n");
    CHECK(std::distance(fs::directory_iterator(scratch.path), fs::directory_iterator()) ==
          1);
    // A folder that does not exist: a message, and nothing made.
    const auto failure = gas::write_whole(scratch.file("no/d.scene"), "x\n");
    REQUIRE(failure.has_value());
    CHECK(failure->find("no/d.scene: cannot be written") != std::string::npos);
  }
}  // TEST_SUITE
