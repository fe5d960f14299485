// Exercise 04, time_to_wall: the provided tests (suite exercise-04).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage4_first_collision.cpp. Don't change this file
// to make a test pass: change your time_to_wall.cpp.
//
// In every test the centre may move between the limits low = 1 and
// high = 9. The numbers are exact in binary and so are the answers: the
// checks ask for equality.
#include <doctest/doctest.h>

#include <cmath>

#include "exercise_test.hpp"
#include "stage4_first_collision.hpp"

using gas::never;
using gas::time_to_wall;

TEST_SUITE("exercise-04") {
  EXERCISE_TEST("exercise-04 a centre moving up reaches the upper limit") {
    INFO("from 3 up to 9 is 6; at speed 2 that takes 3");
    CHECK(time_to_wall(3, 2, 1, 9) == 3);
    CHECK(time_to_wall(3, 0.5, 1, 9) == 12);
    CHECK(time_to_wall(1, 4, 1, 9) == 2);
  }

  EXERCISE_TEST("exercise-04 a centre moving down reaches the lower limit") {
    INFO("from 3 down to 1 is 2; at speed 0.5 that takes 4 (a time is never negative)");
    CHECK(time_to_wall(3, -0.5, 1, 9) == 4);
    CHECK(time_to_wall(8, -7, 1, 9) == 1);
    CHECK(time_to_wall(9, -2, 1, 9) == 4);
  }

  EXERCISE_TEST(
      "exercise-04 a centre at rest reaches no wall and nothing is divided by zero") {
    INFO("return gas::never; 0 / 0 would be NaN, and a double has two zeros, +0 and -0");
    for (const double position : {5.0, 1.0, 9.0}) {
      for (const double zero : {0.0, -0.0}) {
        CAPTURE(position);
        CAPTURE(zero);
        const double t = time_to_wall(position, zero, 1, 9);
        CHECK_FALSE(std::isnan(t));
        CHECK(t == never);
      }
    }
  }

  EXERCISE_TEST(
      "exercise-04 a centre at or beyond the limit it moves towards reaches it now") {
    INFO(
        "round-off can leave a centre a hair beyond its limit: the wall is due now, at "
        "0");
    CHECK(time_to_wall(9, 1, 1, 9) == 0);     // on the upper limit, moving up
    CHECK(time_to_wall(10, 1, 1, 9) == 0);    // beyond it
    CHECK(time_to_wall(0.5, -1, 1, 9) == 0);  // beyond the lower limit, moving down
    INFO(
        "beyond one limit but moving away from it, the other limit is the one it "
        "reaches");
    CHECK(time_to_wall(10, -1, 1, 9) == 9);  // from 10 down to 1
  }
}
