// Exercise 02, scene_text: the provided tests (suite exercise-02).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage2_input.cpp. Don't change this file to make a
// test pass: change your scene_text.cpp.
//
// Each test writes a gas with scene_text and reads the text back with the
// project's own reader (stage 2: parse_scene_description, then build_gas),
// then compares: the table, T0, T and every ball's column of R (x, y, vx, vy and
// since), bit for bit, because that is what "reads back exactly" means.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstddef>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "exercise_test.hpp"
#include "stage2_input.hpp"

namespace {

// The gas that the text describes; fails the test if stage 2 refuses it.
gas::Gas read_back(const std::string& text) {
  INFO("scene_text wrote:\n" << text);
  gas::Gas read;
  REQUIRE_NOTHROW(
      read = gas::build_gas(gas::parse_scene_description(text, "your scene_text")));
  return read;
}

// The same table, T0, and for every ball the same velocity and the centre
// `centres[i]`, each number to the last bit.
void check_same(const gas::Gas& read, const gas::Gas& written,
                const std::vector<gas::Point>& centres) {
  CHECK(read.radius == written.radius);
  CHECK(read.width == written.width);
  CHECK(read.height == written.height);
  CHECK(read.display_step == written.display_step);
  REQUIRE(read.balls.size() == written.balls.size());
  for (std::size_t i = 0; i < read.balls.size(); ++i) {
    CAPTURE(i + 1);  // the ball's number
    CHECK(read.balls[i].x == centres[i].x);
    CHECK(read.balls[i].y == centres[i].y);
    CHECK(read.balls[i].vx == written.balls[i].vx);
    CHECK(read.balls[i].vy == written.balls[i].vy);
  }
}

}  // namespace

