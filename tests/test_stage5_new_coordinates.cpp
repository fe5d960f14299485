// Stage 5 of the article, "new coordinates": the step T1 (step_end), the
// shift of time that keeps the old centres RS (shift_time), the new
// velocities of two balls by the article's VI (collide_balls), carrying out a
// collision found by stage 4 (apply_collision), and the B key
// (reverse_velocities). Hand-made states and random ones (fixed seed).
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "stage5_new_coordinates.hpp"
#include "support.hpp"

namespace {

using gas::Ball;
using gas::Collision;
using gas::CollisionKind;
using gas::Gas;

constexpr double eps = std::numeric_limits<double>::epsilon();  // 2.2e-16

using gas::testing::table_with;

void check_same(const Ball& a, const Ball& b) {
  CHECK(a.x == b.x);
  CHECK(a.y == b.y);
  CHECK(a.vx == b.vx);
  CHECK(a.vy == b.vy);
  CHECK(a.since == b.since);
}

void check_point(gas::Point p, double x, double y) {
  CHECK(p.x == x);
  CHECK(p.y == y);
}

// Sums over a pair in long double, so that they add no rounding of their
// own: momentum (unit masses) and kinetic energy.
long double momentum_x(const Ball& p, const Ball& q) {
  return static_cast<long double>(p.vx) + q.vx;
}
long double momentum_y(const Ball& p, const Ball& q) {
  return static_cast<long double>(p.vy) + q.vy;
}
long double energy(const Ball& p, const Ball& q) {
  const long double v[4] = {p.vx, p.vy, q.vx, q.vy};
  return (v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]) / 2;
}

// Two balls' velocities, as (v1x, v1y, v2x, v2y).
struct Pair {
  double v1x, v1y, v2x, v2y;
};

// The article's stage 5 with the printed denominator 4a^2:
//   VI = {(x2 - x1)(v2x - v1x) + (y2 - y1)(v2y - v1y)} / 4a^2,
//   v1' = v1 + VI (r2 - r1),  v2' = v2 - VI (r2 - r1).
Pair article_vi(const Ball& p, const Ball& q, double a) {
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double vi = (dx * (q.vx - p.vx) + dy * (q.vy - p.vy)) / (4 * a * a);
  return {p.vx + vi * dx, p.vy + vi * dy, q.vx - vi * dx, q.vy - vi * dy};
}

}  // namespace

