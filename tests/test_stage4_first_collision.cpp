// Stage 4 of the article, "first collision": the time a centre needs to reach
// a wall (time_to_wall), the time two balls come 2a apart (time_of_contact,
// the article's quadratic, solved in a form that does not cancel), and the
// scan for the earliest event TC with its kind K and balls N1, N2
// (find_first_collision). Hand-made states with exact binary values, and
// random ones (fixed seed) so that a sign error cannot hide in a symmetry.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "stage4_first_collision.hpp"
#include "support.hpp"

namespace {

using gas::Ball;
using gas::Collision;
using gas::CollisionKind;
using gas::Gas;
using gas::never;

using gas::testing::table_with;

Collision first_of(const Gas& gas) {
  return gas::find_first_collision(gas, gas::centre_limits(gas));
}

void check_collision(const Collision& c, double time, CollisionKind kind, int n1,
                     int n2) {
  CHECK(c.time == time);
  CHECK(static_cast<int>(c.kind) == static_cast<int>(kind));
  CHECK(c.first == n1);
  CHECK(c.second == n2);
}

long double relative_error(long double value, long double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

}  // namespace

TEST_SUITE("stage4") {
  TEST_CASE("stage4 time_to_wall") {
    // The centre moves in [1, 9]. Values are exact in binary.
    CHECK(gas::time_to_wall(3, 2, 1, 9) == 3);     // up to 9
    CHECK(gas::time_to_wall(3, -0.5, 1, 9) == 4);  // down to 1
    CHECK(gas::time_to_wall(9, 1, 1, 9) == 0);     // on the limit, moving out
    CHECK(gas::time_to_wall(10, 1, 1, 9) == 0);    // already beyond: now
    CHECK(gas::time_to_wall(0.5, -1, 1, 9) == 0);  // already beyond: now
    CHECK(gas::time_to_wall(10, -1, 1, 9) == 9);   // beyond the top, moving down
  }

  TEST_CASE("stage4 time_to_wall of a centre at rest is never") {
    // Wherever the centre is — inside, on a limit, beyond one — and whatever
    // the sign of zero, a velocity of zero gives `never` (no 0/0, no x/0).
    for (const double position : {-3.0, 1.0, 5.0, 9.0, 12.0}) {
      for (const double zero : {0.0, -0.0}) {
        CAPTURE(position);
        const double t = gas::time_to_wall(position, zero, 1, 9);
        CHECK_FALSE(std::isnan(t));
        CHECK(t == never);
      }
    }
  }

  TEST_CASE("stage4 time_of_contact of hand-made pairs") {
    const double diameter = 2;
    SUBCASE("head-on: 10 apart and closing at 2 -> 2 apart at t = 4") {
      CHECK(gas::time_of_contact({0, 0, 1, 0}, {10, 0, -1, 0}, diameter) == 4);
    }
    SUBCASE("oblique: q passes 1 above p's centre") {
      // (10 - 2t)^2 + 1^2 = 2^2  ->  t = (10 - sqrt 3) / 2.
      const Ball p{0, 0, 0, 0}, q{10, 1, -2, 0};
      const double t = gas::time_of_contact(p, q, diameter);
      // Why 1e-15: a handful of roundings in a well-conditioned root (the
      // hit is far from grazing); one ulp of 4.1 is 9e-16.
      CHECK(t == doctest::Approx((10 - std::sqrt(3.0)) / 2).epsilon(1e-15));
      // The order of the pair does not matter.
      CHECK(t == gas::time_of_contact(q, p, diameter));
    }
    SUBCASE("miss: q passes 3 above p's centre (D < 0)") {
      CHECK(gas::time_of_contact({0, 0, 0, 0}, {10, 3, -2, 0}, diameter) == never);
    }
    SUBCASE("grazing: q passes exactly 2 above p's centre (D = 0)") {
      // d = (10, 2), w = (-1, 0): b = -10, c = 100, |w|^2 = 1, D = 0 exactly.
      // The balls only touch sideways and exchange nothing: never.
      CHECK(gas::time_of_contact({0, 0, 0, 0}, {10, 2, -1, 0}, diameter) == never);
    }
    SUBCASE("moving apart") {
      CHECK(gas::time_of_contact({0, 0, -1, 0}, {10, 0, 1, 0}, diameter) == never);
    }
    SUBCASE("at rest relative to each other") {
      CHECK(gas::time_of_contact({0, 0, 1, 1}, {10, 0, 1, 1}, diameter) == never);
      CHECK(gas::time_of_contact({0, 0, 0, 0}, {2, 0, 0, 0}, diameter) == never);
    }
    SUBCASE("touching and approaching: collides now") {
      CHECK(gas::time_of_contact({0, 0, 0, 0, 3}, {2, 0, -1, 0, 3}, diameter) == 3);
    }
    SUBCASE("overlapping (round-off) and approaching: now") {
      CHECK(gas::time_of_contact({0, 0, 0, 0, 3}, {1.5, 0, -1, 0, 3}, diameter) == 3);
    }
    SUBCASE("touching or overlapping and moving apart: never") {
      CHECK(gas::time_of_contact({0, 0, 0, 0, 3}, {2, 0, 1, 0, 3}, diameter) == never);
      CHECK(gas::time_of_contact({0, 0, 0, 0, 3}, {1.5, 0, 1, 0, 3}, diameter) == never);
    }
    SUBCASE("different `since`: both are taken to the later one") {
      // p written at 0 at x = 0, q written at 2 at x = 10. At time 2 p is at
      // x = 2, 8 from q, closing at 2: 2 apart at time 2 + 3 = 5.
      const Ball p{0, 0, 1, 0, 0}, q{10, 0, -1, 0, 2};
      CHECK(gas::time_of_contact(p, q, diameter) == 5);
      CHECK(gas::time_of_contact(q, p, diameter) == 5);
      // The same balls, touching at the later `since`: now, i.e. at 2.
      const Ball r{8, 0, -1, 0, 2};
      CHECK(gas::time_of_contact(Ball{4, 0, 1, 0, 0}, r, diameter) == 2);
      // Overlapping (round-off) at the later `since` 3 and approaching: due
      // at 3. (Followed back to 0, q's line would first touch p at 2.5.)
      CHECK(gas::time_of_contact(Ball{0, 0, 0, 0, 0}, Ball{1.5, 0, -1, 0, 3}, diameter) ==
            3);
      // q turned at its `since` 10 (a wall, say) and now moves away from p:
      // never. Its row is not valid before 10; followed back to p's time 0
      // its line would cross p, touching it at 2.
      CHECK(gas::time_of_contact(Ball{0, 0, 0, 0, 0}, Ball{6, 0, 1, 0, 10}, diameter) ==
            never);
    }
  }

  TEST_CASE("stage4 time_of_contact agrees with the textbook root in long double") {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> position(0, 100), distance(2.5, 50),
        angle(0, 2 * std::numbers::pi), velocity(-10, 10), aim(-0.6, 0.6), speed(0.1, 10);
    const double diameter = 2;
    int hits = 0, misses = 0;
    for (int i = 0; i < 5000; ++i) {
      const double x = position(rng), y = position(rng), r = distance(rng),
                   phi = angle(rng);
      const Ball p{x, y, velocity(rng), velocity(rng)};
      Ball q{x + r * std::cos(phi), y + r * std::sin(phi), velocity(rng), velocity(rng)};
      if (i % 4 != 0) {
        // Three draws in four: q's velocity relative to p aimed within
        // +-0.6 rad of p, so that hits are frequent (about a quarter).
        const double w = speed(rng), towards = phi + std::numbers::pi + aim(rng);
        q.vx = p.vx + w * std::cos(towards);
        q.vy = p.vy + w * std::sin(towards);
      }
      // The reference: the article's quadratic with the same double inputs,
      // d = r2 - r1, w = v2 - v1, solved as printed in textbooks.
      const long double dx = static_cast<long double>(q.x) - p.x,
                        dy = static_cast<long double>(q.y) - p.y;
      const long double wx = static_cast<long double>(q.vx) - p.vx,
                        wy = static_cast<long double>(q.vy) - p.vy;
      const long double b = dx * wx + dy * wy, ww = wx * wx + wy * wy;
      const long double c =
          dx * dx + dy * dy - static_cast<long double>(diameter) * diameter;
      const long double discriminant = b * b - ww * c;
      // Grazing hits (D within 1e-4 of b^2 from 0) are left out: there the
      // root itself moves by |b| / sqrt(D) times any rounding of the inputs,
      // in any form of the formula, and hit or miss is decided by round-off.
      if (std::abs(discriminant) < 1e-4L * b * b) continue;
      const double t = gas::time_of_contact(p, q, diameter);
      CAPTURE(i);
      if (b >= 0 || discriminant < 0) {
        CHECK(t == never);
        ++misses;
        continue;
      }
      const long double reference = (-b - std::sqrt(discriminant)) / ww;
      // Why 1e-12: away from grazing, the double computation of b, c, D and
      // the root has a few roundings, each amplified at most |b| / sqrt(D)
      // <= 100 times: ~100 * 4 ulps ~ 1e-13. The long double reference is
      // ~2000 times more precise even where its subtraction cancels (c is at
      // least a third of |d|^2 here). A wrong sign or the wrong root is off
      // by O(1), far above 1e-12; but 1e-6 would let a genuine loss of half
      // the digits pass.
      CHECK(relative_error(t, reference) < 1e-12L);
      CHECK(t > 0);
      ++hits;
    }
    // The draws must test both branches substantially.
    CHECK(hits > 500);
    CHECK(misses > 500);
  }

  TEST_CASE("stage4 nearly touching balls: only the textbook root cancels") {
    // Integer centres with dx^2 + dy^2 = n^2 + 1 exactly: dx = 2m,
    // dy = 2m^2 - 1, n = 2m^2 (m = 224). With diameter n the gap term
    // c = |d|^2 - n^2 is exactly 1, i.e. 1e-10 of |d|^2: the balls are a
    // hair from touching. Every input, b, c, |w|^2 and D are integers below
    // 2^53, hence exact in double; only the square root and the root's own
    // arithmetic round. (Units do not matter: scaling all lengths by a power
    // of two changes no digit.)
    const double dx = 448, dy = 100351, diameter = 100352;
    const Ball p{0, 0, 0.5, 0.75}, q{dx, dy, -0.5, -0.25};  // w = v2 - v1 = (-1, -1)
    const double b = -(dx + dy), ww = 2, c = dx * dx + dy * dy - diameter * diameter;
    REQUIRE(c == 1);
    const double discriminant = b * b - ww * c;

    // Reference: the same root in long double, in the form without
    // subtraction; its inputs are exact, so it is good to ~1e-19.
    const long double reference =
        1.0L /
        (std::sqrt(static_cast<long double>(discriminant)) - static_cast<long double>(b));
    const double stable = gas::time_of_contact(p, q, diameter);
    const double textbook = (-b - std::sqrt(discriminant)) / ww;  // in double
    const long double stable_error = relative_error(stable, reference);
    const long double textbook_error = relative_error(textbook, reference);
    MESSAGE(fmt::format(
        "t = {:.17g}: stable form off by {:.2g}, textbook form in double off by {:.2g}",
        static_cast<double>(reference), static_cast<double>(stable_error),
        static_cast<double>(textbook_error)));
    // Why 1e-15: three roundings (sqrt, sum, division) of ~1.1e-16 each.
    CHECK(stable_error < 1e-15L);
    // The textbook form subtracts sqrt(D) ~ 100799 from 100799 to get ~1e-5:
    // the rounding of sqrt(D) (up to 7e-12) becomes a relative error of up to
    // ~7e-7; here it is 5.8e-7. 1e-9 is a million times the stable bound.
    CHECK(textbook_error > 1e-9L);
  }

  TEST_CASE("stage4 a single ball and the four walls") {
    // Ball 1 at (10, 20), written at time 5 = T; limits [1, 39] x [1, 29].
    const auto one_ball = [](double vx, double vy) {
      return first_of(table_with({{10, 20, vx, vy, 5}}, 5));
    };
    // Up to y = 29, down to y = 1, right to x = 39, left to x = 1.
    check_collision(one_ball(0, 3), 5 + 3, CollisionKind::horizontal_wall, 1, 0);
    check_collision(one_ball(0, -2), 5 + 9.5, CollisionKind::horizontal_wall, 1, 0);
    check_collision(one_ball(4, 0), 5 + 7.25, CollisionKind::vertical_wall, 1, 0);
    check_collision(one_ball(-3, 0), 5 + 3, CollisionKind::vertical_wall, 1, 0);
    // Both components moving: the nearer wall in time wins.
    check_collision(one_ball(1, 1), 5 + 9, CollisionKind::horizontal_wall, 1, 0);
    check_collision(one_ball(4, -0.5), 5 + 7.25, CollisionKind::vertical_wall, 1, 0);
  }

  TEST_CASE("stage4 a ball at rest collides with nothing") {
    const Collision c = first_of(table_with({{10, 20, 0, 0, 0}}));
    check_collision(c, never, CollisionKind::none, 0, 0);
    check_collision(first_of(table_with({})), never, CollisionKind::none, 0, 0);
  }

  TEST_CASE("stage4 a pair that collides before any wall") {
    // Ball 1 at rest far away; balls 2 and 3 head-on, 10 apart, closing at 2:
    // contact at t = 4, before ball 3 reaches x = 1 at t = 19.
    const Gas gas = table_with({{35, 5, 0, 0}, {10, 15, 1, 0}, {20, 15, -1, 0}});
    check_collision(first_of(gas), 4, CollisionKind::balls, 2, 3);
    // Listed the other way round, the pair is still named N1 < N2.
    const Gas swapped = table_with({{35, 5, 0, 0}, {20, 15, -1, 0}, {10, 15, 1, 0}});
    check_collision(first_of(swapped), 4, CollisionKind::balls, 2, 3);
  }

  TEST_CASE("stage4 touching balls moving apart do not collide") {
    // The first event is ball 1 reaching x = 1 at t = 9.
    const Gas gas = table_with({{10, 15, -1, 0}, {12, 15, 1, 0}});
    check_collision(first_of(gas), 9, CollisionKind::vertical_wall, 1, 0);
  }

  TEST_CASE("stage4 ties go to the first event scanned") {
    SUBCASE("ball 1's walls before ball 2's") {
      // Ball 1 reaches y = 29 at t = 3; ball 2 reaches x = 1 at t = 3.
      check_collision(first_of(table_with({{10, 20, 0, 3}, {7, 5, -2, 0}})), 3,
                      CollisionKind::horizontal_wall, 1, 0);
      // Ball 1 reaches x = 1 at t = 3; ball 2 reaches y = 29 at t = 3.
      check_collision(first_of(table_with({{7, 5, -2, 0}, {10, 20, 0, 3}})), 3,
                      CollisionKind::vertical_wall, 1, 0);
    }
    SUBCASE("K = 1 before K = 2 for the same ball (a corner)") {
      // From (36, 26) at (1, 1): x = 39 and y = 29 both at t = 3.
      check_collision(first_of(table_with({{36, 26, 1, 1}})), 3,
                      CollisionKind::horizontal_wall, 1, 0);
    }
    SUBCASE("every wall before any pair") {
      // Balls 1 and 2 come 2 apart at t = 4; ball 3 reaches y = 1 at t = 4.
      const Gas gas = table_with({{10, 15, 0, 0}, {10, 21, 0, -1}, {30, 5, 0, -1}});
      check_collision(first_of(gas), 4, CollisionKind::horizontal_wall, 3, 0);
    }
    SUBCASE("pairs in the order (1, 2), (1, 3), (2, 3)") {
      // Ball 1 at rest; ball 2 reaches it from the right and ball 3 from the
      // left, both at t = 6; balls 2 and 3 would meet only at t = 7.
      const Gas gas = table_with({{20, 15, 0, 0}, {28, 15, -1, 0}, {12, 15, 1, 0}});
      check_collision(first_of(gas), 6, CollisionKind::balls, 1, 2);
    }
  }

  TEST_CASE("stage4 TC is never earlier than the present time") {
    // Round-off can leave a collision a hair in the past (a ball written at
    // 9 that reached its limit at 9 + 1e-7); it is due now, at T = 10.
    const Gas wall = table_with({{39 - 1e-7, 15, 1, 0, 9}}, 10);
    check_collision(first_of(wall), 10, CollisionKind::vertical_wall, 1, 0);
    // Touching and approaching since 9.5: collides now.
    const Gas pair = table_with({{10, 15, 0, 0, 9.5}, {12, 15, -1, 0, 9.5}}, 10);
    check_collision(first_of(pair), 10, CollisionKind::balls, 1, 2);
  }

  TEST_CASE("stage4 on random gases the event at TC is real and nothing happens before") {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> x(2.5, 37.5), y(2.5, 27.5), v(-5, 5),
        start(0, 100), fraction(0, 1);
    int kinds[4] = {0, 0, 0, 0};
    for (int trial = 0; trial < 300; ++trial) {
      // Five balls in free flight since `start`, their centres then 1.5 from
      // the limits and 5 apart; a ball moves at most 5 * sqrt(2) * 0.2 < 1.5
      // by `time` = start + 0.2, so no event can happen before `time`. Each
      // ball's row is written at its own moment between start and time.
      const double begin = start(rng), time = begin + 0.2;
      std::vector<gas::Point> at_start;
      while (at_start.size() < 5) {
        const gas::Point c{x(rng), y(rng)};
        const bool free = std::all_of(
            at_start.begin(), at_start.end(),
            [&](gas::Point o) { return std::hypot(c.x - o.x, c.y - o.y) > 5; });
        if (free) at_start.push_back(c);
      }
      std::vector<Ball> balls;
      for (const gas::Point c : at_start) {
        const Ball flying{c.x, c.y, v(rng), v(rng), begin};
        const double since = begin + 0.2 * fraction(rng);
        const gas::Point written = gas::centre_at(flying, since);
        balls.push_back({written.x, written.y, flying.vx, flying.vy, since});
      }
      const Gas gas = table_with(balls, time);
      const gas::CentreLimits l = gas::centre_limits(gas);
      const Collision c = gas::find_first_collision(gas, l);
      CAPTURE(trial);
      REQUIRE(c.time < never);
      REQUIRE(c.time > time);
      ++kinds[static_cast<int>(c.kind)];
      // Why 1e-9: TC and the centres carry rounding errors of ~1e-13 (times
      // up to ~100, lengths up to 40); 1e-9 is far above that, and far below
      // the overlap that a missed event leaves at the samples below (a speed
      // of order 1 times a sampling interval of order 1e-3).
      const double tolerance = 1e-9;
      const auto centre = [&](int n, double t) {
        return gas::centre_at(gas.balls[static_cast<std::size_t>(n - 1)], t);
      };
      const gas::Point p = centre(c.first, c.time);
      if (c.kind == CollisionKind::horizontal_wall) {
        CHECK(std::min(std::abs(p.y - l.y_min), std::abs(p.y - l.y_max)) < tolerance);
      } else if (c.kind == CollisionKind::vertical_wall) {
        CHECK(std::min(std::abs(p.x - l.x_min), std::abs(p.x - l.x_max)) < tolerance);
      } else {
        REQUIRE(static_cast<int>(c.kind) == static_cast<int>(CollisionKind::balls));
        CHECK(c.first < c.second);
        const gas::Point q = centre(c.second, c.time);
        CHECK(std::hypot(q.x - p.x, q.y - p.y) == doctest::Approx(2).epsilon(tolerance));
      }
      // Before TC: every centre within its limits, every pair 2a apart or
      // more (sampled at 400 moments; the worst case is checked).
      double beyond_limits = -never, closest = never;
      for (int k = 0; k < 400; ++k) {
        const double t = time + (c.time - time) * k / 400;
        for (int i = 1; i <= 5; ++i) {
          const gas::Point a = centre(i, t);
          beyond_limits = std::max({beyond_limits, l.x_min - a.x, a.x - l.x_max,
                                    l.y_min - a.y, a.y - l.y_max});
          for (int j = i + 1; j <= 5; ++j) {
            const gas::Point b = centre(j, t);
            closest = std::min(closest, std::hypot(b.x - a.x, b.y - a.y));
          }
        }
      }
      CHECK(beyond_limits < tolerance);
      CHECK(closest > 2 - tolerance);
    }
    // All three kinds must have been exercised.
    CHECK(kinds[1] > 10);
    CHECK(kinds[2] > 10);
    CHECK(kinds[3] > 10);
  }
}