TEST_SUITE("exercise-02") {
  TEST_CASE("exercise-02 a gas of one ball reads back") {
    gas::Gas one;
    one.radius = 4;
    one.width = 256;
    one.height = 192;
    one.display_step = 1;
    one.balls = {{30, 40, 1.5, -0.5}};
    const gas::Gas read = read_back(gas::scene_text(one));
    check_same(read, one, {{30, 40}});
  }

  TEST_CASE("exercise-02 every number comes back to the last bit") {
    // Numbers that need up to 17 significant digits (1/3, pi, 20 and a bit):
    // 6 digits (printf's %g) or 6 decimals (std::to_string) change them.
    gas::Gas odd = gas::exercises::table({{1.0 / 3, 2.0 / 3, 0.1, -std::numbers::pi},
                                          {20.000000000000004, 7.7, 1e-7, 5e7}});
    odd.radius = 0.3;
    odd.width = 40.123456789012345;
    odd.height = 30.5 + 1.0 / 7;
    odd.display_step = std::numbers::sqrt2 / 10;
    const gas::Gas read = read_back(gas::scene_text(odd));
    check_same(read, odd,
               {{odd.balls[0].x, odd.balls[0].y}, {odd.balls[1].x, odd.balls[1].y}});
  }

  TEST_CASE("exercise-02 T and every column of R comes back as it is with since") {
    // T = 10. Ball 1's column of R was written at 4: (20, 15) is its centre at 4, at 10
    // it is at (29, 12). Ball 2's column was written at 10. A checkpoint keeps
    // the columns of R, not the centres at T (recomputing them rounds).
    const gas::Gas now =
        gas::exercises::table({{20, 15, 1.5, -0.5, 4}, {5, 25, -1, 0.25, 10}}, 10);
    INFO("write the line 'T 10' and each column of R as it is: 'ball x y vx vy since'");
    const gas::Gas read = read_back(gas::scene_text(now));
    check_same(read, now, {{20, 15}, {5, 25}});
    CHECK(read.time == 10);
    CHECK(read.balls[0].since == 4);
    CHECK(read.balls[1].since == 10);
  }

  TEST_CASE("exercise-02 many balls come back in order and N is written") {
    std::vector<gas::Ball> grid;
    for (int row = 0; row < 4; ++row) {
      for (int column = 0; column < 6; ++column)
        grid.push_back(
            {3.0 + 6 * column, 3.0 + 7 * row, 0.25 * column - 1, 0.5 * row - 1});
    }
    const gas::Gas many = gas::exercises::table(grid);
    const std::string text = gas::scene_text(many);
    std::vector<gas::Point> centres;
    for (const gas::Ball& ball : grid) centres.push_back({ball.x, ball.y});
    check_same(read_back(text), many, centres);

    // The line "N 24": optional for the reader, but it lets a reader check
    // that no ball line is lost.
    INFO("scene_text wrote:\n" << text);
    bool n_line = false;
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
      std::istringstream words(line);
      std::string keyword, count;
      if (words >> keyword >> count && keyword == "N") n_line = count == "24";
    }
    CHECK_MESSAGE(n_line, "no line 'N 24' (the number of balls)");
  }

  TEST_CASE("exercise-02 200 generated gases read back to the last bit") {
    // Tables, radii, T, T0 and velocities with all 53 bits drawn; 1 to 30
    // balls, each in a cell of its own (so that none overlaps another), its
    // row written at T or up to 1 earlier (computed back from its centre at
    // T, so that stage 2 finds it on the table).
    gas::exercises::Draw draw(201);
    for (int n = 1; n <= 200; ++n) {
      gas::Gas gas;
      gas.radius = draw.uniform(0.5, 3);
      const double cell = 2.5 * gas.radius;
      const int columns = draw.integer(1, 6), rows = draw.integer(1, 5);
      gas.width = columns * cell + draw.uniform(0, 100);
      gas.height = rows * cell + draw.uniform(0, 100);
      gas.time = draw.coin() ? 0.0 : draw.uniform(0, 1000);
      gas.display_step = draw.magnitude(-3, 2);
      const int count = draw.integer(1, columns * rows);  // stage 2 wants a ball
      for (int k = 0; k < count; ++k) {
        const double margin = 0.05 * gas.radius,
                     room = cell - 2 * gas.radius - 2 * margin;
        const double cx =
            gas.radius + (k % columns) * cell + margin + draw.uniform(0, room);
        const double cy =
            gas.radius + (k / columns) * cell + margin + draw.uniform(0, room);
        const double vx = draw.uniform(-10, 10), vy = draw.uniform(-10, 10);
        const double since =
            gas.time - (draw.coin() ? 0.0 : std::min(gas.time, draw.uniform(0, 1)));
        gas.balls.push_back(
            {cx - vx * (gas.time - since), cy - vy * (gas.time - since), vx, vy, since});
      }
      CAPTURE(n);
      const std::string text = gas::scene_text(gas);
      const gas::Gas read = read_back(text);
      INFO("scene_text of " << gas::exercises::describe(gas) << "\nwrote:\n" << text);
      bool right = CHECK_NUMBER("T", read.time, gas.time, 0) &&
                   CHECK_NUMBER("a", read.radius, gas.radius, 0) &&
                   CHECK_NUMBER("A1", read.width, gas.width, 0) &&
                   CHECK_NUMBER("A2", read.height, gas.height, 0) &&
                   CHECK_NUMBER("T0", read.display_step, gas.display_step, 0);
      REQUIRE_MESSAGE(
          read.balls.size() == gas.balls.size(),
          "read back " << read.balls.size() << " balls of " << gas.balls.size());
      for (std::size_t i = 0; i < gas.balls.size() && right; ++i) {
        const gas::Ball &got = read.balls[i], &wanted = gas.balls[i];
        const std::string ball = "ball " + std::to_string(i + 1) + " read back: ";
        right = CHECK_NUMBER(ball + "x", got.x, wanted.x, 0) &&
                CHECK_NUMBER(ball + "y", got.y, wanted.y, 0) &&
                CHECK_NUMBER(ball + "vx", got.vx, wanted.vx, 0) &&
                CHECK_NUMBER(ball + "vy", got.vy, wanted.vy, 0) &&
                CHECK_NUMBER(ball + "since", got.since, wanted.since, 0);
      }
      if (!right) break;
    }
  }
}
