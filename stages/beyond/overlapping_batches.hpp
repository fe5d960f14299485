// Overlapping batch means (beyond the article): the mean of a correlated
// series and its standard error from every batch of b consecutive samples,
// overlapping, not only the n / b that do not overlap.
//
// What this file does: keeps the samples x_1 ... x_n and, for a batch length
// b about n / batches_per_run, the batches x_j+1 ... x_j+b for every start
// j = 0 ... n - b (n - b + 1 of them, overlapping). With Y_j their means and
// Y the mean of all samples, the standard error of Y is
//   e^2 = b / ((n - b + 1) (n - b)) * sum over j of (Y_j - Y)^2
// (M. S. Meketon and B. Schmeiser, "Overlapping batch means: something for
// nothing?", Proceedings of the 1984 Winter Simulation Conference): for
// independent samples of variance s^2 its expectation is s^2 / n exactly
// (the factor makes it so; tests/test_overlapping_batches.cpp checks it),
// and for a correlated series it tends to the true error as b grows past
// the correlations. Used for the Lyapunov exponent (beyond/lyapunov.hpp),
// whose samples are anticorrelated over tens of samples: its batches must
// be long, a sixth of the run, and non-overlapping batches that long would
// be six, too few to say their own scatter.
// Article: none. Everything here is beyond it.
// Lesson: lessons/15-chaos.md
//
// Why overlapping: with the same b, the overlapping batches' e^2 scatters
// less than that of the n / b separate batches (beyond/blocking.hpp): its
// variance is about 2/3 of theirs (Meketon and Schmeiser, for long runs;
// 0.68 in the test, independent samples, n / b = 6), as if it had half as
// many batches again.
// The batch length follows the run: b is n / batches_per_run, renewed when
// n / batches_per_run has grown by an eighth past it (by one while b < 8).
// A renewal sums every batch afresh, O(n); between renewals each sample adds
// one batch in O(1); a run of n samples costs O(n log n) in all.
//
// Assumptions: the samples are of one stationary series, of equal weight.
#pragma once

#include <cstddef>
#include <vector>

namespace gas {

class OverlappingBatchMeans {
 public:
  // b is n / batches_per_run, and never shorter than shortest_batch: no error
  // before n = batches_per_run * shortest_batch samples.
  OverlappingBatchMeans(std::size_t batches_per_run, std::size_t shortest_batch);

  void add(double x);  // one sample; O(1) but at a renewal of b, O(n)
  void clear();        // forgets every sample

  std::size_t count() const { return samples_.size(); }  // n
  double mean() const;                                   // Y (NaN if no sample)
  // The standard error e of the mean (NaN before there are
  // batches_per_run * shortest_batch samples).
  double error() const;
  std::size_t batch_length() const { return batch_; }  // b, 0 before the error is known

 private:
  void renew_batches();  // b from n, and every batch of b summed again
  void add_batch(double sum);

  std::size_t batches_per_run_;
  std::size_t shortest_batch_;
  double origin_ = 0;            // x_1
  std::vector<double> samples_;  // x_i - x_1: a large mean does not swamp the sums
  double total_ = 0;             // their sum
  std::size_t batch_ = 0;        // b
  double batch_sum_ = 0;         // the sum of the last b samples
  // Welford's running mean and sum of squared deviations of the batches'
  // sums: no cancellation however long the run.
  std::size_t batches_ = 0;
  double batch_mean_ = 0;
  double batch_squares_ = 0;
};

}  // namespace gas
