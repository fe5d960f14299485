// Exercise 08, shift_time: the provided tests (suite exercise-08).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage5_new_coordinates.cpp. Don't change this file
// to make a test pass: change your shift_time.cpp.
//
// The centres must be computed from the rows of R as centre_at does (stage
// 1), not by moving the old centres on: then they are the same doubles as
// centre_at's, and the checks can ask for equality.
#include <doctest/doctest.h>

#include <cstddef>
#include <vector>

#include "exercise_test.hpp"
#include "stage5_new_coordinates.hpp"

namespace {

using gas::Point;

// Three balls in free flight, their rows written at different moments.
gas::Gas three_balls() {
  return gas::exercises::table(
      {{10, 10, 1, 0.5, 0}, {20, 15, -0.25, 1, 1.5}, {30.3, 5.7, 0.1, -0.3, 0.75}}, 2);
}

// Each centre equal, to the last bit, to where its ball is at `time`.
void check_centres(const std::vector<Point>& centres, const gas::Gas& gas, double time) {
  REQUIRE_MESSAGE(centres.size() == gas.balls.size(), "one centre per ball");
  for (std::size_t i = 0; i < centres.size(); ++i) {
    CAPTURE(i + 1);  // the ball's number
    const Point wanted = gas::centre_at(gas.balls[i], time);
    CHECK(centres[i].x == wanted.x);
    CHECK(centres[i].y == wanted.y);
  }
}

}  // namespace

TEST_SUITE("exercise-08") {
  TEST_CASE("exercise-08 the new centres are the centres at the new time") {
    gas::Gas gas = three_balls();
    gas::Picture picture;
    picture.centres = gas::centres_at(gas, 2);
    picture.old_centres = picture.centres;
    gas::shift_time(gas, picture, 3.5);
    CHECK(gas.time == 3.5);
    INFO("picture.centres: where each ball is at the new T (centre_at or centres_at)");
    check_centres(picture.centres, gas, 3.5);
  }

  TEST_CASE("exercise-08 the old centres are the ones drawn last time (RS)") {
    gas::Gas gas = three_balls();
    gas::Picture picture;
    picture.centres = gas::centres_at(gas, 2);
    picture.old_centres = picture.centres;
    gas::shift_time(gas, picture, 3);
    gas::shift_time(gas, picture, 4.25);
    INFO(
        "picture.old_centres: the centres of the picture before, at T = 3, for stage 6 "
        "to erase");
    check_centres(picture.old_centres, gas, 3);
    check_centres(picture.centres, gas, 4.25);
  }

  TEST_CASE("exercise-08 the first picture has no past") {
    gas::Gas gas = three_balls();
    gas::Picture empty;  // no picture drawn yet: no centres at all
    gas::shift_time(gas, empty, 2.5);
    check_centres(empty.centres, gas, 2.5);
    INFO(
        "with nothing drawn before, the old centres are the new ones (nothing to erase)");
    check_centres(empty.old_centres, gas, 2.5);
  }

  TEST_CASE(
      "exercise-08 no ball moves: R is left as it was and only the picture changes") {
    gas::Gas gas = three_balls();
    const gas::Gas before = gas;
    gas::Picture picture;
    for (const double t : {2.5, 3.0, 7.75}) gas::shift_time(gas, picture, t);
    INFO(
        "the rows of R change only at collisions (stage 5's apply_collision), never in "
        "shift_time");
    for (std::size_t i = 0; i < gas.balls.size(); ++i) {
      CAPTURE(i + 1);
      CHECK(gas.balls[i].x == before.balls[i].x);
      CHECK(gas.balls[i].y == before.balls[i].y);
      CHECK(gas.balls[i].since == before.balls[i].since);
    }
    check_centres(picture.centres, gas, 7.75);
  }

  TEST_CASE("exercise-08 a thousand small steps end where one big step would") {
    gas::Gas gas = three_balls();
    gas::Picture picture;
    double t = 2, before = 2;
    for (int step = 0; step < 1000; ++step) {
      before = t;
      t += 0.1;  // T0 = 0.1, which is not exact in binary
      gas::shift_time(gas, picture, t);
    }
    INFO("adding v * T1 to the old centres a thousand times adds a thousand roundings");
    check_centres(picture.centres, gas, t);
    check_centres(picture.old_centres, gas, before);
  }
}
