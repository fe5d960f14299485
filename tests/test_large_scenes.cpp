// Large scenes all the way: what stage 2 reads and --dump writes at the
// program's largest sizes (beyond/overlap_cells.*, stage 2's reader and
// write_scene_text, program/run_outputs.*).
//
// - The search for overlaps through cells names the very pair the plain
//   search of every pair names (the first by line, and the first ball before
//   it), on random gases with overlaps planted, on ties at exactly the least
//   distance, and on awkward boxes (a line, a point, a far outlier).
// - Every scene of data/bad/ gets the same message from stage 2 with either
//   search.
// - The program, on 10^5 balls with overlaps planted, refuses the scene with
//   exit 2 and names the first pair by line, with both lines.
// - A gas of 10^5 balls dumped at T = 1 and continued to T = 2 is, to the
//   last byte of its dump, the gas run straight to T = 2.
// - The bounds: 10^6 balls read, one more refused at its line; a line longer
//   than longest_scene_line refused, /dev/zero among them; a file read in
//   blocks says what the same text in memory says, lines across the blocks'
//   edges included.
// - write_scene_text hands out scene_text's very text in pieces of some 64 kB.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "beyond/overlap_cells.hpp"
#include "beyond/random_placement.hpp"
#include "stage2_input.hpp"
#include "support.hpp"

namespace {

using gas::testing::read_file;
using gas::testing::run_program;
using gas::testing::Scratch;
using gas::testing::source_path;

// Both searches' answers on `centres`: they must be the same pair (or none).
void same_answer(const std::vector<gas::Point>& centres, double closest) {
  const auto plain = gas::first_overlap_of_all_pairs(centres, closest);
  const auto cells = gas::first_overlap_by_cells(centres, closest);
  REQUIRE(plain.has_value() == cells.has_value());
  if (plain) {
    CHECK(cells->later == plain->later);
    CHECK(cells->earlier == plain->earlier);
  }
}

// `count` centres that do not overlap (at least 1.05 apart, `closest` = 1):
// a jittered square lattice of spacing 1.25 from (x0, y0), in a random order.
std::vector<gas::Point> apart(std::size_t count, std::mt19937_64& random, double x0 = 0,
                              double y0 = 0) {
  const auto across = static_cast<std::size_t>(std::ceil(std::sqrt(count)));
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<gas::Point> centres;
  for (std::size_t k = 0; k < count; ++k) {
    centres.push_back({x0 + 1.25 * static_cast<double>(k % across) + jitter(random),
                       y0 + 1.25 * static_cast<double>(k / across) + jitter(random)});
  }
  std::shuffle(centres.begin(), centres.end(), random);
  return centres;
}

// What stage 2 says about the scene file at `path` with `search`: its
// message, or "" if it accepts it.
std::string refusal(const std::string& path, const gas::OverlapSearch& search) {
  try {
    gas::read_scene_description(path, search);
  } catch (const gas::SceneError& error) {
    return error.what();
  }
  return "";
}

// The same for scene text in memory.
std::string text_refusal(const std::string& text) {
  try {
    gas::parse_scene_description(text, "t.scene", gas::first_overlap_by_cells);
  } catch (const gas::SceneError& error) {
    return error.what();
  }
  return "";
}

// A table of radius 1 holding `across` x `down` balls on a square lattice 3
// apart, one 'ball' line each after the four lines of the table; ball k
// (from 0) is on line 5 + k, at (2 + 3 (k % across), 2 + 3 (k / across)).
constexpr int first_ball_line = 5;
std::string lattice_scene(std::size_t across, std::size_t down) {
  std::string text =
      fmt::format("a 1\nT0 1\nA1 {}\nA2 {}\n", 3 * across + 1, 3 * down + 1);
  for (std::size_t k = 0; k < across * down; ++k)
    text += fmt::format("ball {} {} 1 0\n", 2 + 3 * (k % across), 2 + 3 * (k / across));
  return text;
}

}  // namespace

