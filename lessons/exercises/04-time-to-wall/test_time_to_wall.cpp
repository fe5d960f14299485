// Exercise 04, time_to_wall: the provided tests (suite exercise-04).
//
// Every test here fails against the untouched stub (CI checks that), passes
// against stages/stage4_first_collision.cpp, and catches the wrong answers
// in wrong/ (CI checks those too). Don't change this file to make a test
// pass: change your time_to_wall.cpp.
//
// The first tests use the limits low = 1 and high = 9 and numbers exact in
// binary, so the answers are exact: the checks ask for equality. The
// generated ones draw limits, positions and velocities of every size.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "exercise_test.hpp"
#include "stage4_first_collision.hpp"

namespace {

using gas::never;
using gas::time_to_wall;
using gas::exercises::digits;
using gas::exercises::Draw;

std::string call(double position, double velocity, double low, double high) {
  return fmt::format("time_to_wall(position {}, velocity {}, low {}, high {})",
                     digits(position), digits(velocity), digits(low), digits(high));
}

#define CHECK_WALL(position, velocity, low, high, wanted, relative) \
  CHECK_NUMBER(call(position, velocity, low, high),                 \
               time_to_wall(position, velocity, low, high), wanted, relative)

// The time as it must be, worked out in long double (11 more bits than
// double) and rounded once: within 1.1e-16 of it, relative.
double exact_time(double position, double velocity, double low, double high) {
  if (velocity == 0) return never;
  const long double target = velocity > 0 ? high : low;
  const long double t = (target - position) / static_cast<long double>(velocity);
  return static_cast<double>(std::max(0.0L, t));
}

// Why 1e-13 in the generated tests: (high - position) / velocity rounds
// twice, by 1.1e-16 of the result each time; 1e-13 leaves room for any
// careful way of writing it. The wrong limit, a wrong sign or a distance
// measured from elsewhere is off by far more.
constexpr double careful = 1e-13;

// Limits of any size and place: low anywhere from -1000 to 1000, the room
// from 0.01 to 10000 wide.
double draw_low(Draw& draw) {
  return draw.uniform(-1000, 1000);
}
double draw_high(Draw& draw, double low) {
  return low + draw.magnitude(-2, 4);
}

}  // namespace

TEST_SUITE("exercise-04") {
  TEST_CASE("exercise-04 a centre moving up reaches the upper limit") {
    INFO("from 3 up to 9 is 6; at speed 2 that takes 3");
    CHECK_WALL(3, 2, 1, 9, 3, 0);
    CHECK_WALL(3, 0.5, 1, 9, 12, 0);
    CHECK_WALL(1, 4, 1, 9, 2, 0);
  }

  TEST_CASE("exercise-04 a centre moving down reaches the lower limit") {
    INFO("from 3 down to 1 is 2; at speed 0.5 that takes 4 (a time is never negative)");
    CHECK_WALL(3, -0.5, 1, 9, 4, 0);
    CHECK_WALL(8, -7, 1, 9, 1, 0);
    CHECK_WALL(9, -2, 1, 9, 4, 0);
  }

  TEST_CASE(
      "exercise-04 a centre at or beyond the limit it moves towards reaches it now") {
    INFO(
        "round-off can leave a centre a hair beyond its limit: the wall is due now, at "
        "0");
    CHECK_WALL(9, 1, 1, 9, 0, 0);     // on the upper limit, moving up
    CHECK_WALL(10, 1, 1, 9, 0, 0);    // beyond it
    CHECK_WALL(0.5, -1, 1, 9, 0, 0);  // beyond the lower limit, moving down
    INFO(
        "beyond one limit but moving away from it, the other limit is the one it "
        "reaches");
    CHECK_WALL(10, -1, 1, 9, 9, 0);  // from 10 down to 1
  }

  // The trap of the article, caught by this test and the next: a velocity of
  // 0 must never be divided by.
  TEST_CASE("exercise-04 at rest on a limit: 0 / 0 must not become NaN or 0") {
    INFO(
        "return gas::never; on a limit 0 / 0 is NaN, and a double has two zeros, +0 and "
        "-0");
    for (const double position : {1.0, 9.0}) {
      for (const double zero : {0.0, -0.0}) CHECK_WALL(position, zero, 1, 9, never, 0);
    }
    CHECK_WALL(-250.5, 0.0, -250.5, 1e6, never, 0);
    CHECK_WALL(1e6, -0.0, -250.5, 1e6, never, 0);
  }

  TEST_CASE("exercise-04 300 generated centres at rest reach no wall wherever they are") {
    INFO("at rest along this axis (velocity +0 or -0) the answer is gas::never");
    Draw draw(402);
    for (int n = 1; n <= 300; ++n) {
      const double low = draw_low(draw);
      const double high = draw_high(draw, low);
      // Inside, on either limit, or beyond either.
      const double places[] = {draw.uniform(low, high), low, high,
                               low - draw.uniform(0, 1), high + draw.uniform(0, 1)};
      const double position = places[draw.integer(0, 4)];
      const double zero = draw.coin() ? 0.0 : -0.0;
      CAPTURE(n);
      if (!CHECK_WALL(position, zero, low, high, never, 0)) break;
    }
  }

  TEST_CASE("exercise-04 500 generated centres between other limits moving either way") {
    INFO(
        "moving up: (high - position) / velocity; moving down: (low - position) / "
        "velocity");
    Draw draw(403);
    for (int n = 1; n <= 500; ++n) {
      const double low = draw_low(draw);
      const double high = draw_high(draw, low);
      const double position = draw.uniform(low, high);
      const double velocity = (draw.coin() ? 1 : -1) * draw.magnitude(-3, 3);
      CAPTURE(n);
      const double wanted = exact_time(position, velocity, low, high);
      if (!CHECK_WALL(position, velocity, low, high, wanted, careful)) break;
    }
  }

  TEST_CASE("exercise-04 200 generated centres beyond a limit moving on or back") {
    INFO("beyond the limit it moves towards: 0 (now); beyond the other: the far limit");
    Draw draw(404);
    for (int n = 1; n <= 200; ++n) {
      const double low = draw_low(draw);
      const double high = draw_high(draw, low);
      const bool above = draw.coin();
      const double hair = (high - low) * draw.magnitude(-12, -1);
      const double position = above ? high + hair : low - hair;
      const double speed = draw.magnitude(-3, 3);
      const double velocity = draw.coin() ? speed : -speed;
      CAPTURE(n);
      const double wanted = exact_time(position, velocity, low, high);
      if (!CHECK_WALL(position, velocity, low, high, wanted, careful)) break;
    }
  }
}
