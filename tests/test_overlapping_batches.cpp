// Tests for overlapping batch means (stages/beyond/overlapping_batches.*,
// lessons/15-chaos.md): the formula batch by batch, its expectation for
// independent samples, its scatter beside separate batches', and a
// correlated series whose true error is known in closed form.
//
// Every series is seeded, so each check gives the same result every time;
// each tolerance says where it comes from.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "beyond/overlapping_batches.hpp"

namespace {

// e by the definition, summing every batch of b afresh: b / ((n - b + 1)
// (n - b)) times the sum over the n - b + 1 batches of (batch mean - mean)^2.
double error_by_definition(const std::vector<double>& x, std::size_t b) {
  const std::size_t n = x.size();
  double mean = 0;
  for (const double v : x) mean += v;
  mean /= static_cast<double>(n);
  double squares = 0;
  for (std::size_t j = 0; j + b <= n; ++j) {
    double sum = 0;
    for (std::size_t i = j; i < j + b; ++i) sum += x[i];
    const double d = sum / static_cast<double>(b) - mean;
    squares += d * d;
  }
  const auto nn = static_cast<double>(n);
  const auto bb = static_cast<double>(b);
  return std::sqrt(bb * squares / ((nn - bb + 1) * (nn - bb)));
}

// n independent standard normal samples.
std::vector<double> normal_series(std::size_t n, std::mt19937_64& random) {
  std::normal_distribution<double> normal(0, 1);
  std::vector<double> x(n);
  for (double& v : x) v = normal(random);
  return x;
}

gas::OverlappingBatchMeans fed(const std::vector<double>& x, std::size_t per_run,
                               std::size_t shortest) {
  gas::OverlappingBatchMeans batches(per_run, shortest);
  for (const double v : x) batches.add(v);
  return batches;
}

}  // namespace

