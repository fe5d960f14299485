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

using gas::exercises::table;

TEST_SUITE("exercise-11") {
  TEST_CASE("exercise-11 one ball moving at (3 4) has speed 5") {
    INFO("the speed is the length of the velocity: sqrt(vx^2 + vy^2)");
    CHECK(gas::mean_speed(table({{10, 10, 3, 4}})) == 5);
    CHECK(gas::mean_speed(table({{10, 10, -3, -4}})) == 5);
  }

  TEST_CASE("exercise-11 the mean of the speeds and not the speed of the mean velocity") {
    INFO(
        "two balls flying apart at speed 5 have mean speed 5, though their velocities "
        "add up to 0");
    CHECK(gas::mean_speed(table({{10, 10, 3, 4}, {20, 10, -3, -4}})) == 5);
    // Speeds 1, 2 and 6: the mean is 3.
    CHECK(gas::mean_speed(table({{5, 5, 0, 1}, {10, 5, -2, 0}, {15, 5, 0, -6}})) == 3);
  }

  TEST_CASE("exercise-11 a gas at rest or without balls has mean speed 0") {
    CHECK(gas::mean_speed(table({{5, 5, 0, 0}, {10, 5, 0, 0}})) == 0);
    INFO("no balls: the mean of nothing is taken as 0 here (not 0 / 0, which is NaN)");
    CHECK(gas::mean_speed(table({})) == 0);
  }

  TEST_CASE("exercise-11 the default scene's mean speed is 1.44524 as lesson 1 shows") {
    const gas::Gas scene = gas::build_gas(
        gas::parse_scene_description(gas::default_scene_text, "default scene"));
    // Why 5e-6: the screen prints 6 significant digits, so the true value is
    // within half a unit of the last one, 0.000005, of 1.44524. A mean of
    // the squared speeds, or a sum not divided by N, is off by 0.5 or more.
    const double mean = gas::mean_speed(scene);
    CAPTURE(mean);
    CHECK(std::fabs(mean - 1.44524) <= 5e-6);
  }
}
