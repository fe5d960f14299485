// Blocking analysis (beyond the article): the mean of a correlated series and
// an honest standard error for it, worked out as the samples arrive.
//
// What this file does: takes a series of equal-weight samples x_1, x_2, ...
// (the wall push per collision, say, whose neighbours are correlated) and
// keeps, at every blocking level k = 0, 1, 2, ..., the statistics of the
// means of blocks of 2^k consecutive samples (H. Flyvbjerg and H. G. Petersen,
// "Error estimates on averages of correlated data", J. Chem. Phys. 91, 461
// (1989)). Neighbouring blocks are paired as soon as both exist, so a sample
// costs O(1) amortised time and the whole analysis O(log n) memory. From the
// levels it chooses the standard error of the mean by the plateau rule below,
// and says "not known" (NaN) until the rule can be applied.
// Article: none; the article averages nothing. Everything here is beyond it.
// Lesson: lessons/11-kinetic-theory.md
//
// Why blocks: for a correlated series the naive error sqrt(s^2 / n) is too
// small by the square root of the statistical inefficiency (for a series with
// correlation time tau, about 2 tau). The means of blocks much longer than tau
// are nearly independent, so their naive error is the right one. The estimate
// rises with the block length and levels off (the plateau) once the blocks are
// long enough; it is known only when the plateau is seen.
//
// The rule (documented here because the screen's "±" depends on it). Level k
// holds n_k blocks; its estimate of the standard error of the mean is
//   e_k = sqrt(s_k^2 / n_k),   s_k^2 the sample variance of the block means,
// and e_k has its own statistical uncertainty d_k = e_k / sqrt(2 (n_k - 1))
// (Flyvbjerg and Petersen). Only levels with at least `fewest_blocks` = 16
// blocks are used. The chosen level is the lowest level k that has
// `confirming_levels` = 2 usable levels above it, neither of which is above
// e_k by more than its own uncertainty (e_j <= e_k + d_j for j = k+1, k+2):
// from k on the estimates have stopped rising. If no level qualifies (the
// estimates still rise at the top, or there are too few samples) the error is
// NaN. So for independent samples an error appears after 16 * 2^2 = 64
// samples (at 64 ... 200 samples it is still NaN about one time in ten, when
// the top levels happen to fluctuate up); for a series with correlation time
// tau, once blocks of a few tau fit 64 times. The rule was tuned on AR(1)
// series (the cases of tests/test_blocking.cpp, 200 seeds each): comparing
// with the next two levels, by one d_j, was about 2 % low for phi = 0.9 and
// n = 2^16 and never NaN in long runs; comparing with every higher level made
// the error flicker to NaN in long runs (the top levels are noisy), and
// allowing 2 d_j stopped too early (6 % low). M. Jonsson's automated test
// (Phys. Rev. E 98, 043304 (2018)) was not used: it needs the whole series,
// cut to a power of two, and chi-squared quantiles, and we did not check its
// formula against the paper.
//
// The chosen e_k is biased low by the correlation left between blocks of
// length b = 2^k, a fraction of order tau / b; the rule picks k where that is
// no larger than the statistical uncertainty d_k.
#pragma once

#include <cstddef>
#include <vector>

namespace gas {

// One blocking level: blocks of 2^level samples.
struct BlockingLevel {
  std::size_t block_size = 1;  // samples per block, 2^level
  std::size_t blocks = 0;      // complete blocks so far, n_k
  double error = 0;            // e_k: standard error of the mean from them (NaN if < 2)
  double error_of_error = 0;   // d_k = e_k / sqrt(2 (n_k - 1)) (NaN if < 2)
};

class BlockingAnalysis {
 public:
  // The fewest blocks a level needs to be used, and the usable levels that
  // must lie above the chosen one (see the rule above).
  static constexpr std::size_t fewest_blocks = 16;
  static constexpr std::size_t confirming_levels = 2;

  // Adds one sample. O(1) amortised (each sample climbs one level on
  // average), O(log n) worst case.
  void add(double x);
  // Forgets every sample (to restart the averages).
  void clear();

  std::size_t count() const { return count_; }  // samples so far
  // The mean of all samples so far (NaN if none).
  double mean() const;
  // The naive standard error sqrt(s^2 / n), as if the samples were
  // independent (NaN with fewer than 2 samples).
  double naive_error() const;
  // The standard error of the mean chosen by the plateau rule; NaN ("not
  // known") until the rule finds a confirmed plateau.
  double error() const;
  // The level the error was taken from, or -1 if the error is not known.
  int chosen_level() const;
  // (error / naive error)^2: the statistical inefficiency, about 2 tau for a
  // series with integrated correlation time tau (1 for independent samples);
  // NaN while the error is not known.
  double statistical_inefficiency() const;
  // Every level that has at least one complete block, lowest first (for the
  // lesson's table of e_k against the block size).
  std::vector<BlockingLevel> levels() const;

 private:
  // The statistics of one level: Welford's running mean and sum of squared
  // deviations (no cancellation when the mean is large against the spread),
  // and the block waiting for its partner.
  struct Level {
    std::size_t blocks = 0;
    double mean = 0;
    double squares = 0;  // sum of (block mean - mean)^2
    bool waiting = false;
    double waiting_value = 0;
  };
  double level_error(const Level& level) const;

  std::size_t count_ = 0;
  std::vector<Level> levels_;
};

}  // namespace gas
