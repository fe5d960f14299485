// Tests for the push on the walls' middles (stages/beyond/wall_push.*;
// lessons/14-error-bars.md): the friction of a whole wall in closed form,
// the shear near the middles' ends against the flow found by minimising the
// dissipation on a grid, and one sound wave written out by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "beyond/wall_push.hpp"

namespace {

constexpr double pi = std::numbers::pi;

// The table of data/large-1000.scene and Enskog's viscosities at eta = 0.29,
// kT = 0.54 in round figures (the formulas do not care which).
constexpr double radius = 1, width = 118.16, height = 88.62;
constexpr gas::Viscosities viscosities{0.17, 0.077};

// The shear part of the friction for one wave q across, found without the
// closed form: the stream function X(u) on a grid of `steps` intervals,
// X = 0 at both walls, chosen to minimise the dissipation
//   eta_s (L2 / 2) integral (a1^2 + a2^2) du,
//   a1 = 2 k^2 Y + 2 k X',  a2 = -2 k Y' - k^2 X - X''
// (the strain rates of phi + psi for this wave; Y the potential flow that
// moves the middles), by least squares: the normal equations, whose matrix
// has five diagonals, solved by Gaussian elimination.
double shear_by_least_squares(int q, double from, double to, int steps) {
  const double side1 = width - 2 * radius, side2 = height - 2 * radius;
  const double k = q * pi / side2;
  const double s =
      (std::sin(k * (to - radius)) - std::sin(k * (from - radius))) / k / (side2 / 2);
  const double h = side1 / steps, half = k * side1 / 2;
  auto y = [&](double u) {
    return -(s / k) * std::cosh(k * (u - side1 / 2)) / std::sinh(half);
  };
  auto y_slope = [&](double u) {
    return -s * std::sinh(k * (u - side1 / 2)) / std::sinh(half);
  };
  // Rows r(X) = sum_j coefficient_j X_j + constant at the inner points.
  struct Row {
    int first = 0;  // index of the first of three unknowns X_{i-1}, X_i, X_{i+1}
    double coefficient[3]{};  // 0 where the unknown is a wall's X = 0
    double constant = 0;
  };
  const int unknowns = steps - 1;  // X_1 ... X_{steps-1}
  std::vector<Row> rows;
  for (int i = 1; i < steps; ++i) {
    const double u = i * h;
    Row a1{i - 2, {-k / h, 0, k / h}, 2 * k * k * y(u)};
    Row a2{
        i - 2, {-1 / (h * h), -k * k + 2 / (h * h), -1 / (h * h)}, -2 * k * y_slope(u)};
    for (Row* r : {&a1, &a2}) {
      if (i == 1) r->coefficient[0] = 0;
      if (i == steps - 1) r->coefficient[2] = 0;
      rows.push_back(*r);
    }
  }
  // Normal equations M X = b, M with bandwidth 2.
  std::vector<std::vector<double>> m(static_cast<std::size_t>(unknowns),
                                     std::vector<double>(5, 0.0));  // m[i][j - i + 2]
  std::vector<double> b(static_cast<std::size_t>(unknowns), 0.0);
  for (const Row& r : rows)
    for (int p = 0; p < 3; ++p) {
      const int i = r.first + p;
      if (i < 0 || i >= unknowns || r.coefficient[p] == 0) continue;
      b[static_cast<std::size_t>(i)] -= r.coefficient[p] * r.constant;
      for (int o = 0; o < 3; ++o) {
        const int j = r.first + o;
        if (j < 0 || j >= unknowns || r.coefficient[o] == 0) continue;
        m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j - i + 2)] +=
            r.coefficient[p] * r.coefficient[o];
      }
    }
  for (int i = 0; i < unknowns; ++i)
    for (int r = i + 1; r <= std::min(i + 2, unknowns - 1); ++r) {
      auto& row = m[static_cast<std::size_t>(r)];
      const auto& pivot = m[static_cast<std::size_t>(i)];
      const double f = row[static_cast<std::size_t>(i - r + 2)] / pivot[2];
      for (int c = i; c <= std::min(i + 2, unknowns - 1); ++c)
        row[static_cast<std::size_t>(c - r + 2)] -=
            f * pivot[static_cast<std::size_t>(c - i + 2)];
      b[static_cast<std::size_t>(r)] -= f * b[static_cast<std::size_t>(i)];
    }
  std::vector<double> x(static_cast<std::size_t>(unknowns), 0.0);
  for (int i = unknowns - 1; i >= 0; --i) {
    double sum = b[static_cast<std::size_t>(i)];
    for (int c = i + 1; c <= std::min(i + 2, unknowns - 1); ++c)
      sum -= m[static_cast<std::size_t>(i)][static_cast<std::size_t>(c - i + 2)] *
             x[static_cast<std::size_t>(c)];
    x[static_cast<std::size_t>(i)] = sum / m[static_cast<std::size_t>(i)][2];
  }
  double dissipation = 0;
  for (const Row& r : rows) {
    double value = r.constant;
    for (int p = 0; p < 3; ++p)
      if (r.coefficient[p] != 0)
        value += r.coefficient[p] * x[static_cast<std::size_t>(r.first + p)];
    dissipation += value * value * h;
  }
  return viscosities.shear * (side2 / 2) * dissipation;
}

}  // namespace

