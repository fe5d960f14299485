// Overlapping batch means (beyond the article). See
// beyond/overlapping_batches.hpp.
#include "beyond/overlapping_batches.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gas {

OverlappingBatchMeans::OverlappingBatchMeans(std::size_t batches_per_run,
                                             std::size_t shortest_batch)
    : batches_per_run_(std::max<std::size_t>(batches_per_run, 2)),
      shortest_batch_(std::max<std::size_t>(shortest_batch, 1)) {}

void OverlappingBatchMeans::clear() {
  samples_.clear();
  total_ = 0;
  batch_ = 0;
  batch_sum_ = 0;
  batches_ = 0;
  batch_mean_ = 0;
  batch_squares_ = 0;
}

void OverlappingBatchMeans::add(double x) {
  if (samples_.empty()) origin_ = x;
  samples_.push_back(x - origin_);
  total_ += samples_.back();
  const std::size_t n = samples_.size();
  const std::size_t wanted = n / batches_per_run_;  // b as n asks
  if (wanted < shortest_batch_) return;
  // A new b once n / batches_per_run has grown an eighth past it (by one
  // while b < 8).
  if (batch_ == 0 || wanted >= batch_ + std::max<std::size_t>(batch_ / 8, 1)) {
    renew_batches();
    return;
  }
  // The batch ending at the new sample: the last b samples.
  batch_sum_ += samples_[n - 1] - samples_[n - 1 - batch_];
  add_batch(batch_sum_);
}

void OverlappingBatchMeans::renew_batches() {
  const std::size_t n = samples_.size();
  batch_ = n / batches_per_run_;
  batches_ = 0;
  batch_mean_ = 0;
  batch_squares_ = 0;
  batch_sum_ = 0;
  for (std::size_t i = 0; i < batch_; ++i) batch_sum_ += samples_[i];
  add_batch(batch_sum_);
  for (std::size_t i = batch_; i < n; ++i) {
    batch_sum_ += samples_[i] - samples_[i - batch_];
    add_batch(batch_sum_);
  }
}

void OverlappingBatchMeans::add_batch(double sum) {
  ++batches_;
  const double delta = sum - batch_mean_;
  batch_mean_ += delta / static_cast<double>(batches_);
  batch_squares_ += delta * (sum - batch_mean_);
}

double OverlappingBatchMeans::mean() const {
  if (samples_.empty()) return std::numeric_limits<double>::quiet_NaN();
  return origin_ + total_ / static_cast<double>(samples_.size());
}

double OverlappingBatchMeans::error() const {
  if (batch_ == 0) return std::numeric_limits<double>::quiet_NaN();
  const auto n = static_cast<double>(samples_.size());
  const auto b = static_cast<double>(batch_);
  // The sum over the batches of (batch sum - b Y)^2: about their own mean,
  // and the shift from it to b Y.
  const double shift = batch_mean_ - b * total_ / n;
  const double squares = batch_squares_ + static_cast<double>(batches_) * shift * shift;
  // e^2 = b / ((n - b + 1)(n - b)) * sum (Y_j - Y)^2, with Y_j - Y = that / b.
  return std::sqrt(squares / (b * (n - b + 1) * (n - b)));
}

}  // namespace gas