TEST_SUITE("large-scenes") {
  TEST_CASE(
      "the search through cells names the pair the search of every pair names: the "
      "first by line") {
    std::mt19937_64 random(37);
    std::uniform_int_distribution<int> sizes(2, 2500);
    std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), within(0, 1);
    for (int trial = 0; trial < 150; ++trial) {
      CAPTURE(trial);
      std::vector<gas::Point> centres =
          apart(static_cast<std::size_t>(sizes(random)), random, 5, -3);
      same_answer(centres, 1);  // none
      // Overlaps planted: ball j moved to within 1 of ball i, a few times.
      const int planted = 1 + trial % 4;
      for (int p = 0; p < planted; ++p) {
        std::uniform_int_distribution<std::size_t> pick(0, centres.size() - 1);
        const std::size_t i = pick(random), j = pick(random);
        if (i == j) continue;
        const double r = within(random), phi = angle(random);
        centres[j] = {centres[i].x + r * std::cos(phi), centres[i].y + r * std::sin(phi)};
      }
      same_answer(centres, 1);
    }

    SUBCASE("ties: exactly the least distance is no overlap, a hair less is") {
      // Ball 3 at exactly 1 from ball 1, then a hair nearer to ball 0.
      const std::vector<gas::Point> touching{{0, 0}, {3, 0}, {6, 0}, {4, 0}};
      CHECK_FALSE(gas::first_overlap_by_cells(touching, 1).has_value());
      same_answer(touching, 1);
      const std::vector<gas::Point> hair{
          {0, 0}, {3, 0}, {6, 0}, {std::nextafter(4.0, 0.0), 0}};
      REQUIRE(gas::first_overlap_by_cells(hair, 1).has_value());
      CHECK(gas::first_overlap_by_cells(hair, 1)->earlier == 1);
      same_answer(hair, 1);
    }
    SUBCASE("the first ball before it, not the nearest nor the last met") {
      // Ball 3 overlaps balls 0, 1 and 2 (0.90, 0.90 and 0.7 away), which do
      // not overlap each other: the answer is ball 0.
      const std::vector<gas::Point> fan{{0, 0}, {1.5, 0}, {0.75, 1.2}, {0.75, 0.5}};
      const auto first = gas::first_overlap_by_cells(fan, 1);
      REQUIRE(first.has_value());
      CHECK(first->later == 3);
      CHECK(first->earlier == 0);
      same_answer(fan, 1);
    }
    SUBCASE("awkward boxes: a line, a point, one ball, a far outlier, huge and tiny") {
      std::vector<gas::Point> line;
      for (int k = 0; k < 500; ++k) line.push_back({1.5 * k, 7});
      same_answer(line, 1);
      line.push_back({1.5 * 250 + 0.5, 7});
      same_answer(line, 1);
      same_answer(std::vector<gas::Point>(300, gas::Point{2, 2}), 1);
      same_answer({{2, 2}}, 1);
      same_answer({}, 1);
      std::vector<gas::Point> cluster = apart(2000, random);
      cluster.push_back({1e9, 1e9});
      same_answer(cluster, 1);
      cluster.push_back({cluster[1234].x + 0.3, cluster[1234].y});
      same_answer(cluster, 1);
      for (const double scale : {1e-70, 1e70}) {
        CAPTURE(scale);
        std::vector<gas::Point> scaled = apart(1000, random);
        scaled.push_back({scaled[17].x + 0.99, scaled[17].y});
        for (gas::Point& p : scaled) p = {p.x * scale, p.y * scale};
        same_answer(scaled, scale);
        REQUIRE(gas::first_overlap_by_cells(scaled, scale).has_value());
      }
    }
  }

  TEST_CASE("every scene of data/bad/ gets the same message with either search") {
    int overlapping = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(source_path("data/bad"))) {
      if (entry.path().extension() != ".scene") continue;
      CAPTURE(entry.path().filename().string());
      const std::string plain =
          refusal(entry.path().string(), gas::first_overlap_of_all_pairs);
      CHECK(plain == refusal(entry.path().string(), gas::first_overlap_by_cells));
      if (plain.find("overlaps") != std::string::npos) ++overlapping;
    }
    CHECK(overlapping >= 4);
  }

  TEST_CASE(
      "the program refuses 10^5 balls with overlaps planted: exit 2 and the first pair "
      "by line with both its lines") {
    // 400 x 250 balls; ball 70001 (k = 70000) moved 1 from ball 124 (k = 123),
    // and ball 90001 onto ball 6: the first pair by line is (70001, 124). Ball
    // 70001 also touches ball 125, exactly 2a = 2 away: no overlap.
    std::string text = lattice_scene(400, 250);
    auto move = [&](std::size_t k, std::size_t near, double dx) {
      const std::string old =
          fmt::format("ball {} {} 1 0\n", 2 + 3 * (k % 400), 2 + 3 * (k / 400));
      const std::string moved = fmt::format("ball {} {} 1 0\n", 2 + 3 * (near % 400) + dx,
                                            2 + 3 * (near / 400));
      const std::size_t at = text.find(old);
      REQUIRE(at != std::string::npos);
      text.replace(at, old.size(), moved);
    };
    Scratch scratch;
    const std::string clean = scratch.file("clean.scene");
    std::ofstream(clean) << text;
    move(70000, 123, 1);
    move(90000, 5, 0.5);
    const std::string planted = scratch.file("planted.scene");
    std::ofstream(planted) << text;

    const auto accepted = run_program({clean, "--until", "0", "--mode", "none"});
    CHECK(accepted.status == 0);
    CHECK(accepted.err.empty());
    const auto refused = run_program({planted, "--until", "0", "--mode", "none"});
    CHECK(refused.status == 2);
    CHECK(refused.out.empty());
    CHECK(refused.err == fmt::format("{}:{}: ball 70001 overlaps ball 124 (line {}): "
                                     "centres 1 apart, less than 2a = 2\n",
                                     planted, first_ball_line + 70000,
                                     first_ball_line + 123));
  }

  TEST_CASE(
      "10^5 balls dumped at T = 1 and continued to T = 2: the dump of the gas run "
      "straight to T = 2 byte for byte") {
    // (Some 87 thousand collisions to T = 2; the program as a process.)
    Scratch scratch;
    const std::string scene = source_path("data/large-100000.scene");
    const std::string at_1 = scratch.file("at-1.scene"), on = scratch.file("on.scene"),
                      straight = scratch.file("straight.scene");
    REQUIRE(
        run_program({scene, "--until", "1", "--mode", "none", "--dump", at_1}).status ==
        0);
    REQUIRE(run_program({at_1, "--until", "2", "--mode", "none", "--dump", on}).status ==
            0);
    REQUIRE(run_program({scene, "--until", "2", "--mode", "none", "--dump", straight})
                .status == 0);
    const std::string continued = read_file(on);
    CHECK(continued.find("\nT  2\n") != std::string::npos);
    CHECK(continued.find("\nN  100000\n") != std::string::npos);
    CHECK(continued.size() > 90 * 100000);
    CHECK(continued == read_file(straight));
    // The gas moved between the two dumps: rows were written after T = 1.
    CHECK(continued != read_file(at_1));
  }

  TEST_CASE("a scene holds 10^6 balls: the next ball line is refused at its line") {
    std::string text = lattice_scene(1000, 1000);
    const gas::Gas million = gas::parse_scene(text, "million.scene");
    CHECK(million.balls.size() == 1000000);
    text += "ball 1 1 0 0\n";
    CHECK(text_refusal(text) == fmt::format("t.scene:{}: ball 1000001: a scene holds at "
                                            "most 1000000 balls",
                                            first_ball_line + 1000000));
  }

  TEST_CASE(
      "lines: a file read in blocks says what the text in memory says and a line too "
      "long is refused") {
    // Some 2.5 MB: lines across the edges of the reader's 1 MiB blocks, CRLF
    // ends, comments of every length up to the longest line allowed.
    std::string text = "\xEF\xBB\xBFT 0\r\na 1\r\nT0 1\r\nA1 2000\r\nA2 2000\r\n";
    std::mt19937_64 random(6);
    std::uniform_int_distribution<std::size_t> comment(0, 300);
    for (std::size_t k = 0; k < 20000; ++k) {
      text += fmt::format("ball {} {} 0.5 -0.25 # {}\r\n", 2 + 3 * (k % 600),
                          2 + 3 * (k / 600), std::string(comment(random), 'c'));
    }
    text += "#" + std::string(gas::longest_scene_line - 1, 'x') + "\n";
    text += "ball 1990 1990 0 0";  // the last line, without a line end
    Scratch scratch;
    const std::string path = scratch.file("blocks.scene");
    std::ofstream(path, std::ios::binary) << text;
    const gas::Gas from_file =
        gas::build_gas(gas::read_scene_description(path, gas::first_overlap_by_cells));
    const gas::Gas from_text = gas::build_gas(
        gas::parse_scene_description(text, path, gas::first_overlap_by_cells));
    CHECK(from_file.balls.size() == 20001);
    CHECK(gas::scene_text(from_file) == gas::scene_text(from_text));

    // One character more, in a file and in memory; at the end, and before a
    // line that ends.
    const std::string longer = text.substr(0, text.rfind('#')) + "##" +
                               std::string(gas::longest_scene_line - 1, 'x');
    std::ofstream(path, std::ios::binary) << longer;
    const std::string message = fmt::format(
        "{}:20006: the line is longer than 65536 characters, the most a scene's line "
        "may have",
        path);
    CHECK(refusal(path, gas::first_overlap_by_cells) == message);
    std::ofstream(path, std::ios::binary) << longer + "\nball 1 1 0 0\n";
    CHECK(refusal(path, gas::first_overlap_by_cells) == message);
    CHECK(text_refusal(longer) == message.substr(path.size()).insert(0, "t.scene"));

    // No line ends at all: refused after the first line's worth, not read to
    // the end (there is none).
    const auto zero = run_program({"/dev/zero", "--frames", "1"});
    CHECK(zero.status == 2);
    CHECK(zero.err ==
          "/dev/zero:1: the line is longer than 65536 characters, the most a scene's "
          "line may have\n");
  }

  TEST_CASE("write_scene_text hands out scene_text's text in pieces of some 64 kB") {
    const gas::Gas gas = gas::read_scene_file(source_path("data/large-10000.scene"));
    std::vector<std::string> pieces;
    gas::write_scene_text(gas,
                          [&](std::string_view piece) { pieces.emplace_back(piece); });
    std::string joined;
    for (const std::string& piece : pieces) joined += piece;
    CHECK(joined == gas::scene_text(gas));
    REQUIRE(pieces.size() > 10);  // some 0.95 MB
    for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
      CAPTURE(k);
      CHECK(pieces[k].size() >= 65536);
      CHECK(pieces[k].size() < 65536 + 200);  // a piece ends with its first full line
    }
    // A small gas: one piece, the whole text.
    const gas::Gas seven = gas::read_scene_file(source_path("data/default.scene"));
    pieces.clear();
    gas::write_scene_text(seven,
                          [&](std::string_view piece) { pieces.emplace_back(piece); });
    REQUIRE(pieces.size() == 1);
    CHECK(pieces[0] == gas::scene_text(seven));
  }
}  // TEST_SUITE
