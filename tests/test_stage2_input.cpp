// Stage 2 of the article, "input": the scene-file reader.
//
// - Every teaching scene (data/*.scene) and every edge scene (data/edge/)
//   is accepted, with as many balls as the file has 'ball' lines (and as
//   its 'random' line places: the whole reader, beyond/random_placement).
// - Every malformed scene (data/bad/) is refused by the program: exit status
//   2, nothing on standard output, and on standard error one line
//   "FILE:LINE: what is wrong" equal to the golden file beside the scene
//   (data/bad/NAME.err), whose LINE is the one the scene's comment names.
// - Stage 2's own reader on text in memory (parse_scene_description, then
//   build_gas): comments, blank lines, tabs, N optional, a missing keyword
//   named, CRLF and a byte-order mark, the contact tolerance for touching
//   balls; a 'random' line kept as a request that build_gas refuses.
// - A missing file and a directory given as the scene.
// - scene_text and stage 2 round-trip every number bit for bit: T and every
//   ball's row with its `since`, also after runs of the default scene, the
//   crowd and large-1000 (the --dump checkpoint).
// - A scene's T and a ball's SINCE: the rows kept as written, the checks made
//   on the centres at T; a scene without them means what it always meant.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "stage2_input.hpp"
#include "stage7_control.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;
using gas::testing::check_golden;
using gas::testing::read_file;
using gas::testing::run_program;
using gas::testing::source_path;

// The files NAME.`extension` directly in data/`folder`, sorted by name.
std::vector<std::string> files_in(const std::string& folder,
                                  const std::string& extension) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(source_path("data/" + folder))) {
    if (entry.is_regular_file() && entry.path().extension() == extension) {
      names.push_back(entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The number of 'ball' lines of a scene file, counted without stage 2: the
// first word of each line, after cutting comments and a CR; plus the COUNT of
// a 'random' line.
std::size_t count_ball_lines(const std::string& text) {
  std::size_t count = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    line = line.substr(0, line.find('#'));
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 5, "ball ") == 0) ++count;
    // 'random COUNT SEED SPEED' and 'lattice COUNT SEED SPEED' place COUNT balls.
    for (const std::string keyword : {"random ", "lattice "}) {
      if (first != std::string::npos && line.compare(first, keyword.size(), keyword) == 0)
        count += std::stoul(line.substr(first + keyword.size()));
    }
    start = end + 1;
  }
  return count;
}

// The gas of scene text, read by stage 2 alone.
gas::Gas read_text(const std::string& text, const std::string& name = "t.scene") {
  return gas::build_gas(gas::parse_scene_description(text, name));
}

// What stage 2 says about `text`: its message, or "" if it accepts it.
std::string refusal(const std::string& text, const std::string& name = "t.scene") {
  try {
    read_text(text, name);
  } catch (const gas::SceneError& error) {
    return error.what();
  }
  return "";
}

// The bits of a double: "the same number" below means the same bits.
std::uint64_t bits(double value) {
  return std::bit_cast<std::uint64_t>(value);
}

const std::string small_table = "a 4\nT0 1\nA1 100\nA2 100\n";

}  // namespace

