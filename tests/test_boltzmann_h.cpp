// Tests for Boltzmann's H of the speeds (stages/beyond/boltzmann_h.*,
// lessons/12-statistics-screen.md): H = sum p_i ln(p_i / q_i) against the 2D
// Maxwell-Boltzmann distribution at the same energy.
//
// - Every ball at one speed (the H-theorem scene's start): H is large, and
//   exactly -ln q of the one bin they are in.
// - Maxwell-Boltzmann's own bin probabilities: H = 0.
// - A sample drawn from Maxwell-Boltzmann: H is the multinomial noise,
//   (bins - 1) / (2N) on average, within a few of its spread.
// - Speeds uniform over a disc of velocities: fine bins give the continuum
//   value 1 - ln 2 worked out from Boltzmann's integral of f ln f.
// - Random histograms: H is never negative.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "beyond/boltzmann_h.hpp"

namespace {

// Speeds of n balls with velocities from 2D Maxwell-Boltzmann at kT (unit
// mass): two independent normal components of variance kT.
std::vector<double> maxwell_speeds(std::size_t n, double kT, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0, std::sqrt(kT));
  std::vector<double> speeds(n);
  for (double& v : speeds) v = std::hypot(normal(random), normal(random));
  return speeds;
}

// The Maxwell-Boltzmann probability of [lo, hi) at kT.
double maxwell_bin(double lo, double hi, double kT) {
  return std::exp(-lo * lo / (2 * kT)) - std::exp(-hi * hi / (2 * kT));
}

}  // namespace

