// The program `gas` on a terminal whose window changes size.
//
// Each test starts build/gas on a pseudo-terminal of a given size (forkpty),
// lets it draw, changes the window's size with TIOCSWINSZ (the kernel sends
// the program SIGWINCH), and replays what the program wrote since its last
// clear-screen on a small model of a terminal of the new size:
// - a resized window: the screen is laid out afresh at the new size (stage 3
//   again), cleared and drawn whole, with nothing written outside the window;
// - a window too small for the smallest table: one line says so, and the
//   frame comes back when the window grows; a too-small window at the start
//   gives the same line, not an error (but --trace, which prints frames
//   whole, still refuses it);
// - --cols and --rows keep their size in a smaller window, and the frame is
//   cut at the window's edges;
// - E still ends the run with status 0, and the cursor is shown again;
// - what a newcomer meets at 80 x 24: the key line under the table, colour on
//   the table's glyphs only (never the status line, the border, the keys or
//   the figures), the statistics screen with its histogram and one line
//   naming what a taller window adds; a window of 20 x 6 keeps the size it
//   asks for; TERM=dumb gets plain frames with no escape byte at all.
// Every wait is bounded: a program that hangs is killed and the test fails.
#include <doctest/doctest.h>
#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

// build/gas running on a pseudo-terminal, with TERM=xterm and colour (no
// NO_COLOR) unless `environment` says otherwise ("NAME=value", or "NAME"
// alone: unset); killed if still running at the end.
class PtyRun {
 public:
  PtyRun(int columns, int rows, const std::vector<std::string>& arguments,
         const std::vector<std::string>& environment = {}) {
    winsize size{};
    size.ws_col = static_cast<unsigned short>(columns);
    size.ws_row = static_cast<unsigned short>(rows);
    child_ = forkpty(&master_, nullptr, nullptr, &size);
    REQUIRE_MESSAGE(child_ >= 0, "forkpty failed");
    if (child_ == 0) {
      std::vector<std::string> words{GAS_PROGRAM};
      words.insert(words.end(), arguments.begin(), arguments.end());
      std::vector<char*> argv;
      for (std::string& word : words) argv.push_back(word.data());
      argv.push_back(nullptr);
      setenv("TERM", "xterm", 1);
      unsetenv("NO_COLOR");
      for (const std::string& setting : environment) {
        const std::size_t equals = setting.find('=');
        if (equals == std::string::npos) {
          unsetenv(setting.c_str());
        } else {
          setenv(setting.substr(0, equals).c_str(), setting.substr(equals + 1).c_str(),
                 1);
        }
      }
      if (chdir(GAS_SOURCE_DIR) != 0) _exit(126);
      execv(GAS_PROGRAM, argv.data());
      _exit(127);
    }
  }
  ~PtyRun() {
    if (child_ > 0 && !exited_) {
      kill(child_, SIGKILL);
      waitpid(child_, nullptr, 0);
    }
    if (master_ >= 0) close(master_);
  }
  PtyRun(const PtyRun&) = delete;
  PtyRun& operator=(const PtyRun&) = delete;

  // Everything the program has written so far.
  const std::string& output() const { return output_; }

  // Reads what the program writes for `ms` milliseconds.
  void read_for(int ms) {
    read_until([] { return false; }, ms);
  }

