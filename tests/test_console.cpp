// The console program `gas`: its command line and what it prints.
//
// - parse_options on good command lines (every option, both spellings
//   "--opt value" and "--opt=value") and on bad ones (unknown option,
//   missing value, negative or non-numeric numbers, unknown mode, --frames
//   with --until, two scenes, a value given to a flag).
// - The program itself: bad usage gives exit status 2, a message on stderr
//   and nothing on stdout; --help gives exit 0 and the help text; five
//   frames are five frames, each a status line and a bordered screen.
// - Scripted runs of every teaching scene against golden outputs in
//   data/golden/runs/ (balls, trails, stats, the keys ..B.., --trace).
// - --trace says what stages 1, 2 and 3 set up (the variables, the scene
//   read, G1, G2 and the screen) before the first stage 4.
// - --trace marks stage 6 "frozen at the collision" at exactly the steps
//   that end on one (the moments of --events).
// - The key 0: stage 3 again, so the trails screen after it holds the new
//   step's segments alone, inside a whole border.
// - The files: --events and --csv (headers, one row per collision and per
//   frame), --dump (a scene read_scene_file accepts, equal to the same run
//   done in this process; continued from, it gives the uninterrupted run's
//   collision lines bit for bit; its first frame shows its T).
// - --bell: a '\a' for a run with collisions, none without --bell; at most
//   one every bell_interval_seconds (bell_may_ring, and the program itself).
#include <doctest/doctest.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "beyond/kinetic_csv.hpp"
#include "beyond/lyapunov_screen.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "program/console.hpp"
#include "program/event_lines.hpp"
#include "program/run_outputs.hpp"
#include "stage2_input.hpp"
#include "stage7_control.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;
using gas::testing::check_golden;
using gas::testing::lines_of;
using gas::testing::read_file;
using gas::testing::run_program;
using gas::testing::source_path;

// The message parse_options gives for `arguments`, or "" if it accepts them.
std::string usage_error(const std::vector<std::string>& arguments) {
  try {
    gas::parse_options(arguments);
  } catch (const gas::UsageError& error) {
    return error.what();
  }
  return "";
}

using gas::testing::Scratch;

// The frames of a plain (not a terminal) run: each a status line starting
// "T=", then a screen from a '+' border line to the next one. (A status line
// alone marks a tick of a stopped model: no frame.)
struct Frame {
  std::string status;
  std::vector<std::string> screen;
};

std::vector<Frame> frames_of(const std::string& out) {
  std::vector<Frame> frames;
  const std::vector<std::string> lines = lines_of(out);
  for (std::size_t i = 0; i < lines.size();) {
    if (lines[i].rfind("T=", 0) != 0) {  // e.g. --trace lines
      ++i;
      continue;
    }
    Frame frame{lines[i++], {}};
    auto starts = [&](char c) {
      return i < lines.size() && !lines[i].empty() && lines[i][0] == c;
    };
    if (starts('+')) {
      frame.screen.push_back(lines[i++]);
      while (starts('|')) frame.screen.push_back(lines[i++]);
      if (starts('+')) frame.screen.push_back(lines[i++]);
    }
    if (!frame.screen.empty()) frames.push_back(frame);
  }
  return frames;
}

// The distinct moments of the collisions in an --events file, in order: the
// moments at which a display step ended on a collision. (T is written in
// the fewest digits that read back to the same double.)
std::vector<double> collision_moments(const std::string& events_path) {
  std::vector<double> moments;
  const std::vector<std::string> lines = lines_of(read_file(events_path));
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const double t = std::stod(lines[i].substr(0, lines[i].find(',')));
    if (moments.empty() || moments.back() != t) moments.push_back(t);
  }
  return moments;
}

// Is the screen a box of '+', '-', '|' around its inside, every line as wide?
bool bordered(const std::vector<std::string>& screen) {
  if (screen.size() < 3) return false;
  const std::size_t width = screen.front().size();
  const std::regex edge("^\\+-+\\+$"), middle("^\\|.*\\|$");
  for (std::size_t i = 0; i < screen.size(); ++i) {
    if (screen[i].size() != width) return false;
    const bool end = i == 0 || i + 1 == screen.size();
    if (!std::regex_match(screen[i], end ? edge : middle)) return false;
  }
  return true;
}

}  // namespace

