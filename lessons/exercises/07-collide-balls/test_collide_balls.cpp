// Exercise 07, collide_balls: the provided tests (suite exercise-07).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage5_new_coordinates.cpp. Don't change this file
// to make a test pass: change your collide_balls.cpp.
//
// A Ball is {x, y, vx, vy}: both balls written at the same moment, in
// contact (their centres one diameter apart, whatever the diameter is).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "exercise_test.hpp"
#include "stage5_new_coordinates.hpp"

namespace {

using gas::Ball;

double dot(double ax, double ay, double bx, double by) {
  return ax * bx + ay * by;
}
double cross(double ax, double ay, double bx, double by) {
  return ax * by - ay * bx;
}

}  // namespace

TEST_SUITE("exercise-07") {
  EXERCISE_TEST("exercise-07 head-on equal balls exchange their velocities") {
    INFO("VI = (d.w) / |d|^2 with d = r2 - r1 and w = v2 - v1; v1 += VI d, v2 -= VI d");
    // Along x: d = (2, 0), w = (-4, 0), VI = -8 / 4 = -2.
    Ball p{0, 0, 1, 0}, q{2, 0, -3, 0};
    gas::collide_balls(p, q);
    CHECK(p.vx == -3);
    CHECK(q.vx == 1);
    CHECK(p.vy == 0);
    CHECK(q.vy == 0);
    // Along y: d = (0, 2), w = (0, -3), VI = -6 / 4 = -1.5.
    Ball r{5, 5, 0, 2}, s{5, 7, 0, -1};
    gas::collide_balls(r, s);
    CHECK(r.vy == -1);
    CHECK(s.vy == 2);
    CHECK(r.vx == 0);
    CHECK(s.vx == 0);
  }

  EXERCISE_TEST("exercise-07 a glancing hit changes only the components along d") {
    // p moves right at 2 and strikes q, at rest, off-centre: d = (1.5, 2)
    // (the balls have diameter 2.5), w = (-2, 0), d.w = -3, |d|^2 = 6.25,
    // VI = -0.48. So p' = (2, 0) - 0.48 (1.5, 2) = (1.28, -0.96) and
    // q' = (0.72, 0.96): q leaves along d, p across it.
    Ball p{0, 0, 2, 0}, q{1.5, 2, 0, 0};
    gas::collide_balls(p, q);
    // Why 1e-14: VI, VI d and the sums round a few times, by 1.1e-16 of
    // numbers below 3 each; a wrong sign or a missing term is off by 0.1
    // or more.
    CHECK(p.vx == doctest::Approx(1.28).epsilon(1e-14));
    CHECK(p.vy == doctest::Approx(-0.96).epsilon(1e-14));
    CHECK(q.vx == doctest::Approx(0.72).epsilon(1e-14));
    CHECK(q.vy == doctest::Approx(0.96).epsilon(1e-14));
  }

  EXERCISE_TEST(
      "exercise-07 random hits keep momentum and energy and reverse the approach") {
    INFO(
        "the radius is not passed in: at contact 4a^2 is |d|^2, the squared distance of "
        "the centres");
    std::mt19937_64 random(7);  // a fixed seed: the same hits every run
    std::uniform_real_distribution<double> place(0, 30), distance(1.5, 3),
        angle(0, 2 * std::numbers::pi), speed(-5, 5), aim(-1, 1), closing(0.5, 5);
    for (int hit = 0; hit < 200; ++hit) {
      CAPTURE(hit);
      // q at distance |d| from p in a random direction; the relative
      // velocity w aimed within 1 radian of -d, so that they approach.
      const double x = place(random), y = place(random), r = distance(random),
                   phi = angle(random);
      Ball p{x, y, speed(random), speed(random)};
      Ball q{x + r * std::cos(phi), y + r * std::sin(phi), 0, 0};
      const double towards = phi + std::numbers::pi + aim(random), w = closing(random);
      q.vx = p.vx + w * std::cos(towards);
      q.vy = p.vy + w * std::sin(towards);

      const double dx = q.x - p.x, dy = q.y - p.y;
      const double approach = dot(q.vx - p.vx, q.vy - p.vy, dx, dy);  // d.w < 0
      const double momentum_x = p.vx + q.vx, momentum_y = p.vy + q.vy;
      const double energy = dot(p.vx, p.vy, p.vx, p.vy) + dot(q.vx, q.vy, q.vx, q.vy);
      const double p_across = cross(p.vx, p.vy, dx, dy);
      const double q_across = cross(q.vx, q.vy, dx, dy);
      gas::collide_balls(p, q);

      // Why 1e-13: the velocities are below 15 and |d| below 3; the formula
      // rounds a few times by 1.1e-16 of such numbers, so each quantity
      // below comes out within about 1e-14 of its size, and 1e-13 (relative,
      // and as much again absolute: Approx adds a scale of 1) leaves room.
      // Dividing by 4 instead of |d|^2 changes the energy, far beyond that,
      // whenever |d| is not 2; a wrong sign turns nothing round. (REQUIRE: the first hit
      // that goes wrong stops the test, instead of 200 messages.)
      REQUIRE(p.vx + q.vx == doctest::Approx(momentum_x).epsilon(1e-13));
      REQUIRE(p.vy + q.vy == doctest::Approx(momentum_y).epsilon(1e-13));
      REQUIRE(dot(p.vx, p.vy, p.vx, p.vy) + dot(q.vx, q.vy, q.vx, q.vy) ==
              doctest::Approx(energy).epsilon(1e-13));
      // Along d the relative velocity is reversed: they now move apart as
      // fast as they approached.
      REQUIRE(dot(q.vx - p.vx, q.vy - p.vy, dx, dy) ==
              doctest::Approx(-approach).epsilon(1e-13));
      // Across d nothing changes, for either ball.
      REQUIRE(cross(p.vx, p.vy, dx, dy) == doctest::Approx(p_across).epsilon(1e-13));
      REQUIRE(cross(q.vx, q.vy, dx, dy) == doctest::Approx(q_across).epsilon(1e-13));
    }
  }
}