  // Reads until `done` holds or `ms` milliseconds have passed; true if done.
  bool read_until(const std::function<bool()>& done, int ms) {
    const auto deadline = Clock::now() + std::chrono::milliseconds(ms);
    while (!done()) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now())
              .count();
      if (left <= 0) return false;
      pollfd input{master_, POLLIN, 0};
      if (poll(&input, 1, static_cast<int>(left)) <= 0) continue;
      char buffer[4096];
      const ssize_t count = read(master_, buffer, sizeof buffer);
      if (count <= 0) return done();  // the program has gone (EIO)
      output_.append(buffer, static_cast<std::size_t>(count));
    }
    return true;
  }

  // Changes the window's size; the kernel sends the program SIGWINCH.
  void resize(int columns, int rows) {
    winsize size{};
    size.ws_col = static_cast<unsigned short>(columns);
    size.ws_row = static_cast<unsigned short>(rows);
    REQUIRE(ioctl(master_, TIOCSWINSZ, &size) == 0);
  }

  // Types `keys` on the keyboard.
  void type(const std::string& keys) {
    REQUIRE(write(master_, keys.data(), keys.size()) ==
            static_cast<ssize_t>(keys.size()));
  }

  // The exit status, reading the output meanwhile; -1 if the program is still
  // running after `ms` milliseconds (it is killed) or did not exit normally.
  int wait_exit(int ms) {
    const auto deadline = Clock::now() + std::chrono::milliseconds(ms);
    int raw = 0;
    while (waitpid(child_, &raw, WNOHANG) == 0) {
      if (Clock::now() >= deadline) {
        kill(child_, SIGKILL);
        waitpid(child_, nullptr, 0);
        exited_ = true;
        return -1;
      }
      read_for(20);
    }
    exited_ = true;
    read_for(50);  // what is left in the pty
    return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  }

 private:
  int master_ = -1;
  pid_t child_ = -1;
  bool exited_ = false;
  std::string output_;
};

// A terminal of `columns` x `rows` that understands what the program sends
// (cursor moves, clear screen, colours, showing and hiding the cursor), and
// notes every character written outside its window.
struct Terminal {
  Terminal(int columns_, int rows_)
      : columns(columns_),
        rows(rows_),
        lines(static_cast<std::size_t>(rows_),
              std::string(static_cast<std::size_t>(columns_), ' ')),
        coloured(static_cast<std::size_t>(rows_),
                 std::vector<bool>(static_cast<std::size_t>(columns_), false)) {}

  void play(const std::string& text) {
    for (std::size_t k = 0; k < text.size(); ++k) {
      const char c = text[k];
      if (c == '\x1b' && k + 1 < text.size() && text[k + 1] == '[') {
        std::size_t end = k + 2;
        while (end < text.size() && !(text[end] >= '@' && text[end] <= '~')) ++end;
        if (end == text.size()) break;
        escape(text.substr(k + 2, end - k - 2), text[end]);
        k = end;
      } else if (c == '\n') {
        ++row;
        column = 1;
      } else if (c == '\r') {
        column = 1;
      } else if (c == '\a') {
      } else {
        if (row < 1 || row > rows || column < 1 || column > columns) {
          ++outside;
        } else {
          lines[static_cast<std::size_t>(row - 1)][static_cast<std::size_t>(column - 1)] =
              c;
          coloured[static_cast<std::size_t>(row - 1)]
                  [static_cast<std::size_t>(column - 1)] = colour_on;
        }
        ++column;
      }
    }
  }

  void escape(const std::string& parameters, char final) {
    if (final == 'H') {  // cursor to row;column
      row = 1;
      column = 1;
      if (!parameters.empty()) {
        const std::size_t semicolon = parameters.find(';');
        row = std::stoi(parameters.substr(0, semicolon));
        if (semicolon != std::string::npos)
          column = std::stoi(parameters.substr(semicolon + 1));
      }
      if (row > rows || column > columns) ++moves_outside;
    } else if (final == 'J' && parameters == "2") {
      for (std::string& line : lines) line.assign(static_cast<std::size_t>(columns), ' ');
      for (auto& line : coloured) line.assign(static_cast<std::size_t>(columns), false);
    } else if (final == 'K' && row >= 1 && row <= rows) {
      lines[static_cast<std::size_t>(row - 1)].assign(static_cast<std::size_t>(columns),
                                                      ' ');
    } else if (final == 'm') {
      colour_on = !(parameters.empty() || parameters == "0");
    }  // the cursor shown or hidden ('h', 'l') changes no cell
  }

