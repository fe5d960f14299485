// Exercise 07, collide_balls: the provided tests (suite exercise-07).
//
// Every test here fails against the untouched stub (CI checks that), passes
// against stages/stage5_new_coordinates.cpp, and catches the wrong answers
// in wrong/ (CI checks those too). Don't change this file to make a test
// pass: change your collide_balls.cpp.
//
// A Ball is {x, y, vx, vy, since}: both balls written at the same moment, in
// contact (their centres one diameter apart, whatever the diameter is).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "exercise_test.hpp"
#include "stage5_new_coordinates.hpp"

namespace {

using gas::Ball;
using gas::exercises::column_of_r;
using gas::exercises::Draw;

double dot(double ax, double ay, double bx, double by) {
  return ax * bx + ay * by;
}
double cross(double ax, double ay, double bx, double by) {
  return ax * by - ay * bx;
}

// A collision of p and q, as a failed check tells it.
struct Hit {
  Ball p, q;          // before
  Ball p_new, q_new;  // after your collide_balls
  std::string text() const {
    return fmt::format("collide_balls(p {}, q {})\n  gave p {}, q {}", column_of_r(p),
                       column_of_r(q), column_of_r(p_new), column_of_r(q_new));
  }
};

Hit collide(const Ball& p, const Ball& q) {
  Hit hit{p, q, p, q};
  gas::collide_balls(hit.p_new, hit.q_new);
  return hit;
}

// Checks that x, y and since of one ball are as they were, to the bit:
// collide_balls changes velocities only.
bool same_place(const Hit& hit, const char* name, const Ball& before, const Ball& after) {
  const std::string what = fmt::format("{}\n  {}'s ", hit.text(), name);
  return CHECK_NUMBER(what + "x changed: only the velocities change", after.x, before.x,
                      0) &&
         CHECK_NUMBER(what + "y changed: only the velocities change", after.y, before.y,
                      0) &&
         CHECK_NUMBER(what + "since changed: only the velocities change", after.since,
                      before.since, 0);
}

// The same for both balls.
bool same_places(const Hit& hit) {
  const bool p_same = same_place(hit, "p", hit.p, hit.p_new);
  const bool q_same = same_place(hit, "q", hit.q, hit.q_new);
  return p_same && q_same;
}

// The velocities as they must be: VI = (d.w) / (d.d), worked out in long
// double (each product of doubles to 64 bits) and rounded at the end.
std::array<double, 4> exact_velocities(const Ball& p, const Ball& q) {
  using real = long double;
  const real dx = real{q.x} - p.x, dy = real{q.y} - p.y;
  const real vi =
      (dx * (real{q.vx} - p.vx) + dy * (real{q.vy} - p.vy)) / (dx * dx + dy * dy);
  return {static_cast<double>(p.vx + vi * dx), static_cast<double>(p.vy + vi * dy),
          static_cast<double>(q.vx - vi * dx), static_cast<double>(q.vy - vi * dy)};
}

// Two balls in contact, |d| from 1.5 to 3 apart in a random direction, with
// relative velocity w aimed within 1 radian of -d, so that they approach;
// written at a random moment.
std::pair<Ball, Ball> random_contact(Draw& draw) {
  const double x = draw.uniform(0, 30), y = draw.uniform(0, 30), r = draw.uniform(1.5, 3),
               phi = draw.uniform(0, 2 * std::numbers::pi), since = draw.uniform(0, 100);
  Ball p{x, y, draw.uniform(-5, 5), draw.uniform(-5, 5), since};
  Ball q{x + r * std::cos(phi), y + r * std::sin(phi), 0, 0, since};
  const double towards = phi + std::numbers::pi + draw.uniform(-1, 1),
               w = draw.uniform(0.5, 5);
  q.vx = p.vx + w * std::cos(towards);
  q.vy = p.vy + w * std::sin(towards);
  return {p, q};
}

}  // namespace

