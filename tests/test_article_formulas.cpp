// The article's printed formulas and exercise answers, one at a time.
//
// Each printed statement is checked twice: against an independent derivation
// (the two centres marched in small time steps in long double, plain
// geometry, exact integer cases, conservation laws) and against the stage
// code that implements it. Where the print is wrong, or right only under a
// condition, the test shows a concrete case where the printed form fails
// beside the corrected form that passes. Random cases use std::mt19937_64
// with fixed seeds; a failure prints the seed and the case (INFO).
// Lesson: lessons/8-errata.md (each entry names the test case proving it).
//
// Notation used throughout: d = r2 - r1, w = v2 - v1 (ball 2 seen from ball
// 1), n = d / |d| the unit vector along the line of centres, t = n turned by
// +90 degrees. The article's quadratic is written with p = r1 - r2 = -d and
// u = v1 - v2 = -w: A t^2 + B t + C = 0 with A = u.u, B = 2 p.u,
// C = p.p - 4a^2, D = B^2 - 4AC.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"
#include "stage5_new_coordinates.hpp"
#include "stage7_control.hpp"

namespace {

// The references' numbers: a 64-bit mantissa, 11 bits more than the stages'.
using Real = long double;

// ---------------------------------------------------------------------------
// Vectors of the plane, in long double.

struct Vec {
  Real x = 0;
  Real y = 0;
};
Vec operator+(Vec p, Vec q) {
  return {p.x + q.x, p.y + q.y};
}
Vec operator-(Vec p, Vec q) {
  return {p.x - q.x, p.y - q.y};
}
Vec operator-(Vec p) {
  return {-p.x, -p.y};
}
Vec operator*(Real s, Vec p) {
  return {s * p.x, s * p.y};
}
Real dot(Vec p, Vec q) {
  return p.x * q.x + p.y * q.y;
}
// p x q, in the plane a number.
Real cross(Vec p, Vec q) {
  return p.x * q.y - p.y * q.x;
}
Real length(Vec p) {
  return std::sqrt(dot(p, p));
}
// p turned by +90 degrees.
Vec turned(Vec p) {
  return {-p.y, p.x};
}
Real sq(Real x) {
  return x * x;
}

// Two balls of radius a: centres r1, r2 and velocities v1, v2 at time 0.
struct Pair {
  Vec r1, r2, v1, v2;
  Real a = 1;
};

gas::Ball ball(double x, double y, double vx, double vy) {
  return {x, y, vx, vy, 0};
}

// A pair of stage balls (written at time 0), widened exactly to long double.
Pair pair_of(const gas::Ball& p, const gas::Ball& q, double a) {
  return {{p.x, p.y}, {q.x, q.y}, {p.vx, p.vy}, {q.vx, q.vy}, a};
}
Vec velocity(const gas::Ball& b) {
  return {b.vx, b.vy};
}

// ---------------------------------------------------------------------------
// Independent references for the quadratic: march the two centres.

// The article's left side: the squared distance of the centres after time t,
// each centre moved on its own, x1 + v1x t - x2 - v2x t and so on.
Real squared_distance(const Pair& c, Real t) {
  const Vec r1 = c.r1 + t * c.v1;
  const Vec r2 = c.r2 + t * c.v2;
  return dot(r1 - r2, r1 - r2);
}
bool apart(const Pair& c, Real t) {
  return squared_distance(c, t) > 4 * c.a * c.a;
}

// The first moment, marching from `from` to `to` (either way) in `steps` equal
// steps, at which the distance of the centres crosses 2a: from more than 2a
// to at most 2a if `closing`, the other way if not. The step in which it
// crosses is then halved 100 times (far below long double's resolution, so
// the answer is the crossing to the last bit). No crossing: nothing.
std::optional<Real> march(const Pair& c, Real from, Real to, int steps, bool closing) {
  const Real h = (to - from) / steps;
  bool before = apart(c, from);
  for (int i = 1; i <= steps; ++i) {
    const Real t = from + h * i;
    const bool now = apart(c, t);
    if (now != before && before == closing) {
      Real lo = from + h * (i - 1), hi = t;
      for (int k = 0; k < 100; ++k) {
        const Real mid = (lo + hi) / 2;
        (apart(c, mid) == before ? lo : hi) = mid;
      }
      return (lo + hi) / 2;
    }
    before = now;
  }
  return std::nullopt;
}

// The closest the centres ever come, over all time: the distance is a convex
// function of t (the length of an affine function), so a ternary search over
// a wide window finds its minimum without any algebra.
Real closest_distance(const Pair& c) {
  Real lo = -1e7L, hi = 1e7L;
  for (int k = 0; k < 400; ++k) {
    const Real m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (squared_distance(c, m1) < squared_distance(c, m2)) {
      hi = m2;  // the minimum is not beyond m2
    } else {
      lo = m1;  // nor before m1
    }
  }
  return std::sqrt(squared_distance(c, (lo + hi) / 2));
}

// The article's quadratic, its coefficients and both roots (long double; the
// roots in the form that never subtracts nearly equal numbers).
struct Quadratic {
  Real A, B, C, D;
  Real smaller = 0, larger = 0;  // valid if D > 0
};
Quadratic quadratic(const Pair& c) {
  const Vec p = c.r1 - c.r2, u = c.v1 - c.v2;
  Quadratic q{dot(u, u), 2 * dot(p, u), dot(p, p) - 4 * c.a * c.a, 0};
  q.D = q.B * q.B - 4 * q.A * q.C;
  if (q.D > 0) {
    const Real k = -(q.B + std::copysign(std::sqrt(q.D), q.B)) / 2;
    const Real t1 = k / q.A, t2 = q.C / k;
    q.smaller = std::min(t1, t2);
    q.larger = std::max(t1, t2);
  }
  return q;
}

// Exercise 1's answer exactly as printed, with the inner term
// {(v2x - v1x)(x1 - x2) - (v2y - v1y)(y1 - y2)}^2.
Real exercise1_printed(const Pair& c) {
  const Real x1 = c.r1.x, y1 = c.r1.y, x2 = c.r2.x, y2 = c.r2.y;
  const Real v1x = c.v1.x, v1y = c.v1.y, v2x = c.v2.x, v2y = c.v2.y, a = c.a;
  return 1 / (sq(v1x - v2x) + sq(v1y - v2y)) *
         ((v2x - v1x) * (x1 - x2) + (v2y - v1y) * (y1 - y2) -
          std::sqrt(4 * a * a * (sq(v2x - v1x) + sq(v2y - v1y)) -
                    sq((v2x - v1x) * (x1 - x2) - (v2y - v1y) * (y1 - y2))));
}

// The corrected answer: the inner term is the cross product
// (v2x - v1x)(y1 - y2) - (v2y - v1y)(x1 - x2), x and y swapped in the
// position factors.
Real exercise1_corrected(const Pair& c) {
  const Real x1 = c.r1.x, y1 = c.r1.y, x2 = c.r2.x, y2 = c.r2.y;
  const Real v1x = c.v1.x, v1y = c.v1.y, v2x = c.v2.x, v2y = c.v2.y, a = c.a;
  return 1 / (sq(v1x - v2x) + sq(v1y - v2y)) *
         ((v2x - v1x) * (x1 - x2) + (v2y - v1y) * (y1 - y2) -
          std::sqrt(4 * a * a * (sq(v2x - v1x) + sq(v2y - v1y)) -
                    sq((v2x - v1x) * (y1 - y2) - (v2y - v1y) * (x1 - x2))));
}

// The two inner terms, to say when the misprint is harmless.
Real printed_inner(const Pair& c) {
  return (c.v2.x - c.v1.x) * (c.r1.x - c.r2.x) - (c.v2.y - c.v1.y) * (c.r1.y - c.r2.y);
}
Real corrected_inner(const Pair& c) {
  return (c.v2.x - c.v1.x) * (c.r1.y - c.r2.y) - (c.v2.y - c.v1.y) * (c.r1.x - c.r2.x);
}

// ---------------------------------------------------------------------------
// Random cases.

// Two balls flying towards a known closest approach: ball 2 passes ball 1 at
// the distance rho (the impact parameter) at time t0, with relative speed s.
// Plain geometry (Pythagoras) then says when the centres are 2a apart:
// t0 -/+ sqrt(4a^2 - rho^2) / s, if rho < 2a. The centres and velocities are
// rounded to double, so `geometric` is the contact time of the intended, not
// of the rounded, pair (they differ by rounding only).
struct Flight {
  gas::Ball p, q;
  double a = 1;
  Real geometric = 0;  // the earlier contact, if rho < 2a
  Real closest = 0;    // t0
  Real rho = 0;
};

// rho / 2a is drawn in [lowest, highest]; the closest approach comes 1 to 50
// time units after the time the gap of 2a + 1 takes to close, so the balls
// are apart at time 0 and meet well after it.
Flight random_flight(std::mt19937_64& rng, Real lowest, Real highest) {
  std::uniform_real_distribution<double> radius(0.5, 5), speed(0.2, 5),
      angle(0, 2 * std::numbers::pi), where(-50, 50), vel(-5, 5);
  std::uniform_real_distribution<Real> fraction(lowest, highest), delay(1, 50);
  Flight f;
  f.a = radius(rng);
  const Real s = speed(rng), phi = angle(rng);
  const Vec e{std::cos(phi), std::sin(phi)};
  f.rho = fraction(rng) * 2 * f.a;
  f.closest = (2 * f.a + 1) / s + delay(rng);
  const Vec d = f.rho * turned(e) - (s * f.closest) * e;  // r2 - r1 at time 0
  const Vec r1{where(rng), where(rng)}, v1{vel(rng), vel(rng)};
  const Vec r2 = r1 + d, v2 = v1 + s * e;
  f.p = ball(static_cast<double>(r1.x), static_cast<double>(r1.y),
             static_cast<double>(v1.x), static_cast<double>(v1.y));
  f.q = ball(static_cast<double>(r2.x), static_cast<double>(r2.y),
             static_cast<double>(v2.x), static_cast<double>(v2.y));
  if (f.rho < 2 * f.a)
    f.geometric = f.closest - std::sqrt(4 * f.a * f.a - f.rho * f.rho) / s;
  return f;
}

// Two balls in contact now (centres 2a apart, up to the rounding of the
// centres to double), approaching: the moment VI is applied.
struct Contact {
  gas::Ball p, q;
  double a = 1;
};
Contact random_contact(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> radius(0.5, 5), angle(0, 2 * std::numbers::pi),
      where(-50, 50), vel(-5, 5);
  Contact c;
  c.a = radius(rng);
  const double phi = angle(rng);
  const double x1 = where(rng), y1 = where(rng);
  const double x2 = x1 + 2 * c.a * std::cos(phi), y2 = y1 + 2 * c.a * std::sin(phi);
  for (;;) {  // approaching, and not nearly grazing: (w.n) < -0.05 |w|
    const double v1x = vel(rng), v1y = vel(rng), v2x = vel(rng), v2y = vel(rng);
    const double wn = (v2x - v1x) * std::cos(phi) + (v2y - v1y) * std::sin(phi);
    if (wn < -0.05 * std::hypot(v2x - v1x, v2y - v1y)) {
      c.p = ball(x1, y1, v1x, v1y);
      c.q = ball(x2, y2, v2x, v2y);
      return c;
    }
  }
}

// ---------------------------------------------------------------------------
// Collisions of two balls, by other means than VI.

// The head-on exchange in the frame of the line of centres: the normal
// components are exchanged, the tangential ones kept.
void exchange_along_line(const Pair& c, Vec& v1, Vec& v2) {
  const Vec n = (1 / length(c.r2 - c.r1)) * (c.r2 - c.r1), t = turned(n);
  v1 = dot(c.v2, n) * n + dot(c.v1, t) * t;
  v2 = dot(c.v1, n) * n + dot(c.v2, t) * t;
}

// VI exactly as printed, over 4a^2.
void vi_printed(const Pair& c, Vec& v1, Vec& v2) {
  const Real x1 = c.r1.x, y1 = c.r1.y, x2 = c.r2.x, y2 = c.r2.y, a = c.a;
  const Real vi =
      ((x2 - x1) * (c.v2.x - c.v1.x) + (y2 - y1) * (c.v2.y - c.v1.y)) / (4 * a * a);
  v1 = {c.v1.x + vi * (x2 - x1), c.v1.y + vi * (y2 - y1)};
  v2 = {c.v2.x - vi * (x2 - x1), c.v2.y - vi * (y2 - y1)};
}

// collide_balls on a copy of the pair.
void stage_collision(const Contact& c, Vec& v1, Vec& v2) {
  gas::Ball p = c.p, q = c.q;
  gas::collide_balls(p, q);
  v1 = velocity(p);
  v2 = velocity(q);
}

bool near(Vec p, Vec q, Real tolerance) {
  return std::fabs(p.x - q.x) <= tolerance && std::fabs(p.y - q.y) <= tolerance;
}

// ---------------------------------------------------------------------------
// Stage 4 as the article writes it, in long double, for comparison.

// A division that counts the times it is asked to divide by zero.
Real divide(Real numerator, Real denominator, int& zero_divisions) {
  if (denominator == 0) ++zero_divisions;
  return numerator / denominator;
}

// One axis of the wall scan, the article's way: "x + vx (TC - T) < G1" — if
// the centre, moved on to TC, is still inside, no wall is due and nothing is
// divided; else the wall is hit first, at T + (G1 - x) / vx. The same for
// the lower limit. Returns whether TC was changed.
bool article_wall(Real position, Real velocity, Real low, Real high, Real now, Real& tc,
                  int& zero_divisions) {
  const Real reach = position + velocity * (tc - now);
  if (!(reach < high)) {
    tc = now + divide(high - position, velocity, zero_divisions);
    return true;
  }
  if (!(reach > low)) {
    tc = now + divide(low - position, velocity, zero_divisions);
    return true;
  }
  return false;
}

struct ArticleCollision {
  Real time = 0;  // TC
  int kind = 0, first = 0, second = 0;
  int zero_divisions = 0;
};

// How the literal scan reads "N3 and N4 do not collide in the time up to TC"
// (「TC までの時間に」, up to and including TC: lessons/README.md, glossary),
// for which the article prints no inequality: a pair replaces TC only if
// strictly earlier, or also at a tie (as the wall's "x + vx (TC - T) < G1"
// does: a wall reached exactly at TC fails the test and replaces it).
enum class PairTies { kept, replaced };

// Which of one ball's walls the literal scan tests first. The article says
// the balls go in turn by number, and gives the x-test against G1 as its one
// example; it does not say whether a ball's horizontal walls come before its
// vertical ones. The stages test the horizontal ones first.
enum class WallOrder { horizontal_first, vertical_first };

// The article's stage 4 for balls all written at the gas's time T: start
// with a large TC and K = N1 = N2 = 0, scan every ball, by number, against
// the walls by the condition above, then every pair N3 < N4 by the quadratic
// (D > 0, the smaller root, not in the past). The limits are our contract's,
// a and A - a.
ArticleCollision article_first_collision(
    const gas::Gas& gas, Real large, PairTies pair_ties = PairTies::kept,
    WallOrder wall_order = WallOrder::horizontal_first) {
  ArticleCollision c;
  c.time = large;
  const Real now = gas.time, a = gas.radius;
  const Real low = a, right = Real(gas.width) - a, top = Real(gas.height) - a;
  const int n = static_cast<int>(gas.balls.size());
  for (int i = 1; i <= n; ++i) {
    const gas::Ball& b = gas.balls[static_cast<std::size_t>(i - 1)];
    auto horizontal = [&] {
      if (article_wall(b.y, b.vy, low, top, now, c.time, c.zero_divisions)) {
        c.kind = 1;  // a horizontal wall
        c.first = i;
        c.second = 0;
      }
    };
    auto vertical = [&] {
      if (article_wall(b.x, b.vx, low, right, now, c.time, c.zero_divisions)) {
        c.kind = 2;  // a vertical wall
        c.first = i;
        c.second = 0;
      }
    };
    if (wall_order == WallOrder::horizontal_first) {
      horizontal();
      vertical();
    } else {
      vertical();
      horizontal();
    }
  }
  for (int n3 = 1; n3 < n; ++n3) {
    for (int n4 = n3 + 1; n4 <= n; ++n4) {
      const Pair pair = pair_of(gas.balls[static_cast<std::size_t>(n3 - 1)],
                                gas.balls[static_cast<std::size_t>(n4 - 1)], gas.radius);
      const Quadratic q = quadratic(pair);
      if (!(q.D > 0)) continue;  // D <= 0: they miss or only touch; nothing divided
      const Real root = divide(-q.B - std::sqrt(q.D), 2 * q.A, c.zero_divisions);
      const bool earlier = now + root < c.time ||
                           (pair_ties == PairTies::replaced && now + root == c.time);
      if (root >= 0 && earlier) {
        c.time = now + root;
        c.kind = 3;
        c.first = n3;
        c.second = n4;
      }
    }
  }
  return c;
}

// Everything a take_step wrote to its trace.
struct TraceFile {
  std::FILE* file = std::tmpfile();
  ~TraceFile() {
    if (file != nullptr) std::fclose(file);
  }
  std::string text() const {
    std::string all;
    std::rewind(file);
    for (int ch = std::fgetc(file); ch != EOF; ch = std::fgetc(file))
      all += static_cast<char>(ch);
    return all;
  }
};

int count_of(const std::string& text, const std::string& word) {
  int count = 0;
  for (std::size_t at = text.find(word); at != std::string::npos;
       at = text.find(word, at + 1))
    ++count;
  return count;
}

gas::Gas table(double width, double height, double radius, std::vector<gas::Ball> balls,
               double display_step = 1) {
  gas::Gas g;
  g.width = width;
  g.height = height;
  g.radius = radius;
  g.balls = std::move(balls);
  g.display_step = display_step;
  return g;
}

}  // namespace