TEST_SUITE("kinetic-theory") {
  TEST_CASE("Boltzmann's H: every ball at one speed is far from equilibrium") {
    // Speed 1 for all: kT = <v^2> / 2 = 0.5. 20 bins of 0.125 (up to 2.5
    // v_rms, as the statistics screen's histogram): all in [1, 1.125), whose
    // Maxwell-Boltzmann probability is e^-1 - e^-1.265625 = 0.0858.
    const std::vector<double> speeds(1000, 1.0);
    const double h = gas::boltzmann_h_of_speeds(speeds, 20, 0.125);
    CHECK(h == doctest::Approx(-std::log(maxwell_bin(1, 1.125, 0.5))).epsilon(1e-12));
    CHECK(h > 2.4);
    // Narrower bins put it further still (the fine-grained H is infinite).
    CHECK(gas::boltzmann_h_of_speeds(speeds, 200, 0.0125) > h + 2);
  }

  TEST_CASE("Boltzmann's H: zero for Maxwell-Boltzmann's own histogram") {
    const double kT = 1.7;
    const double width = 0.3;
    std::vector<double> fractions;
    for (int i = 0; i < 25; ++i)
      fractions.push_back(maxwell_bin(i * width, (i + 1) * width, kT));
    const double beyond = std::exp(-std::pow(25 * width, 2) / (2 * kT));
    CHECK(std::abs(gas::boltzmann_h(fractions, beyond, width, kT)) < 1e-14);
    // Counts work as well as fractions (they are normalised).
    for (double& p : fractions) p *= 1e6;
    CHECK(std::abs(gas::boltzmann_h(fractions, beyond * 1e6, width, kT)) < 1e-14);
    // The same histogram at the wrong temperature is not in equilibrium.
    CHECK(gas::boltzmann_h(fractions, beyond * 1e6, width, 1.2 * kT) > 1e-3);
  }

  TEST_CASE("Boltzmann's H: a Maxwell-Boltzmann sample shows only its noise") {
    // 2N H of N Maxwellian speeds, kT their own mean v^2 / 2, is about
    // chi-squared with bins - 1 degrees of freedom (boltzmann_h.hpp says why):
    // mean (bins - 1) / (2N), spread sqrt(2 (bins - 1)) / (2N). One sample
    // each: the floor plus four spreads.
    for (std::size_t n : {1000, 100000}) {
      const std::size_t bins = 20;
      const double kT = 0.8;
      const double width = 2.5 * std::sqrt(2 * kT) / bins;
      const double h = gas::boltzmann_h_of_speeds(maxwell_speeds(n, kT, 11), bins, width);
      const double floor = gas::boltzmann_h_noise_floor(bins, n);
      const double spread = gas::boltzmann_h_noise_spread(bins, n);
      INFO(n << " balls: H = " << h << ", noise floor " << floor);
      CHECK(h >= 0);
      CHECK(h < floor + 4 * spread);
    }
    CHECK(gas::boltzmann_h_noise_floor(20, 1000) == doctest::Approx(0.0095));
    CHECK(gas::boltzmann_h_noise_spread(20, 1000) ==
          doctest::Approx(std::sqrt(38.0) / 2000));
    // The degrees of freedom, counted: the mean of 2N H over 400 samples of
    // N = 4000 speeds in 12 bins (each expects 7 balls or more) is within
    // three of its standard errors (sqrt(2 * 11 / 400) = 0.23) of
    // bins - 1 = 11; a floor that forgot the energy's constraint (12) is
    // four errors off.
    const std::size_t n = 4000, bins = 12, samples = 400;
    const double kT = 0.8, width = 2.5 * std::sqrt(2 * kT) / bins;
    double sum = 0;
    for (std::size_t k = 0; k < samples; ++k) {
      const double h = gas::boltzmann_h_of_speeds(
          maxwell_speeds(n, kT, static_cast<unsigned>(100 + k)), bins, width);
      sum += 2.0 * n * h / samples;
    }
    const double expected = 2.0 * n * gas::boltzmann_h_noise_floor(bins, n);
    CAPTURE(sum);
    CHECK(expected == doctest::Approx(11));
    CHECK(std::abs(sum - expected) < 3 * std::sqrt(2.0 * 11 / samples));
  }

  TEST_CASE(
      "Boltzmann's H: fine bins give Boltzmann's continuum H (velocity-space check)") {
    // Velocities uniform over a disc of radius V: f = 1 / (pi V^2), so
    // Boltzmann's H = integral f ln f = -ln(pi V^2). Maxwell-Boltzmann at the
    // same energy (<v^2> = V^2 / 2, kT = V^2 / 4) has H = -ln(2 pi kT) - 1 =
    // -ln(pi V^2 / 2) - 1. The difference is 1 - ln 2 = 0.3069; the speeds'
    // relative entropy must give it (the Jacobian 2 pi v cancels).
    const double V = 2;
    const double kT = V * V / 4;
    const int bins = 4000;
    const double width = V / bins;
    std::vector<double> fractions;
    for (int i = 0; i < bins; ++i) {
      const double lo = i * width;
      const double hi = lo + width;
      fractions.push_back((hi * hi - lo * lo) / (V * V));  // P(v) = 2 v / V^2
    }
    CHECK(gas::boltzmann_h(fractions, 0, width, kT) ==
          doctest::Approx(1 - std::log(2.0)).epsilon(1e-4));
  }

  TEST_CASE("Boltzmann's H: never negative, and not known for nonsense") {
    std::mt19937_64 random(17);
    std::uniform_real_distribution<double> uniform(0, 1);
    for (int trial = 0; trial < 2000; ++trial) {
      const int bins = 1 + static_cast<int>(uniform(random) * 40);
      const double kT = 0.05 + 3 * uniform(random);
      const double width = (0.2 + 3 * uniform(random)) * std::sqrt(kT) / bins * 4;
      std::vector<double> fractions(static_cast<std::size_t>(bins));
      // Near Maxwell-Boltzmann (a few per cent off) or anything at all.
      const bool near = trial % 2 == 0;
      for (int i = 0; i < bins; ++i) {
        fractions[static_cast<std::size_t>(i)] =
            near ? maxwell_bin(i * width, (i + 1) * width, kT) *
                       (1 + 0.05 * (uniform(random) - 0.5))
                 : uniform(random) * (uniform(random) < 0.3 ? 0 : 1);
      }
      const double beyond =
          near ? std::exp(-std::pow(bins * width, 2) / (2 * kT)) : uniform(random);
      const double h = gas::boltzmann_h(fractions, beyond, width, kT);
      if (std::isnan(h)) continue;  // an all-zero draw
      INFO("trial " << trial);
      CHECK(h >= 0);
    }
    const std::vector<double> some = {0.5, 0.5};
    CHECK(std::isnan(gas::boltzmann_h(some, 0, 0.1, 0)));
    CHECK(std::isnan(gas::boltzmann_h(some, 0, 0, 1)));
    CHECK(std::isnan(gas::boltzmann_h(std::vector<double>{0.5, -0.5}, 0, 0.1, 1)));
    CHECK(std::isnan(gas::boltzmann_h(std::vector<double>{0, 0}, 0, 0.1, 1)));
    CHECK(std::isnan(gas::boltzmann_h_of_speeds(std::vector<double>{}, 10, 0.1)));
    CHECK(std::isnan(gas::boltzmann_h_of_speeds(std::vector<double>{0, 0}, 10, 0.1)));
    CHECK(std::isnan(gas::boltzmann_h_of_speeds(std::vector<double>{1, -1}, 10, 0.1)));
  }
}
