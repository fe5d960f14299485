// Exercise 02, scene_text: the provided tests (suite exercise-02).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage2_input.cpp. Don't change this file to make a
// test pass: change your scene_text.cpp.
//
// Each test writes a gas with scene_text and reads the text back with the
// project's own reader (stage 2: parse_scene_description, then build_gas),
// then compares: the table, T0, T and every ball's row (x, y, vx, vy and
// since), bit for bit, because that is what "reads back exactly" means.
#include <doctest/doctest.h>

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

  TEST_CASE("exercise-02 T and every row come back as they are with since") {
    // T = 10. Ball 1's row was written at 4: (20, 15) is its centre at 4, at 10
    // it is at (29, 12). Ball 2's row was written at 10. A checkpoint keeps the
    // rows, not the centres at T (recomputing them rounds).
    const gas::Gas now =
        gas::exercises::table({{20, 15, 1.5, -0.5, 4}, {5, 25, -1, 0.25, 10}}, 10);
    INFO("write the line 'T 10' and each row as it is: 'ball x y vx vy since'");
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
}