TEST_SUITE("console") {
  TEST_CASE("parse_options: no arguments means the default scene on the balls screen") {
    const gas::Options o = gas::parse_options({});
    CHECK_FALSE(o.scene_path);
    CHECK_FALSE(o.frames);
    CHECK_FALSE(o.until);
    CHECK_FALSE(o.keys);
    CHECK(o.mode == gas::ScreenMode::balls);
    CHECK_FALSE(o.step);
    CHECK_FALSE(o.trace);
    CHECK_FALSE(o.bell);
    CHECK_FALSE(o.help);
  }

  TEST_CASE("parse_options: every option and the --option=value spelling") {
    const gas::Options o = gas::parse_options(
        {"data/crowd.scene", "--frames", "12",       "--keys",  "..B<",
         "--mode",           "trails",   "--events", "e.csv",   "--dump",
         "d.scene",          "--csv",    "c.csv",    "--cols",  "100",
         "--rows",           "30",       "--step",   "--trace", "--bell"});
    CHECK(o.scene_path == "data/crowd.scene");
    CHECK(o.frames == 12);
    CHECK(o.keys == "..B<");
    CHECK(o.mode == gas::ScreenMode::trails);
    CHECK(o.events_path == "e.csv");
    CHECK(o.dump_path == "d.scene");
    CHECK(o.csv_path == "c.csv");
    CHECK(o.columns == 100);
    CHECK(o.rows == 30);
    CHECK(o.step);
    CHECK(o.trace);
    CHECK(o.bell);

    const gas::Options p =
        gas::parse_options({"--until=2.5", "--mode=stats", "--keys=", "--cols=8"});
    CHECK(p.until == 2.5);
    CHECK(p.mode == gas::ScreenMode::stats);
    CHECK(p.keys == "");
    CHECK(p.columns == 8);
    CHECK(gas::parse_options({"--mode", "balls"}).mode == gas::ScreenMode::balls);
    CHECK(gas::parse_options({"--frames", "0"}).frames == 0);
    CHECK(gas::parse_options({"--until", "0"}).until == 0);
    CHECK(gas::parse_options({"--help"}).help);
    CHECK(gas::parse_options({"-h"}).help);
    CHECK(gas::parse_options({}).drawn);
    CHECK_FALSE(gas::parse_options({"--mode", "none", "--until", "5"}).drawn);
    CHECK_FALSE(gas::parse_options({}).pictures);
    CHECK(gas::parse_options({"--pictures", "steps"}).pictures ==
          gas::PictureRule::display_steps);
    CHECK(gas::parse_options({"--pictures=collisions"}).pictures ==
          gas::PictureRule::every_collision);
  }

  TEST_CASE(
      "parse_options: bad command lines are refused with a message that names the "
      "problem") {
    CHECK(usage_error({"--frobnicate"}) == "unknown option '--frobnicate'");
    CHECK(usage_error({"-x"}) == "unknown option '-x'");
    CHECK(usage_error({"--frames"}) == "--frames needs a value");
    CHECK(usage_error({"data/default.scene", "--events"}) == "--events needs a value");
    CHECK(usage_error({"--frames", "-1"}) == "--frames must not be negative, not -1");
    CHECK(usage_error({"--until", "-0.5"}) == "--until must not be negative, not -0.5");
    CHECK(usage_error({"--mode", "fancy"}) ==
          "--mode takes balls, trails, stats or none, not 'fancy'");
    CHECK(usage_error({"--mode", "Balls"}) ==
          "--mode takes balls, trails, stats or none, not 'Balls'");
    CHECK(usage_error({"--frames", "3", "--until", "4"}) ==
          "--frames and --until exclude each other");
    CHECK(usage_error({"--mode", "none"}) ==
          "--mode none draws nothing: give it --until or --frames");
    CHECK(usage_error({"--pictures", "sometimes"}) ==
          "--pictures takes collisions or steps, not 'sometimes'");
    CHECK(usage_error({"--pictures"}) == "--pictures needs a value");
    CHECK(usage_error({"--frames", "five"}) ==
          "--frames takes a whole number, not 'five'");
    CHECK(usage_error({"--frames", "5x"}) == "--frames takes a whole number, not '5x'");
    CHECK(usage_error({"--frames", "2.5"}) == "--frames takes a whole number, not '2.5'");
    CHECK(usage_error({"--frames", ""}) == "--frames takes a whole number, not ''");
    // Numbers written right but too large: said as such.
    CHECK(usage_error({"--frames", "99999999999999999999"}) ==
          "--frames 99999999999999999999: too large (at most 9223372036854775807)");
    CHECK(usage_error({"--frames", "-99999999999999999999"}) ==
          "--frames -99999999999999999999: too small");
    CHECK(usage_error({"--cols", "99999999999999999999"}) ==
          "--cols 99999999999999999999: too large (at most 10000)");
    CHECK(usage_error({"--until", "1e999"}) ==
          "--until 1e999: too large (a double holds none beyond +-1.79769e+308)");
    CHECK(usage_error({"--until", "1e-999"}) ==
          "--until 1e-999: too near zero (a double holds none nearer than 4.94066e-324)");
    // An option given twice, whatever its values (-h is --help).
    CHECK(usage_error({"--until", "5", "--until", "6"}) == "--until is given twice");
    CHECK(usage_error({"--until=5", "--until", "5"}) == "--until is given twice");
    CHECK(usage_error({"--step", "--step"}) == "--step is given twice");
    CHECK(usage_error({"-h", "--help"}) == "--help is given twice");
    CHECK(usage_error({"--mode", "none", "--mode", "stats"}) == "--mode is given twice");
    // --keys: the keys of the keyboard and '.', nothing else.
    CHECK(usage_error({"--keys", "xyz"}) ==
          "--keys takes the keys S R B > < 0 E A (upper or lower case) and '.' for none, "
          "not 'x'");
    CHECK(usage_error({"--keys", "S. R"}) ==
          "--keys takes the keys S R B > < 0 E A (upper or lower case) and '.' for none, "
          "not ' '");
    CHECK(gas::parse_options({"--keys", "srb><0ea.SRB><0EA"}).keys ==
          "srb><0ea.SRB><0EA");
    // An empty file name, and an empty scene name.
    for (const char* option : {"--events", "--dump", "--csv", "--structure"}) {
      CHECK(usage_error({option, ""}) ==
            fmt::format("{} takes a file name, not an empty one", option));
      CHECK(usage_error({fmt::format("{}=", option)}) ==
            fmt::format("{} takes a file name, not an empty one", option));
    }
    CHECK(usage_error({""}) ==
          "an empty scene name: give a scene file or a teaching scene's name");
    CHECK(usage_error({"--until", "soon"}) ==
          "--until takes a finite number, not 'soon'");
    CHECK(usage_error({"--until", "inf"}) == "--until takes a finite number, not 'inf'");
    CHECK(usage_error({"--until", "nan"}) == "--until takes a finite number, not 'nan'");
    CHECK(usage_error({"--cols", "wide"}) == "--cols takes a whole number, not 'wide'");
    CHECK(usage_error({"--cols", "7"}) == "--cols takes a number from 8 to 10000, not 7");
    CHECK(usage_error({"--rows", "6"}) == "--rows takes a number from 7 to 10000, not 6");
    CHECK(usage_error({"--rows", "10001"}) ==
          "--rows takes a number from 7 to 10000, not 10001");
    CHECK(usage_error({"a.scene", "b.scene"}) ==
          "one scene only: 'a.scene' and 'b.scene'");
    CHECK(usage_error({"--trace=yes"}) == "--trace takes no value");
  }

  TEST_CASE(
      "the program: bad usage gives exit status 2 and a message on stderr and nothing on "
      "stdout") {
    const std::vector<std::vector<std::string>> bad = {
        {"--frobnicate"},
        {"--frames"},
        {"--frames", "-3"},
        {"--mode", "fancy"},
        {"--frames", "3", "--until", "4"},
        {"--until", "soon"},
        {"data/default.scene", "data/crowd.scene"},
    };
    for (const auto& arguments : bad) {
      CAPTURE(arguments.front());
      const auto run = run_program(arguments);
      CHECK(run.status == 2);
      CHECK(run.out.empty());
      CHECK(run.err ==
            fmt::format("gas: {}\nTry 'gas --help'.\n", usage_error(arguments)));
    }
  }

  TEST_CASE("the program: --help prints the help text and exits 0") {
    const auto run = run_program({"--help"});
    CHECK(run.status == 0);
    CHECK(run.err.empty());
    CHECK(run.out == gas::help_text());
    CHECK(run.out.find("usage: gas [SCENE]") != std::string::npos);
    for (const char* option :
         {"--frames", "--until", "--keys", "--mode", "--events", "--dump", "--csv",
          "--cols", "--rows", "--step", "--trace", "--bell"}) {
      CHECK(run.out.find(option) != std::string::npos);
    }
  }

  TEST_CASE(
      "the program: --frames 5 prints exactly five frames each a status line and a "
      "screen") {
    const auto run = run_program({"data/default.scene", "--frames", "5"});
    CHECK(run.status == 0);
    CHECK(run.err.empty());
    const std::vector<Frame> frames = frames_of(run.out);
    REQUIRE(frames.size() == 5);
    std::size_t lines = 0;
    for (std::size_t k = 0; k < frames.size(); ++k) {
      CAPTURE(k);
      // T0 = 1 in the default scene and its first collision is at T = 34.5:
      // the frames are at T = 1 ... 5.
      CHECK(frames[k].status.rfind(fmt::format("T={}.000000 T0=1 ", k + 1), 0) == 0);
      CHECK(bordered(frames[k].screen));
      CHECK(frames[k].screen.size() ==
            22);  // 24 rows, less the status line and the cursor's
      CHECK(frames[k].screen.front().size() <= 80);
      lines += 1 + frames[k].screen.size();
    }
    CHECK(lines == lines_of(run.out).size());  // nothing else printed
  }

  TEST_CASE("the program: E ends the run and a stopped run with no key left ends too") {
    const auto ended =
        run_program({"data/default.scene", "--keys", "..E", "--frames", "10"});
    CHECK(ended.status == 0);
    CHECK(frames_of(ended.out).size() == 2);

    // S stops: no frame while stopped; R starts again.
    const auto stopped =
        run_program({"data/default.scene", "--keys", ".S..R", "--frames", "3"});
    CHECK(stopped.status == 0);
    const std::vector<Frame> frames = frames_of(stopped.out);
    REQUIRE(frames.size() == 3);
    CHECK(frames[2].status.rfind("T=3.000000 ", 0) == 0);
    // The ticks of the stopped model (S and the two dots) marked by one
    // status line alone, between the first frame and the second.
    const std::vector<std::string> lines = lines_of(stopped.out);
    REQUIRE(lines.size() == 3 * 23 + 1);
    CHECK(
        lines[23] ==
        "T=1.000000 T0=1 collisions=0 (walls 0, balls 0) screen=balls [stopped 3 ticks]");
    CHECK(lines[24].rfind("T=2.000000 ", 0) == 0);

    const auto stuck =
        run_program({"data/default.scene", "--keys", ".S", "--frames", "10"});
    CHECK(stuck.status == 0);
    CHECK(frames_of(stuck.out).size() == 1);

    // B on a stopped model: reverse, change the tone, and go on computing
    // (the article's words): the run goes on, drawn in the other tone.
    const auto reversed =
        run_program({"data/default.scene", "--keys", ".SB", "--frames", "3"});
    CHECK(reversed.status == 0);
    const std::vector<Frame> after_b = frames_of(reversed.out);
    REQUIRE(after_b.size() == 3);
    auto other_tone = [](const Frame& frame) {
      for (const std::string& line : frame.screen)
        if (line.find('@') != std::string::npos) return true;
      return false;
    };
    CHECK_FALSE(other_tone(after_b[0]));
    CHECK(other_tone(after_b[1]));
  }

  TEST_CASE(
      "the program: a piped run takes 100 frames, or as many as its keys, --frames or "
      "--until ask") {
    // Its output a pipe and nothing said of its length: 100 frames, then the
    // run ends by itself (and does not fill a disk).
    const std::vector<std::string> small{"--cols", "20", "--rows", "9"};
    auto run = [&](std::vector<std::string> arguments) {
      arguments.insert(arguments.begin(), "data/default.scene");
      arguments.insert(arguments.end(), small.begin(), small.end());
      const auto result = run_program(arguments);
      CHECK(result.status == 0);
      return frames_of(result.out);
    };
    CHECK(run({}).size() == 100);
    // More than 100 keys: every one is pressed, one a frame; B is the 101st,
    // and from frame 101 the balls are drawn in the other tone ('@').
    const std::vector<Frame> keyed =
        run({"--keys", std::string(100, '.') + "B........."});
    REQUIRE(keyed.size() == 110);
    auto drawn_with = [](const Frame& frame, char glyph) {
      for (const std::string& line : frame.screen)
        if (line.find(glyph) != std::string::npos) return true;
      return false;
    };
    CHECK(drawn_with(keyed[99], 'O'));
    CHECK_FALSE(drawn_with(keyed[99], '@'));
    CHECK(drawn_with(keyed[100], '@'));
    CHECK_FALSE(drawn_with(keyed[100], 'O'));
    // --frames, above 100 or below the keys: that many.
    CHECK(run({"--frames", "130"}).size() == 130);
    CHECK(run({"--frames", "3", "--keys", std::string(110, '.')}).size() == 3);
    // --until past T = 100 (T0 = 1): frames up to T = 150, however many.
    const std::vector<Frame> until = run({"--until", "150"});
    CHECK(until.size() > 150);  // a frame at every T + T0, and at collisions
    CHECK(until.back().status.rfind("T=150.000000 ", 0) == 0);
  }

  TEST_CASE("scripted runs of every scene against golden outputs") {
    // name: the scene and the options, so that the file says how to remake it.
    struct Script {
      std::string golden;
      std::vector<std::string> arguments;
    };
    const std::vector<Script> scripts = {
        {"default--frames-3", {"data/default.scene", "--frames", "3"}},
        {"default--keys-..B..--frames-5--cols-60--rows-18",
         {"data/default.scene", "--keys", "..B..", "--frames", "5", "--cols", "60",
          "--rows", "18"}},
        {"one-ball--keys->>>>>>--frames-8--cols-40--rows-14",
         {"data/one-ball.scene", "--keys", ">>>>>>", "--frames", "8", "--cols", "40",
          "--rows", "14"}},
        {"head-on--trace--keys->>>>--frames-6--cols-40--rows-12",
         {"data/head-on.scene", "--trace", "--keys", ">>>>", "--frames", "6", "--cols",
          "40", "--rows", "12"}},
        {"crowd--frames-2--cols-60--rows-20",
         {"data/crowd.scene", "--frames", "2", "--cols", "60", "--rows", "20"}},
        {"crowd--mode-stats--frames-4--cols-60--rows-18",
         {"data/crowd.scene", "--mode", "stats", "--frames", "4", "--cols", "60",
          "--rows", "18"}},
        {"trajectories--mode-trails--keys->>>>--frames-14--cols-60--rows-20",
         {"data/trajectories.scene", "--mode", "trails", "--keys", ">>>>", "--frames",
          "14", "--cols", "60", "--rows", "20"}},
    };
    for (const Script& script : scripts) {
      CAPTURE(script.golden);
      const auto run = run_program(script.arguments);
      CHECK(run.status == 0);
      CHECK(run.err.empty());
      CHECK_FALSE(frames_of(run.out).empty());
      for (const Frame& frame : frames_of(run.out)) CHECK(bordered(frame.screen));
      check_golden("golden/runs/" + script.golden + ".txt", run.out);
    }
  }

  TEST_CASE(
      "--trace: stages 1, 2 and 3 before the first stage 4, with the scene's values") {
    // Head-on: N = 2, a = 4, the table A1 x A2 = 256 x 192, T0 = 1, so the
    // centres stay within 4 <= x <= 252 and 4 <= y <= 188. On 40 x 10
    // characters (12 rows less the status line and the cursor) a column is
    // max(256 / 38, 192 / (2 * 8)) = 12 long and a row 24; the table then
    // takes 22 x 8 characters inside the border.
    const auto run = run_program({"data/head-on.scene", "--trace", "--frames", "1",
                                  "--cols", "40", "--rows", "12"});
    REQUIRE(run.status == 0);
    const std::vector<std::string> lines = lines_of(run.out);
    const auto stage4 = std::find_if(lines.begin(), lines.end(), [](const auto& line) {
      return line.rfind("stage 4  ", 0) == 0;
    });
    REQUIRE(stage4 != lines.end());
    const std::vector<std::string> before_stage4(lines.begin(), stage4);
    const std::vector<std::string> expected = {
        "stage 1  variables and data: N=2 a=4 A1=256 A2=192 T=0 T0=1",
        "stage 2  input: 2 balls from data/head-on.scene",
        "stage 3  screen preparation: a=4 <= x <= G1=A1-a=252, a <= y <= G2=A2-a=188",
        "stage 3  screen preparation: 24 x 10 characters, border included",
        "stage 3  screen preparation: column 12, row 24",
    };
    CHECK(before_stage4 == expected);

    // The built-in scene is named as the file it was built from; one ball is
    // one ball; the statistics screen has no table to measure.
    const auto built_in = run_program({"--trace", "--frames", "1"});
    REQUIRE(lines_of(built_in.out).size() > 1);
    CHECK(lines_of(built_in.out)[1] ==
          "stage 2  input: 7 balls from data/default.scene (built in)");
    const auto stats = run_program({"data/one-ball.scene", "--trace", "--frames", "1",
                                    "--mode", "stats", "--cols", "30", "--rows", "9"});
    const std::vector<std::string> stats_lines = lines_of(stats.out);
    REQUIRE(stats_lines.size() > 4);
    CHECK(stats_lines[0] ==
          "stage 1  variables and data: N=1 a=4 A1=256 A2=192 T=0 T0=2");
    CHECK(stats_lines[1] == "stage 2  input: 1 ball from data/one-ball.scene");
    CHECK(stats_lines[3] ==
          "stage 3  screen preparation: 30 x 7 characters, border included");
    CHECK(stats_lines[4] == "stage 3  screen preparation: figures only, no table");
  }

  TEST_CASE(
      "--trace: stage 6 says 'frozen at the collision' at exactly the steps that end on "
      "one") {
    // The crowd (many collisions, each at a moment of its own), and the
    // touching balls (three collisions at T = 0, in one step: one mark).
    for (const std::string scene : {"data/crowd.scene", "data/edge/touching.scene"}) {
      CAPTURE(scene);
      const Scratch scratch;
      const std::string events = scratch.file("events.csv");
      const auto run = run_program({scene, "--trace", "--until", "60", "--cols", "30",
                                    "--rows", "9", "--events", events});
      REQUIRE(run.status == 0);
      const std::string plain = "stage 6  output: the balls screen";
      const std::string frozen = plain + ", frozen at the collision T = TC = ";
      std::vector<double> marked;
      std::size_t stage6_lines = 0;
      for (const std::string& line : lines_of(run.out)) {
        if (line.rfind("stage 6  ", 0) != 0) continue;
        ++stage6_lines;
        if (line.rfind(frozen, 0) == 0) {
          marked.push_back(std::stod(line.substr(frozen.size())));
        } else {
          CHECK(line == plain);
        }
      }
      CHECK(stage6_lines == frames_of(run.out).size());  // one a frame
      // T is printed shortest round-trip: each mark reads back to the same
      // double as the collision's moment in --events.
      const std::vector<double> moments = collision_moments(events);
      CHECK(moments.size() >= 1);
      CHECK(marked == moments);
    }
  }

  TEST_CASE(
      "the key 0: stage 3 again, so the trails screen after it holds the new step "
      "alone") {
    // Trails are never erased; after 0 the screen is prepared again, and the
    // ninth step draws its segments on an empty table. The same steps done
    // here give that screen exactly.
    auto with_keys = [](const std::string& keys) {
      const auto run =
          run_program({"data/trajectories.scene", "--mode", "trails", "--keys", keys,
                       "--frames", "9", "--cols", "60", "--rows", "20"});
      REQUIRE(run.status == 0);
      return frames_of(run.out);
    };
    const std::vector<Frame> redrawn = with_keys(">>>>....0");
    const std::vector<Frame> kept = with_keys(">>>>.....");
    REQUIRE(redrawn.size() == 9);
    REQUIRE(kept.size() == 9);

    gas::Control control = gas::start_control_for(
        gas::read_scene_file(source_path("data/trajectories.scene")));
    for (const char key : std::string(">>>>....")) {
      gas::press_key(control, key);
      gas::take_step(control, gas::never, nullptr);
    }
    gas::TextScreen screen = gas::prepare_screen(control.gas, 60, 18);  // stage 3
    gas::take_step(control, gas::never, nullptr);
    gas::draw_trails(screen, control.picture, gas::tones[0]);  // stage 6

    CHECK(redrawn[8].screen == screen.lines);
    CHECK(bordered(redrawn[8].screen));
    CHECK(redrawn[8].status == kept[8].status);  // the same step, T and all
    // Without 0 the earlier trails stay: there was something to clear.
    CHECK(kept[8].screen != redrawn[8].screen);
    auto trail_cells = [](const Frame& frame) {
      std::size_t cells = 0;
      for (const std::string& line : frame.screen)
        cells += std::count(line.begin(), line.end(), gas::tones[0].trail_glyph);
      return cells;
    };
    CHECK(trail_cells(redrawn[8]) < trail_cells(redrawn[7]));
  }

  TEST_CASE("the keys ..B..: after B the balls retrace their steps in the other tone") {
    // B is pressed before the third step, at T = 2, so the frame at T = 3
    // shows the balls where they were at T = 1 (no collision before T = 34).
    const auto run =
        run_program({"data/default.scene", "--keys", "..B..", "--frames", "5"});
    REQUIRE(run.status == 0);
    const std::vector<Frame> frames = frames_of(run.out);
    REQUIRE(frames.size() == 5);
    const char forward = gas::tones[0].ball_glyph, backward = gas::tones[1].ball_glyph;
    std::vector<std::string> retraced = frames[2].screen;
    for (std::string& line : retraced)
      std::replace(line.begin(), line.end(), backward, forward);
    CHECK(retraced == frames[0].screen);
    CHECK(frames[2].screen != frames[0].screen);  // it is drawn in the other glyph
    CHECK(run.out.find(backward) != std::string::npos);
  }

  TEST_CASE("--events and --csv: their headers and one row per collision and per frame") {
    // The crowd (many collisions), and the touching balls (three collisions
    // at T = 0, in one step).
    for (const std::string scene : {"data/crowd.scene", "data/edge/touching.scene"}) {
      CAPTURE(scene);
      const int balls_in_scene =
          static_cast<int>(gas::read_scene_file(source_path(scene)).balls.size());
      const Scratch scratch;
      const std::string events = scratch.file("events.csv"),
                        csv = scratch.file("stats.csv");
      const auto run = run_program(
          {scene, "--until", "60", "--mode", "stats", "--events", events, "--csv", csv});
      REQUIRE(run.status == 0);
      CHECK(run.err.empty());
      const std::vector<Frame> frames = frames_of(run.out);
      REQUIRE(!frames.empty());
      CHECK(frames.back().status.rfind("T=60.000000 ", 0) == 0);

      // The last status line says how many collisions there were.
      std::smatch counts;
      REQUIRE(std::regex_search(
          frames.back().status, counts,
          std::regex(R"(collisions=([0-9]+) \(walls ([0-9]+), balls ([0-9]+)\))")));
      const std::size_t collisions = std::stoul(counts[1]);
      CHECK(collisions >= 5);

      const std::vector<std::string> event_lines = lines_of(read_file(events));
      REQUIRE(event_lines.size() >= 1);
      CHECK(event_lines[0] == "T,K,N1,N2");
      CHECK(event_lines.size() - 1 == collisions);
      std::size_t walls = 0, balls = 0;
      double last = 0;
      for (std::size_t i = 1; i < event_lines.size(); ++i) {
        CAPTURE(event_lines[i]);
        double t = 0;
        int k = 0, n1 = 0, n2 = 0;
        REQUIRE(std::sscanf(event_lines[i].c_str(), "%lf,%d,%d,%d", &t, &k, &n1, &n2) ==
                4);
        CHECK(t >= last);  // in order of time
        CHECK(t <= 60);
        last = t;
        CHECK((k >= 1 && k <= 3));
        CHECK((n1 >= 1 && n1 <= balls_in_scene));
        if (k == 3) {
          CHECK((n2 > n1 && n2 <= balls_in_scene));
          ++balls;
        } else {
          CHECK(n2 == 0);
          ++walls;
        }
      }
      CHECK(walls == std::stoul(counts[2]));
      CHECK(balls == std::stoul(counts[3]));

      const std::vector<std::string> csv_lines = lines_of(read_file(csv));
      REQUIRE(csv_lines.size() >= 1);
      CHECK(csv_lines[0] == gas::csv_header() + gas::lyapunov_csv_header());
      CHECK(csv_lines.size() - 1 == frames.size());
      for (std::size_t i = 1; i < csv_lines.size(); ++i) {
        CHECK(std::count(csv_lines[i].begin(), csv_lines[i].end(), ',') ==
              std::count(csv_lines[0].begin(), csv_lines[0].end(), ','));
      }
      CHECK(csv_lines.back().rfind("60,", 0) == 0);
    }
  }

  TEST_CASE(
      "--events: every T, in its shortest round-trip digits, reads back to the very "
      "double the stages computed") {
    // The crowd to T = 200 (hundreds of collisions, each at a moment of its own,
    // most needing 15 to 17 digits) and the default scene: the same run done
    // here, collision by collision; each line's T read back must be that
    // collision's TC bit for bit (== on doubles, no tolerance: fewer digits
    // than the double needs would read back to a neighbouring double).
    for (const std::string scene : {"data/crowd.scene", "data/default.scene"}) {
      CAPTURE(scene);
      const Scratch scratch;
      const std::string events = scratch.file("events.csv");
      REQUIRE(run_program({scene, "--until", "200", "--mode", "none", "--events", events})
                  .status == 0);
      const std::vector<std::string> lines = lines_of(read_file(events));

      gas::Control control =
          gas::start_control_for(gas::read_scene_file(source_path(scene)));
      std::vector<gas::Collision> done;
      while (control.gas.time < 200) {
        const gas::Step step = gas::take_step(control, 200, nullptr);
        done.insert(done.end(), step.collisions.begin(), step.collisions.end());
      }
      REQUIRE(done.size() >= 10);
      REQUIRE(lines.size() == done.size() + 1);
      for (std::size_t i = 0; i < done.size(); ++i) {
        const std::string& line = lines[i + 1];
        CAPTURE(line);
        const std::string t = line.substr(0, line.find(','));
        CHECK(std::strtod(t.c_str(), nullptr) == done[i].time);
        CHECK(line.substr(t.size()) == fmt::format(",{},{},{}",
                                                   static_cast<int>(done[i].kind),
                                                   done[i].first, done[i].second));
      }
    }
  }

  TEST_CASE(
      "an --events line written fast is fmt's \"{},{},{},{}\" of the collision, to the "
      "character") {
    // write_event_line lays out T itself (from fmt's own shortest digits) for
    // exponents -4 to 15 and leaves the rest to fmt: every case of its layout
    // (digits only, a point inside, 0.000 before), each edge of its range,
    // the values it leaves to fmt, and a million moments at random, both
    // from every exponent a double has (any bit pattern) and from a run's
    // range 0 to 10^5; the integers at each change of their digit count.
    std::mt19937_64 random(22);
    std::vector<double> times = {0.0,
                                 -0.0,
                                 1e-4,
                                 9.9999999999999991e-5,
                                 0.00012,
                                 0.5,
                                 1,
                                 10,
                                 123400,
                                 1e15,
                                 9999999999999998.0,
                                 1e16,
                                 1.2345678901234567e16,
                                 5e-324,
                                 2.2250738585072014e-308,
                                 std::numeric_limits<double>::max(),
                                 -3.25,
                                 gas::never,
                                 -gas::never,
                                 std::numeric_limits<double>::quiet_NaN(),
                                 0.1 + 0.2,
                                 4545.454545454545,
                                 1e-300,
                                 123456789012345680.0};
    std::uniform_real_distribution<double> run_range(0, 1e5);
    for (int i = 0; i < 500000; ++i) {
      times.push_back(std::bit_cast<double>(random()));
      times.push_back(run_range(random));
    }
    std::vector<int> numbers = {0, 1, -1, std::numeric_limits<int>::max(),
                                std::numeric_limits<int>::min()};
    for (int power = 10;; power *= 10) {  // 10 ... 10^9 (10^10 is past an int)
      for (const int n : {power - 1, power, power + 1, -power}) numbers.push_back(n);
      if (power > std::numeric_limits<int>::max() / 10) break;
    }
    char line[gas::longest_event_line];
    std::size_t checked = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
      const gas::Collision c{times[i], static_cast<gas::CollisionKind>(i % 4),
                             numbers[i % numbers.size()],
                             numbers[(i / numbers.size() + i) % numbers.size()]};
      const std::string expected = fmt::format(
          "{},{},{},{}\n", c.time, static_cast<int>(c.kind), c.first, c.second);
      const std::string written(line, gas::write_event_line(line, c));
      if (written != expected) {
        CAPTURE(expected);
        CHECK(written == expected);
      }
      ++checked;
    }
    CHECK(checked == times.size());
  }

  TEST_CASE(
      "--dump writes a scene that read_scene_file accepts: the same gas as the run") {
    const Scratch scratch;
    const std::string dump = scratch.file("dump.scene");
    const auto run =
        run_program({"data/default.scene", "--frames", "50", "--dump", dump});
    REQUIRE(run.status == 0);
    const gas::Gas dumped = gas::read_scene_file(dump);
    CHECK(dumped.balls.size() == 7);

    // The same 50 steps here (some end on a collision, so T < 50): the dump
    // is this gas's scene text, to the byte.
    gas::Control control =
        gas::start_control_for(gas::read_scene_file(source_path("data/default.scene")));
    for (int k = 0; k < 50; ++k) gas::take_step(control, gas::never, nullptr);
    REQUIRE(control.wall_collisions + control.ball_collisions > 0);
    CHECK(read_file(dump) == gas::scene_text(control.gas));

    // And the dumped scene runs on as the original would.
    const auto again = run_program({dump, "--frames", "1"});
    CHECK(again.status == 0);
    CHECK(again.err.empty());
  }

  TEST_CASE(
      "a dump continues the run: to T1 with --dump, on from the dump to T2, the same "
      "collision lines as one run to T2, bit for bit") {
    const Scratch scratch;
    // The lines of an events file after its header.
    auto events = [](const std::string& path) {
      std::vector<std::string> lines = lines_of(read_file(path));
      REQUIRE(!lines.empty());
      CHECK(lines[0] == "T,K,N1,N2");
      lines.erase(lines.begin());
      return lines;
    };
    auto check_continues = [&](const std::vector<std::string>& scene,
                               const std::string& t1, const std::string& t2) {
      CAPTURE(t1);
      const std::string whole = scratch.file("whole.csv"), first = scratch.file("1.csv"),
                        second = scratch.file("2.csv"), dump = scratch.file("d.scene");
      auto with = [&](std::vector<std::string> arguments) {
        arguments.insert(arguments.begin(), scene.begin(), scene.end());
        return arguments;
      };
      REQUIRE(run_program(with({"--until", t2, "--events", whole})).status == 0);
      REQUIRE(
          run_program(with({"--until", t1, "--events", first, "--dump", dump})).status ==
          0);
      // --until is a moment of model time: the dump starts at T1, so "to T2".
      REQUIRE(run_program({dump, "--until", t2, "--events", second}).status == 0);
      std::vector<std::string> continued = events(first);
      const std::vector<std::string> after = events(second);
      REQUIRE(!after.empty());  // the test is about the collisions after the dump
      continued.insert(continued.end(), after.begin(), after.end());
      const std::vector<std::string> uninterrupted = events(whole);
      REQUIRE(continued.size() == uninterrupted.size());
      for (std::size_t i = 0; i < continued.size(); ++i) {
        CAPTURE(i);
        CHECK(continued[i] == uninterrupted[i]);
      }
    };
    // The moment of a collision, as --events writes it (shortest round-trip: the same
    // double again), to stop the first run exactly on it.
    auto collision_time = [&](const std::vector<std::string>& scene, std::size_t k) {
      const std::string path = scratch.file("k.csv");
      std::vector<std::string> arguments = scene;
      for (const char* word : {"--until", "1000", "--events"}) arguments.push_back(word);
      arguments.push_back(path);
      REQUIRE(run_program(arguments).status == 0);
      const std::vector<std::string> lines = events(path);
      REQUIRE(lines.size() > k);
      return lines[k].substr(0, lines[k].find(','));
    };

    SUBCASE("the default scene") {
      const std::vector<std::string> seven;  // the built-in scene
      for (const std::string t1 : {"7.25", "100", "1000"})
        check_continues(seven, t1, "1500");
      check_continues(seven, collision_time(seven, 40), "1500");
    }
    SUBCASE("the crowd") {
      const std::vector<std::string> crowd = {"data/crowd.scene"};
      for (const std::string t1 : {"7.25", "100"}) check_continues(crowd, t1, "250");
      check_continues(crowd, collision_time(crowd, 150), "250");
    }
  }

  TEST_CASE(
      "a dump read back: the first frame's status line shows its T, and --until "
      "at or before it takes no step") {
    const Scratch scratch;
    const std::string dump = scratch.file("d.scene");
    REQUIRE(run_program({"--until", "123.5", "--dump", dump}).status == 0);
    const auto frame = run_program({dump, "--frames", "1"});
    REQUIRE(frame.status == 0);
    CHECK(frame.out.rfind("T=124.500000 T0=1 ", 0) == 0);  // 123.5 and one step
    const std::string again = scratch.file("again.scene");
    REQUIRE(run_program({dump, "--until", "100", "--dump", again}).status == 0);
    CHECK(read_file(again) == read_file(dump));
  }

  TEST_CASE(
      "an output file that cannot be written is an error (exit 1) before any frame") {
    const auto run = run_program(
        {"data/default.scene", "--frames", "1", "--events", "/no-such-dir/e.csv"});
    CHECK(run.status == 1);
    CHECK(run.out.empty());
    CHECK(run.err == "gas: /no-such-dir/e.csv: cannot write this file\n");
  }

  TEST_CASE("--bell: a bell for a run with collisions, and none without --bell") {
    // The crowd has collisions before T = 60 (the --events test counts them).
    const auto rung = run_program({"data/crowd.scene", "--bell", "--until", "60",
                                   "--mode", "stats", "--cols", "8", "--rows", "7"});
    REQUIRE(rung.status == 0);
    CHECK(std::count(rung.out.begin(), rung.out.end(), '\a') >= 1);

    const auto silent = run_program({"data/crowd.scene", "--until", "60", "--mode",
                                     "stats", "--cols", "8", "--rows", "7"});
    REQUIRE(silent.status == 0);
    CHECK(std::count(silent.out.begin(), silent.out.end(), '\a') == 0);
  }

  TEST_CASE("--bell: at most one bell every bell_interval_seconds") {
    using Clock = std::chrono::steady_clock;
    using std::chrono::milliseconds;
    const auto interval = std::chrono::duration<double>(gas::bell_interval_seconds);

    SUBCASE("bell_may_ring: only once the interval has passed since the last ring") {
      const Clock::time_point last = Clock::time_point{} + std::chrono::hours(1);
      CHECK_FALSE(gas::bell_may_ring(last, last));
      CHECK_FALSE(gas::bell_may_ring(last, last + milliseconds(149)));
      CHECK(gas::bell_may_ring(last, last + milliseconds(151)));

      // A collision every 7 ms for a second, the bell rung as RunOutputs does
      // (it starts with "last rang" at the clock's epoch, long ago): rings at
      // 0, 154, 308, 462, 616, 770 and 924 ms, each the first multiple of 7
      // at least 150 ms after the last (no moment falls on the boundary).
      Clock::time_point rang{};
      std::vector<long long> rings;
      for (int ms = 0; ms <= 1000; ms += 7) {
        const Clock::time_point now = last + milliseconds(ms);
        if (gas::bell_may_ring(rang, now)) {
          rings.push_back(ms);
          rang = now;
        }
      }
      CHECK(rings == std::vector<long long>{0, 154, 308, 462, 616, 770, 924});
    }

    SUBCASE("the program: hundreds of collision steps in a fraction of a second") {
      // The crowd until T = 500: about 600 steps end on a collision, and the
      // whole run (process start included) takes a tenth of a second or so.
      // Bells at least an interval apart, all within `elapsed`, number at
      // most elapsed / interval + 1: a sure bound, no tolerance needed.
      const Scratch scratch;
      const std::string events = scratch.file("events.csv");
      const auto start = Clock::now();
      const auto run =
          run_program({"data/crowd.scene", "--bell", "--until", "500", "--mode", "stats",
                       "--cols", "8", "--rows", "7", "--events", events});
      const auto elapsed = Clock::now() - start;
      REQUIRE(run.status == 0);
      const double most_bells = elapsed / interval + 1;
      const auto bells = std::count(run.out.begin(), run.out.end(), '\a');
      CAPTURE(most_bells);
      CHECK(bells >= 1);
      CHECK(static_cast<double>(bells) <= most_bells);
      // The check means something only if a bell at every collision step
      // would break it (it would, unless the run took about a minute).
      CHECK(static_cast<double>(collision_moments(events).size()) > most_bells);
    }
  }

}  // TEST_SUITE
