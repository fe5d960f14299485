// Tests for the statistics screen's physics (stages/beyond/kinetic_theory.*,
// lessons/11-kinetic-theory.md): the gas, run by the program's own stages,
// against kinetic theory.
//
// - The formulas themselves: the 2D Maxwell-Boltzmann mean, Henderson's Z
//   and g(2a) through the virial theorem, Enskog's rate through the contact
//   relation.
// - One ball: the wall push gives P (A1 - 2a)(A2 - 2a) = N kT exactly.
// - A gas started with every ball at one speed relaxes to 2D Maxwell-
//   Boltzmann: a Kolmogorov-Smirnov test on speeds sampled at well-separated
//   times, and the mean speed.
// - The equation of state at area fractions 0.1, 0.3 and 0.5: Z measured on
//   the walls for N = 100 and N = 400, the wall correction (proportional to
//   perimeter / area, so to 1 / sqrt(N)) extrapolated away, against
//   Henderson; and Z against the collision rate through the contact relation.
//
// Every run is seeded (the lattice start and the directions), so the checks
// give the same result every time; the tolerances are statistical, from the
// run lengths, and each comment says how. Each test takes about a second or
// less in a Release build.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "beyond/kinetic_theory.hpp"
#include "beyond/strategy.hpp"
#include "stage7_control.hpp"

namespace {

using gas::Average;
using gas::Control;
using gas::Gas;
using gas::GasStatistics;
constexpr double pi = std::numbers::pi;

// side x side balls of radius 1 on a square lattice, in the middle of the
// cells of a square table sized for the area fraction `eta` (N pi / A1^2 =
// eta), every ball at speed 1 in a random direction: a start as far from
// Maxwell-Boltzmann as one likes (every speed the same).
Gas lattice_gas(int side, double eta, unsigned seed) {
  Gas g;
  g.radius = 1;
  const int n = side * side;
  g.width = g.height = std::sqrt(n * pi / eta);
  g.display_step = 1e9;  // take_step's time limit decides every step
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> angle(0, 2 * pi);
  const double cell = g.width / side;  // > 2a for eta < pi / 4
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const double a = angle(random);
      g.balls.push_back(
          {(i + 0.5) * cell, (j + 0.5) * cell, std::cos(a), std::sin(a), 0});
    }
  }
  return g;
}

// A run of stage 7 with kinetic theory's statistics on its hook, as the
// program runs it: every figure kept up to date collision by collision, from
// the moment start_statistics is called.
struct ObservedRun {
  Control control;
  std::optional<GasStatistics> statistics;
  explicit ObservedRun(Gas g) : control(gas::start_control_for(std::move(g))) {}
  ObservedRun(const ObservedRun&) = delete;
  ObservedRun& operator=(const ObservedRun&) = delete;
  GasStatistics& start_statistics(int bins) {
    statistics.emplace(control.gas, bins);
    control.observer = &*statistics;
    return *statistics;
  }
};

void run_until(Control& control, double time) {
  while (control.gas.time < time) gas::take_step(control, time, nullptr);
}

// The measured figures of one run: warm up, then measure for `length` time
// units.
struct Measured {
  double kT = 0;
  Average z, rate;
  double z_from_rate = 0, z_from_rate_error = 0;  // the contact relation
};

Measured measure_run(int side, double eta, double warm_up, double length, unsigned seed) {
  ObservedRun run(lattice_gas(side, eta, seed));
  Control& control = run.control;
  run_until(control, warm_up);
  const GasStatistics& statistics = run.start_statistics(10);
  run_until(control, warm_up + length);
  Measured m;
  m.kT = gas::kinetic_energy(control.gas) / (side * side);
  m.z = statistics.compressibility_at(control.gas.time);
  m.rate = statistics.collision_rate_at(control.gas.time);
  // Contact relation (lesson 11): Z - 1 = rate * s * sqrt(pi m / kT) / 4.
  const double factor = 2 * control.gas.radius * std::sqrt(pi / m.kT) / 4;
  m.z_from_rate = 1 + factor * m.rate.value;
  m.z_from_rate_error = factor * m.rate.error;
  return m;
}

