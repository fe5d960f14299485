// Exercise 05, time_of_contact: the provided tests (suite exercise-05).
//
// Every test here fails against the untouched stub (CI checks that), passes
// against stages/stage4_first_collision.cpp, and catches the wrong answers
// in wrong/ (CI checks those too). Don't change this file to make a test
// pass: change your time_of_contact.cpp.
//
// Balls of diameter 2 (radius 1) unless a test says otherwise. A Ball is
// {x, y, vx, vy, since}; `since` is 0 when it is left out.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "exercise_test.hpp"
#include "stage4_first_collision.hpp"

namespace {

using gas::Ball;
using gas::never;
using gas::time_of_contact;
using gas::exercises::column_of_r;
using gas::exercises::digits;
using gas::exercises::Draw;

constexpr double diameter = 2;

std::string call(const Ball& p, const Ball& q, double d) {
  return fmt::format("time_of_contact(p {}, q {}, diameter {})", column_of_r(p),
                     column_of_r(q), digits(d));
}

#define CHECK_CONTACT(p, q, d, wanted, relative) \
  CHECK_NUMBER(call(p, q, d), time_of_contact(p, q, d), wanted, relative)

// The moment of contact as it must be, from the same centres at the later
// `since` (centre_at, as the instructions ask), in long double and in the
// form that does not cancel; `never` when they do not approach or miss.
double exact_contact(const Ball& p, const Ball& q, double d) {
  using real = long double;
  const double start = std::max(p.since, q.since);
  const gas::Point rp = gas::centre_at(p, start), rq = gas::centre_at(q, start);
  const real dx = real{rq.x} - rp.x, dy = real{rq.y} - rp.y;
  const real wx = real{q.vx} - p.vx, wy = real{q.vy} - p.vy;
  const real b = dx * wx + dy * wy;
  if (b >= 0) return never;
  const real c = dx * dx + dy * dy - real{d} * d;
  if (c <= 0) return start;
  const real discriminant = b * b - (wx * wx + wy * wy) * c;
  if (discriminant <= 0) return never;
  return static_cast<double>(start + c / (std::sqrt(discriminant) - b));
}

}  // namespace

