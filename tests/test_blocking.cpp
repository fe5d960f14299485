// Tests for the blocking analysis (stages/beyond/blocking.*,
// lessons/14-error-bars.md) on series whose standard error of the mean is
// known in closed form.
//
// AR(1): x_{t+1} = phi x_t + sqrt(1 - phi^2) e_t, e_t independent standard
// normal, x_1 standard normal: a stationary series of variance 1 whose
// correlation at lag t is phi^t. The variance of the mean of n samples is
//   (1/n) [ (1 + phi)/(1 - phi) - 2 phi (1 - phi^n) / (n (1 - phi)^2) ],
// about (1/n)(1 + phi)/(1 - phi) for long series: for phi = 0.9, 19 times the
// naive 1/n (statistical inefficiency 19, correlation time tau = 9.5).
//
// For phi < 0 the series is anticorrelated and the truth is below the naive
// error: (1 + phi)/(1 - phi) = 1/3 of its variance for phi = -0.5.
//
// Every series is seeded, so each check gives the same result every time; the
// tolerances come from the estimator's own spread (batch means over 16 to 31
// batches: e^2 scatters like chi-squared with n_k - 1 degrees of freedom over
// n_k - 1) and its known bias, as each comment says. The rule's false alarms
// and power, which blocking.hpp states, are measured here too.
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
  TEST_CASE("blocking: correlated and anticorrelated series get their true error") {
    // For each phi, 200 series of n = 2^14 (batches of 2^10, 16 of them): the
    // average of e^2 over the series against the closed form's variance of
    // the mean. e^2 is the truth times chi-squared with 15 degrees of freedom
    // over 15 (relative spread sqrt(2/15) = 0.37), so its average over 200
    // series is within 4 x 0.37 / sqrt(200) = 0.10 of the truth, less the
    // bias batches of b leave, a fraction 2 phi (1 - phi^b) / (b (1 - phi^2))
    // of the variance for a positive phi (0.9 % at phi = 0.9), and above it
    // by as much for a negative one. A plateau rule once took the naive
    // error for phi = -0.5 (a falling curve looked flat): 3 times the
    // variance. And (mean / e) over the series scatters like Student's t
    // with 15 degrees of freedom: mean square 15/13, within 0.5 over 200
    // series (t^2's spread there is 1.8, over 200 series 0.13, four of
    // those). The batches' own level is used, whatever Jonsson's test says
    // of a series (it blanks some 1 % of them: the next test).
    unsigned seed = 5000;
    for (const double phi : {0.9, 0.0, -0.5}) {
      CAPTURE(phi);
      const std::size_t n = std::size_t{1} << 14;
      const double truth = ar1_standard_error(phi, static_cast<double>(n));
      double squares = 0, t_squares = 0;
      const int series = 200;
      for (int i = 0; i < series; ++i) {
        const gas::BlockingAnalysis blocking = ar1_blocking(phi, n, ++seed);
        REQUIRE(blocking.batch_level() == 10);  // 16 batches of 2^10
        const double e = blocking.levels()[10].error;
        squares += e * e;
        t_squares += std::pow(blocking.mean() / e, 2);
      }
      const double ratio = squares / series / (truth * truth);
      const double b = 1024;
      const double bias = 2 * std::abs(phi) / (b * (1 - phi * phi));
      MESSAGE("phi " << phi << ": mean e^2 / truth^2 " << ratio << ", mean t^2 "
                     << t_squares / series);
      CHECK(std::abs(ratio - 1) < 0.10 + bias);
      CHECK(std::abs(t_squares / series - 15.0 / 13) < 0.5);
    }
    // The naive error is 4.4 times too small for phi = 0.9, 1.7 times too
    // large for phi = -0.5.
    const std::size_t n = std::size_t{1} << 16;
    CHECK(ar1_blocking(0.9, n, 1).naive_error() <
          ar1_standard_error(0.9, static_cast<double>(n)) / 3);
    CHECK(ar1_blocking(-0.5, n, 1).naive_error() >
          1.5 * ar1_standard_error(-0.5, static_cast<double>(n)));
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

  TEST_CASE(
      "blocking: no error before 16 samples, nor while the batches are correlated") {
    gas::BlockingAnalysis empty;
    CHECK(empty.count() == 0);
    CHECK(std::isnan(empty.mean()));
    CHECK(std::isnan(empty.naive_error()));
    CHECK(std::isnan(empty.error()));
    CHECK(empty.chosen_level() == -1);
    CHECK(empty.status() == gas::ErrorStatus::few_samples);
    // Independent samples: fewer than 16 leave no level of 16 blocks.
    for (std::size_t n : {1, 2, 8, 15}) {
      const gas::BlockingAnalysis few = ar1_blocking(0, n, 3);
      INFO(n << " samples");
      CHECK(std::isnan(few.error()));
      CHECK(few.status() == gas::ErrorStatus::few_samples);
      CHECK(few.count() == n);
    }
    CHECK(std::isnan(ar1_blocking(0, 1, 3).naive_error()));
    CHECK(!std::isnan(ar1_blocking(0, 2, 3).naive_error()));
    // ... and known from 16 on: the batches are the samples themselves.
    CHECK(ar1_blocking(0, 16, 3).chosen_level() == 0);
    CHECK(ar1_blocking(0, 31, 3).chosen_level() == 0);
    CHECK(ar1_blocking(0, 32, 3).chosen_level() == 1);
    CHECK(ar1_blocking(0, 1000, 3).status() == gas::ErrorStatus::known);
    // A straight ramp: its batches are as correlated as can be. Jonsson's
    // test on the batches' level and the two below sees it: 1000 samples,
    // batches of 32 (31 of them), M over 125, 62 and 31 blocks.
    gas::BlockingAnalysis ramp;
    for (int i = 0; i < 1000; ++i) ramp.add(i);
    REQUIRE(ramp.batch_level() == 5);
    std::size_t terms = 0;
    const double m = ramp.jonsson_m(3, 5, &terms);
    CHECK(terms == 3);
    CHECK(m > gas::chi_squared_quantile(3, 2.326348));
    CHECK(std::isnan(ramp.error()));
    CHECK(ramp.status() == gas::ErrorStatus::correlated_batches);
    // AR(1) with phi = 0.99 (tau = 100): at 1000 samples the batches of 32
    // are still correlated, and the test sees it (the next test: always);
    // at 2^17 samples, batches of 2^12 = 41 tau, it lets the error be.
    for (unsigned s = 0; s < 10; ++s)
      CHECK(ar1_blocking(0.99, 1000, s).status() == gas::ErrorStatus::correlated_batches);
    CHECK(!std::isnan(ar1_blocking(0.99, std::size_t{1} << 17, 3).error()));
    // Rule 2: batches shorter than asked leave the error unknown, whatever
    // the test says; long enough, and it is known again.
    gas::BlockingAnalysis slow = ar1_blocking(0, 1000, 3);  // batches of 32
    slow.set_shortest_batch(33);
    CHECK(std::isnan(slow.error()));
    CHECK(slow.status() == gas::ErrorStatus::short_batches);
    slow.set_shortest_batch(32);
    CHECK(slow.status() == gas::ErrorStatus::known);
    CHECK(slow.error() == ar1_blocking(0, 1000, 3).error());
  }

  TEST_CASE("blocking: Jonsson's test leaves out the levels rule 2 calls too short") {
    // Independent noise plus a square wave of period 16 (+1 for 8 samples,
    // -1 for 8): blocks of 8 swing +1, -1, +1, ... (the test's terms for
    // them are huge), blocks of 16 and 32 hold whole periods and see the
    // noise alone. 1000 samples: batches of 32 (level 5), the test on
    // levels 3, 4, 5. Told that batches must be 16 long, it looks at levels
    // 4 and 5 only, and the error (the noise's: the wave adds nothing to a
    // block of 32) is known; told nothing, the swinging level 3 blanks it.
    auto swinging = [](std::size_t shortest) {
      std::mt19937_64 random(11);
      std::normal_distribution<double> normal(0, 1);
      gas::BlockingAnalysis blocking;
      blocking.set_shortest_batch(shortest);
      for (int t = 0; t < 1000; ++t)
        blocking.add(normal(random) + ((t / 8) % 2 == 0 ? 1 : -1));
      return blocking;
    };
    const gas::BlockingAnalysis told = swinging(16), untold = swinging(1);
    REQUIRE(told.batch_level() == 5);
    std::size_t terms = 0;
    CHECK(untold.jonsson_m(3, 3, &terms) > 50);  // one term: chi-squared's 99 % is 6.6
    CHECK(untold.status() == gas::ErrorStatus::correlated_batches);
    CHECK(told.status() == gas::ErrorStatus::known);
    // Within 30 % of the noise's error sqrt(1 / 1000) (31 batches: the
    // estimate's own scatter is 13 %).
    CHECK(told.error() == doctest::Approx(std::sqrt(1 / 1000.0)).epsilon(0.3));
  }

  TEST_CASE("blocking: the test's false alarms and power, as blocking.hpp states them") {
    // Each case: 2000 seeded series (the same every run), the share whose
    // error the rule leaves unknown. Each bound sits some four binomial
    // spreads from what was measured (in brackets), so that a change of the
    // rule that moves a share shows.
    auto unknown_share = [](double phi, std::size_t n, unsigned first_seed) {
      int unknown = 0;
      for (unsigned s = 0; s < 2000; ++s)
        unknown += std::isnan(ar1_blocking(phi, n, first_seed + s).error());
      return unknown / 2000.0;
    };
    // False alarms: independent normal samples, 16 to 10^4 of them: about
    // 1 % (0.2 % to 1.3 %): chi-squared's 99 % point, a little conservative
    // for so few blocks.
    double most = 0;
    for (const std::size_t n : {16, 31, 64, 300, 1000, 10000}) {
      const double share = unknown_share(0, n, 1000 * static_cast<unsigned>(n));
      CAPTURE(n);
      CAPTURE(share);
      CHECK(share < 0.025);
      most = std::max(most, share);
    }
    CHECK(most > 0.001);  // the test does say no at times
    // Power on AR(1), tau = (1 + phi) / (2 (1 - phi)): batches shorter than
    // a few tau are nearly always caught, batches of 10 tau or more rarely.
    // phi = 0.5 (tau 1.5) at 100 samples, batches of 4: [97 %].
    CHECK(unknown_share(0.5, 100, 1) > 0.9);
    // phi = 0.9 (tau 9.5) at 300 samples, batches of 16: [100 %]; at 1000,
    // batches of 32: [100 %]; at 3000, batches of 128 = 13 tau: [13 %].
    CHECK(unknown_share(0.9, 300, 1) > 0.97);
    CHECK(unknown_share(0.9, 1000, 1) > 0.97);
    const double long_batches = unknown_share(0.9, 3000, 1);
    CAPTURE(long_batches);
    CHECK(long_batches > 0.05);
    CHECK(long_batches < 0.25);
    // A ramp whose whole rise is the noise's spread, x_t = e_t + t / n:
    // [60 %] of series of 256, [100 %] of 1000.
    auto ramp_share = [](std::size_t n) {
      int unknown = 0;
      for (unsigned s = 0; s < 2000; ++s) {
        std::mt19937_64 random(77 + s);
        std::normal_distribution<double> normal(0, 1);
        gas::BlockingAnalysis blocking;
        for (std::size_t i = 0; i < n; ++i)
          blocking.add(normal(random) + static_cast<double>(i) / static_cast<double>(n));
        unknown += std::isnan(blocking.error());
      }
      return unknown / 2000.0;
    };
    const double ramp_256 = ramp_share(256);
    CAPTURE(ramp_256);
    CHECK(ramp_256 > 0.5);
    CHECK(ramp_256 < 0.7);
    CHECK(ramp_share(1000) > 0.99);
  }

  TEST_CASE("blocking: a slow drift under fast noise passes the test; rule 2 holds it") {
    // Like a gas's heat: white noise of variance 1 plus a slow AR(1) part of
    // variance 1/2000 and phi = 0.999 (tau = 1000), as much to the variance
    // of a long mean as the noise. 1000 series of 3000 samples (batches of
    // 128, an eighth of tau): the test lets [99 %] of the errors be, and
    // those are too small, (mean / error) scattering [1.4] times as wide as
    // Student's t allows. Asked for batches of 2048 (rule 2), the error
    // waits: none known at 3000 samples.
    auto run = [](std::size_t shortest, double* rms) {
      int known = 0;
      double squares = 0;
      for (unsigned s = 0; s < 1000; ++s) {
        std::mt19937_64 random(9000 + s);
        std::normal_distribution<double> normal(0, 1);
        const double slow_variance = 1.0 / 2000, phi = 0.999;
        const double kick = std::sqrt(slow_variance * (1 - phi * phi));
        double slow = normal(random) * std::sqrt(slow_variance);
        gas::BlockingAnalysis blocking;
        blocking.set_shortest_batch(shortest);
        for (int i = 0; i < 3000; ++i) {
          blocking.add(normal(random) + slow);
          slow = phi * slow + kick * normal(random);
        }
        if (std::isnan(blocking.error())) continue;
        ++known;
        squares += std::pow(blocking.mean() / blocking.error(), 2);
      }
      *rms = known > 0 ? std::sqrt(squares / known) : 0;
      return known / 1000.0;
    };
    double rms = 0;
    const double known = run(1, &rms);
    CAPTURE(known);
    CAPTURE(rms);
    CHECK(known > 0.95);
    // Student's t with 22 degrees of freedom (3000 / 128 = 23 batches):
    // root mean square 1.05, and over 1000 series within 0.1 of it.
    CHECK(rms > 1.25);
    CHECK(run(2048, &rms) == 0);
  }

  TEST_CASE("blocking: the chi-squared quantile against a table") {
    // Wilson and Hilferty's approximation against Abramowitz and Stegun,
    // table 26.8, at the 99 % the test uses and at 99.9 %. In the far tail
    // with few degrees of freedom it errs by a few per cent (at 99.9 % high
    // by 3 % at one degree, at 99 % low by 0.8 % at one): 3.5 %.
    struct Tabled {
      double z;         // the standard normal quantile of the level
      double degrees;   // degrees of freedom
      double quantile;  // the table's chi-squared at that level
    };
    for (const Tabled& tabled : {Tabled{2.326348, 1.0, 6.635},
                                 {2.326348, 2.0, 9.210},
                                 {2.326348, 3.0, 11.345},
                                 {2.326348, 4.0, 13.277},
                                 {2.326348, 5.0, 15.086},
                                 {2.326348, 10.0, 23.209},
                                 {2.326348, 20.0, 37.566},
                                 {2.326348, 30.0, 50.892},
                                 {3.090232, 1.0, 10.828},
                                 {3.090232, 2.0, 13.816},
                                 {3.090232, 3.0, 16.266},
                                 {3.090232, 4.0, 18.467},
                                 {3.090232, 5.0, 20.515},
                                 {3.090232, 10.0, 29.588},
                                 {3.090232, 20.0, 45.315},
                                 {3.090232, 30.0, 59.703}}) {
      const double z = tabled.z;
      const double degrees = tabled.degrees;
      CAPTURE(z);
      CAPTURE(degrees);
      CHECK(gas::chi_squared_quantile(degrees, z) ==
            doctest::Approx(tabled.quantile).epsilon(0.035));
    }
    // Three degrees of freedom, the test's usual case: within 0.5 % at 99 %.
    CHECK(gas::chi_squared_quantile(3, 2.326348) ==
          doctest::Approx(11.345).epsilon(0.005));
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

// The mean of `values`, and their sum of squared deviations from it.
double mean_of(const std::vector<double>& values) {
  double mean = 0;
  for (const double x : values) mean += x / static_cast<double>(values.size());
  return mean;
}
double squares_of(const std::vector<double>& values) {
  const double mean = mean_of(values);
  double squares = 0;
  for (const double x : values) squares += (x - mean) * (x - mean);
  return squares;
}

// The standard error of the mean of `values` as if they were independent:
// sqrt(s^2 / n) with the sample variance s^2 = sum (x - mean)^2 / (n - 1).
double standard_error(const std::vector<double>& values) {
  const auto n = static_cast<double>(values.size());
  return std::sqrt(squares_of(values) / (n - 1) / n);
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

// Jonsson's sigma^2 and gamma (his Eq. 6) of a series, both over n.
double variance_over_n(const std::vector<double>& y) {
  return squares_of(y) / static_cast<double>(y.size());
}
double lag_one(const std::vector<double>& y) {
  const auto n = static_cast<double>(y.size());
  const double mean = mean_of(y);
  double sum = 0;
  for (std::size_t t = 0; t + 1 < y.size(); ++t) sum += (y[t] - mean) * (y[t + 1] - mean);
  return sum / n;
}

// The rule of blocking.hpp, worked out here from the samples themselves: the
// batches are the highest level with at least 16 blocks; the error is known
// if Jonsson's M over the batches' level and the two below it (those that
// exist) is under the 99 % quantile of chi-squared with as many degrees of
// freedom as it has terms. -1 if not known.
int rule_level(const std::vector<double>& samples) {
  int top = -1;
  while (block_means(samples, static_cast<std::size_t>(top + 1)).size() >= 16) ++top;
  if (top < 0) return -1;
  double m = 0;
  int terms = 0;
  for (int i = std::max(top - 2, 0); i <= top; ++i) {
    const std::vector<double> y = block_means(samples, static_cast<std::size_t>(i));
    const auto n = static_cast<double>(y.size());
    const double sigma2 = variance_over_n(y);
    const double c = (n - 1) * sigma2 / (n * n) + lag_one(y);
    m += n * c * c / (sigma2 * sigma2);
    ++terms;
  }
  return m < gas::chi_squared_quantile(terms, 2.326348) ? top : -1;
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
      // Jonsson's sigma^2 and gamma. (Why 1e-9 of sigma^2 for gamma: it is a
      // difference of sums of products taken from the first sample, some
      // three spreads from the mean, so each carries a few units of 1e-16 of
      // ten times sigma^2, summed over up to 3000 terms.)
      CHECK(all[k].variance == doctest::Approx(variance_over_n(means)).epsilon(1e-12));
      CHECK(std::abs(all[k].lag_one - lag_one(means)) < 1e-9 * all[k].variance);
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

  TEST_CASE("blocking: the error is the rule's level, series by series") {
    // 840 series of every kind the rule meets — independent, correlated and
    // anticorrelated, short and long, and noisy ramps — and the level
    // error() is taken from checked against the rule as blocking.hpp words
    // it, worked out here from the samples. Every outcome of the rule must
    // occur among them: not known before 16 samples, not known for
    // correlated batches, level 0, and a higher level. (So many that a test
    // near its quantile comes up: a quantile of 99.9 % instead of 99 %,
    // Jonsson's M over one level fewer or more, or without its bias term,
    // changes some series' outcome.)
    int too_few = 0, correlated = 0, level_zero = 0, higher = 0;
    unsigned seed = 100;
    for (const double phi : {-0.5, 0.0, 0.5, 0.9, 0.99, 2.0}) {
      for (const std::size_t n : {5, 15, 20, 100, 300, 1000, 5000}) {
        for (int repeat = 0; repeat < 20; ++repeat) {
          std::mt19937_64 random(++seed);
          std::normal_distribution<double> normal(0, 1);
          std::vector<double> samples;
          if (phi > 1) {  // phi = 2 marks a ramp of 3 standard deviations
            for (std::size_t i = 0; i < n; ++i)
              samples.push_back(3 * static_cast<double>(i) / static_cast<double>(n) +
                                normal(random));
          } else {
            const double kick = std::sqrt(1 - phi * phi);
            double x = normal(random);
            for (std::size_t i = 0; i < n; ++i) {
              samples.push_back(x);
              x = phi * x + kick * normal(random);
            }
          }
          gas::BlockingAnalysis blocking;
          for (const double x : samples) blocking.add(x);
          CAPTURE(phi);
          CAPTURE(n);
          CAPTURE(seed);
          const int level = rule_level(samples);
          CHECK(blocking.chosen_level() == level);
          if (level < 0) {
            CHECK(std::isnan(blocking.error()));
            ++(n < 16 ? too_few : correlated);
          } else {
            const double e =
                standard_error(block_means(samples, static_cast<std::size_t>(level)));
            CHECK(blocking.error() == doctest::Approx(e).epsilon(1e-12));
            ++(level == 0 ? level_zero : higher);
          }
        }
      }
    }
    MESSAGE(too_few << " too few, " << correlated << " correlated, " << level_zero
                    << " at level 0, " << higher << " higher");
    CHECK(too_few > 0);
    CHECK(correlated > 0);
    CHECK(level_zero > 0);
    CHECK(higher > 0);
  }
}