// The Kolmogorov-Smirnov distance between the speeds and 2D Maxwell-
// Boltzmann at kT.
double ks_distance(std::vector<double> speeds, double kT) {
  std::sort(speeds.begin(), speeds.end());
  const auto n = static_cast<double>(speeds.size());
  double d = 0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double f = gas::maxwell_fraction_below(speeds[i], kT);
    d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
  }
  return d;
}

// Henderson's formula is within about 0.5 % of the simulated hard-disc fluid
// up to eta = 0.5 (Henderson 1975; Kolafa and Rottner, Mol. Phys. 104, 3435
// (2006) for accurate values), which the comparisons allow for.
constexpr double henderson_accuracy = 0.005;

void check_equation_of_state(double eta, double length) {
  // N = 100 and N = 400 at the same area fraction, with the same length of
  // run. The walls raise Z above the bulk value by an amount proportional to
  // the walls' length over the area, ~ 1 / sqrt(N) (lesson 11 measures it at
  // N = 100, 400, 1600), so Z(inf) = Z(400) - (Z(100) - Z(400)) = 2 Z(400) -
  // Z(100), with error sqrt(4 e400^2 + e100^2) from the block errors.
  const Measured small = measure_run(10, eta, 30, length, 7);
  const Measured large = measure_run(20, eta, 30, length, 8);
  const double henderson = gas::henderson_compressibility(eta);
  const double extrapolated = 2 * large.z.value - small.z.value;
  const double error = std::hypot(2 * large.z.error, small.z.error);
  CAPTURE(eta);
  CAPTURE(small.z.value);
  CAPTURE(small.z.error);
  CAPTURE(large.z.value);
  CAPTURE(large.z.error);
  CAPTURE(extrapolated);
  CAPTURE(henderson);
  REQUIRE(std::isfinite(error));
  // Three standard errors, plus Henderson's own accuracy.
  CHECK(std::abs(extrapolated - henderson) <= 3 * error + henderson_accuracy * henderson);
  // The contact relation holds at each size, walls and all (lesson 11): the
  // two estimates come from the same run, so within three errors of either.
  for (const Measured* m : {&small, &large}) {
    CAPTURE(m->z_from_rate);
    CHECK(std::abs(m->z.value - m->z_from_rate) <=
          3 * std::hypot(m->z.error, m->z_from_rate_error));
  }
}

}  // namespace