TEST_SUITE("exercise-05") {
  TEST_CASE("exercise-05 head-on: 10 apart and closing at 2 they touch at t = 4") {
    INFO("the centres come 2 apart when they have closed 8 of their 10: at 8 / 2 = 4");
    CHECK_CONTACT(Ball({0, 0, 1, 0}), Ball({10, 0, -1, 0}), diameter, 4, 0);
    INFO("the order of the two balls does not matter");
    CHECK_CONTACT(Ball({10, 0, -1, 0}), Ball({0, 0, 1, 0}), diameter, 4, 0);
  }

  TEST_CASE("exercise-05 an oblique hit is the smaller root of the quadratic") {
    // q comes from the right at speed 2 along the line y = 1, p waits at the
    // origin: (10 - 2t)^2 + 1^2 = 2^2 at t = (10 - sqrt(3)) / 2 and again at
    // (10 + sqrt(3)) / 2, when q would leave p after passing through it.
    const Ball p{0, 0, 0, 0}, q{10, 1, -2, 0};
    // Why 1e-15: t is about 4.13, far from grazing; any form of the root
    // rounds a handful of times, each by 1.1e-16 of t. The larger root is
    // off by 0.4 of t.
    const double first = (10 - std::sqrt(3.0)) / 2;
    CHECK_CONTACT(p, q, diameter, first, 1e-15);
    CHECK_CONTACT(q, p, diameter, first, 1e-15);
  }

  TEST_CASE("exercise-05 balls that miss or move apart or move together never meet") {
    INFO(
        "the quadratic has no root (D < 0), only a grazing one (D = 0), or its roots lie "
        "in the past");
    // q passes 3 above p's centre: they miss (D < 0).
    CHECK_CONTACT(Ball({0, 0, 0, 0}), Ball({10, 3, -2, 0}), diameter, never, 0);
    // q passes exactly 2 above: the balls graze, exchange nothing (D = 0).
    CHECK_CONTACT(Ball({0, 0, 0, 0}), Ball({10, 2, -1, 0}), diameter, never, 0);
    // Moving apart: both roots are in the past.
    CHECK_CONTACT(Ball({0, 0, -1, 0}), Ball({10, 0, 1, 0}), diameter, never, 0);
    INFO("moving together the relative speed w is 0: don't divide by w.w");
    CHECK_CONTACT(Ball({0, 0, 1, 0.5}), Ball({10, 0, 1, 0.5}), diameter, never, 0);
    CHECK_CONTACT(Ball({0, 0, 0, 0}), Ball({5, 5, 0, 0}), diameter, never, 0);
  }

  TEST_CASE("exercise-05 touching or overlapping balls that approach collide now") {
    // Both columns of R written at 3, the balls 2 apart (touching) or 1.5 apart (a
    // hair inside each other, as round-off can leave them).
    INFO(
        "if they approach, the collision is due at once: at the balls' time 3, not in "
        "the past");
    CHECK_CONTACT(Ball({0, 0, 0, 0, 3}), Ball({2, 0, -1, 0, 3}), diameter, 3, 0);
    CHECK_CONTACT(Ball({0, 0, 0, 0, 3}), Ball({1.5, 0, -1, 0, 3}), diameter, 3, 0);
    INFO("if they move apart they have just collided: never again");
    CHECK_CONTACT(Ball({0, 0, 0, 0, 3}), Ball({2, 0, 1, 0, 3}), diameter, never, 0);
    CHECK_CONTACT(Ball({0, 0, 0, 0, 3}), Ball({1.5, 0, 1, 0, 3}), diameter, never, 0);
  }

  TEST_CASE(
      "exercise-05 balls written at different moments are compared at the later one") {
    // p's column of R was written at 0 at x = 0, q's at 2 at x = 14. At 2 p is at
    // x = 2, 12 from q, and they close at 2: 2 apart at 2 + 10 / 2 = 7.
    INFO("take both centres at max(p.since, q.since) with centre_at (stage 1)");
    CHECK_CONTACT(Ball({0, 0, 1, 0, 0}), Ball({14, 0, -1, 0, 2}), diameter, 7, 0);
    CHECK_CONTACT(Ball({14, 0, -1, 0, 2}), Ball({0, 0, 1, 0, 0}), diameter, 7, 0);
  }

  // The trap of this exercise, caught by this test and the next: the
  // textbook root cancels when the balls nearly touch.
  TEST_CASE("exercise-05 nearly touching balls: the root keeps its digits") {
    // Two big balls, diameter n = 1000003. q is straight above p, 3 to the
    // side: the centres are sqrt(n^2 + 9), a hair (4.5e-6) more than n,
    // apart, and q falls onto p at speed 1. With d = (3, n), w = (0, -1):
    // b = d.w = -n, c = d.d - n^2 = 9 and D = b^2 - (w.w) c = n^2 - 9, all
    // exact in double (below 2^53). The contact comes at about 4.5e-6.
    const double n = 1000003;
    const Ball p{0, 0, 0, 0}, q{3, n, 0, -1};
    INFO(
        "solve the quadratic in a form that does not subtract two nearly equal numbers "
        "(lesson 4)");
    // Why 1e-15: the stable form c / (sqrt(D) - b) rounds three times (the
    // root, the sum, the quotient), 1.1e-16 each. The textbook form
    // (-b - sqrt(D)) / (w.w) subtracts 1000003 - 1000002.9999955 and keeps
    // only the rounding error of sqrt(D): it is off by about 1e-5 here.
    CHECK_CONTACT(p, q, n, exact_contact(p, q, n), 1e-15);
  }

  TEST_CASE(
      "exercise-05 200 generated nearly touching pairs: the root keeps its digits") {
    // Integer centres and velocities: d = (k, n) with n from 10^4 to 10^6
    // and k from 1 to 30, so c = d.d - n^2 = k^2 and b = d.w exactly, and
    // D = b^2 - (w.w) c is exact too (below 2^53). The balls are n apart
    // plus a hair of k^2 / 2n: the textbook root loses about n^2 / k^2
    // times 1e-16 of itself, 1e-10 at the least.
    Draw draw(502);
    for (int m = 1; m <= 200; ++m) {
      const double n = draw.integer(10000, 1000000), k = draw.integer(1, 30);
      double dx = k, dy = n, wx = draw.integer(-20, 20), wy = draw.integer(-20, -1);
      if (draw.coin()) std::swap(dx, dy), std::swap(wx, wy);  // turned by exact moves
      if (draw.coin()) dx = -dx, wx = -wx;
      if (draw.coin()) dy = -dy, wy = -wy;
      const double x = draw.integer(-1000, 1000), y = draw.integer(-1000, 1000);
      const double vx = draw.integer(-10, 10), vy = draw.integer(-10, 10);
      const Ball p{x, y, vx, vy}, q{x + dx, y + dy, vx + wx, vy + wy};
      CAPTURE(m);
      // Why 1e-14: the stable form rounds three times, 1.1e-16 each.
      if (!CHECK_CONTACT(p, q, n, exact_contact(p, q, n), 1e-14)) break;
    }
  }

  TEST_CASE(
      "exercise-05 300 generated hits of every size and place and speed and clock") {
    Draw draw(503);
    for (int m = 1; m <= 300; ++m) {
      // The contact: at time `when`, p's centre at (cx, cy) and q's one
      // diameter away in direction phi, w aimed within 1.2 radians of
      // straight at p. Then each column of R is written back at its own `since`.
      const double d = draw.magnitude(-0.3, 2);  // 0.5 to 100
      const double cx = draw.uniform(-100, 100), cy = draw.uniform(-100, 100);
      const double phi = draw.uniform(0, 2 * std::numbers::pi);
      const double speed = draw.magnitude(-1, 1) * d;
      const double aim = phi + std::numbers::pi + draw.uniform(-1.2, 1.2);
      const double closing = speed * draw.uniform(0.2, 2);
      const double pvx = speed * draw.uniform(-1, 1), pvy = speed * draw.uniform(-1, 1);
      const double qvx = pvx + closing * std::cos(aim),
                   qvy = pvy + closing * std::sin(aim);
      const double p_since = draw.uniform(0, 10), q_since = draw.uniform(0, 10);
      // At least 0.5 d of flight before the contact, so they start apart.
      const double when =
          std::max(p_since, q_since) + (0.5 + draw.uniform(0, 20)) * d / closing;
      const Ball p{cx - pvx * (when - p_since), cy - pvy * (when - p_since), pvx, pvy,
                   p_since};
      const Ball q{cx + d * std::cos(phi) - qvx * (when - q_since),
                   cy + d * std::sin(phi) - qvy * (when - q_since), qvx, qvy, q_since};
      CAPTURE(m);
      // Why 1e-11: the centres are taken at the later since and rounded
      // there, by 1.1e-16 of up to a few hundred; the pair is at least half
      // a diameter apart and at most 1.2 radians off head-on, so that error
      // grows to at most about 1e-13 of the time. A wrong root, a missed
      // since or a wrong sign is off by far more.
      if (!CHECK_CONTACT(p, q, d, exact_contact(p, q, d), 1e-11)) break;
      if (!CHECK_CONTACT(q, p, d, exact_contact(p, q, d), 1e-11)) break;
    }
  }

  TEST_CASE("exercise-05 300 generated pairs that move apart or miss never meet") {
    Draw draw(504);
    for (int m = 1; m <= 300; ++m) {
      const double d = draw.magnitude(-0.3, 2);
      const double phi = draw.uniform(0, 2 * std::numbers::pi);
      const double x = draw.uniform(-100, 100), y = draw.uniform(-100, 100);
      const double pvx = draw.uniform(-5, 5), pvy = draw.uniform(-5, 5);
      const double ux = std::cos(phi), uy = std::sin(phi);  // a unit vector
      const double w = draw.magnitude(-1, 1) * d;
      double ox, oy, wx, wy;  // q's centre from p's, and q's velocity from p's
      if (draw.coin()) {
        // q moves away from p: w within 1.4 radians of d.
        const double apart = d * draw.uniform(1.01, 10),
                     away = phi + draw.uniform(-1.4, 1.4);
        ox = apart * ux, oy = apart * uy;
        wx = w * std::cos(away), wy = w * std::sin(away);
      } else {
        // q flies along -u on a line h to the side of p, 1.05 to 3
        // diameters: it comes no closer than h.
        const double h = d * draw.uniform(1.05, 3) * (draw.coin() ? 1 : -1);
        const double along = d * draw.uniform(0.5, 10);
        ox = along * ux - h * uy, oy = along * uy + h * ux;
        wx = -w * ux, wy = -w * uy;
      }
      const Ball p{x, y, pvx, pvy, 1};
      const Ball q{x + ox, y + oy, pvx + wx, pvy + wy, 1};
      CAPTURE(m);
      if (!CHECK_CONTACT(p, q, d, never, 0)) break;
    }
  }
}
