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

namespace {

// The standard error of the mean of `values` as if they were independent:
// sqrt(s^2 / n) with the sample variance s^2 = sum (x - mean)^2 / (n - 1).
double standard_error(const std::vector<double>& values) {
  const auto n = static_cast<double>(values.size());
  double mean = 0;
  for (const double x : values) mean += x / n;
  double squares = 0;
  for (const double x : values) squares += (x - mean) * (x - mean);
  return std::sqrt(squares / (n - 1) / n);
}

// The means of the complete blocks of 2^level consecutive samples.
std::vector<double> block_means(const std::vector<double>& samples, std::size_t level) {
  const std::size_t size = std::size_t{1} << level;
  std::vector<double> means;
  for (std::size_t start = 0; start + size <= samples.size(); start += size) {
    double sum = 0;
    for (std::size_t i = start; i < start + size; ++i) sum += samples[i];
    means.push_back(sum / static_cast<double>(size));
  }
  return means;
}

// The plateau rule of blocking.hpp, from the table of levels: levels with at
// least 16 blocks are usable; the chosen one is the lowest k with two usable
// levels above it, each within its own d_j of e_k; -1 if there is none.
int plateau_level(const std::vector<gas::BlockingLevel>& levels) {
  std::size_t usable = 0;
  while (usable < levels.size() && levels[usable].blocks >= 16) ++usable;
  for (std::size_t k = 0; k + 2 < usable; ++k) {
    if (levels[k + 1].error <= levels[k].error + levels[k + 1].error_of_error &&
        levels[k + 2].error <= levels[k].error + levels[k + 2].error_of_error) {
      return static_cast<int>(k);
    }
  }
  return -1;
}

}  // namespace

TEST_SUITE("kinetic-theory") {
  TEST_CASE("blocking: every level's error is that of its block means, with n - 1") {
    // By hand: 1, 3, 5, 7. Level 0: mean 4, squares 9 + 1 + 1 + 9 = 20,
    // e_0 = sqrt(20 / (3 x 4)); level 1: blocks 2 and 6, e_1 = sqrt(8 / (1 x 2))
    // = 2; level 2: one block, no error. (Why 1e-15: each side is a few
    // roundings of numbers of order 1, a few units of 1.1e-16.)
    gas::BlockingAnalysis hand;
    for (const double x : {1.0, 3.0, 5.0, 7.0}) hand.add(x);
    const std::vector<gas::BlockingLevel> levels = hand.levels();
    REQUIRE(levels.size() == 3);
    CHECK(levels[0].error == doctest::Approx(std::sqrt(20.0 / 12)).epsilon(1e-15));
    CHECK(levels[0].error_of_error ==
          doctest::Approx(std::sqrt(20.0 / 12) / std::sqrt(6.0)).epsilon(1e-15));
    CHECK(hand.naive_error() == levels[0].error);
    CHECK(levels[1].error == doctest::Approx(2).epsilon(1e-15));
    CHECK(levels[1].error_of_error == doctest::Approx(2 / std::sqrt(2.0)).epsilon(1e-15));
    CHECK(std::isnan(levels[2].error));
    // A seeded series of 3000: every level against its block means, taken
    // here directly from the samples. Why 1e-12: the two sides add the same
    // numbers in different orders (blocks by pairs there, in a row here).
    std::mt19937_64 random(11);
    std::normal_distribution<double> normal(3, 2);
    std::vector<double> samples(3000);
    gas::BlockingAnalysis blocking;
    for (double& x : samples) blocking.add(x = normal(random));
    const std::vector<gas::BlockingLevel> all = blocking.levels();
    REQUIRE(all.size() == 12);  // 2^11 = 2048 <= 3000 < 4096
    for (std::size_t k = 0; k + 1 < all.size(); ++k) {
      CAPTURE(k);
      const std::vector<double> means = block_means(samples, k);
      REQUIRE(all[k].blocks == means.size());
      const double e = standard_error(means);
      CHECK(all[k].error == doctest::Approx(e).epsilon(1e-12));
      CHECK(
          all[k].error_of_error ==
          doctest::Approx(e / std::sqrt(2.0 * double(means.size() - 1))).epsilon(1e-12));
    }
    CHECK(std::isnan(all.back().error));  // one block of 2048
  }

  TEST_CASE("blocking: over many short series of white noise the error is unbiased") {
    // Four independent standard normal samples: the variance of their mean is
    // exactly 1/4, and e^2 = s^2 / 4 with s^2 the n - 1 sample variance has
    // that expectation. So 4 e^2 averages to 1 over many series: its spread
    // is 2/3 a series (s^2 is chi^2 with 3 degrees of freedom over 3), over
    // 20000 series 0.0058; four of those is the tolerance. (With n for
    // n - 1 the average would be 0.75.)
    std::mt19937_64 random(2024);
    std::normal_distribution<double> normal(0, 1);
    const int series = 20000;
    double sum = 0;
    for (int i = 0; i < series; ++i) {
      gas::BlockingAnalysis blocking;
      for (int j = 0; j < 4; ++j) blocking.add(normal(random));
      sum += 4 * blocking.naive_error() * blocking.naive_error();
    }
    const double mean = sum / series;
    CAPTURE(mean);
    CHECK(std::abs(mean - 1) < 4 * std::sqrt(2.0 / 3 / series));
  }

  TEST_CASE("blocking: the error is the plateau rule's level, series by series") {
    // 700 series of every kind the rule meets — independent and correlated,
    // short and long — and the level error() is taken from checked against
    // the rule as blocking.hpp words it, applied here to the table of
    // levels. Every outcome of the rule must occur among them: not known
    // (-1), level 0, and a higher level. (So many that a comparison within a
    // few per cent of its threshold d_j comes up: a d_j from n_j rather than
    // n_j - 1 blocks changes some series' level.)
    int not_known = 0, level_zero = 0, higher = 0;
    unsigned seed = 100;
    for (const double phi : {0.0, 0.5, 0.9, 0.99}) {
      for (const std::size_t n : {40, 64, 100, 300, 1000, 5000, 20000}) {
        for (int repeat = 0; repeat < 25; ++repeat) {
          const gas::BlockingAnalysis blocking = ar1_blocking(phi, n, ++seed);
          CAPTURE(phi);
          CAPTURE(n);
          CAPTURE(seed);
          const std::vector<gas::BlockingLevel> levels = blocking.levels();
          const int level = plateau_level(levels);
          CHECK(blocking.chosen_level() == level);
          if (level < 0) {
            CHECK(std::isnan(blocking.error()));
            ++not_known;
          } else {
            CHECK(blocking.error() == levels[static_cast<std::size_t>(level)].error);
            ++(level == 0 ? level_zero : higher);
          }
        }
      }
    }
    CHECK(not_known > 0);
    CHECK(level_zero > 0);
    CHECK(higher > 0);
  }
}
