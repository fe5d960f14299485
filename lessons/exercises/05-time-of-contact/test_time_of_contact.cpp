// Exercise 05, time_of_contact: the provided tests (suite exercise-05).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage4_first_collision.cpp. Don't change this file
// to make a test pass: change your time_of_contact.cpp.
//
// Balls of diameter 2 (radius 1) unless a test says otherwise. A Ball is
// {x, y, vx, vy, since}; `since` is 0 when it is left out.
#include <doctest/doctest.h>

#include <cmath>

#include "exercise_test.hpp"
#include "stage4_first_collision.hpp"

namespace {

using gas::Ball;
using gas::never;
using gas::time_of_contact;

constexpr double diameter = 2;

}  // namespace

TEST_SUITE("exercise-05") {
  EXERCISE_TEST("exercise-05 head-on: 10 apart and closing at 2 they touch at t = 4") {
    INFO("the centres come 2 apart when they have closed 8 of their 10: at 8 / 2 = 4");
    CHECK(time_of_contact({0, 0, 1, 0}, {10, 0, -1, 0}, diameter) == 4);
    INFO("the order of the two balls does not matter");
    CHECK(time_of_contact({10, 0, -1, 0}, {0, 0, 1, 0}, diameter) == 4);
  }

  EXERCISE_TEST("exercise-05 an oblique hit is the smaller root of the quadratic") {
    // q comes from the right at speed 2 along the line y = 1, p waits at the
    // origin: (10 - 2t)^2 + 1^2 = 2^2 at t = (10 - sqrt(3)) / 2 and again at
    // (10 + sqrt(3)) / 2, when q would leave p after passing through it.
    const Ball p{0, 0, 0, 0}, q{10, 1, -2, 0};
    // Why 1e-15: t is about 4.13, far from grazing; any form of the root
    // rounds a handful of times, each by 1.1e-16 of t. The larger root is
    // off by 0.4 of t.
    const double first = (10 - std::sqrt(3.0)) / 2;
    CHECK(time_of_contact(p, q, diameter) == doctest::Approx(first).epsilon(1e-15));
    CHECK(time_of_contact(q, p, diameter) == doctest::Approx(first).epsilon(1e-15));
  }

  EXERCISE_TEST("exercise-05 balls that miss or move apart or move together never meet") {
    INFO(
        "the quadratic has no root (D < 0), only a grazing one (D = 0), or its roots lie "
        "in the past");
    // q passes 3 above p's centre: they miss (D < 0).
    CHECK(time_of_contact({0, 0, 0, 0}, {10, 3, -2, 0}, diameter) == never);
    // q passes exactly 2 above: the balls graze, exchange nothing (D = 0).
    CHECK(time_of_contact({0, 0, 0, 0}, {10, 2, -1, 0}, diameter) == never);
    // Moving apart: both roots are in the past.
    CHECK(time_of_contact({0, 0, -1, 0}, {10, 0, 1, 0}, diameter) == never);
    INFO("moving together the relative speed w is 0: don't divide by w.w");
    CHECK(time_of_contact({0, 0, 1, 0.5}, {10, 0, 1, 0.5}, diameter) == never);
    CHECK(time_of_contact({0, 0, 0, 0}, {5, 5, 0, 0}, diameter) == never);
  }

  EXERCISE_TEST("exercise-05 touching or overlapping balls that approach collide now") {
    // Both rows written at 3, the balls 2 apart (touching) or 1.5 apart (a
    // hair inside each other, as round-off can leave them).
    INFO(
        "if they approach, the collision is due at once: at the balls' time 3, not in "
        "the past");
    CHECK(time_of_contact({0, 0, 0, 0, 3}, {2, 0, -1, 0, 3}, diameter) == 3);
    CHECK(time_of_contact({0, 0, 0, 0, 3}, {1.5, 0, -1, 0, 3}, diameter) == 3);
    INFO("if they move apart they have just collided: never again");
    CHECK(time_of_contact({0, 0, 0, 0, 3}, {2, 0, 1, 0, 3}, diameter) == never);
    CHECK(time_of_contact({0, 0, 0, 0, 3}, {1.5, 0, 1, 0, 3}, diameter) == never);
  }

  EXERCISE_TEST(
      "exercise-05 balls written at different moments are compared at the later one") {
    // p's row was written at 0 at x = 0, q's at 2 at x = 14. At 2 p is at
    // x = 2, 12 from q, and they close at 2: 2 apart at 2 + 10 / 2 = 7.
    INFO("take both centres at max(p.since, q.since) with centre_at (stage 1)");
    CHECK(time_of_contact({0, 0, 1, 0, 0}, {14, 0, -1, 0, 2}, diameter) == 7);
    CHECK(time_of_contact({14, 0, -1, 0, 2}, {0, 0, 1, 0, 0}, diameter) == 7);
  }

  EXERCISE_TEST("exercise-05 nearly touching balls: the root keeps its digits") {
    // Two big balls, diameter n = 1000003. q is straight above p, 3 to the
    // side: the centres are sqrt(n^2 + 9), a hair (4.5e-6) more than n,
    // apart, and q falls onto p at speed 1. With d = (3, n), w = (0, -1):
    // b = d.w = -n, c = d.d - n^2 = 9 and D = b^2 - (w.w) c = n^2 - 9, all
    // exact in double (below 2^53). The contact comes at about 4.5e-6.
    const double n = 1000003;
    const Ball p{0, 0, 0, 0}, q{3, n, 0, -1};
    // The reference: the same root in long double, in the form that does
    // not subtract; its inputs are exact, so it is good to about 1e-19.
    const long double exact_d = static_cast<long double>(n) * n - 9;
    const long double reference = 9 / (std::sqrt(exact_d) + n);
    const double t = time_of_contact(p, q, n);
    const long double error = std::fabs(t - reference) / reference;
    CAPTURE(t);
    CAPTURE(static_cast<double>(reference));
    // Why 1e-15: the stable form c / (sqrt(D) - b) rounds three times (the
    // root, the sum, the quotient), 1.1e-16 each. The textbook form
    // (-b - sqrt(D)) / (w.w) subtracts 1000003 - 1000002.9999955 and keeps
    // only the rounding error of sqrt(D): it is off by about 1e-5 here.
    INFO(
        "solve the quadratic in a form that does not subtract two nearly equal numbers "
        "(lesson 4)");
    CHECK(error < 1e-15L);
  }
}