TEST_SUITE("stage5") {
  TEST_CASE("stage5 step_end: T1 is T0, or just up to the collision") {
    // T1 = T0: the step ends at T + T0 and on no collision.
    auto whole_step = [](gas::StepEnd end, double t, double t0) {
      return end.time == t + t0 && !end.on_collision;
    };
    // T1 = TC - T: the step ends at exactly TC, on the collision.
    auto up_to_collision = [](gas::StepEnd end, double tc) {
      return end.time == tc && end.on_collision;
    };
    CHECK(whole_step(gas::step_end(10, 0.5, 12), 10, 0.5));          // TC > T + T0
    CHECK(whole_step(gas::step_end(10, 0.5, gas::never), 10, 0.5));  // no collision
    CHECK(up_to_collision(gas::step_end(10, 0.5, 10.25), 10.25));    // TC < T + T0
    CHECK(up_to_collision(gas::step_end(10, 0.5, 10.5), 10.5));      // TC = T + T0
    CHECK(up_to_collision(gas::step_end(10, 0.5, 10), 10));          // a collision now
    std::mt19937_64 rng(51);
    std::uniform_real_distribution<double> now(0, 100), step(0.01, 1), ahead(0, 2);
    for (int i = 0; i < 1000; ++i) {
      const double t = now(rng), t0 = step(rng), tc = t + ahead(rng);
      const gas::StepEnd end = gas::step_end(t, t0, tc);
      if (tc > t + t0) {
        CHECK(whole_step(end, t, t0));
      } else {
        CHECK(up_to_collision(end, tc));
      }
    }
  }

  TEST_CASE("stage5 shift_time keeps the old centres and computes the new ones") {
    Gas gas = table_with({{10, 20, 2, -1, 0}, {5, 5, -0.5, 4, 1}}, 1);
    const std::vector<Ball> rows = gas.balls;
    gas::Picture picture;
    picture.centres = gas::centres_at(gas, gas.time);
    picture.old_centres = picture.centres;

    gas::shift_time(gas, picture, 1.5);
    CHECK(gas.time == 1.5);
    REQUIRE(picture.old_centres.size() == 2);
    REQUIRE(picture.centres.size() == 2);
    check_point(picture.old_centres[0], 12, 19);  // at time 1
    check_point(picture.old_centres[1], 5, 5);
    check_point(picture.centres[0], 13, 18.5);  // at time 1.5
    check_point(picture.centres[1], 4.75, 7);

    gas::shift_time(gas, picture, 2);
    check_point(picture.old_centres[0], 13, 18.5);  // RS is the last picture
    check_point(picture.old_centres[1], 4.75, 7);
    check_point(picture.centres[0], 14, 18);
    check_point(picture.centres[1], 4.5, 9);

    // The balls' rows are not rewritten: free flight needs no update.
    REQUIRE(gas.balls.size() == rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) check_same(gas.balls[i], rows[i]);

    // The first picture has no past: the old centres are the new ones.
    gas::Picture first;
    gas::shift_time(gas, first, 3);
    REQUIRE(first.old_centres.size() == 2);
    check_point(first.old_centres[0], 16, 17);
    check_point(first.centres[0], 16, 17);
  }

  TEST_CASE("stage5 collide_balls head-on exchanges the velocities along the line") {
    Ball p{0, 0, 3, 1}, q{2, 0, -1, 2};  // centres 2 apart along x
    gas::collide_balls(p, q);
    CHECK(p.vx == -1);
    CHECK(p.vy == 1);
    CHECK(q.vx == 3);
    CHECK(q.vy == 2);
    CHECK(p.x == 0);  // positions are not touched
    CHECK(q.x == 2);
  }

  TEST_CASE("stage5 collide_balls on random contacts conserves momentum and energy") {
    std::mt19937_64 rng(52);
    std::uniform_real_distribution<double> position(0, 100),
        angle(0, 2 * std::numbers::pi), radius(0.5, 5), velocity(-10, 10);
    for (int i = 0; i < 2000; ++i) {
      const double a = radius(rng), phi = angle(rng);
      const double x = position(rng), y = position(rng);
      const Ball p0{x, y, velocity(rng), velocity(rng)};
      const Ball q0{x + 2 * a * std::cos(phi), y + 2 * a * std::sin(phi), velocity(rng),
                    velocity(rng)};
      Ball p = p0, q = q0;
      gas::collide_balls(p, q);
      CAPTURE(i);

      // The line of centres as stored (rounding moved it off n by ~1e-16),
      // in long double: unit normal n and tangent t.
      const long double dx = static_cast<long double>(q0.x) - p0.x,
                        dy = static_cast<long double>(q0.y) - p0.y;
      const long double length = std::sqrt(dx * dx + dy * dy);
      const long double nx = dx / length, ny = dy / length, tx = -ny, ty = nx;
      const auto along_n = [&](long double vx, long double vy) {
        return vx * nx + vy * ny;
      };
      const auto along_t = [&](long double vx, long double vy) {
        return vx * tx + vy * ty;
      };

      // Tolerances. Let s be the largest speed. VI (r2 - r1) is computed
      // with ~4 roundings of terms of size |w| <= 2s, and adding it to a
      // velocity one more: each new component is off by at most ~10 eps s.
      // Sums of two components are then off by ~20 eps s, energies
      // (sum of v^2 / 2, four components) by ~4 * s * 10 eps s = 40 eps s^2.
      // We allow 32 eps s per component sum and 128 eps s^2 for the energy
      // — a few ulps, with a margin of ~1.5-3 over the bound (observed: at
      // most 3 eps s and 5 eps s^2). A sign error or a wrong component is
      // off by O(s) or O(s^2), ~10^15 times more.
      const double s = std::max(std::hypot(p0.vx, p0.vy), std::hypot(q0.vx, q0.vy));
      const long double velocity_tolerance = 32 * eps * s,
                        energy_tolerance = 128 * eps * s * s;

      CHECK(std::abs(momentum_x(p, q) - momentum_x(p0, q0)) < velocity_tolerance);
      CHECK(std::abs(momentum_y(p, q) - momentum_y(p0, q0)) < velocity_tolerance);
      CHECK(std::abs(energy(p, q) - energy(p0, q0)) < energy_tolerance);
      // Perpendicular to the line of centres nothing changes ...
      CHECK(std::abs(along_t(p.vx, p.vy) - along_t(p0.vx, p0.vy)) < velocity_tolerance);
      CHECK(std::abs(along_t(q.vx, q.vy) - along_t(q0.vx, q0.vy)) < velocity_tolerance);
      // ... and along it the balls swap, as in a head-on collision.
      CHECK(std::abs(along_n(p.vx, p.vy) - along_n(q0.vx, q0.vy)) < velocity_tolerance);
      CHECK(std::abs(along_n(q.vx, q.vy) - along_n(p0.vx, p0.vy)) < velocity_tolerance);
    }
  }

  TEST_CASE(
      "stage5 collide_balls is the article's VI when the centres are exactly 2a apart") {
    // Centres 2a apart exactly in binary: r2 - r1 = 2^k (A, B) with
    // A^2 + B^2 = C^2 (Pythagorean triples), 2a = 2^k C, integer multiples of
    // 2^k as positions. Then |r2 - r1|^2 = 4a^2 with no rounding at all.
    const std::array<std::array<int, 3>, 7> triples{{{3, 4, 5},
                                                     {5, 12, 13},
                                                     {8, 15, 17},
                                                     {7, 24, 25},
                                                     {20, 21, 29},
                                                     {12, 35, 37},
                                                     {9, 40, 41}}};
    std::mt19937_64 rng(53);
    std::uniform_int_distribution<int> pick(0, 6), power(-3, 3), coin(0, 1),
        place(0, 100);
    std::uniform_real_distribution<double> velocity(-10, 10);
    for (int i = 0; i < 2000; ++i) {
      const auto [A, B, C] = triples[static_cast<std::size_t>(pick(rng))];
      const double scale = std::ldexp(1.0, power(rng));
      double dx = A * scale * (coin(rng) ? 1 : -1), dy = B * scale * (coin(rng) ? 1 : -1);
      if (coin(rng)) std::swap(dx, dy);
      const double a = C * scale / 2;
      const double x = place(rng) * scale, y = place(rng) * scale;
      Ball p{x, y, velocity(rng), velocity(rng)};
      Ball q{x + dx, y + dy, velocity(rng), velocity(rng)};
      REQUIRE(dx * dx + dy * dy == 4 * a * a);
      const Pair expected = article_vi(p, q, a);
      const double s = std::max(std::hypot(p.vx, p.vy), std::hypot(q.vx, q.vy));
      gas::collide_balls(p, q);
      CAPTURE(i);
      // The same arithmetic on the same exact denominator, so equal to the
      // last bit unless the compiler orders or fuses the operations
      // differently: 4 eps s allows for that and nothing more.
      CHECK(std::abs(p.vx - expected.v1x) <= 4 * eps * s);
      CHECK(std::abs(p.vy - expected.v1y) <= 4 * eps * s);
      CHECK(std::abs(q.vx - expected.v2x) <= 4 * eps * s);
      CHECK(std::abs(q.vy - expected.v2y) <= 4 * eps * s);
    }
  }

  TEST_CASE(
      "stage5 apply_collision with a wall flips one component and puts the centre on its "
      "limit") {
    const gas::CentreLimits l{1, 39, 1, 29};
    const Ball other{30, 10, 0.25, 0.5, 4};
    // Ball 1 written at time 5 at (10, 20); the collision times are exact.
    const auto after = [&](double vx, double vy, double tc, CollisionKind kind) {
      Gas gas = table_with({{10, 20, vx, vy, 5}, other}, 5);
      gas::apply_collision(gas, l, Collision{tc, kind, 1, 0});
      check_same(gas.balls[1], other);  // the other ball is left alone
      return gas.balls[0];
    };
    SUBCASE("K = 1, top") {
      const Ball b = after(0.5, 3, 8, CollisionKind::horizontal_wall);
      check_same(b, {11.5, 29, 0.5, -3, 8});
    }
    SUBCASE("K = 1, bottom") {
      const Ball b = after(0.5, -2, 14.5, CollisionKind::horizontal_wall);
      check_same(b, {14.75, 1, 0.5, 2, 14.5});
    }
    SUBCASE("K = 2, right") {
      const Ball b = after(4, 0.5, 12.25, CollisionKind::vertical_wall);
      check_same(b, {39, 23.625, -4, 0.5, 12.25});
    }
    SUBCASE("K = 2, left") {
      const Ball b = after(-3, 0.5, 8, CollisionKind::vertical_wall);
      check_same(b, {1, 21.5, 3, 0.5, 8});
    }
  }

  TEST_CASE(
      "stage5 apply_collision with a wall on random balls lands exactly on the limit") {
    std::mt19937_64 rng(54);
    std::uniform_real_distribution<double> x(1, 39), y(1, 29), v(-7, 7), since(0, 50);
    int landed_off_without_snap = 0, walls[3] = {0, 0, 0};
    for (int i = 0; i < 1000; ++i) {
      const double t = since(rng);
      Gas gas = table_with({{x(rng), y(rng), v(rng), v(rng), t}}, t);
      const gas::CentreLimits l = gas::centre_limits(gas);
      const Collision c = gas::find_first_collision(gas, l);
      REQUIRE(c.first == 1);
      const Ball before = gas.balls[0];
      const gas::Point flown = gas::centre_at(before, c.time);
      gas::apply_collision(gas, l, c);
      const Ball& b = gas.balls[0];
      CAPTURE(i);
      CHECK(b.since == c.time);
      ++walls[static_cast<int>(c.kind)];
      if (c.kind == CollisionKind::horizontal_wall) {
        const double limit = before.vy > 0 ? l.y_max : l.y_min;
        CHECK(b.y == limit);
        CHECK(b.vy == -before.vy);
        CHECK(b.x == flown.x);
        CHECK(b.vx == before.vx);
        if (flown.y != limit) ++landed_off_without_snap;
      } else {
        REQUIRE(static_cast<int>(c.kind) ==
                static_cast<int>(CollisionKind::vertical_wall));
        const double limit = before.vx > 0 ? l.x_max : l.x_min;
        CHECK(b.x == limit);
        CHECK(b.vx == -before.vx);
        CHECK(b.y == flown.y);
        CHECK(b.vy == before.vy);
        if (flown.x != limit) ++landed_off_without_snap;
      }
    }
    CHECK(walls[1] > 100);
    CHECK(walls[2] > 100);
    // Free flight alone misses the limit by an ulp in many draws: these are
    // the cases where putting the centre on the limit matters.
    MESSAGE("free flight missed the limit in " << landed_off_without_snap
                                               << " of 1000 draws");
    CHECK(landed_off_without_snap > 10);
  }

  TEST_CASE("stage5 apply_collision of two balls moves both to TC") {
    // Ball 2 written at 0, ball 3 at 2: at time 2 they are 8 apart along x
    // and 1 apart along y, closing at 2. Ball 1 is a bystander at rest.
    Gas gas = table_with({{30, 25, 0, 0, 0}, {10, 15, 1, 0, 0}, {20, 16, -1, 0, 2}}, 2);
    const gas::CentreLimits l = gas::centre_limits(gas);
    const Collision c = gas::find_first_collision(gas, l);
    REQUIRE(static_cast<int>(c.kind) == static_cast<int>(CollisionKind::balls));
    REQUIRE(c.first == 2);
    REQUIRE(c.second == 3);
    // Why 1e-15: the root (8 - sqrt 3) / 2 is well conditioned; a few roundings.
    CHECK(c.time == doctest::Approx(2 + (8 - std::sqrt(3.0)) / 2).epsilon(1e-15));

    // What apply_collision must do: both rows rewritten at TC, then VI.
    const Ball bystander = gas.balls[0];
    Ball p = gas.balls[1], q = gas.balls[2];
    const gas::Point rp = gas::centre_at(p, c.time), rq = gas::centre_at(q, c.time);
    p = {rp.x, rp.y, p.vx, p.vy, c.time};
    q = {rq.x, rq.y, q.vx, q.vy, c.time};
    gas::collide_balls(p, q);

    gas::apply_collision(gas, l, c);
    check_same(gas.balls[0], bystander);
    check_same(gas.balls[1], p);
    check_same(gas.balls[2], q);
    // Why 1e-12: the centres at TC carry roundings of ~1e-14.
    CHECK(std::hypot(rq.x - rp.x, rq.y - rp.y) == doctest::Approx(2).epsilon(1e-12));
    // After the collision the pair separates: no second contact.
    CHECK(gas::time_of_contact(gas.balls[1], gas.balls[2], 2) == gas::never);
  }

  TEST_CASE("stage5 reverse_velocities negates every velocity at the present time") {
    Gas gas =
        table_with({{10, 20, 2, -1, 0}, {5, 5, -0.5, 4, 3}, {30, 10, 1.5, 0.25, 7}}, 7);
    const Gas before = gas;
    gas::reverse_velocities(gas);
    REQUIRE(gas.balls.size() == 3);
    CHECK(gas.time == 7);
    for (std::size_t i = 0; i < 3; ++i) {
      const Ball& old = before.balls[i];
      const gas::Point now = gas::centre_at(old, 7);
      check_same(gas.balls[i], {now.x, now.y, -old.vx, -old.vy, 7});
      // Time reversed: s after the B key the ball is where it was s before.
      for (const double s : {0.5, 1.75, 3.0}) {
        const gas::Point ahead = gas::centre_at(gas.balls[i], 7 + s);
        const gas::Point behind = gas::centre_at(old, 7 - s);
        // Binary-exact values: no rounding at all.
        CHECK(ahead.x == behind.x);
        CHECK(ahead.y == behind.y);
      }
    }
  }
}
