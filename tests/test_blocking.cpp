// Tests for the blocking analysis (stages/beyond/blocking.*,
// lessons/11-kinetic-theory.md) on series whose standard error of the mean is
// known in closed form.
//
// AR(1): x_{t+1} = phi x_t + sqrt(1 - phi^2) e_t, e_t independent standard
// normal, x_1 standard normal: a stationary series of variance 1 whose
// correlation at lag t is phi^t. The variance of the mean of n samples is
//   (1/n) [ (1 + phi)/(1 - phi) - 2 phi (1 - phi^n) / (n (1 - phi)^2) ],
// about (1/n)(1 + phi)/(1 - phi) for long series: for phi = 0.9, 19 times the
// naive 1/n (statistical inefficiency 19, correlation time tau = 9.5).
//
// Every series is seeded, so each check gives the same result every time; the
// tolerances come from the estimator's own spread (its d_k) and its known
// bias, as each comment says.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <vector>

#include "beyond/blocking.hpp"

namespace {

// The standard error of the mean of n samples of the AR(1) series above.
double ar1_standard_error(double phi, double n) {
  const double one_minus = 1 - phi;
  return std::sqrt(((1 + phi) / one_minus -
                    2 * phi * (1 - std::pow(phi, n)) / (n * one_minus * one_minus)) /
                   n);
}

// n samples of the AR(1) series, fed to a blocking analysis.
gas::BlockingAnalysis ar1_blocking(double phi, std::size_t n, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal(0, 1);
  const double kick = std::sqrt(1 - phi * phi);
  gas::BlockingAnalysis blocking;
  double x = normal(random);
  for (std::size_t i = 0; i < n; ++i) {
    blocking.add(x);
    x = phi * x + kick * normal(random);
  }
  return blocking;
}

// d_k, the uncertainty of the chosen level's error.
double chosen_error_of_error(const gas::BlockingAnalysis& blocking) {
  return blocking.levels()
      .at(static_cast<std::size_t>(blocking.chosen_level()))
      .error_of_error;
}

}  // namespace

