// The structure of the fluid. See beyond/fluid_structure.hpp and
// lessons/13-box-and-bulk.md.
#include "beyond/fluid_structure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>

#include "beyond/cell_layout.hpp"
#include "beyond/hard_disc_fluid.hpp"

namespace gas {
namespace {

// The mean of s^power over a bin s0 ... s1 (s in radii from contact), each s
// weighted by `base` + s: the length of a circle of radius 2a + s for a shell
// (base 2), 1 for a strip along a straight wall (base infinite: plain mean).
double bin_mean(int power, double s0, double s1, double base) {
  auto integral = [](int p, double s) { return std::pow(s, p + 1) / (p + 1); };
  if (std::isinf(base)) return (integral(power, s1) - integral(power, s0)) / (s1 - s0);
  return (base * (integral(power, s1) - integral(power, s0)) + integral(power + 1, s1) -
          integral(power + 1, s0)) /
         (base * (s1 - s0) + (s1 * s1 - s0 * s0) / 2);
}

double fitted(const std::vector<double>& weights, const std::vector<double>& values) {
  double sum = 0;
  for (std::size_t k = 0; k < weights.size(); ++k) sum += weights[k] * values[k];
  return sum;
}

}  // namespace

// [anchor: contact-fit]
std::vector<double> contact_weights(int bins, int degree, double width, double base) {
  const auto terms = static_cast<std::size_t>(degree + 1);
  // M_km: the bin mean of s^m; the normal equations (M^T M) c = M^T y,
  // solved for the rows of (M^T M)^-1 M^T by Gauss-Jordan elimination.
  std::vector<std::vector<double>> m(static_cast<std::size_t>(bins),
                                     std::vector<double>(terms));
  for (int k = 0; k < bins; ++k)
    for (std::size_t p = 0; p < terms; ++p)
      m[k][p] = bin_mean(static_cast<int>(p), k * width, (k + 1) * width, base);
  // [M^T M | M^T]
  std::vector<std::vector<double>> a(terms, std::vector<double>(terms + bins, 0.0));
  for (std::size_t i = 0; i < terms; ++i) {
    for (int k = 0; k < bins; ++k) {
      for (std::size_t j = 0; j < terms; ++j) a[i][j] += m[k][i] * m[k][j];
      a[i][terms + k] = m[k][i];
    }
  }
  for (std::size_t i = 0; i < terms; ++i) {
    std::size_t pivot = i;
    for (std::size_t r = i + 1; r < terms; ++r)
      if (std::abs(a[r][i]) > std::abs(a[pivot][i])) pivot = r;
    std::swap(a[i], a[pivot]);
    const double diagonal = a[i][i];
    for (double& x : a[i]) x /= diagonal;
    for (std::size_t r = 0; r < terms; ++r) {
      if (r == i) continue;
      const double factor = a[r][i];
      for (std::size_t j = 0; j < a[r].size(); ++j) a[r][j] -= factor * a[i][j];
    }
  }
  return {a[0].begin() + static_cast<std::ptrdiff_t>(terms), a[0].end()};
}
// [/anchor: contact-fit]

FluidStructure::FluidStructure(const Gas& gas, const Region& interior, bool curves)
    : interior_(interior),
      radius_(gas.radius),
      width_(gas.width),
      bin_(structure_bin_radii * gas.radius),
      balls_(gas.balls.size()),
      curves_(curves),
      pair_weights_(
          contact_weights(contact_bins, contact_fit_degree, structure_bin_radii, 2.0)),
      wall_weights_(contact_weights(contact_bins, contact_fit_degree, structure_bin_radii,
                                    std::numeric_limits<double>::infinity())) {
  // The bins: those of the fits, or the whole curves. The walls' bins stop
  // at the middle of the table, where the two walls' strips meet.
  auto count = [](double radii) {
    return static_cast<std::size_t>(std::lround(radii / structure_bin_radii));
  };
  std::size_t pair_bins = contact_bins, wall_bins = contact_bins;
  if (curves_) {
    pair_bins = count(pair_curve_radii - 2);
    const double middle = (gas.width - 2 * gas.radius) / 2;
    wall_bins = std::min(count(wall_profile_radii),
                         static_cast<std::size_t>(std::floor(middle / bin_)));
    pair_bins_.resize(pair_bins);
    wall_bins_.resize(wall_bins);
  }
  reach_ = 2 * radius_ + static_cast<double>(pair_bins) * bin_;
  // Cells reach_ across, up to two per ball (a cell a third larger for many
  // balls would hold nearly twice the centres to compare).
  cells_ =
      lay_out_cells(gas.width, gas.height, reach_, 2 * static_cast<double>(balls_) + 16);
  pair_counts_.assign(pair_bins, 0.0);
  wall_counts_.assign(std::max<std::size_t>(wall_bins, contact_bins), 0.0);
}

void FluidStructure::restart(double time) {
  start_ = time;
  next_ = time + spacing_;
  events_ = 0;
  pair_contact_.clear();
  wall_contact_.clear();
  pair_contact_minus_theory_.clear();
  for (BlockingAnalysis& b : pair_bins_) b.clear();
  for (BlockingAnalysis& b : wall_bins_) b.clear();
}

void FluidStructure::take_snapshots(const Gas& gas, double time) {
  if (interior_.empty() || balls_ == 0) return;
  if (!(spacing_ > 0)) {
    // The spacing: the time of the first N events, about one collision a ball.
    if (++events_ < balls_ || !(time > start_)) return;
    spacing_ = time - start_;
    next_ = time + spacing_;
    return;
  }
  for (; next_ <= time; next_ += spacing_) take_snapshot(gas, next_);
}

// [anchor: structure-snapshot]
void FluidStructure::take_snapshot(const Gas& gas, double time) {
  const double a = radius_;
  centres_.resize(gas.balls.size());
  for (std::size_t i = 0; i < centres_.size(); ++i)
    centres_[i] = centre_at(gas.balls[i], time);

  // The walls x = 0 and x = A1: the centres in strips `bin_` wide from each
  // wall's limit (x = a, x = A1 - a), for y inside the interior's range;
  // density = count / (2 walls x strip area).
  std::fill(wall_counts_.begin(), wall_counts_.end(), 0.0);
  for (const Point& p : centres_) {
    if (p.y < interior_.y_min || p.y > interior_.y_max) continue;
    const double gap = std::min(p.x - a, width_ - a - p.x);  // d, from the limit
    const double k = gap / bin_;  // its bin: the whole part (k >= 0: the floor)
    if (k >= 0 && k < static_cast<double>(wall_counts_.size()))
      wall_counts_[static_cast<std::size_t>(k)] += 1;
  }
  const double strip_area = 2 * (interior_.y_max - interior_.y_min) * bin_;
  for (double& count : wall_counts_) count /= strip_area;  // now n(d)
  wall_contact_.add(fitted(wall_weights_, wall_counts_));
  for (std::size_t k = 0; k < wall_bins_.size(); ++k) wall_bins_[k].add(wall_counts_[k]);

  // Pairs: each ball of the interior with every ball at 2a ... reach_ from
  // it; g in a shell is the count over what a uniform gas of the interior's
  // density would put there. Each pair is found once, in one cell or two
  // neighbouring ones, and counts once for each of its balls inside.
  sort_by_cell();
  std::fill(pair_counts_.begin(), pair_counts_.end(), 0.0);
  double inside = 0;
  for (const double in : inside_) inside += in;
  const int columns = cells_.columns, rows = cells_.rows;
  for (int row = 0; row < rows; ++row) {
    for (int column = 0; column < columns; ++column) {
      const auto cell = static_cast<std::size_t>(row * columns + column);
      const std::size_t end = cell_start_[cell + 1];
      for (std::size_t i = cell_start_[cell]; i < end; ++i) {
        // Its own cell's later centres, the next cell along the row, and
        // the three of the next row: every neighbour once.
        count_pairs(i, i + 1, end);
        if (column + 1 < columns) count_pairs(i, end, cell_start_[cell + 2]);
        if (row + 1 == rows) continue;
        const auto above = cell + static_cast<std::size_t>(columns);
        const std::size_t from = cell_start_[column > 0 ? above - 1 : above];
        const std::size_t to = cell_start_[column + 1 < columns ? above + 2 : above + 1];
        count_pairs(i, from, to);  // three cells' runs follow each other
      }
    }
  }
  if (!(inside > 0)) return;
  const double density = inside / interior_.area();
  for (std::size_t k = 0; k < pair_counts_.size(); ++k) {
    const double r0 = 2 * a + static_cast<double>(k) * bin_, r1 = r0 + bin_;
    pair_counts_[k] /= inside * density * std::numbers::pi * (r1 * r1 - r0 * r0);
  }
  const double contact = fitted(pair_weights_, pair_counts_);
  pair_contact_.add(contact);
  pair_contact_minus_theory_.add(
      contact - hard_disc_fluid_contact_value(density * std::numbers::pi * a * a));
  for (std::size_t k = 0; k < pair_bins_.size(); ++k) pair_bins_[k].add(pair_counts_[k]);
}
// [/anchor: structure-snapshot]

// The centres sorted by cell: counted per cell, each cell's run placed
// after the last one's, then filed in.
void FluidStructure::sort_by_cell() {
  const auto cell_count =
      static_cast<std::size_t>(cells_.columns) * static_cast<std::size_t>(cells_.rows);
  cell_start_.assign(cell_count + 1, 0);
  cell_of_.resize(centres_.size());
  // A centre's column and row: its coordinate over the cell's side, within
  // the table's cells, cut to a whole number (the layout's column_of and
  // row_of, without their floor: the number is never negative here).
  const double last_column = cells_.columns - 1, last_row = cells_.rows - 1;
  for (std::size_t i = 0; i < centres_.size(); ++i) {
    const Point& p = centres_[i];
    const double column = std::clamp(p.x / cells_.cell_width, 0.0, last_column);
    const double row = std::clamp(p.y / cells_.cell_height, 0.0, last_row);
    cell_of_[i] =
        static_cast<std::size_t>(row) * static_cast<std::size_t>(cells_.columns) +
        static_cast<std::size_t>(column);
    ++cell_start_[cell_of_[i] + 1];
  }
  for (std::size_t c = 0; c < cell_count; ++c) cell_start_[c + 1] += cell_start_[c];
  sorted_.resize(centres_.size());
  inside_.resize(centres_.size());
  std::vector<std::size_t>& next = cell_of_;  // each cell's next free place
  for (std::size_t i = 0; i < centres_.size(); ++i) {
    const std::size_t place = cell_start_[next[i]]++;
    sorted_[place] = centres_[i];
    inside_[place] = interior_.contains(centres_[i].x, centres_[i].y) ? 1.0 : 0.0;
  }
  // The places moved on by each cell's count: back to each run's start.
  for (std::size_t c = cell_count; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
}

void FluidStructure::count_pairs(std::size_t i, std::size_t from, std::size_t to) {
  const double a = radius_, closest = 4 * a * a, farthest = reach_ * reach_;
  const Point p = sorted_[i];
  for (std::size_t j = from; j < to; ++j) {
    const double dx = sorted_[j].x - p.x, dy = sorted_[j].y - p.y;
    const double d2 = dx * dx + dy * dy;
    const double weight = inside_[i] + inside_[j];  // 0, 1 or 2 balls inside
    if (d2 >= closest && d2 < farthest && weight > 0) {
      const auto k = static_cast<std::size_t>((std::sqrt(d2) - 2 * a) / bin_);
      pair_counts_[std::min(k, pair_counts_.size() - 1)] += weight;
    }
  }
}

// Each bin's error is its blocking error at the level the contact value's
// analysis chose: the bins are the same snapshots, correlated alike, and one
// level for all keeps a bin from going without an error bar while its own
// test still sees its batches correlated (which happens to some bin of a
// hundred).
std::vector<CurveBin> FluidStructure::curve(const std::vector<BlockingAnalysis>& bins,
                                            double first_edge,
                                            const BlockingAnalysis& contact) const {
  const int level = contact.chosen_level();
  std::vector<CurveBin> out;
  for (std::size_t k = 0; k < bins.size(); ++k) {
    const double from = first_edge + static_cast<double>(k) * bin_;
    double error = std::numeric_limits<double>::quiet_NaN();
    if (level >= 0) error = bins[k].levels()[static_cast<std::size_t>(level)].error;
    out.push_back({from, from + bin_, bins[k].mean(), error});
  }
  return out;
}

std::vector<CurveBin> FluidStructure::pair_curve() const {
  return curve(pair_bins_, 2 * radius_, pair_contact_);
}

std::vector<CurveBin> FluidStructure::wall_profile() const {
  return curve(wall_bins_, 0, wall_contact_);
}

std::string structure_csv(const FluidStructure& structure) {
  fmt::memory_buffer text;
  fmt::format_to(std::back_inserter(text), "curve,from,to,value,error\n");
  for (const auto& [name, bins] : {std::pair{"pair", structure.pair_curve()},
                                   std::pair{"wall", structure.wall_profile()}}) {
    for (const CurveBin& b : bins)
      fmt::format_to(std::back_inserter(text), "{},{:.12g},{:.12g},{:.17g},{:.17g}\n",
                     name, b.from, b.to, b.value, b.error);
  }
  return fmt::to_string(text);
}

}  // namespace gas