  // How many cells of row `n` (from 1) were last written in colour.
  int coloured_in(int n) const {
    const auto& line = coloured[static_cast<std::size_t>(n - 1)];
    return static_cast<int>(std::count(line.begin(), line.end(), true));
  }

  // Row `n` (from 1) without its trailing blanks.
  std::string line(int n) const {
    std::string text = lines[static_cast<std::size_t>(n - 1)];
    text.erase(text.find_last_not_of(' ') + 1);
    return text;
  }

  int columns;
  int rows;
  std::vector<std::string> lines;
  std::vector<std::vector<bool>> coloured;  // cells last written in colour
  bool colour_on = false;
  int row = 1;
  int column = 1;
  int outside = 0;        // characters written outside the window
  int moves_outside = 0;  // cursor moves outside the window
};

const std::string clear_screen = "\x1b[2J";
const std::string show_cursor = "\x1b[?25h";
const std::string too_small = "window too small: at least 8 x 7";

// What the program wrote after `from`, from its last clear-screen on, played
// on a terminal of `columns` x `rows`; empty if there is no clear-screen.
std::optional<Terminal> last_screen(const std::string& output, std::size_t from,
                                    int columns, int rows) {
  const std::size_t start = output.rfind(clear_screen);
  if (start == std::string::npos || start < from) return std::nullopt;
  Terminal terminal(columns, rows);
  terminal.play(output.substr(start));
  return terminal;
}

// Resizes the window to `columns` x `rows`, lets the program answer, and
// returns the screen it drew afresh after the resize, checked to lie within
// the window (nothing written or moved to outside it).
std::optional<Terminal> screen_after_resize(PtyRun& run, int columns, int rows) {
  const std::size_t mark = run.output().size();
  run.resize(columns, rows);
  run.read_for(800);
  auto after = last_screen(run.output(), mark, columns, rows);
  REQUIRE_MESSAGE(after, "no clear-screen after the resize");
  CHECK(after->outside == 0);
  CHECK(after->moves_outside == 0);
  return after;
}

// Does `terminal` show a status line over a whole table: a top border
// "+---+", rows "|...|" of the same width, and a bottom border?
bool shows_whole_frame(const Terminal& terminal) {
  if (terminal.line(1).rfind("T=", 0) != 0) return false;
  const std::string border = terminal.line(2);
  if (border.size() < 3 || border.front() != '+' || border.back() != '+' ||
      border.find_first_not_of('-', 1) != border.size() - 1) {
    return false;
  }
  for (int n = 3; n <= terminal.rows; ++n) {
    const std::string line = terminal.line(n);
    if (line == border) return n >= 4;
    if (line.size() != border.size() || line.front() != '|' || line.back() != '|')
      return false;
  }
  return false;  // no bottom border
}

}  // namespace