TEST_SUITE("kinetic-theory") {
  TEST_CASE("blocking: a correlated series gets its true standard error") {
    const double phi = 0.9;
    const std::size_t n = std::size_t{1} << 20;
    const gas::BlockingAnalysis blocking = ar1_blocking(phi, n, 14);
    const double truth = ar1_standard_error(phi, static_cast<double>(n));
    REQUIRE(blocking.chosen_level() >= 0);
    const std::size_t block = std::size_t{1} << blocking.chosen_level();
    // Tolerance: four of the chosen level's own uncertainty d_k, plus the
    // bias blocks of length b leave, which for AR(1) is a fraction
    // phi (1 - phi^b) / (b (1 - phi^2)) of the error (half the variance's).
    const double b = static_cast<double>(block);
    const double bias = phi * (1 - std::pow(phi, b)) / (b * (1 - phi * phi));
    const double tolerance =
        4 * chosen_error_of_error(blocking) / blocking.error() + bias;
    MESSAGE("blocks of " << block << ": error " << blocking.error() << ", closed form "
                         << truth << ", tolerance " << tolerance * 100 << " %");
    CHECK(std::abs(blocking.error() / truth - 1) < tolerance);
    // The mean is 0 to within four true standard errors.
    CHECK(std::abs(blocking.mean()) < 4 * truth);
    // The naive error is the independent-sample one, 1/sqrt(n) (to within
    // four of its own relative spread 1/sqrt(2n), and the few-percent
    // uncertainty of a correlated sample variance), and far too small: the
    // truth is sqrt(19) = 4.4 times larger.
    CHECK(blocking.naive_error() * std::sqrt(static_cast<double>(n)) ==
          doctest::Approx(1).epsilon(0.05));
    CHECK(blocking.naive_error() < truth / 3);
    CHECK(blocking.statistical_inefficiency() ==
          doctest::Approx((1 + phi) / (1 - phi)).epsilon(2 * tolerance + 0.05));
  }

  TEST_CASE("blocking: over many runs the error bars match the scatter of the means") {
    // 100 independent AR(1) runs (phi = 0.9, n = 2^15): the true mean is 0, so
    // mean_i / error_i should have a root mean square of 1 if the error bars
    // are honest (1.05 for ones 5 % too small). Its spread over 100 runs is
    // about 0.08, so 0.8 ... 1.25 fails only a clearly wrong error (the naive
    // error gives 4.4).
    double squares = 0;
    int known = 0;
    for (unsigned run = 0; run < 100; ++run) {
      const gas::BlockingAnalysis blocking =
          ar1_blocking(0.9, std::size_t{1} << 15, 1000 + run);
      if (std::isnan(blocking.error())) continue;
      squares += std::pow(blocking.mean() / blocking.error(), 2);
      ++known;
    }
    CHECK(known >= 95);
    const double rms = std::sqrt(squares / known);
    MESSAGE("root mean square of mean / error over " << known << " runs: " << rms);
    CHECK(rms > 0.8);
    CHECK(rms < 1.25);
  }

  TEST_CASE("blocking: independent samples get the naive error") {
    const std::size_t n = std::size_t{1} << 16;
    const gas::BlockingAnalysis blocking = ar1_blocking(0, n, 7);
    REQUIRE(!std::isnan(blocking.error()));
    // The same quantity, from blocks of 2^k: within four d_k.
    CHECK(std::abs(blocking.error() / blocking.naive_error() - 1) <
          4 * chosen_error_of_error(blocking) / blocking.error());
    // And both are 1/sqrt(n) to within four of 1/sqrt(2n).
    const double truth = 1 / std::sqrt(static_cast<double>(n));
    CHECK(std::abs(blocking.naive_error() / truth - 1) <
          4 / std::sqrt(2.0 * static_cast<double>(n)));
  }

  TEST_CASE("blocking: no error until a plateau of enough blocks is seen") {
    gas::BlockingAnalysis empty;
    CHECK(empty.count() == 0);
    CHECK(std::isnan(empty.mean()));
    CHECK(std::isnan(empty.naive_error()));
    CHECK(std::isnan(empty.error()));
    CHECK(empty.chosen_level() == -1);
    // Independent samples: fewer than 16 * 2^2 = 64 samples leave fewer than
    // three levels of 16 blocks, so the error is never known before 64.
    for (std::size_t n : {1, 2, 16, 31, 32, 63}) {
      const gas::BlockingAnalysis few = ar1_blocking(0, n, 3);
      INFO(n << " samples");
      CHECK(std::isnan(few.error()));
      CHECK(few.count() == n);
    }
    CHECK(std::isnan(ar1_blocking(0, 1, 3).naive_error()));
    CHECK(!std::isnan(ar1_blocking(0, 2, 3).naive_error()));
    // ... and known soon after (this seed at 64 already; about one seed in
    // ten needs a few more).
    CHECK(!std::isnan(ar1_blocking(0, 64, 3).error()));
    CHECK(!std::isnan(ar1_blocking(0, 1000, 3).error()));
    // A strongly correlated series (tau = 9.5): at 1000 samples the estimates
    // still rise at the top (64 blocks of 16 samples show only 0.6 of the
    // true error), so the error is not known; at 2^16 it is.
    CHECK(std::isnan(ar1_blocking(0.9, 1000, 3).error()));
    CHECK(!std::isnan(ar1_blocking(0.9, std::size_t{1} << 16, 3).error()));
  }

  TEST_CASE("blocking: the levels, the memory, the mean and a restart") {
    gas::BlockingAnalysis blocking;
    double sum = 0;
    const std::size_t n = 1000;
    for (std::size_t i = 0; i < n; ++i) {
      const double x = std::sin(0.1 * static_cast<double>(i));
      blocking.add(x);
      sum += x;
    }
    CHECK(blocking.mean() == doctest::Approx(sum / n).epsilon(1e-12));
    // Level k has floor(n / 2^k) complete blocks; there are log2(n) + 1 levels.
    const std::vector<gas::BlockingLevel> levels = blocking.levels();
    CHECK(levels.size() == 10);  // 2^9 = 512 <= 1000 < 1024
    for (std::size_t k = 0; k < levels.size(); ++k) {
      CHECK(levels[k].block_size == std::size_t{1} << k);
      CHECK(levels[k].blocks == n >> k);
    }
    blocking.clear();
    CHECK(blocking.count() == 0);
    CHECK(blocking.levels().empty());
    blocking.add(2.5);
    CHECK(blocking.mean() == 2.5);
  }

  TEST_CASE("blocking: a large mean does not swamp a small spread") {
    // 1e9 + standard normal noise: a sum and a sum of squares would lose the
    // variance to cancellation (1e18 against 1); Welford's sums do not.
    std::mt19937_64 random(5);
    std::normal_distribution<double> normal(0, 1);
    gas::BlockingAnalysis blocking;
    const std::size_t n = 1 << 14;
    for (std::size_t i = 0; i < n; ++i) blocking.add(1e9 + normal(random));
    CHECK(blocking.naive_error() * std::sqrt(static_cast<double>(n)) ==
          doctest::Approx(1).epsilon(0.05));
    CHECK(blocking.mean() == doctest::Approx(1e9).epsilon(1e-10));
  }
}