TEST_CASE("wall push: a whole wall only squeezes the gas") {
  // Middles that are the whole walls move no wave across, so the friction
  // is the squeeze's alone: (eta_s + zeta) eps^2 A with eps = 2 L2 / A,
  // that is 4 (eta_s + zeta) L2 / L1. The sum's terms for q >= 1 vanish to
  // rounding (sin(q pi) ~ 1e-16 of the terms' size), hence 1e-12.
  const double side1 = width - 2 * radius, side2 = height - 2 * radius;
  const double friction = gas::middles_friction(viscosities, radius, width, height,
                                                {radius, height - radius});
  CHECK(friction ==
        doctest::Approx(4 * (viscosities.shear + viscosities.bulk) * side2 / side1)
            .epsilon(1e-12));
}

TEST_CASE("wall push: the shear at the middles' ends is the least dissipation") {
  // One wave at a time: the friction with waves up to q less that up to
  // q - 1. The grid's minimum converges to the closed form as h^2; with h =
  // L1 / 4000 = 0.03 (k h <= 0.01) the two agree to 1e-4 (measured 2e-6 to
  // 1.5e-5), while a wrong stream function is further: the 2 of 2 x O
  // dropped, 2.3 to 31 times; coth H dropped, 12 % at q = 1. Middles off
  // centre, so that odd waves count too.
  const double side2 = height - 2 * radius;
  const gas::WallMiddles middles{10, 60};
  for (const int q : {1, 2, 5}) {
    auto up_to = [&](double waves) {
      return gas::middles_friction(viscosities, radius, width, height, middles,
                                   waves * pi / side2);
    };
    const double closed = up_to(q + 0.5) - up_to(q - 0.5);
    CAPTURE(q);
    CHECK(closed ==
          doctest::Approx(shear_by_least_squares(q, 10, 60, 4000)).epsilon(1e-4));
  }
}

TEST_CASE("wall push: the wander is the friction's noise and one wave's ringing") {
  // Waves up to k = 0.05 on this table: the squeeze, the shear of q = 1 and
  // the sound wave (m, q) = (0, 1) alone ((2, 0) has k = 0.054). Written out:
  //   Var(F over W) = 2 kT Re Z(0) / W + <F^2> (ringing - 2 alpha / ((alpha^2
  //   + omega^2) W)), <F^2> = n kT c^2 (2 P_1)^2 / (L1 L2 / 2),
  // P_1 = integral of cos(pi v / L2) over the middle. The same arithmetic in
  // another order: 1e-12.
  gas::BoxHydrodynamics fluid;
  fluid.density = 0.092;
  fluid.kT = 0.54;
  fluid.sound_speed = 2.04;
  fluid.sound_attenuation = 3.66;
  const double side1 = width - 2 * radius, side2 = height - 2 * radius;
  const gas::WallMiddles middles{10, 60};
  const double k_max = 0.05;
  const double friction =
      gas::middles_friction(viscosities, radius, width, height, middles, k_max);
  const double k = pi / side2;
  const double p1 = (std::sin(k * (60 - radius)) - std::sin(k * (10 - radius))) / k;
  const double force = fluid.density * fluid.kT * fluid.sound_speed * fluid.sound_speed *
                       4 * p1 * p1 / (side1 * side2 / 2);
  const double alpha = fluid.sound_attenuation * k * k, omega = fluid.sound_speed * k;
  for (const double w : {20.0, 270.0, 3000.0}) {
    const double variance = 2 * fluid.kT * friction / w +
                            force * (gas::averaged_ringing(alpha, omega, w) -
                                     2 * alpha / ((alpha * alpha + omega * omega) * w));
    CAPTURE(w);
    CHECK(gas::middles_push_wander(fluid, viscosities, radius, width, height, middles, w,
                                   k_max) ==
          doctest::Approx(std::sqrt(variance) / (2 * 50)).epsilon(1e-12));
  }
  // Over a long run the ringing fades as 1 / W^2 and the friction's noise
  // is all: at W = 10^7 within 1e-4 of it.
  const double w = 1e7;
  CHECK(gas::middles_push_wander(fluid, viscosities, radius, width, height, middles, w) ==
        doctest::Approx(
            std::sqrt(2 * fluid.kT *
                      gas::middles_friction(viscosities, radius, width, height, middles) /
                      w) /
            (2 * 50))
            .epsilon(1e-4));
}
