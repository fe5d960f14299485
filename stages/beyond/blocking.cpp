// Blocking analysis (beyond the article). See beyond/blocking.hpp for the
// method (Flyvbjerg and Petersen 1989) and the plateau rule.
#include "beyond/blocking.hpp"

#include <cmath>
#include <limits>

namespace gas {

namespace {
constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
}  // namespace

void BlockingAnalysis::add(double x) {
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

double BlockingAnalysis::naive_error() const {
  return count_ < 2 ? unknown : level_error(levels_[0]);
}

int BlockingAnalysis::chosen_level() const {
  // The usable levels: those with at least fewest_blocks blocks. Blocks only
  // get fewer going up, so they are levels 0 ... top - 1.
  std::size_t top = 0;
  while (top < levels_.size() && levels_[top].blocks >= fewest_blocks) ++top;
  // The lowest level k with confirming_levels usable levels above it, none of
  // which is above e_k by more than its own uncertainty d_j.
  for (std::size_t k = 0; k + confirming_levels < top; ++k) {
    const double e_k = level_error(levels_[k]);
    bool plateau = true;
    for (std::size_t j = k + 1; j <= k + confirming_levels && plateau; ++j) {
      const double e_j = level_error(levels_[j]);
      const double d_j =
          e_j / std::sqrt(2 * (static_cast<double>(levels_[j].blocks) - 1));
      plateau = e_j <= e_k + d_j;
    }
    if (plateau) return static_cast<int>(k);
  }
  return -1;
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
    const double d = level.blocks < 2
                         ? unknown
                         : e / std::sqrt(2 * (static_cast<double>(level.blocks) - 1));
    result.push_back({size, level.blocks, e, d});
    size *= 2;
  }
  return result;
}

}  // namespace gas