TEST_SUITE("stage2") {
  TEST_CASE("every scene in data/ and data/edge/ is accepted with all its balls") {
    std::vector<std::string> paths;
    for (const std::string& name : files_in("", ".scene")) paths.push_back(name);
    for (const std::string& name : files_in("edge", ".scene"))
      paths.push_back("edge/" + name);
    // default, one-ball, head-on, crowd, trajectories; crlf-bom, touching.
    REQUIRE(paths.size() >= 7);
    for (const std::string& path : paths) {
      CAPTURE(path);
      const std::string full = source_path("data/" + path);
      gas::Gas gas;
      REQUIRE_NOTHROW(gas = gas::read_scene_file(full));
      CHECK(gas.balls.size() == count_ball_lines(read_file(full)));
      CHECK(gas.balls.size() >= 1);
      CHECK(gas.time == 0);
    }
  }

  TEST_CASE("the crowd scene holds 40 to 60 balls") {
    const gas::Gas crowd = gas::read_scene_file(source_path("data/crowd.scene"));
    CHECK(crowd.balls.size() >= 40);
    CHECK(crowd.balls.size() <= 60);
  }

  TEST_CASE(
      "every scene in data/bad/ is refused with exit 2 and its golden FILE:LINE: "
      "message") {
    const std::vector<std::string> names = files_in("bad", ".scene");
    REQUIRE(names.size() >= 15);
    for (const std::string& name : names) {
      CAPTURE(name);
      const std::string path =
          "data/bad/" + name;  // as a student types it, from the source dir
      const auto run = run_program({path, "--frames", "1"});
      CHECK(run.status == 2);
      CHECK(run.out.empty());

      // One line: "data/bad/NAME.scene:LINE: what is wrong".
      std::smatch match;
      const std::string escaped = std::regex_replace(path, std::regex(R"([.])"), R"(\.)");
      const std::regex shape(fmt::format(R"(^{}:([0-9]+): [^\n]+\n$)", escaped));
      REQUIRE_MESSAGE(std::regex_match(run.err, match, shape), "stderr: " << run.err);

      // The line is the one the scene's own comment names, "(line N)"; an
      // empty file has only line 1.
      const std::string text = read_file(source_path(path));
      std::smatch named;
      const int expected_line =
          std::regex_search(text, named, std::regex(R"(line ([0-9]+)\))"))
              ? std::stoi(named[1])
              : 1;
      CHECK(std::stoi(match[1]) == expected_line);

      // The library says the same as the program (here with the full path:
      // the tests may run in another directory).
      const std::string same =
          source_path(path) +
          run.err.substr(path.size(), run.err.size() - path.size() - 1);
      CHECK_THROWS_WITH_AS(gas::read_scene_file(source_path(path)), same.c_str(),
                           gas::SceneError);

      check_golden("bad/" + fs::path(name).replace_extension(".err").string(), run.err);
    }
    // And no golden message is left without its scene.
    for (const std::string& err : files_in("bad", ".err")) {
      CAPTURE(err);
      CHECK(fs::exists(
          source_path("data/bad/" + fs::path(err).replace_extension(".scene").string())));
    }
  }

  TEST_CASE(
      "parse_scene_description: comments anywhere and blank lines and tabs and N "
      "optional") {
    const std::string text =
        "# a comment line\n"
        "\n"
        "   \t  \n"
        "a\t4   # the radius\n"
        "T0 0.5#no space before the comment\n"
        "  A1 100\n"
        "A2 80\n"
        "ball 10 20 1.5 -2   # first\n"
        "# ball 50 50 0 0    (commented out: not a ball)\n"
        "ball\t30\t40\t-0.25\t0\n";
    const gas::Gas gas = read_text(text);
    CHECK(gas.radius == 4);
    CHECK(gas.display_step == 0.5);
    CHECK(gas.width == 100);
    CHECK(gas.height == 80);
    REQUIRE(gas.balls.size() == 2);
    CHECK(gas.balls[0].x == 10);
    CHECK(gas.balls[0].y == 20);
    CHECK(gas.balls[0].vx == 1.5);
    CHECK(gas.balls[0].vy == -2);
    CHECK(gas.balls[1].x == 30);
    CHECK(gas.balls[1].vx == -0.25);
    CHECK(gas.balls[1].since == 0);

    // With N equal to the count, the same gas; N is optional.
    const gas::Gas with_n = read_text("N 2\n" + text);
    CHECK(with_n.balls.size() == 2);
    CHECK(refusal("N 3\n" + text) == "t.scene:1: N = 3 but the file has 2 'ball' lines");
  }

  TEST_CASE("parse_scene_description: each missing keyword is named at the last line") {
    const std::string ball = "ball 50 50 1 0\n";
    const std::vector<std::pair<std::string, std::string>> lines = {
        {"a", "a 4\n"}, {"T0", "T0 1\n"}, {"A1", "A1 100\n"}, {"A2", "A2 100\n"}};
    for (const auto& left_out : lines) {
      const std::string& missing = left_out.first;
      CAPTURE(missing);
      std::string text;
      for (const auto& [keyword, line] : lines) {
        if (keyword != missing) text += line;
      }
      text += ball;  // line 4: three keyword lines and the ball
      const std::string message = refusal(text);
      CHECK(message.rfind("t.scene:4: missing '" + missing + "'", 0) == 0);
    }
  }

  TEST_CASE(
      "parse_scene_description: CRLF line ends and a UTF-8 byte-order mark read like "
      "plain LF") {
    const std::string lf =
        small_table + "# comment\n\nball 20 30 1 -1   # a ball\nball 60 30 0 2\n";
    std::string crlf = "\xEF\xBB\xBF";
    for (const char c : lf) {
      if (c == '\n') crlf += '\r';
      crlf += c;
    }
    const gas::Gas plain = read_text(lf, "lf.scene");
    const gas::Gas windows = read_text(crlf, "crlf.scene");
    CHECK(gas::scene_text(windows) == gas::scene_text(plain));

    // The lines are still counted right: the error names the same line.
    CHECK(refusal(lf + "bogus 1\n", "f") ==
          "f:9: unknown keyword 'bogus' (expected a, T0, A1, A2, N, ball, random or "
          "lattice)");
    CHECK(refusal(crlf + "bogus 1\r\n", "f") == refusal(lf + "bogus 1\n", "f"));

    // A byte-order mark is only skipped at the very start; elsewhere it is a
    // stray byte, shown escaped.
    CHECK(refusal(small_table + "\xEF\xBB\xBF"
                                "ball 20 30 1 1\n",
                  "f") ==
          "f:5: unknown keyword '\\xef\\xbb\\xbfball' (expected a, T0, A1, A2, N, ball, "
          "random or lattice)");
  }

  TEST_CASE(
      "parse_scene_description: touching balls are accepted within contact_tolerance and "
      "overlaps "
      "refused") {
    // Distances as fractions of the diameter 2a = 8. Half the tolerance is
    // well inside it (a rounding error of a decimal scene is far smaller);
    // 1e-6 of a diameter is 1000 times the tolerance, and must be refused.
    const double diameter = 8;
    auto two_balls = [&](double distance) {
      return small_table +
             fmt::format("ball 30 50 1 0\nball {:.17g} 50 -1 0\n", 30 + distance);
    };
    CHECK(refusal(two_balls(diameter)).empty());
    CHECK(refusal(two_balls(diameter * (1 - gas::contact_tolerance / 2))).empty());
    const std::string overlap = refusal(two_balls(diameter * (1 - 1e-6)));
    CHECK(overlap.rfind("t.scene:6: ball 2 overlaps ball 1 (line 5)", 0) == 0);
    CHECK(
        refusal(two_balls(7)) ==
        "t.scene:6: ball 2 overlaps ball 1 (line 5): centres 7 apart, less than 2a = 8");

    // The 3-4-5 diagonal of data/edge/touching.scene: 8 apart in decimal, a
    // hair closer in binary.
    const double dx = 26.4 - 20, dy = 55.3 - 50.5;
    REQUIRE(dx * dx + dy * dy < 64);  // so the tolerance is what accepts it
    CHECK(refusal(small_table + "ball 20 50.5 0 0\nball 26.4 55.3 0 0\n").empty());

    // The same tolerance at a wall: a centre a hair beyond a, or visibly beyond.
    auto at_x = [&](double x) {
      return small_table + fmt::format("ball {:.17g} 50 0 0\n", x);
    };
    CHECK(refusal(at_x(4)).empty());
    CHECK(refusal(at_x(4 - diameter * gas::contact_tolerance / 2)).empty());
    CHECK(refusal(at_x(4 - diameter * 1e-6))
              .rfind("t.scene:5: ball 1: its centre x = ", 0) == 0);
    CHECK(refusal(at_x(96 + diameter * 1e-6))
              .rfind("t.scene:5: ball 1: its centre x = ", 0) == 0);
  }

  TEST_CASE(
      "a missing scene file and a directory are refused clearly with exit status 2") {
    const auto missing = run_program({"data/no-such.scene", "--frames", "1"});
    CHECK(missing.status == 2);
    CHECK(missing.out.empty());
    // Not a file: looked for by name too, in the source tree's data/
    // (program/scene_lookup.hpp), and the message says where.
    CHECK(missing.err ==
          fmt::format("data/no-such.scene: no such scene file (looked in the "
                      "current folder and at {})\n",
                      source_path("data/data/no-such.scene")));

    const auto directory = run_program({"data/edge", "--frames", "1"});
    CHECK(directory.status == 2);
    CHECK(directory.out.empty());
    CHECK(directory.err == "data/edge: is a directory, not a scene file\n");

    CHECK_THROWS_AS(gas::read_scene_file(source_path("data/no-such.scene")),
                    gas::SceneError);
    CHECK_THROWS_AS(gas::read_scene_file(source_path("data")), gas::SceneError);
  }

  TEST_CASE("scene_text then stage 2 gives back the very same gas, every double") {
    // A --dump is a checkpoint: T, and every ball's row as the run keeps it
    // (x, y at its own moment `since`, vx, vy, since) must come back bit for
    // bit, or the continued run is soon another one (lesson 9). Awkward
    // numbers: thirds and tenths (not exact in binary), the tiniest and
    // largest magnitudes stage 2 accepts, a negative zero, and random ones
    // (fixed seed), some with a `since` before T.
    gas::Gas g;
    g.radius = 1.0 / 3;
    g.width = 1000.1;
    g.height = 700.0 / 3;
    g.display_step = 0.1;
    // T: awkward too, and early enough that the clock can follow a ball at
    // 9.9e74 (stage 2 refuses a T later than 2^32 quickest crossings of the
    // table, here about 1e-63).
    g.time = 1.2345678901234567e-64;
    const std::vector<double> awkward = {1.0 / 3,    0.1,      1.7e-75, -0.0,
                                         1e15 + 0.5, -2.0 / 7, 9.9e74};
    for (std::size_t i = 0; i < awkward.size(); ++i) {
      // Written at T: with speeds up to 9.9e74 any flight would leave the table.
      const double x = 1 + 2 * static_cast<double>(i) + 1.0 / 7;
      g.balls.push_back(
          {x, 100 + x / 3, awkward[i], -awkward[awkward.size() - 1 - i], g.time});
    }
    std::mt19937_64 random(1989);
    std::uniform_real_distribution<double> across(20, 980), down(20, 213), speed(-3, 3),
        before(0, 5);
    while (g.balls.size() < 40) {
      // The centre at T is (x, y); the row is where the ball was at `since`.
      const double x = across(random), y = down(random);
      const double vx = speed(random), vy = speed(random), flight = before(random);
      const gas::Ball b{x - vx * flight, y - vy * flight, vx, vy, g.time - flight};
      bool free = true;
      for (const gas::Ball& other : g.balls) {
        const gas::Point p = gas::centre_at(other, g.time);
        free = free && std::hypot(x - p.x, y - p.y) > 1;
      }
      if (free) g.balls.push_back(b);
    }

    auto same = [](const gas::Gas& back, const gas::Gas& original) {
      CHECK(bits(back.radius) == bits(original.radius));
      CHECK(bits(back.width) == bits(original.width));
      CHECK(bits(back.height) == bits(original.height));
      CHECK(bits(back.display_step) == bits(original.display_step));
      CHECK(bits(back.time) == bits(original.time));
      REQUIRE(back.balls.size() == original.balls.size());
      for (std::size_t i = 0; i < back.balls.size(); ++i) {
        CAPTURE(i);
        CHECK(bits(back.balls[i].x) == bits(original.balls[i].x));
        CHECK(bits(back.balls[i].y) == bits(original.balls[i].y));
        CHECK(bits(back.balls[i].vx) == bits(original.balls[i].vx));
        CHECK(bits(back.balls[i].vy) == bits(original.balls[i].vy));
        CHECK(bits(back.balls[i].since) == bits(original.balls[i].since));
      }
    };
    // `scene` run to model time `until` (stopping there exactly), then
    // written and read back.
    auto run_and_round_trip = [&](const gas::Gas& scene, double until) {
      CAPTURE(until);
      gas::Control control = gas::start_control_for(scene);
      while (control.gas.time < until) gas::take_step(control, until, nullptr);
      REQUIRE(control.wall_collisions + control.ball_collisions > 0);
      same(read_text(gas::scene_text(control.gas), "round"), control.gas);
    };

    SUBCASE("awkward numbers, rows written before T") {
      same(read_text(gas::scene_text(g), "round"), g);
    }
    SUBCASE("the same at T = 0") {
      g.time = 0;
      for (gas::Ball& ball : g.balls) ball.since = 0;
      same(read_text(gas::scene_text(g), "round"), g);
    }
    SUBCASE("the default scene, run to several times") {
      const gas::Gas seven = gas::read_scene_file(source_path("data/default.scene"));
      for (const double until : {40.0, 123.25, 1000.0, 5000.0 / 3})
        run_and_round_trip(seven, until);
    }
    SUBCASE("the crowd and 1000 random balls") {
      run_and_round_trip(gas::read_scene_file(source_path("data/crowd.scene")), 123.25);
      run_and_round_trip(gas::read_scene_file(source_path("data/large-1000.scene")),
                         20.5);
    }
  }

  TEST_CASE(
      "a scene's T and a ball's SINCE: rows kept as written, every check at T, and "
      "without them a scene means what it always meant") {
    // The old form: T = 0, and each row written at T.
    const gas::Gas old = read_text(small_table + "ball 50 60 1 -2\n");
    CHECK(old.time == 0);
    CHECK(old.balls[0].since == 0);
    CHECK(old.balls[0].x == 50);

    // A 'T' line alone: the rows without SINCE are centres at T.
    const gas::Gas later = read_text("T 10\n" + small_table + "ball 50 60 1 -2\n");
    CHECK(later.time == 10);
    CHECK(later.balls[0].since == 10);
    CHECK(later.balls[0].x == 50);

    // A row written at SINCE = 4: kept as it is, although its (x, y) = (2, 60)
    // is outside the table (a = 4); at T = 10 the centre (8, 60) is inside.
    const gas::Gas flown =
        read_text("T 10\n" + small_table + "ball 2 60 1 0 4\nball 20 60 0 0\n");
    CHECK(flown.balls[0].x == 2);
    CHECK(flown.balls[0].since == 4);
    CHECK(flown.balls[1].since == 10);

    // Rows that overlap as written (both at (50, 50)) but not at T = 10:
    // ball 1 has flown 10 to the left since 0, ball 2 stood.
    const gas::Gas apart =
        read_text("T 10\n" + small_table + "ball 50 50 -1 0 0\nball 50 50 0 0 10\n");
    CHECK(apart.balls.size() == 2);

    // SINCE = T is allowed (a row just written), and 'T 0' is the default.
    CHECK(read_text("T 0\n" + small_table + "ball 50 50 1 0 0\n").balls[0].since == 0);
  }

  TEST_CASE(
      "parse_scene_description keeps a 'random' line as a request that build_gas "
      "refuses") {
    const std::string text = small_table + "ball 50 50 1 0\nrandom 3 1989 2.5\n";
    const gas::SceneDescription scene = gas::parse_scene_description(text, "r.scene");
    CHECK(scene.file_name == "r.scene");
    // The gas holds the 'ball' lines only; the request waits to be placed.
    REQUIRE(scene.gas.balls.size() == 1);
    CHECK(scene.gas.balls[0].x == 50);
    CHECK(scene.gas.radius == 4);
    REQUIRE(scene.random.has_value());
    CHECK(scene.random->count == 3);
    CHECK(scene.random->seed == 1989);
    CHECK(scene.random->speed == 2.5);
    CHECK(scene.random->line == 6);
    CHECK_THROWS_WITH_AS(gas::build_gas(scene),
                         "r.scene:6: 'random' asks for balls that stage 2 does not "
                         "place: read the scene with parse_scene or read_scene_file "
                         "(beyond/random_placement.hpp)",
                         gas::SceneError);
    // The whole reader places them, after the 'ball' line's ball.
    const gas::Gas placed = gas::parse_scene(text, "r.scene");
    REQUIRE(placed.balls.size() == 4);
    CHECK(placed.balls[0].x == 50);
    // Without the line there is no request, and build_gas gives the gas.
    const gas::SceneDescription plain =
        gas::parse_scene_description(small_table + "ball 50 50 1 0\n", "p.scene");
    CHECK_FALSE(plain.random.has_value());
    CHECK(gas::scene_text(gas::build_gas(plain)) == gas::scene_text(plain.gas));
  }

  TEST_CASE(
      "every scene without a 'random' line: stage 2 alone gives the gas the whole "
      "reader gives") {
    std::size_t without_random = 0;
    for (const std::string& name : files_in("", ".scene")) {
      CAPTURE(name);
      const std::string path = source_path("data/" + name);
      const gas::SceneDescription scene = gas::read_scene_description(path);
      if (scene.random) {
        CHECK_THROWS_AS(gas::build_gas(scene), gas::SceneError);
        continue;
      }
      ++without_random;
      CHECK(gas::scene_text(gas::build_gas(scene)) ==
            gas::scene_text(gas::read_scene_file(path)));
    }
    CHECK(without_random >= 5);
  }
}  // TEST_SUITE