TEST_SUITE("lyapunov") {
  TEST_CASE("overlapping batches: the error is Meketon and Schmeiser's sum at every n") {
    // Samples with a mean far from 0 (as the exponent's, 0.5 to 1 against a
    // spread of 0.25), and b renewed as n grows: after every sample the
    // running sums give what summing every batch afresh gives. 1e-12
    // relative: a few hundred sums of numbers of order 1 round at 1e-14.
    std::mt19937_64 random(15);
    const std::vector<double> noise = normal_series(300, random);
    gas::OverlappingBatchMeans batches(6, 4);
    std::vector<double> x;
    std::size_t renewals = 0, last_b = 0;
    for (const double v : noise) {
      x.push_back(3 + 0.25 * v);
      batches.add(x.back());
      const std::size_t n = x.size();
      double mean = 0;
      for (const double y : x) mean += y;
      CHECK(batches.mean() ==
            doctest::Approx(mean / static_cast<double>(n)).epsilon(1e-14));
      const std::size_t b = batches.batch_length();
      if (n < 24) {  // 6 batches of at least 4
        CHECK(b == 0);
        CHECK(std::isnan(batches.error()));
        continue;
      }
      // b follows n / 6, renewed when n / 6 has grown an eighth past it (by
      // one while b < 8).
      CHECK(b <= n / 6);
      CHECK(n / 6 < b + std::max<std::size_t>(b / 8, 1));
      if (b != last_b) ++renewals;
      last_b = b;
      CHECK(batches.error() == doctest::Approx(error_by_definition(x, b)).epsilon(1e-12));
    }
    // b = 4, 5, ..., 16, then 18, 20, 22, 24, 27, 30, 33, 37, 41, 46: 23
    // lengths.
    CHECK(renewals == 23);
    batches.clear();
    CHECK(batches.count() == 0);
    CHECK(std::isnan(batches.error()));
    CHECK(batches.batch_length() == 0);
  }

  TEST_CASE("overlapping batches: independent samples, the error's square is s^2 / n") {
    // 4000 series of 96 independent samples of variance 1, b = 16: the mean
    // of n e^2 is 1 (the factor n b / ((n - b + 1)(n - b)) makes it exact).
    // Its spread per series is about sqrt(2 / 7.5) = 0.52, so the mean of
    // 4000 scatters by 0.008: 0.03 is about four of that. Without the factor
    // n / (n - b) (the plain average over the n - b + 1 batches) it would be
    // 1 - 16/96 = 0.83.
    //
    // Beside them, the same series cut into 6 separate batches of 16: n e^2
    // scatters like chi-squared with 5 degrees of freedom over 5, variance
    // 0.4. The overlapping batches' variance is below that: about 2/3 of it
    // for long runs (Meketon and Schmeiser), measured here at n / b = 6.
    std::mt19937_64 random(1984);
    const int series = 4000;
    double sum = 0, squares = 0, separate_sum = 0, separate_squares = 0;
    for (int s = 0; s < series; ++s) {
      const std::vector<double> x = normal_series(96, random);
      const gas::OverlappingBatchMeans batches = fed(x, 6, 16);
      REQUIRE(batches.batch_length() == 16);
      const double v = 96 * batches.error() * batches.error();
      sum += v;
      squares += v * v;
      // Separate batches of 16: their means' sample variance, over 6.
      std::vector<double> means(6, 0);
      for (std::size_t i = 0; i < 96; ++i) means[i / 16] += x[i] / 16;
      double m = 0;
      for (const double y : means) m += y / 6;
      double var = 0;
      for (const double y : means) var += (y - m) * (y - m) / 5;
      const double w = 96 * var / 6;
      separate_sum += w;
      separate_squares += w * w;
    }
    const double mean = sum / series;
    CHECK(mean == doctest::Approx(1).epsilon(0.03));
    const double variance = squares / series - mean * mean;
    const double separate_mean = separate_sum / series;
    const double separate_variance =
        separate_squares / series - separate_mean * separate_mean;
    // The separate batches' variance is 0.4 (0.4 +- 0.02 over 4000 series,
    // the sampling error of a variance of chi-squared(5)/5).
    CHECK(separate_variance == doctest::Approx(0.4).epsilon(0.15));
    const double ratio = variance / separate_variance;
    MESSAGE("overlapping over separate batches, variance of n e^2: " << ratio);
    // About 2/3 (0.6 to 0.7 at n / b = 6); each variance known to some 5 %,
    // so the ratio to 10 %: within 0.5 and 0.8. Separate batches (the same
    // variance as the others) would give 1.
    CHECK(ratio > 0.5);
    CHECK(ratio < 0.8);
  }

  TEST_CASE("overlapping batches: a correlated series gets its true error") {
    // AR(1), x_{t+1} = 0.9 x_t + sqrt(1 - 0.81) e_t (variance 1, correlation
    // time tau = 9.5): the variance of the mean of n samples is
    // (1/n)[(1 + phi)/(1 - phi) - 2 phi (1 - phi^n) / (n (1 - phi)^2)],
    // 19 / n for long series, against the naive 1 / n. 300 series of 6000
    // samples, b about 1000 (929, set at n = 5574 as an eighth past 826): the
    // mean of e^2 over the truth is 1, less a bias of order 2 tau / b = 2 %
    // (the correlation left between batches). Each
    // series' ratio scatters by about sqrt(2 / 7.5) = 0.52, the mean of 300
    // by 0.03: within 0.1 of 1. The naive error would give 1/19.
    std::mt19937_64 random(9);
    std::normal_distribution<double> normal(0, 1);
    const double phi = 0.9, n = 6000;
    const double truth = ((1 + phi) / (1 - phi) - 2 * phi * (1 - std::pow(phi, n)) /
                                                      (n * (1 - phi) * (1 - phi))) /
                         n;
    double sum = 0;
    const int series = 300;
    for (int s = 0; s < series; ++s) {
      gas::OverlappingBatchMeans batches(6, 16);
      double x = normal(random);
      for (int i = 0; i < 6000; ++i) {
        batches.add(x);
        x = phi * x + std::sqrt(1 - phi * phi) * normal(random);
      }
      REQUIRE(batches.batch_length() == 929);
      sum += batches.error() * batches.error() / truth;
    }
    CHECK(sum / series == doctest::Approx(1).epsilon(0.1));
  }
}