TEST_SUITE("console") {
  TEST_CASE(
      "a resized terminal: stage 3 again at the new size, nothing outside the window") {
    PtyRun run(80, 24, {});
    run.read_for(600);
    const auto before = last_screen(run.output(), 0, 80, 24);
    REQUIRE(before);
    CHECK(shows_whole_frame(*before));
    CHECK(before->line(2).size() > 50);  // the 80-column table, wider than 50

    const std::size_t mark = run.output().size();
    const auto after = screen_after_resize(run, 50, 15);
    CHECK(shows_whole_frame(*after));
    CHECK(after->line(2).size() <= 50);
    CHECK(after->line(1).size() <= 50);  // the status line cut to the window

    run.type("E");
    CHECK(run.wait_exit(5000) == 0);
    CHECK(run.output().find(show_cursor, mark) != std::string::npos);
  }

  TEST_CASE(
      "a window too small for the table says so on one line, then draws when it grows") {
    PtyRun run(80, 24, {});
    run.read_for(400);
    std::size_t mark = run.output().size();
    run.resize(40, 6);
    const auto said = [&] {
      return run.output().find(too_small, mark) != std::string::npos;
    };
    REQUIRE_MESSAGE(run.read_until(said, 3000), "no '" << too_small << "'");
    run.read_for(300);
    const auto small = last_screen(run.output(), mark, 40, 6);
    REQUIRE(small);
    CHECK(small->outside == 0);
    CHECK(small->line(1) == too_small);
    for (int n = 2; n <= 6; ++n) CHECK(small->line(n).empty());

    mark = run.output().size();
    run.resize(60, 18);
    run.read_for(800);
    const auto grown = last_screen(run.output(), mark, 60, 18);
    REQUIRE_MESSAGE(grown, "no clear-screen after the window grew");
    CHECK(grown->outside == 0);
    CHECK(shows_whole_frame(*grown));

    run.type("E");
    CHECK(run.wait_exit(5000) == 0);
    CHECK(run.output().find(show_cursor, mark) != std::string::npos);
  }

  TEST_CASE(
      "a window too small at the start: the line, not an error (but --trace refuses "
      "it)") {
    {
      PtyRun run(40, 6, {});
      const auto said = [&] { return run.output().find(too_small) != std::string::npos; };
      REQUIRE_MESSAGE(run.read_until(said, 3000), "no '" << too_small << "'");
      const std::size_t mark = run.output().size();
      run.resize(60, 18);
      run.read_for(800);
      const auto grown = last_screen(run.output(), mark, 60, 18);
      REQUIRE_MESSAGE(grown, "no clear-screen after the window grew");
      CHECK(shows_whole_frame(*grown));
      run.type("E");
      CHECK(run.wait_exit(5000) == 0);
    }
    {
      PtyRun run(40, 6, {"--trace", "--frames", "1"});
      CHECK(run.wait_exit(5000) == 2);
      CHECK(run.output().find("the screen is too small") != std::string::npos);
    }
  }

  TEST_CASE("on a terminal a run has no frame limit: it goes past frame 100 by itself") {
    // A piped run stops after 100 frames (suite console, "a piped run takes
    // 100 frames ..."); one drawn on a terminal runs until E or a signal,
    // even with a script of one key (--keys: no pacing, no keyboard). Each
    // frame moves T by at most T0 = 1, so T = 150 is past frame 150. The
    // status line is redrawn in place, only the characters that changed, so
    // it is read off a terminal that plays what the program wrote.
    PtyRun run(80, 24, {"--keys", "."});
    Terminal terminal(80, 24);
    std::size_t played = 0;
    const auto past = [&] {
      // Up to the last escape, which may not have arrived whole.
      const std::size_t last = run.output().rfind('\x1b');
      if (last == std::string::npos || last <= played) return false;
      terminal.play(run.output().substr(played, last - played));
      played = last;
      const std::string status = terminal.line(1);
      return status.rfind("T=", 0) == 0 && std::stod(status.substr(2)) >= 150;
    };
    CHECK_MESSAGE(run.read_until(past, 10000),
                  "the run ended or stalled before T = 150: " << terminal.line(1));
  }

  TEST_CASE("--cols and --rows keep their size in a smaller window, cut at its edges") {
    PtyRun run(80, 24, {"--cols", "100", "--rows", "30"});
    run.read_for(400);
    const auto after = screen_after_resize(run, 50, 15);
    // The table of 70 columns, cut: a top border with no right corner.
    CHECK(after->line(2).size() == 50);
    CHECK(after->line(2).find_first_not_of('-', 1) == std::string::npos);
    run.type("E");
    CHECK(run.wait_exit(5000) == 0);
  }
  TEST_CASE(
      "at 80 x 24 the key line under the table and colour on the balls only never the "
      "status line") {
    PtyRun run(80, 24, {"data/crowd.scene"});
    const auto drawn = [&] {
      return run.output().find("keys: S stop") != std::string::npos;
    };
    REQUIRE_MESSAGE(run.read_until(drawn, 8000), "no key line");
    run.read_for(500);
    const auto screen = last_screen(run.output(), 0, 80, 24);
    REQUIRE(screen);
    CHECK(shows_whole_frame(*screen));
    CHECK(screen->line(24) ==
          "keys: S stop  R run  B reverse  > T0x2  < T0/2  0 redraw  E end");
    // The balls in colour; the status line (whose T has a '.', tone 0's
    // trail glyph), the border and the keys not.
    int balls = 0;
    for (int n = 3; n <= 22; ++n) balls += screen->coloured_in(n);
    CHECK(balls > 0);
    for (const int n : {1, 2, 23, 24}) {
      CAPTURE(n);
      CHECK(screen->coloured_in(n) == 0);
    }
    // The frames after the first, sent as changes: no colour code in the
    // status line either (row 1 is only ever written without colour).
    Terminal all(80, 24);
    all.play(run.output());
    CHECK(all.coloured_in(1) == 0);
    run.type("E");
    CHECK(run.wait_exit(5000) == 0);
  }

  TEST_CASE(
      "at 80 x 24 the statistics screen shows the histogram and names what it leaves "
      "out") {
    PtyRun run(80, 24, {"data/large-1000.scene", "--mode", "stats"});
    const auto drawn = [&] {
      return run.output().find("more with") != std::string::npos;
    };
    REQUIRE_MESSAGE(run.read_until(drawn, 8000), "no statistics screen");
    run.read_for(300);
    const auto screen = last_screen(run.output(), 0, 80, 24);
    REQUIRE(screen);
    bool histogram = false;
    for (int n = 3; n <= 22; ++n)
      histogram |=
          screen->line(n).rfind("| speeds: # measured  * Maxwell-Boltzmann", 0) == 0;
    CHECK(histogram);
    CHECK(screen->line(22).rfind("| more with ", 0) == 0);
    CHECK(screen->line(22).find("Lyapunov") != std::string::npos);
    CHECK(screen->line(24).find("A new averages") != std::string::npos);
    // A screen of figures: nothing in colour (their '.' and '+' are no balls).
    Terminal all(80, 24);
    all.play(run.output());
    for (int n = 1; n <= 24; ++n) {
      CAPTURE(n);
      CHECK(all.coloured_in(n) == 0);
    }
    run.type("E");
    CHECK(run.wait_exit(5000) == 0);
  }

  TEST_CASE("a window of 20 x 6 is too small and says so with the size it needs") {
    PtyRun run(20, 6, {});
    const auto said = [&] { return run.output().find("8 x 7") != std::string::npos; };
    REQUIRE_MESSAGE(run.read_until(said, 3000), "no size in the notice");
    run.read_for(200);
    const auto small = last_screen(run.output(), 0, 20, 6);
    REQUIRE(small);
    CHECK(small->outside == 0);
    CHECK(small->line(1) == "window too small: at");
    CHECK(small->line(2) == "least 8 x 7");
    run.type("E");
    CHECK(run.wait_exit(5000) == 0);
  }

  TEST_CASE("TERM=dumb on a terminal: plain frames and not one escape byte") {
    PtyRun run(80, 24, {"data/crowd.scene", "--frames", "3"}, {"TERM=dumb"});
    CHECK(run.wait_exit(5000) == 0);
    CHECK(run.output().find('\x1b') == std::string::npos);
    // Three frames, each headed by its status line (the terminal ends lines
    // with \r\n).
    std::size_t frames = 0;
    for (std::size_t at = run.output().find("T="); at != std::string::npos;
         at = run.output().find("\nT=", at + 1))
      ++frames;
    CHECK(frames == 3);
    CHECK(run.output().find("+------") != std::string::npos);
    // And the same for a TERM that is unset, and with keys on the keyboard:
    // the key line follows each frame.
    PtyRun unset(80, 24, {"data/crowd.scene", "--frames", "2"}, {"TERM"});
    CHECK(unset.wait_exit(5000) == 0);
    CHECK(unset.output().find('\x1b') == std::string::npos);
    CHECK(unset.output().find("keys: S stop") != std::string::npos);
  }
}
