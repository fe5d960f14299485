// Exercise 08, shift_time: the provided tests (suite exercise-08).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage5_new_coordinates.cpp. Don't change this file
// to make a test pass: change your shift_time.cpp.
//
// The centres must be computed from the columns of R as centre_at does (stage
// 1), not by moving the old centres on: then they are the same doubles as
// centre_at's, and the checks can ask for equality.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <vector>

#include "exercise_test.hpp"
#include "stage5_new_coordinates.hpp"

namespace {

using gas::Point;

// Three balls in free flight, their columns of R written at different moments.
gas::Gas three_balls() {
  return gas::exercises::table(
      {{10, 10, 1, 0.5, 0}, {20, 15, -0.25, 1, 1.5}, {30.3, 5.7, 0.1, -0.3, 0.75}}, 2);
}

// Each centre equal, to the last bit, to where its ball is at `time`.
bool check_centres(const std::vector<Point>& centres, const gas::Gas& gas, double time,
                   const std::string& which) {
  REQUIRE_MESSAGE(centres.size() == gas.balls.size(),
                  "one centre per ball: " << which << " has " << centres.size() << " for "
                                          << gas.balls.size() << " balls");
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Point wanted = gas::centre_at(gas.balls[i], time);
    const std::string what = fmt::format("{}[{}] of ball {} {} at T = {}", which, i,
                                         i + 1, gas::exercises::column_of_r(gas.balls[i]),
                                         gas::exercises::digits(time));
    if (!CHECK_NUMBER(what + ": x", centres[i].x, wanted.x, 0) ||
        !CHECK_NUMBER(what + ": y", centres[i].y, wanted.y, 0))
      return false;
  }
  return true;
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
    check_centres(picture.centres, gas, 3.5, "picture.centres");
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
    check_centres(picture.old_centres, gas, 3, "picture.old_centres");
    check_centres(picture.centres, gas, 4.25, "picture.centres");
  }

  TEST_CASE("exercise-08 the first picture has no past") {
    gas::Gas gas = three_balls();
    gas::Picture empty;  // no picture drawn yet: no centres at all
    gas::shift_time(gas, empty, 2.5);
    check_centres(empty.centres, gas, 2.5, "picture.centres");
    INFO(
        "with nothing drawn before, the old centres are the new ones (nothing to erase)");
    check_centres(empty.old_centres, gas, 2.5, "picture.old_centres");
  }

  TEST_CASE(
      "exercise-08 no ball moves: R is left as it was and only the picture changes") {
    gas::Gas gas = three_balls();
    const gas::Gas before = gas;
    gas::Picture picture;
    for (const double t : {2.5, 3.0, 7.75}) gas::shift_time(gas, picture, t);
    INFO(
        "the columns of R change only at collisions (stage 5's apply_collision), never "
        "in "
        "shift_time");
    for (std::size_t i = 0; i < gas.balls.size(); ++i) {
      const std::string what = fmt::format("ball {}, {} before", i + 1,
                                           gas::exercises::column_of_r(before.balls[i]));
      CHECK_NUMBER(what + ": x", gas.balls[i].x, before.balls[i].x, 0);
      CHECK_NUMBER(what + ": y", gas.balls[i].y, before.balls[i].y, 0);
      CHECK_NUMBER(what + ": since", gas.balls[i].since, before.balls[i].since, 0);
    }
    check_centres(picture.centres, gas, 7.75, "picture.centres");
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
    check_centres(picture.centres, gas, t, "picture.centres");
    check_centres(picture.old_centres, gas, before, "picture.old_centres");
  }

  TEST_CASE("exercise-08 200 generated gases shifted through random steps") {
    gas::exercises::Draw draw(801);
    for (int n = 1; n <= 200; ++n) {
      std::vector<gas::Ball> balls(static_cast<std::size_t>(draw.integer(1, 30)));
      double now = draw.uniform(0, 1000);
      for (gas::Ball& ball : balls)
        ball = {draw.uniform(1, 39), draw.uniform(1, 29), draw.uniform(-5, 5),
                draw.uniform(-5, 5), now - draw.uniform(0, 10)};
      gas::Gas gas = gas::exercises::table(balls, now);
      const gas::Gas before = gas;
      gas::Picture picture;
      bool right = true;
      CAPTURE(n);
      for (int step = 0; step < 10 && right; ++step) {
        const double earlier = now;
        now += draw.magnitude(-3, 1);  // steps T1 from 0.001 to 10
        gas::shift_time(gas, picture, now);
        right = CHECK_NUMBER("T after shift_time(gas, picture, T)", gas.time, now, 0) &&
                check_centres(picture.centres, gas, now, "picture.centres") &&
                check_centres(picture.old_centres, gas, step == 0 ? now : earlier,
                              "picture.old_centres");
      }
      for (std::size_t i = 0; i < gas.balls.size() && right; ++i) {
        const std::string what = fmt::format(
            "ball {}, {} before", i + 1, gas::exercises::column_of_r(before.balls[i]));
        right =
            CHECK_NUMBER(what + ": x", gas.balls[i].x, before.balls[i].x, 0) &&
            CHECK_NUMBER(what + ": vx", gas.balls[i].vx, before.balls[i].vx, 0) &&
            CHECK_NUMBER(what + ": since", gas.balls[i].since, before.balls[i].since, 0);
      }
      if (!right) break;
    }
  }
}
