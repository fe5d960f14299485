// Blocking analysis (beyond the article). See beyond/blocking.hpp for the
// method (Flyvbjerg and Petersen 1989), the rule (batch means, Schmeiser
// 1982; batches no shorter than the caller says) and its check (Jonsson
// 2018).
#include "beyond/blocking.hpp"

#include <cmath>
#include <limits>

namespace gas {

namespace {
constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
// The standard normal 99 % quantile: Jonsson's test at that level.
constexpr double test_quantile_z = 2.326348;
}  // namespace

double chi_squared_quantile(double degrees, double z) {
  // chi^2_m / m is close to the cube of a normal of mean 1 - 2/(9m) and
  // variance 2/(9m).
  const double v = 2 / (9 * degrees);
  const double root = 1 - v + z * std::sqrt(v);
  return degrees * root * root * root;
}

void BlockingAnalysis::add(double x) {
  if (count_ == 0) origin_ = x;
  ++count_;
  double value = x;
  for (std::size_t k = 0;; ++k) {
    if (k == levels_.size()) levels_.emplace_back();
    Level& level = levels_[k];
    // Welford: the block mean `value` joins level k.
    ++level.blocks;
    const double delta = value - level.mean;
    level.mean += delta / static_cast<double>(level.blocks);
    level.squares += delta * (value - level.mean);
    // Its product with the block before it (Jonsson's gamma).
    const double y = value - origin_;
    if (level.blocks == 1) {
      level.first = y;
    } else {
      level.products += level.last * y;
    }
    level.last = y;
    // Pair it with the block before it, if one is waiting: their mean is a
    // block of the next level.
    if (!level.waiting) {
      level.waiting = true;
      level.waiting_value = value;
      return;
    }
    level.waiting = false;
    value = (level.waiting_value + value) / 2;
  }
}

void BlockingAnalysis::clear() {
  count_ = 0;
  levels_.clear();
}

double BlockingAnalysis::mean() const {
  return count_ == 0 ? unknown : levels_[0].mean;
}

double BlockingAnalysis::level_error(const Level& level) const {
  if (level.blocks < 2) return unknown;
  const double n = static_cast<double>(level.blocks);
  return std::sqrt(level.squares / (n - 1) / n);
}

// gamma = (1/n) sum_{t < n} (y_t - m)(y_{t+1} - m), m the mean of the y:
// expanded, (1/n) [sum y_t y_{t+1} - (n + 1) m^2 + m (y_1 + y_n)].
double BlockingAnalysis::level_lag_one(const Level& level) const {
  if (level.blocks < 2) return unknown;
  const double n = static_cast<double>(level.blocks);
  const double m = level.mean - origin_;
  return (level.products - (n + 1) * m * m + m * (level.first + level.last)) / n;
}

double BlockingAnalysis::naive_error() const {
  return count_ < 2 ? unknown : level_error(levels_[0]);
}

double BlockingAnalysis::jonsson_m(std::size_t first, std::size_t last,
                                   std::size_t* terms) const {
  if (terms != nullptr) *terms = 0;
  if (first >= levels_.size() || levels_[first].blocks < 2) return unknown;
  double m = 0;
  for (std::size_t i = first; i <= last && i < levels_.size() && levels_[i].blocks >= 2;
       ++i) {
    const Level& level = levels_[i];
    const double n = static_cast<double>(level.blocks);
    const double sigma2 = level.squares / n;
    if (terms != nullptr) ++*terms;
    if (!(sigma2 > 0)) continue;  // equal block means: no correlation to see
    const double c = (n - 1) * sigma2 / (n * n) + level_lag_one(level);
    m += n * c * c / (sigma2 * sigma2);
  }
  return m;
}

int BlockingAnalysis::batch_level() const {
  // The highest level with at least fewest_blocks blocks (levels only get
  // fewer blocks going up).
  std::size_t top = 0;
  while (top < levels_.size() && levels_[top].blocks >= fewest_blocks) ++top;
  return static_cast<int>(top) - 1;
}

std::size_t BlockingAnalysis::batches() const {
  const int level = batch_level();
  return level < 0 ? 0 : levels_[static_cast<std::size_t>(level)].blocks;
}

// [anchor: error-rule]
ErrorStatus BlockingAnalysis::status() const {
  // 1. Batch means: fewest_blocks (16) to twice as many less one batches.
  const int batches = batch_level();
  if (batches < 0) return ErrorStatus::few_samples;
  const auto k = static_cast<std::size_t>(batches);
  // 2. Each batch at least shortest_batch_ samples.
  if ((std::size_t{1} << k) < shortest_batch_) return ErrorStatus::short_batches;
  // 3. Jonsson's test on the batches' level and the two below it, as far as
  //    their blocks are no shorter than rule 2's (a level rule 2 rules out
  //    is expected to look correlated).
  std::size_t first = k >= test_levels_below ? k - test_levels_below : 0;
  while (first < k && (std::size_t{1} << first) < shortest_batch_) ++first;
  std::size_t terms = 0;
  const double m = jonsson_m(first, k, &terms);
  if (!(m < chi_squared_quantile(static_cast<double>(terms), test_quantile_z)))
    return ErrorStatus::correlated_batches;
  return ErrorStatus::known;
}
// [/anchor: error-rule]

int BlockingAnalysis::chosen_level() const {
  return status() == ErrorStatus::known ? batch_level() : -1;
}

double BlockingAnalysis::batch_error() const {
  const int k = batch_level();
  return k < 0 ? unknown : level_error(levels_[static_cast<std::size_t>(k)]);
}

double BlockingAnalysis::error() const {
  const int k = chosen_level();
  return k < 0 ? unknown : level_error(levels_[static_cast<std::size_t>(k)]);
}

double BlockingAnalysis::statistical_inefficiency() const {
  const double ratio = error() / naive_error();
  return ratio * ratio;
}

std::vector<BlockingLevel> BlockingAnalysis::levels() const {
  std::vector<BlockingLevel> result;
  std::size_t size = 1;
  for (const Level& level : levels_) {
    if (level.blocks == 0) break;
    const double e = level_error(level);
    const double n = static_cast<double>(level.blocks);
    const bool two = level.blocks >= 2;
    result.push_back({size, level.blocks, e, two ? e / std::sqrt(2 * (n - 1)) : unknown,
                      two ? level.squares / n : unknown, level_lag_one(level)});
    size *= 2;
  }
  return result;
}

}  // namespace gas