TEST_SUITE("exercise-07") {
  TEST_CASE("exercise-07 head-on equal balls exchange their velocities") {
    INFO("VI = (d.w) / |d|^2 with d = r2 - r1 and w = v2 - v1; v1 += VI d, v2 -= VI d");
    // Along x: d = (2, 0), w = (-4, 0), VI = -8 / 4 = -2.
    const Hit along_x = collide({0, 0, 1, 0, 5}, {2, 0, -3, 0, 5});
    CHECK_NUMBER(along_x.text() + "\n  p.vx", along_x.p_new.vx, -3, 0);
    CHECK_NUMBER(along_x.text() + "\n  q.vx", along_x.q_new.vx, 1, 0);
    CHECK_NUMBER(along_x.text() + "\n  p.vy", along_x.p_new.vy, 0, 0);
    CHECK_NUMBER(along_x.text() + "\n  q.vy", along_x.q_new.vy, 0, 0);
    same_places(along_x);
    // Along y: d = (0, 2), w = (0, -3), VI = -6 / 4 = -1.5.
    const Hit along_y = collide({5, 5, 0, 2}, {5, 7, 0, -1});
    CHECK_NUMBER(along_y.text() + "\n  p.vy", along_y.p_new.vy, -1, 0);
    CHECK_NUMBER(along_y.text() + "\n  q.vy", along_y.q_new.vy, 2, 0);
    CHECK_NUMBER(along_y.text() + "\n  p.vx", along_y.p_new.vx, 0, 0);
    CHECK_NUMBER(along_y.text() + "\n  q.vx", along_y.q_new.vx, 0, 0);
    same_places(along_y);
  }

  TEST_CASE("exercise-07 a glancing hit changes only the components along d") {
    // p moves right at 2 and strikes q, at rest, off-centre: d = (1.5, 2)
    // (the balls have diameter 2.5), w = (-2, 0), d.w = -3, |d|^2 = 6.25,
    // VI = -0.48. So p' = (2, 0) - 0.48 (1.5, 2) = (1.28, -0.96) and
    // q' = (0.72, 0.96): q leaves along d, p across it.
    const Hit hit = collide({0, 0, 2, 0, 1.5}, {1.5, 2, 0, 0, 1.5});
    // Why 1e-14: VI, VI d and the sums round a few times, by 1.1e-16 of
    // numbers below 3 each; a wrong sign or a missing term is off by 0.1
    // or more.
    CHECK_NUMBER(hit.text() + "\n  p.vx", hit.p_new.vx, 1.28, 1e-14);
    CHECK_NUMBER(hit.text() + "\n  p.vy", hit.p_new.vy, -0.96, 1e-14);
    CHECK_NUMBER(hit.text() + "\n  q.vx", hit.q_new.vx, 0.72, 1e-14);
    CHECK_NUMBER(hit.text() + "\n  q.vy", hit.q_new.vy, 0.96, 1e-14);
    same_places(hit);
  }

  TEST_CASE("exercise-07 300 generated hits: the velocities change and nothing else") {
    INFO("x, y and since stay as they are: the balls are already where they collide");
    Draw draw(701);
    for (int n = 1; n <= 300; ++n) {
      const auto [p, q] = random_contact(draw);
      const Hit hit = collide(p, q);
      CAPTURE(n);
      // The approach along d, w.d, is reversed: no longer negative.
      const double dx = q.x - p.x, dy = q.y - p.y;
      const double after =
          dot(hit.q_new.vx - hit.p_new.vx, hit.q_new.vy - hit.p_new.vy, dx, dy);
      CHECK_MESSAGE(after > 0, hit.text() << "\n  the balls still approach: w.d = "
                                          << gas::exercises::digits(after));
      if (!same_places(hit) || !(after > 0)) break;
    }
  }

  TEST_CASE("exercise-07 300 generated hits: the velocities of the formula VI") {
    INFO("VI = (d.w) / |d|^2: at contact |d|^2 is 4a^2, and the radius is not passed in");
    Draw draw(702);
    for (int n = 1; n <= 300; ++n) {
      const auto [p, q] = random_contact(draw);
      const Hit hit = collide(p, q);
      const auto wanted = exact_velocities(p, q);
      CAPTURE(n);
      // Why 1e-12 of a component, or 1e-13 for a small one: the velocities
      // are below 15 and |d| at least 1.5; the formula rounds a few times by
      // 1.1e-16 of such numbers, so a component comes out within about
      // 1e-14 of the exact one. Dividing by 4 instead of |d|^2 is off by
      // 10 % or more.
      const double got[] = {hit.p_new.vx, hit.p_new.vy, hit.q_new.vx, hit.q_new.vy};
      const char* names[] = {"p.vx", "p.vy", "q.vx", "q.vy"};
      bool right = true;
      for (std::size_t k = 0; k < 4; ++k)
        right = CHECK_CLOSE(hit.text() + "\n  " + names[k], got[k], wanted[k], 1e-12,
                            1e-13) &&
                right;
      if (!right) break;
    }
  }

  TEST_CASE(
      "exercise-07 200 generated hits keep momentum and energy and reverse the "
      "approach") {
    INFO(
        "the radius is not passed in: at contact 4a^2 is |d|^2, the squared distance of "
        "the centres");
    Draw draw(703);
    for (int n = 1; n <= 200; ++n) {
      const auto [p, q] = random_contact(draw);
      const Hit hit = collide(p, q);
      const Ball &a = hit.p_new, &b = hit.q_new;
      const double dx = q.x - p.x, dy = q.y - p.y;
      CAPTURE(n);
      // Why 1e-13 (relative, and as much again absolute: each sum is of
      // numbers up to 15, which round by 1e-15 each): the velocities are
      // below 15 and |d| below 3, so each quantity comes out within about
      // 1e-14 of its size. Dividing by 4 instead of |d|^2 changes the
      // energy, far beyond that, whenever |d| is not 2; a wrong sign turns
      // nothing round.
      const auto near = [&](const std::string& what, double got, double wanted) {
        return CHECK_CLOSE(hit.text() + "\n  " + what, got, wanted, 1e-13, 1e-13);
      };
      const bool right =
          near("momentum along x, p.vx + q.vx", a.vx + b.vx, p.vx + q.vx) &&
          near("momentum along y, p.vy + q.vy", a.vy + b.vy, p.vy + q.vy) &&
          near("twice the energy, |p.v|^2 + |q.v|^2",
               dot(a.vx, a.vy, a.vx, a.vy) + dot(b.vx, b.vy, b.vx, b.vy),
               dot(p.vx, p.vy, p.vx, p.vy) + dot(q.vx, q.vy, q.vx, q.vy)) &&
          near("the approach along d, w.d (reversed)",
               dot(b.vx - a.vx, b.vy - a.vy, dx, dy),
               -dot(q.vx - p.vx, q.vy - p.vy, dx, dy)) &&
          near("p's velocity across d", cross(a.vx, a.vy, dx, dy),
               cross(p.vx, p.vy, dx, dy)) &&
          near("q's velocity across d", cross(b.vx, b.vy, dx, dy),
               cross(q.vx, q.vy, dx, dy));
      if (!right) break;
    }
  }
}