TEST_SUITE("kinetic-theory") {
  TEST_CASE(
      "the formulas: 2D Maxwell-Boltzmann and Henderson and Enskog agree with each "
      "other") {
    // The mean of the Rayleigh density by the midpoint rule (steps of 1e-4
    // up to 12 sqrt(kT): truncation and step errors below 1e-8).
    for (const double kT : {0.5, 1.0, 3.0}) {
      double mean = 0, total = 0, square = 0;
      const double h = 1e-4 * std::sqrt(kT);
      for (double v = h / 2; v < 12 * std::sqrt(kT); v += h) {
        total += gas::maxwell_density(v, kT) * h;
        mean += v * gas::maxwell_density(v, kT) * h;
        square += v * v * gas::maxwell_density(v, kT) * h;
      }
      CHECK(total == doctest::Approx(1).epsilon(1e-8));
      CHECK(mean == doctest::Approx(std::sqrt(pi * kT / 2)).epsilon(1e-8));
      CHECK(square == doctest::Approx(2 * kT).epsilon(1e-8));
      CHECK(gas::maxwell_fraction_below(std::sqrt(2 * kT), kT) ==
            doctest::Approx(1 - std::exp(-1.0)));
    }
    // The virial theorem in 2D: Z = 1 + 2 eta g(2a).
    for (const double eta : {0.05, 0.3, 0.6}) {
      CHECK(gas::henderson_compressibility(eta) ==
            doctest::Approx(1 + 2 * eta * gas::henderson_contact_value(eta)));
    }
    CHECK(gas::henderson_compressibility(0.5) == 4.125);
    // A hand-made gas: Enskog's rate through the contact relation gives
    // Henderson's Z again, and the mean free path is 1 / (2 sqrt 2 s n g).
    Gas g;
    g.radius = 2;
    g.width = 100;
    g.height = 60;
    g.balls = {{10, 10, 3, 4, 0}, {50, 30, -1, 0, 0}, {80, 50, 0, 2, 0}};
    const gas::KineticTheory t = gas::kinetic_theory(g);
    CHECK(t.kT == doctest::Approx((25.0 + 1 + 4) / 2 / 3));
    CHECK(t.area_fraction == doctest::Approx(3 * pi * 4 / 6000));
    const double s = 4, n = 3.0 / 6000;
    CHECK(1 + t.collision_rate * s * std::sqrt(pi / t.kT) / 4 ==
          doctest::Approx(t.compressibility));
    CHECK(t.mean_free_path ==
          doctest::Approx(1 / (2 * std::sqrt(2.0) * s * n * t.contact_value)));
    CHECK(t.pressure == doctest::Approx(t.compressibility * 3 * t.kT / (96.0 * 56.0)));
  }

  TEST_CASE("one ball: the push on the walls gives P times the centres' area = N kT") {
    // A ball with velocity (3, 4) on a 40 x 30 table, radius 1: its centre
    // crosses 38 in x and 28 in y. Over a whole number of both periods
    // (2 * 38 / 3 and 2 * 28 / 4 = 14; 532 is 21 of the first and 38 of the
    // second) each wall is hit as often as the others of its pair, and
    // Z = 1 to round-off.
    Gas g;
    g.radius = 1;
    g.width = 40;
    g.height = 30;
    g.display_step = 1e9;
    g.balls = {{10, 10, 3, 4, 0}};
    ObservedRun run(g);
    Control& control = run.control;
    const GasStatistics& statistics = run.start_statistics(10);
    run_until(control, 532);
    CHECK(statistics.compressibility_at(532).value == doctest::Approx(1).epsilon(1e-12));
    CHECK(statistics.pressure_at(532).value ==
          doctest::Approx(12.5 / (38.0 * 28.0)).epsilon(1e-12));
    CHECK(statistics.collision_rate_at(532).value == 0);
    CHECK(statistics.mean_speed_at(532).value == doctest::Approx(5));
  }

  TEST_CASE("a gas started at one speed relaxes to the 2D Maxwell-Boltzmann speeds") {
    // 100 balls at area fraction 0.3, all at speed 1. Kinetic theory gives
    // a ball 0.85 collisions per unit time here, so after 30 time units each
    // has collided ~25 times. Then 60 snapshots of the 100 speeds, 6 time
    // units (~5 collisions of each ball) apart: a ball's speed after five
    // collisions has forgotten the one before, so the 6000 speeds are close
    // to independent draws. (Within one snapshot the speeds are tied by the
    // fixed energy; that makes their distribution slightly closer to the
    // curve, never farther, and the exact distribution for a finite N
    // differs from Maxwell-Boltzmann by about 0.2 / N = 0.002 in F, far below
    // what this test can see.)
    Control control = gas::start_control_for(lattice_gas(10, 0.3, 3));
    const double kT = gas::kinetic_energy(control.gas) / 100;
    // At the start the speeds are nowhere near: all of them at one speed.
    std::vector<double> speeds;
    for (const gas::Ball& b : control.gas.balls) speeds.push_back(std::hypot(b.vx, b.vy));
    CHECK(ks_distance(speeds, kT) > 0.3);
    speeds.clear();
    run_until(control, 30);
    for (int k = 1; k <= 60; ++k) {
      run_until(control, 30 + 6 * k);
      for (const gas::Ball& b : control.gas.balls)
        speeds.push_back(std::hypot(b.vx, b.vy));
    }
    // Kolmogorov-Smirnov at the 0.1 % level: D * sqrt(n) < 1.949.
    const double n = static_cast<double>(speeds.size());
    const double critical = 1.949 / std::sqrt(n);
    const double d = ks_distance(speeds, kT);
    CAPTURE(d);
    CAPTURE(critical);
    CHECK(d < critical);
    // The test has the power to see a wrong temperature: 10 % off is rejected.
    CHECK(ks_distance(speeds, 1.1 * kT) > critical);
    // The mean speed: the standard deviation of a Maxwell-Boltzmann speed is
    // sqrt((2 - pi / 2) kT), so the mean of n independent speeds is within
    // 3 sqrt((2 - pi / 2) kT / n) (three standard errors) of sqrt(pi kT / 2).
    double mean = 0;
    for (const double v : speeds) mean += v / n;
    CAPTURE(mean);
    CHECK(std::abs(mean - std::sqrt(pi * kT / 2)) <=
          3 * std::sqrt((2 - pi / 2) * kT / n));
  }

  TEST_CASE(
      "the time-averaged mean speed of GasStatistics converges to sqrt(pi kT / 2)") {
    // The screen's own average over 600 time units after 30 to relax; its
    // block error (some 30000 collisions: at least 16 blocks of 800 or more,
    // over 10 collisions of each ball a block: independent enough) gives the
    // tolerance, three errors.
    ObservedRun run(lattice_gas(10, 0.3, 5));
    Control& control = run.control;
    run_until(control, 30);
    const GasStatistics& statistics = run.start_statistics(10);
    run_until(control, 630);
    const Average mean = statistics.mean_speed_at(630);
    const gas::KineticTheory theory = gas::kinetic_theory(control.gas);
    CAPTURE(mean.value);
    CAPTURE(mean.error);
    REQUIRE(std::isfinite(mean.error));
    CHECK(std::abs(mean.value - theory.mean_speed) <= 3 * mean.error);
    // The histogram's fractions and the fraction beyond make the whole.
    double sum = statistics.fraction_beyond_at(630);
    for (const double f : statistics.speed_fractions_at(630)) sum += f;
    CHECK(sum == doctest::Approx(1));
  }

  // Run lengths: the Z errors they give (from the block averages) are about
  // 0.3 % of Z, against gaps from the walls of 1 to 3 % at N = 100.
  TEST_CASE("the equation of state at area fraction 0.1") {
    check_equation_of_state(0.1, 3000);
  }
  TEST_CASE("the equation of state at area fraction 0.3") {
    check_equation_of_state(0.3, 1200);
  }
  TEST_CASE("the equation of state at area fraction 0.5") {
    check_equation_of_state(0.5, 1000);
  }

  TEST_CASE("the walls' excess pressure shrinks as the walls' share of the gas") {
    // At area fraction 0.5 the wall correction is large enough to measure:
    // Z(100) - Z_H ~ 0.125 and Z(400) - Z_H ~ 0.06 (lesson 11). Both are
    // positive and the larger gas's is smaller, each beyond three errors;
    // their ratio is near 2 = sqrt(400 / 100), within four errors of it.
    const Measured small = measure_run(10, 0.5, 30, 1000, 11);
    const Measured large = measure_run(20, 0.5, 30, 1000, 12);
    const double henderson = gas::henderson_compressibility(0.5);
    const double gap_small = small.z.value - henderson,
                 gap_large = large.z.value - henderson;
    CAPTURE(gap_small);
    CAPTURE(gap_large);
    CHECK(gap_large > 3 * large.z.error);
    CHECK(gap_small - gap_large > 3 * std::hypot(small.z.error, large.z.error));
    const double ratio = gap_small / gap_large;
    const double ratio_error =
        ratio * std::hypot(small.z.error / gap_small, large.z.error / gap_large);
    CAPTURE(ratio);
    CHECK(std::abs(ratio - 2) <= 4 * ratio_error);
  }
}
