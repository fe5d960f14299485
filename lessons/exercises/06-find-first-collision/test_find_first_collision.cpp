// Exercise 06, find_first_collision: the provided tests (suite exercise-06).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage4_first_collision.cpp. Don't change this file
// to make a test pass: change your find_first_collision.cpp.
//
// The table is 40 x 30 and the balls have radius 1, so the centres move
// within 1 <= x <= 39 and 1 <= y <= 29 (gas::exercises::table). All the
// times are exact in binary: the checks ask for equality.
#include <doctest/doctest.h>

#include <string>

#include "exercise_test.hpp"
#include "stage4_first_collision.hpp"

namespace {

using gas::Ball;
using gas::Collision;
using gas::CollisionKind;
using gas::never;
using gas::exercises::table;

Collision first_of(const gas::Gas& gas) {
  return gas::find_first_collision(gas, gas::centre_limits(gas));
}

// Checks TC, K, N1 and N2 at once, and says both what was wanted and what
// came.
void check(const Collision& got, double time, CollisionKind kind, int first, int second) {
  const auto text = [](double tc, CollisionKind k, int n1, int n2) {
    return "TC=" + std::to_string(tc) + " K=" + std::to_string(static_cast<int>(k)) +
           " N1=" + std::to_string(n1) + " N2=" + std::to_string(n2);
  };
  INFO("wanted " << text(time, kind, first, second) << ", got "
                 << text(got.time, got.kind, got.first, got.second));
  CHECK(got.time == time);
  CHECK(static_cast<int>(got.kind) == static_cast<int>(kind));
  CHECK(got.first == first);
  CHECK(got.second == second);
}

}  // namespace

TEST_SUITE("exercise-06") {
  TEST_CASE("exercise-06 one ball finds the wall it reaches first") {
    // From (10, 20): up to y = 29 in 9 / 3 = 3 (K = 1, a horizontal wall).
    check(first_of(table({{10, 20, 0, 3}})), 3, CollisionKind::horizontal_wall, 1, 0);
    // Left to x = 1 in 9 / 3 = 3 (K = 2, a vertical wall).
    check(first_of(table({{10, 20, -3, 0}})), 3, CollisionKind::vertical_wall, 1, 0);
    // Both: the wall y = 29 at 9 comes before x = 39 at 29.
    check(first_of(table({{10, 20, 1, 1}})), 9, CollisionKind::horizontal_wall, 1, 0);
    // At rest: nothing, ever (K = 0, TC = never, N1 = N2 = 0).
    check(first_of(table({{10, 20, 0, 0}})), never, CollisionKind::none, 0, 0);
  }

  TEST_CASE("exercise-06 two balls that meet before any wall") {
    // Ball 1 rests far away; balls 2 and 3 are 10 apart on the line y = 15
    // and close at 2: 2 apart at t = 4, before any wall (ball 3 reaches
    // x = 1 at 19).
    check(first_of(table({{35, 5, 0, 0}, {10, 15, 1, 0}, {20, 15, -1, 0}})), 4,
          CollisionKind::balls, 2, 3);
    // Listed the other way round they are still named N1 < N2.
    check(first_of(table({{35, 5, 0, 0}, {20, 15, -1, 0}, {10, 15, 1, 0}})), 4,
          CollisionKind::balls, 2, 3);
  }

  TEST_CASE("exercise-06 each ball flies on its own clock: since") {
    INFO("time_to_wall counts from the moment the row was written: add ball.since");
    // T = 2.5. Ball 1's row was written at 2, at (10, 20), moving up at 3:
    // it reaches y = 29 at 2 + 9 / 3 = 5. Ball 2's row was written at 0, at
    // (30, 5), moving down at 1: it reaches y = 1 at 0 + 4 / 1 = 4, first.
    check(first_of(table({{10, 20, 0, 3, 2}, {30, 5, 0, -1, 0}}, 2.5)), 4,
          CollisionKind::horizontal_wall, 2, 0);
    // Written at 2.5 instead, ball 2 reaches y = 1 at 6.5: now ball 1 is first.
    check(first_of(table({{10, 20, 0, 3, 2}, {30, 5, 0, -1, 2.5}}, 2.5)), 5,
          CollisionKind::horizontal_wall, 1, 0);
  }

  TEST_CASE("exercise-06 of events at the same moment the first one scanned wins") {
    INFO("replace the best so far only by a strictly earlier event: < not <=");
    // A ball into a corner: y = 29 and x = 39 both at 3; K = 1 is scanned first.
    check(first_of(table({{36, 26, 1, 1}})), 3, CollisionKind::horizontal_wall, 1, 0);
    // Ball 1 reaches x = 1 at 3 and ball 2 reaches y = 29 at 3: ball 1's.
    check(first_of(table({{7, 5, -2, 0}, {10, 20, 0, 3}})), 3,
          CollisionKind::vertical_wall, 1, 0);
    // Balls 1 and 2 come 2 apart at 4; ball 3 reaches y = 1 at 4: walls
    // are scanned before pairs.
    check(first_of(table({{10, 15, 0, 0}, {10, 21, 0, -1}, {30, 5, 0, -1}})), 4,
          CollisionKind::horizontal_wall, 3, 0);
    // Ball 1 at rest is reached by ball 2 from the right and by ball 3 from
    // the left, both at 6: the pair (1, 2) is scanned before (1, 3).
    check(first_of(table({{20, 15, 0, 0}, {28, 15, -1, 0}, {12, 15, 1, 0}})), 6,
          CollisionKind::balls, 1, 2);
  }

  TEST_CASE("exercise-06 TC is never earlier than the present time T") {
    INFO("round-off can put an event a hair in the past: it is due now, TC = T");
    // A row written at 9, its centre 1e-7 short of x = 39 and moving right:
    // it reached its limit at 9.0000001, but T is already 10.
    check(first_of(table({{39 - 1e-7, 15, 1, 0, 9}}, 10)), 10,
          CollisionKind::vertical_wall, 1, 0);
    // Touching and approaching since 9.5: they collide now, at T = 10.
    check(first_of(table({{10, 15, 0, 0, 9.5}, {12, 15, -1, 0, 9.5}}, 10)), 10,
          CollisionKind::balls, 1, 2);
  }
}
