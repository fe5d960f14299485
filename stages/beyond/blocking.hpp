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
// Article: none (the article's character screen and its figures:
// beyond/gas_statistics.hpp). That the article takes no time averages and
// gives them no errors is our reading. Everything here is beyond it.
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
//    (1982): the cost of few batches is small from eight to ten on, and
//    more than 30 gain little): the error is e_k of the highest level with
//    at least `fewest_blocks` = 16 blocks, so 16 to 31 batches, each 1/16
//    to 1/31 of the run. As the run grows the batches grow with it and
//    (mean - truth) / e_k tends to Student's t with n_k - 1 degrees of
//    freedom: root mean square 1.04 to 1.07 (with 8 to 15 batches it would
//    be 1.08 to 1.18, and its scatter over 40 runs twice as wide), beyond 3
//    errors 0.5 % to 0.9 % of the time.
// 2. Not before the batches are `shortest_batch` samples long (set by the
//    caller from what it knows of its samples; 1 unless set). A figure of a
//    gas in a box wanders with the box's slowest motions, heat flowing
//    between the middle of the table and its edges, whose correlation is
//    too faint to see in the run itself (lesson 14): the
//    statistics set it from the table's heat time, and for the mean speed
//    from 25 pair collisions per ball (beyond/gas_statistics).
// 3. Known only once the batches look uncorrelated: M. Jonsson's test
//    ("Standard error estimation by an automated blocking method", Phys.
//    Rev. E 98, 043304 (2018), Eq. (12) and its theorem). With sigma_i^2 =
//    (n_i - 1) s_i^2 / n_i and the lag-one autocovariance gamma_i = (1/n_i)
//    sum_t (y_t - mean)(y_{t+1} - mean) of level i's block means y,
//      M = sum over the levels i = k - 2, k - 1, k (as many as exist) of
//          n_i ((n_i - 1) sigma_i^2 / n_i^2 + gamma_i)^2 / sigma_i^4,
//    which for uncorrelated blocks is about chi-squared with as many degrees
//    of freedom as it has terms. Only the batches' own level and the two
//    below it (16 to 127 blocks): a level of a handful of blocks says
//    nothing (with 2 blocks a term is always 1/8); and of those only the
//    levels whose blocks are no shorter than rule 2's (a shorter one is
//    correlated by what the caller knows, and would blank the error for
//    it). The error is NaN while M exceeds chi-squared's 99 % quantile.
//    Measured (tests/test_blocking.cpp, "the test's false alarms and
//    power", 2000 series each): on independent normal samples it blanks the
//    error 0.2 % to 1.3 % of the time, at any length from 16 samples to
//    10^4. On AR(1) series x_{t+1} = phi x_t + noise, correlation time tau =
//    (1 + phi) / (2 (1 - phi)), it blanks nearly every error while a batch
//    is a few tau long (phi = 0.5 at 100 samples, batches of 4 = 2.7 tau:
//    97 %; phi = 0.9 at 300 and 1000 samples, batches of 16 and 32 = 1.7
//    and 3.4 tau: 100 %) and few once it is ten or more (phi = 0.9 at 3000,
//    128 = 13 tau: 13 %); the errors it lets through then scatter like
//    Student's t (root mean square 1.02 to 1.10). Shorter still it can
//    miss: at 16 samples, phi = 0.5 leaves 90 % of the errors, two times
//    too small. A straight ramp under noise as large as its whole rise is
//    caught in 60 % of series of 256 samples, all of 1000. A slow drift
//    buried in fast noise, like a gas's heat, it cannot see (its variance
//    1/2000 of the noise's, tau = 1000: 99 % of series of 3000 pass, their
//    errors 1.4 times too small): hence rule 2.
// So for independent samples the error is known from 16 samples on. On the
// gas itself (build/gas, data/reports/kinetic-seeds.md, "spread": 40 gases
// like data/large-1000.scene at T = 150 ... 12000) wherever this rule's
// error is shown (x - mean) / error scatters 0.98 to 1.16 over the seeds.
// (While the batches are short the statistics show a theory's error for
// some figures instead: beyond/gas_statistics.hpp, from_theory.)
//
// The chosen e_k is biased low by the correlation left between batches of
// length b = 2^k, a fraction of order tau / b (for a positively correlated
// series; high for an anticorrelated one).
#pragma once

#include <cstddef>
#include <vector>

namespace gas {

// Why an error is not known (NaN), or that it is.
enum class ErrorStatus {
  known,
  few_samples,         // fewer than fewest_blocks samples
  short_batches,       // the batches are shorter than shortest_batch samples
  correlated_batches,  // Jonsson's test sees the batches correlated
};

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
  // The fewest batches the error is taken from (see the rule above). (The
  // Lyapunov exponent, whose samples are anticorrelated, takes longer,
  // overlapping batches instead: beyond/overlapping_batches.hpp.)
  static constexpr std::size_t fewest_blocks = 16;
  // The levels Jonsson's test looks at: the batches' own and this many below.
  static constexpr std::size_t test_levels_below = 2;

  // Adds one sample. O(1) amortised (each sample climbs one level on
  // average), O(log n) worst case.
  void add(double x);
  // Forgets every sample (to restart the averages); keeps shortest_batch.
  void clear();
  // Rule 2: no error until the batches hold at least this many samples.
  void set_shortest_batch(std::size_t samples) { shortest_batch_ = samples; }
  std::size_t shortest_batch() const { return shortest_batch_; }

  std::size_t count() const { return count_; }  // samples so far
  // The mean of all samples so far (NaN if none).
  double mean() const;
  // The naive standard error sqrt(s^2 / n), as if the samples were
  // independent (NaN with fewer than 2 samples).
  double naive_error() const;
  // The standard error of the mean by the rule above; NaN ("not known")
  // before there are 16 samples, while the batches are shorter than
  // shortest_batch, or while they look correlated.
  double error() const;
  // Whether the error is known, and if not why.
  ErrorStatus status() const;
  // e_k of the batches' level whatever rules 2 and 3 say (NaN before 16
  // samples): what the batches alone would claim.
  double batch_error() const;
  // The batches' level, whether or not the error is known there (-1 before
  // there are 16 samples).
  int batch_level() const;
  // How many blocks the batches' level holds (0 before there are 16 samples).
  std::size_t batches() const;
  // The level the error was taken from, or -1 if the error is not known.
  int chosen_level() const;
  // Jonsson's M over levels first ... last (those with at least 2 blocks;
  // NaN if level `first` has fewer), and the number of its terms, the
  // degrees of freedom of its chi-squared.
  double jonsson_m(std::size_t first, std::size_t last,
                   std::size_t* terms = nullptr) const;
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
  std::size_t shortest_batch_ = 1;
  std::vector<Level> levels_;
};

// The p-quantile of the chi-squared distribution with `degrees` degrees of
// freedom, by Wilson and Hilferty's cube-root normal approximation (Proc.
// Natl. Acad. Sci. 17, 684 (1931)); `z` is the standard normal p-quantile.
double chi_squared_quantile(double degrees, double z);

}  // namespace gas
