// Blocking analysis (beyond the article): the mean of a correlated series and
// an honest standard error for it, worked out as the samples arrive.
//
// What this file does: takes a series of equal-weight samples x_1, x_2, ...
// (the wall push over a stretch of collisions, say, whose neighbours are
// correlated) and keeps, at every blocking level k = 0, 1, 2, ..., the
// statistics of the means of blocks of 2^k consecutive samples (H. Flyvbjerg
// and H. G. Petersen, "Error estimates on averages of correlated data",
// J. Chem. Phys. 91, 461 (1989)): their variance and the covariance of each
// block mean with the next. Neighbouring blocks are paired as soon as both
// exist, so a sample costs O(1) amortised time and the whole analysis
// O(log n) memory. From the levels it gives the standard error of the mean by
// the rule below, and says "not known" (NaN) until the rule can be applied.
// Article: none; the article averages nothing. Everything here is beyond it.
// Lesson: lessons/14-error-bars.md
//
// Why blocks: for a correlated series the naive error sqrt(s^2 / n) is wrong
// by the square root of the statistical inefficiency g = 1 + 2 sum of the
// correlations (for a series with correlation time tau, about 2 tau; below 1
// for an anticorrelated series, such as the push on a wall, whose hits
// alternate with flights across the table). The means of blocks much longer
// than the correlations are nearly independent, so their naive error is the
// right one.
//
// The rule (documented here because the screen's "±" depends on it). Level k
// holds n_k blocks; its estimate of the standard error of the mean is
//   e_k = sqrt(s_k^2 / n_k),   s_k^2 the (n_k - 1) sample variance of the block means,
// with its own statistical uncertainty d_k = e_k / sqrt(2 (n_k - 1)).
// 1. Batch means with a fixed number of batches (B. Schmeiser, "Batch size
//    effects in the analysis of simulation output", Oper. Res. 30, 556
//    (1982)): the error is e_k of the highest level with at least
//    `fewest_blocks` = 8 blocks, so 8 to 15 batches, each 1/8 to 1/15 of the
//    run. As the run grows the batches grow with it, their correlation dies
//    away whatever its time, and (mean - truth) / e_k tends to Student's t
//    with n_k - 1 degrees of freedom (root mean square 1.08 to 1.18; beyond
//    3 errors 1 % to 2 % of the time against 0.3 % for a normal). Fewer
//    batches would be noisier; more would be shorter, and the slow modes of
//    a gas (heat diffusing across the table: hundreds of time units at
//    N = 1024) leave too-short batches correlated and their error too small.
// 2. Known only once the batches are seen to be uncorrelated: M. Jonsson's
//    test ("Standard error estimation by an automated blocking method",
//    Phys. Rev. E 98, 043304 (2018), Eq. (12) and its theorem). With
//    sigma_i^2 = (n_i - 1) s_i^2 / n_i and the lag-one autocovariance
//    gamma_i = (1/n_i) sum_t (y_t - mean)(y_{t+1} - mean) of level i's block
//    means y,
//      M_j = sum over levels i >= j with n_i >= 2 of
//            n_i ((n_i - 1) sigma_i^2 / n_i^2 + gamma_i)^2 / sigma_i^4,
//    which for uncorrelated block means is chi-squared with as many degrees
//    of freedom as it has terms. It is taken from the level below the
//    batches (16 to 31 blocks) up: the batches' own level and those above
//    it have too few blocks to see anything (a straight ramp passes them).
//    The error is NaN while M_j exceeds the 99.9 % quantile (a false alarm
//    one time in a thousand; Jonsson picks a level at 99 %, where a false
//    alarm only moves one level up, but here it blanks an error). It catches
//    a ramp, and AR(1) with phi = 0.99 (tau = 100) at 1000 samples (batches
//    of 64) two times in three, never at 10^5. Jonsson's own rule, the
//    lowest level that passes at 99 %, is not used for the error itself: it
//    stops too early on the gas's slow modes (measured: errors of the bulk Z
//    1.6 times too small at N = 1024, T = 800), where batch means hold (1.1).
//    (The test was checked against two implementations that cite Eq. (12),
//    Rimu.jl's and the paper's own code at github.com/computative/block,
//    which compares M_j with the quantile of j + 1 degrees of freedom, not
//    of its number of terms as the theorem says; we follow the theorem. We
//    did not have the paper's full text.)
// So for independent samples the error is known from 8 samples on. The rule
// was chosen on build/gas's own samples (24 lattice runs at eta = 0.5, every
// quantity's error against the scatter of its mean over the runs) and is
// checked on AR(1) series with phi > 0 and < 0 in tests/test_blocking.cpp.
//
// The chosen e_k is biased low by the correlation left between batches of
// length b = 2^k, a fraction of order tau / b (for a positively correlated
// series; high for an anticorrelated one).
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
  double variance = 0;         // sigma_k^2: their variance, over n_k (NaN if < 2)
  double lag_one = 0;          // gamma_k: each with the next, over n_k (NaN if < 2)
};

class BlockingAnalysis {
 public:
  // The fewest blocks the chosen level has (see the rule above).
  static constexpr std::size_t fewest_blocks = 8;

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
  // The standard error of the mean by the rule above; NaN ("not known")
  // before there are 8 samples, or while the batches are still correlated.
  double error() const;
  // The level the error was taken from, or -1 if the error is not known.
  int chosen_level() const;
  // Jonsson's M_k over the levels from k up (NaN if level k has < 2 blocks),
  // and the number of its terms, the degrees of freedom of its chi-squared.
  double jonsson_m(std::size_t k, std::size_t* terms = nullptr) const;
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
  // the products of neighbouring block means, and the block waiting for its
  // partner. The products, the first and the last block are taken from the
  // first sample (`origin_`), so that a large mean does not swamp them.
  struct Level {
    std::size_t blocks = 0;
    double mean = 0;
    double squares = 0;   // sum of (block mean - mean)^2
    double products = 0;  // sum of y_t y_{t+1}, y = block mean - origin
    double first = 0;     // y_1
    double last = 0;      // y_{n_k}
    bool waiting = false;
    double waiting_value = 0;
  };
  double level_error(const Level& level) const;
  double level_lag_one(const Level& level) const;

  std::size_t count_ = 0;
  double origin_ = 0;  // the first sample
  std::vector<Level> levels_;
};

// The p-quantile of the chi-squared distribution with `degrees` degrees of
// freedom, by Wilson and Hilferty's cube-root normal approximation (Proc.
// Natl. Acad. Sci. 17, 684 (1931)); `z` is the standard normal p-quantile.
double chi_squared_quantile(double degrees, double z);

}  // namespace gas