TEST_SUITE("article") {
  // =========================================================================
  // Stage 4: the quadratic (x1 + v1x t - x2 - v2x t)^2 + (...)^2 = 4a^2.

  TEST_CASE("article quadratic: the smaller root is when the centres come 2a apart") {
    // Independent: march the centres in steps of 0.001 and bisect the step in
    // which their distance falls to 2a; and Pythagoras on the flight's
    // impact parameter. Stage: time_of_contact.
    constexpr std::uint64_t seed = 401;
    std::mt19937_64 rng(seed);
    for (int i = 0; i < 200; ++i) {
      INFO("seed " << seed << ", case " << i);
      // rho <= 0.95 * 2a: the dip below 2a lasts at least 0.12 time units,
      // so a march in steps of 0.001 cannot step over it.
      const Flight f = random_flight(rng, 0, 0.95);
      const Pair pair = pair_of(f.p, f.q, f.a);
      const std::optional<Real> marched = march(pair, 0, 160, 160000, true);
      REQUIRE(marched.has_value());
      const Quadratic q = quadratic(pair);
      REQUIRE(q.D > 0);
      // Why 1e-9: the march and the root are both long double answers for the
      // same double inputs (agreeing to ~1e-15); Pythagoras used the inputs
      // before their rounding to double (~1e-14 off), and the stage works in
      // double, where a time of contact is off by (rounding of the positions,
      // ~1e-14) / (normal approach speed, >= 0.3 * 0.2). A wrong root or a
      // wrong formula is off by far more than 1e-9 (tenths at the least).
      CHECK(std::fabs(q.smaller - *marched) <= 1e-9L);
      CHECK(std::fabs(f.geometric - *marched) <= 1e-9L);
      CHECK(std::fabs(gas::time_of_contact(f.p, f.q, 2 * f.a) - *marched) <= 1e-9L);
    }
  }

  TEST_CASE(
      "article quadratic: the larger root is when the balls would part after passing "
      "through") {
    // "The larger root is the time they would touch again after
    // interpenetrating": march on from the first contact until the distance
    // grows back to 2a; Pythagoras says t0 + sqrt(4a^2 - rho^2) / s.
    constexpr std::uint64_t seed = 402;
    std::mt19937_64 rng(seed);
    for (int i = 0; i < 100; ++i) {
      INFO("seed " << seed << ", case " << i);
      const Flight f = random_flight(rng, 0, 0.95);
      const Pair pair = pair_of(f.p, f.q, f.a);
      const std::optional<Real> first = march(pair, 0, 160, 160000, true);
      REQUIRE(first.has_value());
      const std::optional<Real> again = march(pair, *first + 1e-6L, 300, 300000, false);
      REQUIRE(again.has_value());
      const Quadratic q = quadratic(pair);
      // Why 1e-9: as for the smaller root (long double answers for the same
      // inputs, and geometry before rounding the inputs to double).
      CHECK(std::fabs(q.larger - *again) <= 1e-9L);
      CHECK(std::fabs((2 * f.closest - f.geometric) - *again) <= 1e-9L);
      // The stage never reports the larger root: the collision is the first.
      CHECK(gas::time_of_contact(f.p, f.q, 2 * f.a) < q.larger - 0.1L);
    }
  }

  TEST_CASE("article quadratic: negative roots are collisions in the past") {
    // Flights like those above, run backwards: the balls met and parted
    // before time 0. Marching back in time finds the contacts; both roots
    // are < 0; the stage sees no coming collision.
    constexpr std::uint64_t seed = 403;
    std::mt19937_64 rng(seed);
    for (int i = 0; i < 100; ++i) {
      INFO("seed " << seed << ", case " << i);
      Flight f = random_flight(rng, 0, 0.95);
      // Run the same flight backwards: reverse both velocities, so that the
      // approach lies behind time 0 instead of ahead.
      f.p.vx = -f.p.vx, f.p.vy = -f.p.vy, f.q.vx = -f.q.vx, f.q.vy = -f.q.vy;
      const Pair pair = pair_of(f.p, f.q, f.a);
      const std::optional<Real> last_contact = march(pair, 0, -160, 160000, true);
      REQUIRE(last_contact.has_value());
      const Quadratic q = quadratic(pair);
      REQUIRE(q.D > 0);
      CHECK(q.smaller < 0);
      CHECK(q.larger < 0);
      // Why 1e-9: as above. Marching back, the first contact met is the
      // larger (later) root.
      CHECK(std::fabs(q.larger - *last_contact) <= 1e-9L);
      CHECK(gas::time_of_contact(f.p, f.q, 2 * f.a) == gas::never);
      // Nothing ahead: the march forward finds no contact.
      CHECK_FALSE(march(pair, 0, 160, 16000, true).has_value());
    }
  }

  TEST_CASE(
      "article quadratic: a root a hair below zero from round-off is not the past") {
    // Two balls put in contact with double centres are 2a apart only up to
    // rounding: C = p.p - 4a^2 comes out a few ulps negative about half the
    // time, and the smaller root a hair below zero. Read literally ("a
    // negative root means a collision in the past") such a contact would be
    // skipped and the balls would pass through each other. The printed
    // statement holds for balls apart (C > 0); the stage treats touching and
    // approaching balls as colliding now.
    constexpr std::uint64_t seed = 404;
    std::mt19937_64 rng(seed);
    int negative = 0;
    for (int i = 0; i < 400; ++i) {
      INFO("seed " << seed << ", case " << i);
      const Contact c = random_contact(rng);
      const Pair pair = pair_of(c.p, c.q, c.a);
      const Quadratic q = quadratic(pair);
      if (q.C < 0 && q.D > 0) {
        ++negative;
        CHECK(q.smaller < 0);
        // Now, not never. Why 1e-12: the stage computes C in double, where it
        // may round to a tiny positive number instead; then its root is
        // C / (sqrt(D) - b) with |C| ~ 1e-14 and sqrt(D) - b ~ 1: ~1e-14.
        const double t = gas::time_of_contact(c.p, c.q, 2 * c.a);
        CHECK(t >= 0);
        CHECK(t <= 1e-12);
      }
    }
    CHECK(negative > 50);  // the case is common, not contrived
  }

  TEST_CASE("article quadratic: D > 0 collide and D = 0 touch and D < 0 miss") {
    SUBCASE("an exact grazing touch, D = 0 in integers") {
      // Ball 2 at rest at (10, 2), ball 1 from the origin along x at speed 1,
      // a = 1: the distance is sqrt((10 - t)^2 + 4), least at t = 10, where it
      // is exactly 2a. A = 1, B = -20, C = 100: D = 400 - 400 = 0.
      const gas::Ball p = ball(0, 0, 1, 0), q = ball(10, 2, 0, 0);
      const Pair pair = pair_of(p, q, 1);
      const Quadratic quad = quadratic(pair);
      CHECK(quad.D == 0);
      CHECK(closest_distance(pair) == doctest::Approx(2.0).epsilon(1e-15));
      CHECK(squared_distance(pair, 10) == 4);  // touch at t = -B / 2A = 10, exactly
      bool never_closer = true;  // marched in steps of 0.001: never closer than 2a
      for (int k = 0; k <= 20000; ++k)
        never_closer = never_closer && squared_distance(pair, k / 1000.0L) >= 4;
      CHECK(never_closer);
      // The stage does not call a touch a collision, and loses nothing by it:
      // at the touch d.w = 0, so VI = 0 and the velocities would not change.
      CHECK(gas::time_of_contact(p, q, 2) == gas::never);
      gas::Ball p10 = ball(10, 0, 1, 0), q10 = q;  // the touch itself
      gas::collide_balls(p10, q10);
      CHECK(p10.vx == 1);
      CHECK(p10.vy == 0);
      CHECK(q10.vx == 0);
      CHECK(q10.vy == 0);
    }

    SUBCASE("equal velocities: A = 0, and D = 0 keeps the division away") {
      // With no relative motion the equation is not quadratic (A = 0); then
      // B = 2 p.u = 0 too, so D = 0: "D > 0" already excludes the division by
      // 2A = 0.
      const gas::Ball p = ball(0, 0, 1.5, -2), q = ball(1.5, 0.5, 1.5, -2);
      const Quadratic quad = quadratic(pair_of(p, q, 1));
      CHECK(quad.A == 0);
      CHECK(quad.D == 0);
      CHECK(gas::time_of_contact(p, q, 2) == gas::never);
    }

    SUBCASE("random pairs: the sign of D is the sign of 2a - closest distance") {
      // Independent: the closest distance by ternary search. Pairs within
      // 1e-6 of grazing are left out: their class is decided by rounding.
      constexpr std::uint64_t seed = 405;
      std::mt19937_64 rng(seed);
      std::uniform_real_distribution<double> radius(0.5, 5), where(0, 60), vel(-5, 5);
      int hits = 0, misses = 0;
      for (int i = 0; i < 2000; ++i) {
        INFO("seed " << seed << ", case " << i);
        const double a = radius(rng);
        const gas::Ball p = ball(where(rng), where(rng), vel(rng), vel(rng));
        const gas::Ball q = ball(where(rng), where(rng), vel(rng), vel(rng));
        const Pair pair = pair_of(p, q, a);
        const Real closest = closest_distance(pair);
        if (std::fabs(closest - 2 * a) < 1e-6L || !apart(pair, 0)) continue;
        const Quadratic quad = quadratic(pair);
        CHECK((quad.D > 0) == (closest < 2 * a));
        // The stage: a collision ahead exactly when D > 0 and the roots are
        // ahead (approaching, B < 0).
        const bool ahead = quad.D > 0 && quad.B < 0;
        CHECK((gas::time_of_contact(p, q, 2 * a) != gas::never) == ahead);
        (quad.D > 0 ? hits : misses) += 1;
      }
      CHECK(hits > 100);
      CHECK(misses > 100);
    }
  }

  // =========================================================================
  // Exercise 1: the collision time as printed.

  TEST_CASE("article exercise 1 as printed gives NaN for a head-on collision") {
    // Ball 1 at the origin moving at (1, 0), ball 2 at rest at (10, 0), a = 1:
    // the gap of 8 closes at speed 1, so they collide at t = 8.
    const gas::Ball p = ball(0, 0, 1, 0), q = ball(10, 0, 0, 0);
    const Pair pair = pair_of(p, q, 1);
    CHECK(march(pair, 0, 20, 20000, true).value() == doctest::Approx(8.0).epsilon(1e-15));
    CHECK(gas::time_of_contact(p, q, 2) == 8.0);
    // Printed: the inner term is (v2x - v1x)(x1 - x2) = (-1)(-10) = 10, so the
    // root is sqrt(4 - 100): NaN.
    CHECK(printed_inner(pair) == 10);
    CHECK(std::isnan(exercise1_printed(pair)));
    // Corrected: the cross product (v2x - v1x)(y1 - y2) - (v2y - v1y)(x1 - x2)
    // = 0, and (10 - sqrt(4)) / 1 = 8.
    CHECK(corrected_inner(pair) == 0);
    CHECK(exercise1_corrected(pair) == 8);
    // The same along y: the printed form fails the same way.
    const Pair along_y = pair_of(ball(3, 0, 0, 1), ball(3, 10, 0, 0), 1);
    CHECK(std::isnan(exercise1_printed(along_y)));
    CHECK(exercise1_corrected(along_y) == 8);
  }

  TEST_CASE(
      "article exercise 1 as printed survives a diagonal head-on case only by symmetry") {
    // A symmetric example hides the misprint: along the diagonal the printed
    // term (v2x - v1x)(x1 - x2) - (v2y - v1y)(y1 - y2) and the cross product
    // are both 0.
    const Pair diagonal = pair_of(ball(0, 0, 1, 1), ball(10, 10, 0, 0), 1);
    CHECK(printed_inner(diagonal) == 0);
    CHECK(corrected_inner(diagonal) == 0);
    const Real truth = 10 - std::sqrt(2.0L);  // gap 10 sqrt2 - 2 closed at speed sqrt2
    // Why 1e-15: a handful of long double roundings on numbers of order 10.
    CHECK(std::fabs(exercise1_printed(diagonal) - truth) <= 1e-15L);
    CHECK(std::fabs(exercise1_corrected(diagonal) - truth) <= 1e-15L);
  }

  TEST_CASE(
      "article exercise 1: random pairs where the printed form fails and the cross "
      "product passes") {
    // Independent: the march. The printed answer is right exactly when its
    // inner term squared equals the cross product squared; otherwise it is
    // wrong (a wrong number or NaN).
    constexpr std::uint64_t seed = 411;
    std::mt19937_64 rng(seed);
    int printed_wrong = 0, printed_nan = 0;
    for (int i = 0; i < 200; ++i) {
      INFO("seed " << seed << ", case " << i);
      const Flight f = random_flight(rng, 0, 0.95);
      const Pair pair = pair_of(f.p, f.q, f.a);
      const Real marched = march(pair, 0, 160, 160000, true).value();
      // Why 1e-9: the corrected formula is the textbook root, in long double
      // (its cancellation costs at most a few digits of 19), against the
      // march to the last bit; see the first test for the scale of errors.
      CHECK(std::fabs(exercise1_corrected(pair) - marched) <= 1e-9L);
      const Real printed = exercise1_printed(pair);
      const bool printed_right = std::fabs(printed - marched) <= 1e-9L;  // false for NaN
      // Why 1e-12 relative: the two squares are long double sums of products
      // of the same inputs; equal terms would agree to ~1e-18, and random
      // ones differ by order 1.
      const Real pi2 = sq(printed_inner(pair)), ci2 = sq(corrected_inner(pair));
      const bool terms_agree = std::fabs(pi2 - ci2) <= 1e-12L * (1 + pi2 + ci2);
      CHECK(printed_right == terms_agree);
      if (!printed_right) ++printed_wrong;
      if (std::isnan(printed)) ++printed_nan;
    }
    // Random cases almost never hit the symmetric coincidence.
    CHECK(printed_wrong >= 195);
    CHECK(printed_nan > 50);
  }

  TEST_CASE("article exercise 1 corrected: Lagrange's identity exactly") {
    // The discriminant of the quadratic, D / 4 = (p.u)^2 - |u|^2 (|p|^2 - 4a^2),
    // equals 4a^2 |u|^2 - (p x u)^2 because |p|^2 |u|^2 - (p.u)^2 = (p x u)^2.
    // Checked on small integers, where every operation is exact.
    constexpr std::uint64_t seed = 412;
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> small(-50, 50);
    for (int i = 0; i < 1000; ++i) {
      INFO("seed " << seed << ", case " << i);
      const Vec p{Real(small(rng)), Real(small(rng))},
          u{Real(small(rng)), Real(small(rng))};
      const Real a = small(rng);
      CHECK(dot(p, p) * dot(u, u) - sq(dot(p, u)) == sq(cross(p, u)));
      CHECK(sq(dot(p, u)) - dot(u, u) * (dot(p, p) - 4 * a * a) ==
            4 * a * a * dot(u, u) - sq(cross(p, u)));
    }
  }

  // =========================================================================
  // Stage 4: the wall condition "x + vx (TC - T) < G1".

  TEST_CASE(
      "article wall condition: the scan never divides by zero and agrees with "
      "time_to_wall") {
    // A centre strictly inside its limits and a finite TC: if the condition
    // fails, x + vx (TC - T) >= G1 > x, so vx (TC - T) > 0 and vx != 0. A
    // zero component makes the condition true, and nothing is divided.
    constexpr std::uint64_t seed = 421;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1), vel(-5, 5), horizon(0.1, 100);
    int zero_velocities = 0, reached = 0;
    for (int i = 0; i < 5000; ++i) {
      INFO("seed " << seed << ", case " << i);
      const double low = 4, high = 4 + 250 * (0.1 + unit(rng));
      const double x =
          low + (high - low) * (0.001 + 0.998 * unit(rng));  // strictly inside
      const double vx = unit(rng) < 0.25 ? 0.0 : vel(rng);
      const double now = 100 * unit(rng), h = horizon(rng);
      Real tc = now + Real(h);
      int zero_divisions = 0;
      const bool due = article_wall(x, vx, low, high, now, tc, zero_divisions);
      CHECK(zero_divisions == 0);
      const double stage = gas::time_to_wall(x, vx, low, high);
      if (vx == 0) {
        ++zero_velocities;
        CHECK_FALSE(due);
        CHECK(stage == gas::never);
      }
      // The condition fails (a wall is due) exactly when the stage's time to
      // the wall is within the horizon; then the times agree. Why 1e-12 (of
      // a time up to ~1e4 for the slowest centres): one double division
      // against the same in long double, half an ulp, plus the rounding of
      // now + h.
      CHECK(due == (stage <= h));
      if (due) {
        ++reached;
        CHECK(std::fabs((tc - now) - stage) <= 1e-12L * (1 + stage));
      }
    }
    CHECK(zero_velocities > 1000);
    CHECK(reached > 1000);
  }

  TEST_CASE(
      "article wall condition: a centre at rest on its limit or an infinite TC divides "
      "by zero") {
    // The promise holds under two conditions the text leaves unsaid.
    const double low = 1, high = 9;
    SUBCASE("at rest exactly on the limit: the strict < fails and 0 / 0 is asked") {
      Real tc = 1e30L;
      int zero_divisions = 0;
      CHECK(article_wall(high, 0.0, low, high, 0, tc, zero_divisions));
      CHECK(zero_divisions == 1);
      CHECK(std::isnan(tc));
      // time_to_wall asks the sign of the velocity first: at rest, never.
      CHECK(gas::time_to_wall(high, 0.0, low, high) == gas::never);
      CHECK(gas::time_to_wall(low, 0.0, low, high) == gas::never);
    }
    SUBCASE("an infinite 'large TC': 0 * infinity is NaN, the condition fails") {
      // The article starts from "a large TC"; our TC for "nothing" is
      // infinity (gas::never), with which the literal condition breaks for a
      // zero component.
      Real tc = std::numeric_limits<Real>::infinity();
      int zero_divisions = 0;
      CHECK(article_wall(5, 0.0, low, high, 0, tc, zero_divisions));
      CHECK(zero_divisions == 1);
      CHECK(gas::time_to_wall(5, 0.0, low, high) == gas::never);
    }
    SUBCASE("on the limit and moving towards it: the wall is due now") {
      CHECK(gas::time_to_wall(high, 2.0, low, high) == 0);
      CHECK(gas::time_to_wall(low, -2.0, low, high) == 0);
      CHECK(gas::time_to_wall(high, -2.0, low, high) == 4);  // leaving it: the other wall
    }
  }

  TEST_CASE("article stage 4: find_first_collision finds the article's first collision") {
    // Random gases, some velocity components exactly zero and some pairs with
    // equal velocities (A = 0): the article's scan (walls by the condition,
    // pairs by the quadratic, long double) never divides by zero, and the
    // stage finds the same K, N1, N2 and TC.
    constexpr std::uint64_t seed = 422;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1), vel(-3, 3);
    std::uniform_int_distribution<int> count(1, 10);
    int kinds[4] = {0, 0, 0, 0};
    for (int i = 0; i < 1000; ++i) {
      INFO("seed " << seed << ", case " << i);
      const double a = 1 + 5 * unit(rng), width = 60 + 196 * unit(rng),
                   height = 40 + 152 * unit(rng);
      gas::Gas g = table(width, height, a, {});
      g.time = 100 * unit(rng);
      const int n = count(rng);
      for (int tries = 0; static_cast<int>(g.balls.size()) < n && tries < 1000; ++tries) {
        const double x = a + (width - 2 * a) * (0.001 + 0.998 * unit(rng));
        const double y = a + (height - 2 * a) * (0.001 + 0.998 * unit(rng));
        bool free = true;
        for (const gas::Ball& b : g.balls)
          free = free && std::hypot(b.x - x, b.y - y) > 2 * a * 1.01;
        if (!free) continue;
        gas::Ball b{x, y, unit(rng) < 0.2 ? 0.0 : vel(rng),
                    unit(rng) < 0.2 ? 0.0 : vel(rng), g.time};
        if (!g.balls.empty() && unit(rng) < 0.2)
          b.vx = g.balls.back().vx, b.vy = g.balls.back().vy;
        g.balls.push_back(b);
      }
      const ArticleCollision article = article_first_collision(g, 1e30L);
      const gas::Collision stage = gas::find_first_collision(g, gas::centre_limits(g));
      CHECK(article.zero_divisions == 0);
      CHECK(static_cast<int>(stage.kind) == article.kind);
      CHECK(stage.first == article.first);
      CHECK(stage.second == article.second);
      // Why 1e-9 (relative to 1 + TC): wall times are one division (1e-15);
      // pair times as in the quadratic tests above.
      if (article.kind != 0)
        CHECK(std::fabs(stage.time - article.time) <= 1e-9L * (1 + article.time));
      ++kinds[article.kind];
    }
    CHECK(kinds[1] > 50);
    CHECK(kinds[2] > 50);
    CHECK(kinds[3] > 50);
  }

  TEST_CASE(
      "article ties: two balls at one wall at one TC, the article's scan keeps the later "
      "ball, the stages the earlier") {
    // The order the article does give: the balls in turn by number. Its
    // wall test "x + vx (TC - T) < G1" fails when a ball reaches the limit
    // exactly at the TC found so far ("up to TC" includes TC), so that
    // ball's wall replaces TC: of simultaneous walls the later-numbered ball
    // wins. The stages keep the earlier (a later event must be strictly
    // earlier). a = 1 on a 10 x 10 table: balls 1 at (5, 3) and 2 at (5, 7),
    // both moving (1, 0), reach x = G1 = 9 together at T = 4, every number
    // exact in floating point.
    const gas::Gas two = table(10, 10, 1, {ball(5, 3, 1, 0), ball(5, 7, 1, 0)}, 8);
    for (const WallOrder order :
         {WallOrder::horizontal_first, WallOrder::vertical_first}) {
      const ArticleCollision article =
          article_first_collision(two, 1e30L, PairTies::kept, order);
      CHECK(article.time == 4);
      CHECK(article.kind == 2);
      CHECK(article.first == 2);  // the article: the later-numbered ball
    }
    const gas::Collision stage = gas::find_first_collision(two, gas::centre_limits(two));
    CHECK(stage.time == 4);
    CHECK(stage.kind == gas::CollisionKind::vertical_wall);
    CHECK(stage.first == 1);  // the stages: the earlier-numbered ball
    CHECK(stage.second == 0);
    // Stage 7 carries out both at the instant, ball 1 first, and the
    // instant ends as in the article's order: events of different balls
    // commute.
    gas::Control control = gas::start_control(two);
    const gas::Step step = gas::take_step(control, gas::never, nullptr);
    REQUIRE(step.collisions.size() == 2);
    CHECK(step.collisions[0].first == 1);
    CHECK(step.collisions[1].first == 2);
    CHECK(control.gas.time == 4);
    for (const gas::Ball& b : control.gas.balls) {
      CHECK(b.vx == -1);
      CHECK(b.vy == 0);
    }
  }

  TEST_CASE(
      "article ties: the corner's K depends on which wall of a ball is tested first, "
      "which the article leaves open") {
    // A ball aimed into a corner: a = 1 on a 10 x 10 table, a ball at (5, 5)
    // moving (1, 1) meets y = 9 (K = 1) and x = 9 (K = 2) both at T = 4. The
    // literal rule lets the wall tested last win, so its K is whichever wall
    // of the ball comes second: K = 2 in the stages' order (horizontal
    // first), K = 1 had the x-test (the article's one example) come first.
    // The stages keep the one tested first, K = 1.
    const gas::Gas corner = table(10, 10, 1, {ball(5, 5, 1, 1)});
    const ArticleCollision horizontal_first = article_first_collision(
        corner, 1e30L, PairTies::kept, WallOrder::horizontal_first);
    const ArticleCollision vertical_first =
        article_first_collision(corner, 1e30L, PairTies::kept, WallOrder::vertical_first);
    const gas::Collision stage =
        gas::find_first_collision(corner, gas::centre_limits(corner));
    CHECK(horizontal_first.time == 4);
    CHECK(horizontal_first.kind == 2);
    CHECK(vertical_first.time == 4);
    CHECK(vertical_first.kind == 1);
    CHECK(stage.time == 4);
    CHECK(stage.kind == gas::CollisionKind::horizontal_wall);  // the stages: tested first
    // Either order, the instant ends the same: each wall flips its own
    // component of the one ball's velocity, and flips commute.
    const gas::CentreLimits limits = gas::centre_limits(corner);
    auto both_walls = [&](gas::CollisionKind first, gas::CollisionKind second) {
      gas::Gas g = corner;
      g.time = 4;
      gas::apply_collision(g, limits, {4, first, 1, 0});
      gas::apply_collision(g, limits, {4, second, 1, 0});
      return g.balls[0];
    };
    const gas::Ball ours = both_walls(gas::CollisionKind::horizontal_wall,
                                      gas::CollisionKind::vertical_wall);
    const gas::Ball other = both_walls(gas::CollisionKind::vertical_wall,
                                       gas::CollisionKind::horizontal_wall);
    CHECK(ours.x == other.x);
    CHECK(ours.y == other.y);
    CHECK(ours.vx == other.vx);
    CHECK(ours.vy == other.vy);
    CHECK(ours.vx == -1);
    CHECK(ours.vy == -1);
    // And stage 7 carries out both at the instant, in the stages' order.
    gas::Control control = gas::start_control(table(10, 10, 1, {ball(5, 5, 1, 1)}, 8));
    const gas::Step step = gas::take_step(control, gas::never, nullptr);
    REQUIRE(step.collisions.size() == 2);
    CHECK(step.collisions[0].kind == gas::CollisionKind::horizontal_wall);
    CHECK(step.collisions[1].kind == gas::CollisionKind::vertical_wall);
    CHECK(control.gas.balls[0].vx == -1);
    CHECK(control.gas.balls[0].vy == -1);
  }

  TEST_CASE(
      "article ties: where simultaneous collisions share a ball the order decides") {
    // For pairs the article prints no inequality ("N3 and N4 do not collide
    // in the time up to TC", 「TC までの時間に」). Read like its wall test, a
    // pair meeting exactly at TC would replace it and the later pair would
    // win. Then the order matters: ball 2 at rest is struck at T = 3 by ball
    // 1 along x and by ball 3 along (3, 4)/5, both meetings exact in floating
    // point (a = 5: the centres 10 apart along (1, 0) and along (6, 8)).
    const gas::Gas g = table(
        100, 100, 5, {ball(34, 50, 2, 0), ball(50, 50, 0, 0), ball(65, 70, -3, -4)}, 8);
    REQUIRE(gas::pair_time(g, 1, 2) == 3);
    REQUIRE(gas::pair_time(g, 2, 3) == 3);
    const gas::Collision stage = gas::find_first_collision(g, gas::centre_limits(g));
    CHECK(stage.kind == gas::CollisionKind::balls);
    CHECK(stage.first == 1);  // the stages: (1, 2), scanned first
    CHECK(stage.second == 2);
    const ArticleCollision kept = article_first_collision(g, 1e30L, PairTies::kept);
    CHECK(kept.first == 1);
    CHECK(kept.second == 2);
    const ArticleCollision replaced =
        article_first_collision(g, 1e30L, PairTies::replaced);
    CHECK(replaced.first == 2);  // read like the wall test: (2, 3), scanned last
    CHECK(replaced.second == 3);
    // Stage 7 carries out the stages' order, (1, 2) first, until nothing is
    // due at T = 3; starting with (2, 3) instead ends the instant elsewhere.
    gas::Control ours = gas::start_control(g);
    gas::take_step(ours, gas::never, nullptr);
    REQUIRE(ours.gas.time == 3);
    gas::Gas other = g;
    other.time = 3;
    const gas::CentreLimits limits = gas::centre_limits(g);
    gas::apply_collision(other, limits, {3, gas::CollisionKind::balls, 2, 3});
    for (gas::Collision c = gas::find_first_collision(other, limits);
         c.kind != gas::CollisionKind::none && c.time <= 3;
         c = gas::find_first_collision(other, limits)) {
      gas::apply_collision(other, limits, c);
    }
    // Why 1e-12: velocities of order 1 after three collisions, each exact to
    // a few ulps; the two orders differ by more than 1 (ball 1 leaves at
    // -1.72 one way, -3 the other).
    CHECK(std::fabs(ours.gas.balls[0].vx - -1.72) < 1e-12);
    CHECK(std::fabs(other.balls[0].vx - -3) < 1e-12);
    // Both conserve the energy: neither order is wrong physics, it is a
    // three-ball event that the two-ball formula VI does not describe, and
    // each program must pick an order. The stages pick the scan's first.
    CHECK(gas::kinetic_energy(ours.gas) == doctest::Approx(gas::kinetic_energy(g)));
    CHECK(gas::kinetic_energy(other) == doctest::Approx(gas::kinetic_energy(g)));
  }

  // =========================================================================
  // Stage 3: the limits "of the type" G1 = A1 - 2a - 1.

  TEST_CASE(
      "article limits: G1 = A1 - 2a - 1 is the corner of a ball drawn inside a one-pixel "
      "border") {
    // The article's example screen: integer points 1..256 by 1..192. Our
    // reading (the article says only that G1 and G2 are the limits of the
    // centres' positions, 「球の中心の位置の限界」, "of the type" G1 = A1 - 2a - 1):
    // the table's border is a line one point wide on the columns 1 and A1 (the
    // rows 1 and A2); the point (x, y) stored for a ball is where its drawing
    // starts, the corner of its box of 2a + 1 points, so it covers x..x+2a and
    // its centre is the point (x + a, y + a). "2a": the box; "- 1": the border
    // point. Checked by drawing: the corners that keep every drawn point off
    // the border are exactly 2..G1, and at G1 the ball's last point is next to
    // the border (it touches it on the screen).
    for (const int a1 : {256, 100}) {
      for (int a = 0; a <= 12; ++a) {
        INFO("A1 = " << a1 << ", a = " << a);
        const int g1 = a1 - 2 * a - 1;  // as printed
        // The drawn disc: the points within a of the centre (x + a, y + a);
        // along a row through the centre these are x..x+2a.
        auto clear = [&](int corner) {
          for (int px = corner; px <= corner + 2 * a; ++px) {
            if (px <= 1 || px >= a1) return false;  // on or beyond the border
          }
          return true;
        };
        int lowest = 0, highest = 0;
        for (int corner = -20; corner <= a1 + 20; ++corner) {
          if (!clear(corner)) continue;
          if (lowest == 0) lowest = corner;
          highest = corner;
        }
        CHECK(lowest == 2);
        CHECK(highest == g1);
        CHECK(g1 + 2 * a == a1 - 1);  // at G1 the ball's last point touches the border
        // Read instead as a limit of the centre of a disc drawn around it,
        // G1 would stop the ball a points short of the border: the centres
        // that fit go up to A1 - a - 1.
        CHECK(highest + a == a1 - a - 1);
        CHECK((a1 - a - 1) - g1 == a);
      }
    }
  }

  TEST_CASE("article limits: the corner limits 2..G1 are centre_limits' a..A1 - a") {
    // The map to our table: its walls are the innermost free points 2 and
    // A1 - 1 (so its width is A1 - 3), a ball of radius a there covers
    // centre - a .. centre + a, and table x = (corner + a) - 2. Then the
    // stage's contract a <= x <= width - a is the corner's 2 <= x <= G1.
    for (const int a1 : {256, 192, 100, 31}) {
      for (int a = 0; a <= 12; ++a) {
        INFO("A1 = " << a1 << ", a = " << a);
        const gas::CentreLimits l = gas::centre_limits(table(a1 - 3, a1 - 3, a, {}));
        auto corner = [&](double table_x) { return table_x - a + 2; };
        CHECK(corner(l.x_min) == 2);
        CHECK(corner(l.x_max) == a1 - 2 * a - 1);  // G1, exactly
        CHECK(corner(l.y_min) == 2);
        CHECK(corner(l.y_max) == a1 - 2 * a - 1);  // G2 the same way, with A2
      }
    }
  }

  TEST_CASE(
      "article limits: storing corners instead of centres changes no ball-ball formula") {
    // All balls have one radius, so corner = centre - (a, a) for every ball,
    // and d = r2 - r1 is the same: the quadratic and VI do not care which
    // point is stored. Shifts by whole numbers of dyadic coordinates are
    // exact, so the results are equal to the last bit.
    constexpr std::uint64_t seed = 431;
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> where(64 * 10, 64 * 200), vel(-64 * 3, 64 * 3);
    for (int i = 0; i < 500; ++i) {
      INFO("seed " << seed << ", case " << i);
      const double a = 1 + i % 8;
      auto q64 = [](int k) { return k / 64.0; };
      gas::Ball p = ball(q64(where(rng)), q64(where(rng)), q64(vel(rng)), q64(vel(rng)));
      gas::Ball q = ball(q64(where(rng)), q64(where(rng)), q64(vel(rng)), q64(vel(rng)));
      if (p.x == q.x && p.y == q.y) continue;  // no line of centres
      gas::Ball ps = p, qs = q;
      ps.x -= a, ps.y -= a, qs.x -= a, qs.y -= a;
      CHECK(gas::time_of_contact(p, q, 2 * a) == gas::time_of_contact(ps, qs, 2 * a));
      gas::collide_balls(p, q);
      gas::collide_balls(ps, qs);
      CHECK(p.vx == ps.vx);
      CHECK(p.vy == ps.vy);
      CHECK(q.vx == qs.vx);
      CHECK(q.vy == qs.vy);
    }
  }

  // =========================================================================
  // Stage 5: VI and the four velocity updates.

  TEST_CASE(
      "article VI: momentum and energy kept with tangential kept and normal exchanged") {
    // Independent: the head-on exchange in the frame of the line of centres,
    // and the conservation laws. Both the printed VI (over 4a^2, long double)
    // and collide_balls (double) are held to them.
    constexpr std::uint64_t seed = 441;
    std::mt19937_64 rng(seed);
    for (int i = 0; i < 2000; ++i) {
      INFO("seed " << seed << ", case " << i);
      const Contact c = random_contact(rng);
      const Pair pair = pair_of(c.p, c.q, c.a);
      Vec e1, e2, p1, p2, s1, s2;
      exchange_along_line(pair, e1, e2);
      vi_printed(pair, p1, p2);
      stage_collision(c, s1, s2);
      const Vec n = (1 / length(pair.r2 - pair.r1)) * (pair.r2 - pair.r1), t = turned(n);
      // Why 1e-12: velocities are at most ~10; the printed VI divides by 4a^2
      // where |d|^2 is 4a^2 only up to the rounding of the centres (~1e-16
      // relative), and the stage rounds in double: errors ~1e-15. A wrong sign
      // or a wrong component is off by the velocities themselves.
      for (const auto& [v1, v2] : {std::pair{p1, p2}, std::pair{s1, s2}}) {
        CHECK(near(v1, e1, 1e-12L));
        CHECK(near(v2, e2, 1e-12L));
        CHECK(near(v1 + v2, pair.v1 + pair.v2, 1e-12L));  // momentum
        CHECK(std::fabs(dot(v1, v1) + dot(v2, v2) - dot(pair.v1, pair.v1) -
                        dot(pair.v2, pair.v2)) <=
              1e-12L * (1 + dot(pair.v1, pair.v1) + dot(pair.v2, pair.v2)));  // energy
        CHECK(std::fabs(dot(v1, t) - dot(pair.v1, t)) <= 1e-12L);  // tangential kept
        CHECK(std::fabs(dot(v2, t) - dot(pair.v2, t)) <= 1e-12L);
        CHECK(std::fabs(dot(v1, n) - dot(pair.v2, n)) <= 1e-12L);  // normal exchanged
        CHECK(std::fabs(dot(v2, n) - dot(pair.v1, n)) <= 1e-12L);
      }
      // After the collision the balls move apart.
      CHECK(dot(s2 - s1, pair.r2 - pair.r1) > 0);
    }
  }

  TEST_CASE(
      "article VI: over 4a^2 it needs the centres exactly 2a apart while collide_balls "
      "divides by the actual squared distance") {
    // The energy (here v1^2 + v2^2, twice the kinetic energy of unit masses)
    // changes under the printed update by 2 VI (VI |d|^2 - d.w): zero when
    // |d|^2 = 4a^2. Centres 2a (1 + 1e-3) apart (a contact found with a
    // round-off error, much exaggerated) make the printed VI change the
    // energy by about 4e-3 (d.w)^2 / 4a^2; the stage, dividing by the
    // actual |d|^2, keeps it.
    const double a = 2;
    const double gap = 2 * a * (1 + 1e-3);
    const gas::Ball p = ball(0, 0, 1, 0.5), q = ball(gap, 0, -1, 0.25);
    const Pair pair = pair_of(p, q, a);
    Vec p1, p2;
    vi_printed(pair, p1, p2);
    const Real before = dot(pair.v1, pair.v1) + dot(pair.v2, pair.v2);
    const Real printed_after = dot(p1, p1) + dot(p2, p2);
    const Real dw = gap * (-2.0L);  // d.w = gap * (-1 - 1)
    const Real vi = dw / (4 * a * a);
    const Real predicted = 2 * vi * (vi * gap * gap - dw);
    // Why 1e-15: a few long double roundings of numbers of order 1.
    CHECK(std::fabs((printed_after - before) - predicted) <= 1e-15L);
    CHECK(std::fabs(printed_after - before) > 1e-3L);
    Contact c{p, q, a};
    Vec s1, s2;
    stage_collision(c, s1, s2);
    // Why 1e-14: the stage's few double roundings (2.2e-16 each) on
    // velocities and energies of order 1.
    CHECK(std::fabs(dot(s1, s1) + dot(s2, s2) - before) <= 1e-14L);
    CHECK(near(s1, {-1, 0.5}, 1e-14L));  // normal components exchanged
    CHECK(near(s2, {1, 0.25}, 1e-14L));
  }

  // =========================================================================
  // Exercise 2: v1' = -v2, v2' = -v1.

  TEST_CASE(
      "article exercise 2 as printed: v1' = -v2 and v2' = -v1 answers no real "
      "collision") {
    // As vectors in one frame: v1 + (w.n) n = -v2 and v2 - (w.n) n = -v1
    // together need v1 + v2 = 0 and w.n = 0 — the centre-of-mass frame and a
    // grazing touch, where nothing changes. The printed pair also reverses
    // the total momentum, v1' + v2' = -(v1 + v2).
    SUBCASE("head-on in the lab: exchange, not the printed form") {
      const Contact c{ball(0, 0, 3, 0), ball(2, 0, -1, 0), 1};
      Vec v1, v2;
      stage_collision(c, v1, v2);
      CHECK(near(v1, {-1, 0}, 0));                   // v1' = v2
      CHECK(near(v2, {3, 0}, 0));                    // v2' = v1
      CHECK_FALSE(near(v1, -velocity(c.q), 1e-9L));  // printed: v1' = (1, 0)
      CHECK_FALSE(near(v2, -velocity(c.p), 1e-9L));  // printed: v2' = (-3, 0)
    }
    SUBCASE("head-on in the centre-of-mass frame: the printed form changes nothing") {
      const Contact c{ball(0, 0, 2, 0), ball(2, 0, -2, 0), 1};
      Vec v1, v2;
      stage_collision(c, v1, v2);
      CHECK(near(v1, {-2, 0}, 0));
      CHECK(near(v2, {2, 0}, 0));
      CHECK(near(-velocity(c.q), velocity(c.p), 0));  // printed v1' = -v2 = v1: no bounce
    }
    SUBCASE("one ball at rest: half of it holds") {
      const Contact c{ball(0, 0, 2, 0), ball(2, 0, 0, 0), 1};
      Vec v1, v2;
      stage_collision(c, v1, v2);
      CHECK(near(v1, -velocity(c.q), 0));            // v1' = 0 = -v2
      CHECK_FALSE(near(v2, -velocity(c.p), 1e-9L));  // v2' = (2, 0), not (-2, 0)
    }
    SUBCASE("where it holds: a grazing touch seen from the centre of mass") {
      const Contact c{ball(0, 0, 0, 1), ball(2, 0, 0, -1), 1};
      Vec v1, v2;
      stage_collision(c, v1, v2);
      CHECK(near(v1, -velocity(c.q), 0));
      CHECK(near(v2, -velocity(c.p), 0));
    }
    SUBCASE("random real collisions: it never holds") {
      constexpr std::uint64_t seed = 451;
      std::mt19937_64 rng(seed);
      for (int i = 0; i < 1000; ++i) {
        INFO("seed " << seed << ", case " << i);
        const Contact c = random_contact(rng);
        Vec v1, v2;
        stage_collision(c, v1, v2);
        // Why 1e-6: the printed form misses by |v1 + v2| or |w.n| (at least
        // 0.05 |w| here), not by rounding; 1e-6 only keeps a freak near-miss
        // of the random draw from counting as a hit.
        CHECK_FALSE((near(v1, -velocity(c.q), 1e-6L) && near(v2, -velocity(c.p), 1e-6L)));
      }
    }
  }

  TEST_CASE("article exercise 2 corrected: head-on equal balls exchange velocities") {
    // v1' = v2, v2' = v1 for any collision along the line of centres; and the
    // printed signs hold for balls moving towards each other when each
    // velocity is a speed counted along that ball's own direction of motion:
    // ball 1 comes at speed s1 along +n and leaves along -n at s2, so its
    // signed speed becomes -s2; ball 2 likewise becomes -s1.
    constexpr std::uint64_t seed = 452;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> angle(0, 2 * std::numbers::pi), speed(0.1, 5),
        along(-5, 5);
    for (int i = 0; i < 1000; ++i) {
      INFO("seed " << seed << ", case " << i);
      const double phi = angle(rng), a = 1.5;
      const double nx = std::cos(phi), ny = std::sin(phi);
      double u1 = along(rng), u2 = along(rng);  // components along n
      if (u1 <= u2) std::swap(u1, u2);          // approaching: u1 > u2
      const Contact c{ball(0, 0, u1 * nx, u1 * ny),
                      ball(2 * a * nx, 2 * a * ny, u2 * nx, u2 * ny), a};
      Vec v1, v2;
      stage_collision(c, v1, v2);
      // Why 1e-12: double roundings of velocities of order 5.
      CHECK(near(v1, velocity(c.q), 1e-12L));
      CHECK(near(v2, velocity(c.p), 1e-12L));
      // Towards each other: the printed reading as signed speeds.
      const double s1 = speed(rng), s2 = speed(rng);
      const Contact towards{ball(0, 0, s1 * nx, s1 * ny),
                            ball(2 * a * nx, 2 * a * ny, -s2 * nx, -s2 * ny), a};
      stage_collision(towards, v1, v2);
      const Vec own1{nx, ny}, own2{-nx, -ny};  // each ball's own direction of motion
      CHECK(std::fabs(dot(v1, own1) - (-s2)) <= 1e-12L);  // "v1' = -v2" in speeds
      CHECK(std::fabs(dot(v2, own2) - (-s1)) <= 1e-12L);  // "v2' = -v1" in speeds
    }
  }

  // =========================================================================
  // Exercise 3: r2 - r1 = 2a n, x along n: v1' = (v2.n, |v1 x n|), ...

  TEST_CASE(
      "article exercise 3 as printed: the modulus drops the sign of the tangential "
      "component") {
    // In the frame with x along n (and y along t, n turned by +90 degrees),
    // v x n = -(v.t), so |v x n| = |v.t|: the printed answer holds exactly
    // when both tangential components are >= 0.
    SUBCASE("a concrete failure") {
      // n = (1, 0); v1 = (1, 1), v2 = (-1, -1). True: v1' = (-1, 1),
      // v2' = (1, -1). Printed: v2' = (1, |v2 x n|) = (1, 1), and the total
      // momentum goes from (0, 0) to (0, 2).
      const Contact c{ball(0, 0, 1, 1), ball(2, 0, -1, -1), 1};
      Vec v1, v2;
      stage_collision(c, v1, v2);
      CHECK(near(v1, {-1, 1}, 0));
      CHECK(near(v2, {1, -1}, 0));
      const Vec n{1, 0};
      const Vec printed2{dot(velocity(c.p), n), std::fabs(cross(velocity(c.q), n))};
      CHECK(near(printed2, {1, 1}, 0));
      CHECK_FALSE(near(printed2, v2, 1e-9L));
      const Vec corrected2{dot(velocity(c.p), n), cross(n, velocity(c.q))};
      CHECK(near(corrected2, v2, 0));
    }
    SUBCASE(
        "random collisions: printed right exactly when both tangential components are >= "
        "0") {
      constexpr std::uint64_t seed = 461;
      std::mt19937_64 rng(seed);
      int right = 0, wrong = 0;
      for (int i = 0; i < 2000; ++i) {
        INFO("seed " << seed << ", case " << i);
        const Contact c = random_contact(rng);
        const Pair pair = pair_of(c.p, c.q, c.a);
        const Vec n = (1 / length(pair.r2 - pair.r1)) * (pair.r2 - pair.r1),
                  t = turned(n);
        Vec s1, s2;
        stage_collision(c, s1, s2);
        const Vec true1{dot(s1, n), dot(s1, t)},
            true2{dot(s2, n), dot(s2, t)};  // in (n, t)
        const Vec printed1{dot(pair.v2, n), std::fabs(cross(pair.v1, n))};
        const Vec printed2{dot(pair.v1, n), std::fabs(cross(pair.v2, n))};
        const Real t1 = dot(pair.v1, t), t2 = dot(pair.v2, t);
        if (std::fabs(t1) < 1e-6L || std::fabs(t2) < 1e-6L)
          continue;  // sign decided by rounding
        // Why 1e-9: the stage's double roundings (~1e-15) against a miss of
        // 2 |v.t| >= 2e-6 when the sign is dropped.
        const bool holds = near(printed1, true1, 1e-9L) && near(printed2, true2, 1e-9L);
        CHECK(holds == (t1 > 0 && t2 > 0));
        (holds ? right : wrong) += 1;
      }
      CHECK(right > 200);
      CHECK(wrong > 1000);
    }
  }

  TEST_CASE(
      "article exercise 3 corrected: n x v1 in place of |v1 x n| is VI in the frame of "
      "n") {
    // Without the modulus, and with the cross product as n x v (= v.t), the
    // answer is right for every collision, and it is VI written in the axes
    // (n, t).
    constexpr std::uint64_t seed = 462;
    std::mt19937_64 rng(seed);
    for (int i = 0; i < 2000; ++i) {
      INFO("seed " << seed << ", case " << i);
      const Contact c = random_contact(rng);
      const Pair pair = pair_of(c.p, c.q, c.a);
      const Vec n = (1 / length(pair.r2 - pair.r1)) * (pair.r2 - pair.r1), t = turned(n);
      const Vec corrected1{dot(pair.v2, n), cross(n, pair.v1)};
      const Vec corrected2{dot(pair.v1, n), cross(n, pair.v2)};
      Vec s1, s2, p1, p2;
      stage_collision(c, s1, s2);
      vi_printed(pair, p1, p2);
      // Why 1e-12: as in the VI test.
      CHECK(near(corrected1, {dot(s1, n), dot(s1, t)}, 1e-12L));
      CHECK(near(corrected2, {dot(s2, n), dot(s2, t)}, 1e-12L));
      CHECK(near(corrected1, {dot(p1, n), dot(p1, t)}, 1e-12L));
      CHECK(near(corrected2, {dot(p2, n), dot(p2, t)}, 1e-12L));
    }
  }

  // =========================================================================
  // Stages 5 and 7: T1 and the control rule.

  TEST_CASE("article T1 rule: T1 = T0 if TC > T + T0 and T1 = TC - T if TC < T + T0") {
    // T1 as the step's end: T + T1.
    auto t1 = [](double now, double t0, double tc) {
      return gas::step_end(now, t0, tc).time - now;
    };
    CHECK(t1(10, 1, 12.5) == 1);        // TC > T + T0
    CHECK(t1(10, 1, 10.25) == 0.25);    // TC < T + T0
    CHECK(t1(10, 1, gas::never) == 1);  // nothing will ever collide
    constexpr std::uint64_t seed = 471;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int i = 0; i < 10000; ++i) {
      INFO("seed " << seed << ", case " << i);
      const double now = 1000 * unit(rng), t0 = 2 * unit(rng) + 1e-3;
      const double tc = i % 10 == 0 ? now + t0 : now + 4 * unit(rng);
      const gas::StepEnd end = gas::step_end(now, t0, tc);
      // TC > T + T0: T1 = T0, the step ends at T + T0 with no collision.
      if (tc > now + t0) CHECK((end.time == now + t0 && !end.on_collision));
      // TC < T + T0: T1 = TC - T, the step ends at TC on the collision.
      if (tc < now + t0) CHECK((end.time == tc && end.on_collision));
      if (tc == now + t0) CHECK((end.time == tc && end.on_collision));  // left open
    }
  }

  TEST_CASE("article T1 rule at TC = T + T0: the code takes the collision branch") {
    // Print assigns TC > T + T0 and TC < T + T0 and leaves TC = T + T0 open.
    // Both branches give the same T1 in exact arithmetic, but only the second
    // computes the new velocities. The code takes the second: T1 = TC - T,
    // and the step ends exactly at TC with the collision carried out.
    SUBCASE("step_end: T1 = TC - T, which in floating point need not equal T0") {
      const double now = 0.1, t0 = 0.2, tc = now + t0;  // tc = 0.30000000000000004
      REQUIRE(tc - now != t0);                          // the branches differ here
      const gas::StepEnd end = gas::step_end(now, t0, tc);
      CHECK(end.on_collision);
      CHECK(end.time - now == tc - now);
    }
    SUBCASE("take_step: the collision at T + T0 is carried out in this step") {
      // a = 1, A1 = 10: the centre at x = 5 moving at 1 meets x = 9 at TC = 4,
      // and T0 = 4.
      gas::Control control = gas::start_control(table(10, 10, 1, {ball(5, 5, 1, 0)}, 4));
      const gas::Step step = gas::take_step(control, gas::never, nullptr);
      CHECK(step.length == 4);
      CHECK(control.gas.time == 4);
      REQUIRE(step.collisions.size() == 1);
      CHECK(step.collisions[0].kind == gas::CollisionKind::vertical_wall);
      CHECK(control.gas.balls[0].vx == -1);
      CHECK(control.gas.balls[0].x == 9);
    }
  }

  TEST_CASE("article control: TC > T back to stage 5 and TC <= T back to stage 4") {
    SUBCASE("two walls at one instant: TC <= T, so stage 4 runs again at once") {
      // A ball heading for the corner reaches x = 9 and y = 9 together at
      // t = 4: after the first wall TC = T again (the second wall), and with
      // "TC <= T" (not "<") both are carried out in the same step.
      gas::Control control = gas::start_control(table(10, 10, 1, {ball(5, 5, 1, 1)}, 10));
      const gas::Step step = gas::take_step(control, gas::never, nullptr);
      CHECK(control.gas.time == 4);
      REQUIRE(step.collisions.size() == 2);
      CHECK(step.collisions[0].kind ==
            gas::CollisionKind::horizontal_wall);  // scanned first
      CHECK(step.collisions[1].kind == gas::CollisionKind::vertical_wall);
      CHECK(control.gas.balls[0].vx == -1);
      CHECK(control.gas.balls[0].vy == -1);
      CHECK(control.next.time > control.gas.time);  // TC > T: the next step is stage 5
    }
    SUBCASE("a run: stage 4 only after collisions, each step T0 or up to TC") {
      gas::Gas g =
          table(40, 30, 1.5,
                {ball(5, 5, 1.3, 0.7), ball(20, 15, -0.9, 1.1), ball(30, 8, 0.4, -1.5),
                 ball(10, 22, -1.2, -0.6), ball(33, 25, 0.8, -1.0)},
                0.7);
      gas::Control control = gas::start_control(g);
      TraceFile trace;
      REQUIRE(trace.file != nullptr);
      long long collisions = 0;
      for (int i = 0; i < 1000; ++i) {
        INFO("step " << i);
        const double before = control.gas.time;
        const double t0 = control.gas.display_step;
        const gas::Step step = gas::take_step(control, gas::never, trace.file);
        collisions += static_cast<long long>(step.collisions.size());
        if (step.collisions.empty()) {
          // T1 = T0. Why 1e-12: T1 is (T + T0) - T in double, off from T0 by
          // at most one rounding of T (T < 700 here, ulp < 1.2e-13).
          CHECK(std::fabs(step.length - t0) <= 1e-12);
        } else {
          // T1 = TC - T: the step ends exactly at the collision(s).
          for (const gas::Collision& c : step.collisions)
            CHECK(c.time == control.gas.time);
          CHECK(step.length <= t0 + 1e-12);  // the same rounding as above
        }
        CHECK(control.gas.time >= before);            // time never runs back
        CHECK(control.next.time > control.gas.time);  // TC > T: stage 5 next
      }
      CHECK(collisions > 50);
      // Stage 4 ran once at the start and once after every collision, never
      // on a step without one.
      CHECK(count_of(trace.text(), "stage 4 ") == 1 + collisions);
    }
  }
}
