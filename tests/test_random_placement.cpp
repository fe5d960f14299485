// Beyond the article, the scene line 'random COUNT SEED SPEED': large scenes
// the reader makes itself (beyond/random_placement.*, data/README.md).
//
// - The balls are where a scene may have them: on the table, no two closer
//   than 2a, none on top of a 'ball' line's ball; numbered after the 'ball'
//   lines.
// - Speeds between 0.5 and 1.5 SPEED, directions all round the circle.
// - The same scene on every machine: the first ball's numbers are pinned to
//   the bit (they follow from std::mt19937_64, whose output the C++ standard
//   fixes, our own mapping to [0, 1), and correctly rounded arithmetic).
// - The line 'lattice COUNT SEED SPEED': the balls on a lattice filling the
//   table, every speed SPEED.
// - What it refuses is in data/bad/random-*.scene (suite stage2's golden
//   messages); here, the limits one by one (COUNT, SEED and SPEED are
//   checked by stage 2, the density by the placement).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "beyond/random_placement.hpp"
#include "stage2_input.hpp"

namespace {

// Ball 1 of 'random 100 1989 1' on a 100 x 100 table of radius 1.
constexpr double PINNED_X = 0x1.18ded5e46d1bep+4, PINNED_Y = 0x1.3f19d9394d5a5p+6,
                 PINNED_VX = -0x1.0c4b65e9bf1d6p-1, PINNED_VY = 0x1.5a55b8cb3a9eap+0;

gas::Gas parse(const std::string& text) {
  return gas::parse_scene(text, "random.scene");
}

std::string refusal(const std::string& text) {
  try {
    parse(text);
  } catch (const gas::SceneError& error) {
    return error.what();
  }
  return "";
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

}  // namespace

TEST_SUITE("random-placement") {
  TEST_CASE(
      "random: the balls lie on the table apart from each other and the ball lines") {
    const gas::Gas gas = parse(
        "a 1\nT0 1\nA1 170\nA2 123\nball 50 40 1 0\nball 10 10 0 0\nrandom 2000 7 2\n");
    REQUIRE(gas.balls.size() == 2002);
    // The 'ball' lines come first, as written.
    CHECK(gas.balls[0].x == 50);
    CHECK(gas.balls[1].y == 10);
    double slowest = 10, fastest = 0, sum_vx = 0, sum_vy = 0;
    bool on_table = true, apart = true, written_at_zero = true;
    for (std::size_t i = 0; i < gas.balls.size(); ++i) {
      const gas::Ball& b = gas.balls[i];
      written_at_zero = written_at_zero && b.since == 0;
      on_table = on_table && b.x >= 1 && b.x <= 169 && b.y >= 1 && b.y <= 122;
      for (std::size_t j = 0; j < i; ++j) {
        const double dx = b.x - gas.balls[j].x, dy = b.y - gas.balls[j].y;
        apart = apart && dx * dx + dy * dy >= 4;
      }
      if (i < 2) continue;
      const double speed = std::hypot(b.vx, b.vy);
      slowest = std::min(slowest, speed);
      fastest = std::max(fastest, speed);
      sum_vx += b.vx / speed;
      sum_vy += b.vy / speed;
    }
    CHECK(written_at_zero);
    CHECK(on_table);
    CHECK(apart);
    // Speeds in [1, 3) = [0.5, 1.5) x 2 (up to the rounding of hypot), and
    // with 2000 balls close to both ends.
    CHECK(slowest >= 1 - 1e-15);
    CHECK(fastest < 3 + 1e-15);
    CHECK(slowest < 1.01);
    CHECK(fastest > 2.99);
    // Directions all round: the mean of 2000 unit vectors is ~1/sqrt(2000)
    // ~ 0.02 long if they are uniform; 0.1 would mean a bias.
    CHECK(std::hypot(sum_vx, sum_vy) / 2000 < 0.1);
  }

  TEST_CASE(
      "random: the same seed gives the same scene to the last bit on every machine") {
    const std::string text = "a 1\nT0 1\nA1 100\nA2 100\nrandom 100 1989 1\n";
    const gas::Gas one = parse(text), two = parse(text);
    REQUIRE(one.balls.size() == 100);
    bool same = true;
    for (std::size_t i = 0; i < 100; ++i) {
      same = same && bits(one.balls[i].x) == bits(two.balls[i].x) &&
             bits(one.balls[i].y) == bits(two.balls[i].y) &&
             bits(one.balls[i].vx) == bits(two.balls[i].vx) &&
             bits(one.balls[i].vy) == bits(two.balls[i].vy);
    }
    CHECK(same);
    // Pinned: what any standard library and any IEEE machine must give.
    const gas::Ball& first = one.balls[0];
    MESSAGE(
        fmt::format("ball 1: {:a} {:a} {:a} {:a}", first.x, first.y, first.vx, first.vy));
    CHECK(bits(first.x) == bits(PINNED_X));
    CHECK(bits(first.y) == bits(PINNED_Y));
    CHECK(bits(first.vx) == bits(PINNED_VX));
    CHECK(bits(first.vy) == bits(PINNED_VY));
    // Another seed, another scene.
    const gas::Gas other = parse("a 1\nT0 1\nA1 100\nA2 100\nrandom 100 1990 1\n");
    CHECK(bits(other.balls[0].x) != bits(first.x));
  }

  TEST_CASE("random: COUNT and SEED and SPEED and the density are checked") {
    const std::string table = "a 1\nT0 1\nA1 100\nA2 100\n";
    CHECK(refusal(table + "random 0 1 1\n") ==
          "random.scene:5: 'random' COUNT = 0 must be a whole number from 1 to 1000000");
    CHECK(refusal(table + "random 1000001 1 1\n") ==
          "random.scene:5: 'random' COUNT = 1000001 must be a whole number from 1 to "
          "1000000");
    CHECK(refusal(table + "random 3 -1 1\n") ==
          "random.scene:5: 'random' SEED = -1 must be a whole number from 0 to 2^53");
    CHECK(refusal(table + "random 3 0.5 1\n") ==
          "random.scene:5: 'random' SEED = 0.5 must be a whole number from 0 to 2^53");
    CHECK(refusal(table + "random 3 1 -2\n").find("SPEED = -2 must be positive") !=
          std::string::npos);
    CHECK(refusal(table + "random 3 1 1e75\n")
              .find("SPEED = 1e+75 must be positive and "
                    "at most") != std::string::npos);
    CHECK(refusal(table + "random 3 1\n") ==
          "random.scene:5: 'random' takes 3 numbers (COUNT SEED SPEED), found 2");
    CHECK(refusal(table + "Random 3 1 1\n") ==
          "random.scene:5: unknown keyword 'Random' (names are case-sensitive: did you "
          "mean 'random'?)");
    // N counts both kinds of balls.
    CHECK(refusal(table + "N 4\nball 50 50 0 0\nrandom 2 1 1\n") ==
          "random.scene:5: N = 4 but the file has 1 'ball' line and 'random' places 2");
    CHECK(parse(table + "N 3\nball 50 50 0 0\nrandom 2 1 1\n").balls.size() == 3);
    // 'random' alone is a whole gas.
    CHECK(parse(table + "random 1 1 1\n").balls.size() == 1);
    // The largest COUNT, and 2^53 as SEED, are accepted (radius 0.5: 10^6
    // balls on 3000 x 3000 cover 0.087).
    CHECK(parse("a 0.5\nT0 1\nA1 3000\nA2 3000\nrandom 1000000 9007199254740992 1\n")
              .balls.size() == 1000000);
  }

  TEST_CASE("lattice: COUNT balls on a lattice filling the table and every speed SPEED") {
    // 10 balls on a 40 x 20 table: 5 across (ceil(sqrt(10 * 2)) = 5) and 2
    // down, a point every 8 across and 10 down, half a spacing from the walls.
    const gas::Gas g = parse("a 1\nT0 1\nA1 40\nA2 20\nball 2 2 0 0\nlattice 10 7 2.5\n");
    REQUIRE(g.balls.size() == 11);
    for (std::size_t k = 0; k < 10; ++k) {
      CAPTURE(k);
      const gas::Ball& b = g.balls[k + 1];  // after the 'ball' line's ball
      CHECK(b.x == 4 + 8.0 * static_cast<double>(k % 5));
      CHECK(b.y == 5 + 10.0 * static_cast<double>(k / 5));
      // Every speed SPEED, to rounding: |v| = SPEED (u / l, v / l) with
      // l = sqrt(u^2 + v^2) is SPEED within a few units in the last place.
      CHECK(std::hypot(b.vx, b.vy) == doctest::Approx(2.5).epsilon(1e-15));
    }
    // The directions come from SEED: another seed, other directions.
    const gas::Gas other =
        parse("a 1\nT0 1\nA1 40\nA2 20\nball 2 2 0 0\nlattice 10 8 2.5\n");
    CHECK(other.balls[1].vx != g.balls[1].vx);
    // The dense scenes of lesson 13: 64 x 64 at area fraction 0.5.
    const gas::Gas dense = gas::read_scene_file(GAS_SOURCE_DIR "/data/eos-0.5.scene");
    CHECK(dense.balls.size() == 4096);
    CHECK(dense.balls[64].y > dense.balls[0].y);  // row by row
  }

  TEST_CASE("lattice: what it refuses") {
    const std::string table = "a 1\nT0 1\nA1 100\nA2 100\n";
    // 50 x 50 points on 100 x 100 are 2 apart: touching.
    CHECK(refusal(table + "lattice 2500 1 1\n") ==
          "random.scene:5: 'lattice' cannot place 2500 balls of radius 1 on a 100 x 100 "
          "table: 50 x 50 points are 2 x 2 apart, less than a diameter");
    CHECK(refusal(table + "ball 50 50 0 0\nlattice 1 1 1\n") ==
          "random.scene:6: 'lattice' point (50, 50) for ball 2 is taken by a 'ball' "
          "line's ball");
    CHECK(refusal(table + "lattice 0 1 1\n") ==
          "random.scene:5: 'lattice' COUNT = 0 must be a whole number from 1 to 1000000");
    CHECK(refusal(table + "random 3 1 1\nlattice 3 1 1\n") ==
          "random.scene:6: one 'random' or 'lattice' line only ('random' is on line 5)");
    CHECK(refusal(table + "lattice 3 1 1\nlattice 3 1 1\n") ==
          "random.scene:6: 'lattice' is given twice (first on line 5)");
    CHECK(refusal(table + "N 4\nlattice 3 1 1\n") ==
          "random.scene:5: N = 4 but the file has 0 'ball' lines and 'lattice' places 3");
  }
}
