// Exercise 11, mean_speed: the provided tests (suite exercise-11).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage1_data.cpp. Don't change this file to make a
// test pass: change your mean_speed.cpp.
//
// The velocities of the first tests are chosen so that every speed is a
// whole number ((3, 4) has speed 5 exactly): the checks ask for equality.
#include <doctest/doctest.h>

#include <cmath>

#include "exercise_test.hpp"
#include "program/console.hpp"
#include "stage1_data.hpp"
#include "stage2_input.hpp"

namespace {

using gas::exercises::describe;
using gas::exercises::Draw;
using gas::exercises::table;

#define CHECK_MEAN(of, wanted, relative) \
  CHECK_NUMBER("mean_speed of " + describe(of), gas::mean_speed(of), wanted, relative)

// The mean speed as it must be: each speed and the sum in long double (11
// more bits than double), rounded once at the end.
double exact_mean(const gas::Gas& gas) {
  if (gas.balls.empty()) return 0;
  long double sum = 0;
  for (const gas::Ball& ball : gas.balls)
    sum += std::sqrt(static_cast<long double>(ball.vx) * ball.vx +
                     static_cast<long double>(ball.vy) * ball.vy);
  return static_cast<double>(sum / static_cast<long double>(gas.balls.size()));
}

}  // namespace

TEST_SUITE("exercise-11") {
  TEST_CASE("exercise-11 one ball moving at (3 4) has speed 5") {
    INFO("the speed is the length of the velocity: sqrt(vx^2 + vy^2)");
    CHECK_MEAN(table({{10, 10, 3, 4}}), 5, 0);
    CHECK_MEAN(table({{10, 10, -3, -4}}), 5, 0);
  }

  TEST_CASE("exercise-11 the mean of the speeds and not the speed of the mean velocity") {
    INFO(
        "two balls flying apart at speed 5 have mean speed 5, though their velocities "
        "add up to 0");
    CHECK_MEAN(table({{10, 10, 3, 4}, {20, 10, -3, -4}}), 5, 0);
    // Speeds 1, 2 and 6: the mean is 3.
    CHECK_MEAN(table({{5, 5, 0, 1}, {10, 5, -2, 0}, {15, 5, 0, -6}}), 3, 0);
  }

  TEST_CASE("exercise-11 a gas at rest or without balls has mean speed 0") {
    CHECK_MEAN(table({{5, 5, 0, 0}, {10, 5, 0, 0}}), 0, 0);
    INFO("no balls: the mean of nothing is taken as 0 here (not 0 / 0, which is NaN)");
    CHECK_MEAN(table({}), 0, 0);
  }

  TEST_CASE("exercise-11 the default scene's mean speed is 1.44524 as lesson 1 shows") {
    const gas::Gas scene = gas::build_gas(
        gas::parse_scene_description(gas::default_scene_text, "default scene"));
    // Why 5e-6: the screen prints 6 significant digits, so the true value is
    // within half a unit of the last one, 0.000005, of 1.44524. A mean of
    // the squared speeds, or a sum not divided by N, is off by 0.5 or more.
    CHECK_CLOSE("mean_speed of " + describe(scene), gas::mean_speed(scene), 1.44524, 0,
                5e-6);
  }

  TEST_CASE("exercise-11 300 generated gases of any number of balls at any speeds") {
    Draw draw(1101);
    for (int n = 1; n <= 300; ++n) {
      std::vector<gas::Ball> balls(static_cast<std::size_t>(draw.integer(0, 60)));
      const double scale = draw.magnitude(-3, 3);  // speeds from 0.001 to 1000
      for (gas::Ball& ball : balls)
        ball = {draw.uniform(1, 39), draw.uniform(1, 29), scale * draw.uniform(-1, 1),
                scale * draw.uniform(-1, 1), draw.uniform(0, 50)};
      const gas::Gas gas = table(balls, draw.uniform(50, 100));
      CAPTURE(n);
      // Why 1e-14: each speed rounds once or twice (sqrt or hypot), the sum
      // of at most 60 positive terms 60 times, the mean once, each by
      // 1.1e-16 of the value: within 7e-15 of the exact mean, which
      // exact_mean gives to 1e-19. The mean of the squared speeds, or of
      // the velocities, is off by far more.
      if (!CHECK_MEAN(gas, exact_mean(gas), 1e-14)) break;
    }
  }
}
