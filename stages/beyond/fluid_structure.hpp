// The structure of the fluid (beyond the article): how the balls crowd each
// other, and how they crowd a wall.
//
// What this file does: looks at the centres at fixed moments of time (a
// snapshot every so often, on a grid of times that does not depend on when
// collisions happen) and averages two curves — the pair correlation g(r)
// among the balls of the interior (r = 2a: contact), and the density of
// centres n(d) at a distance d from the limit of the walls x = 0 and x = A1
// (for y inside the interior's range: the walls' middles) — in bins 0.05a
// wide. From the first bins of each it fits the value at contact: g(2a+),
// the g(2a) of the virial theorem and of Enskog's collision rate, and
// n(contact), which the contact theorem ties to the pressure: kT n(contact)
// = P. The statistics (beyond/gas_statistics) keep one of these and tell it
// of every event; the whole curves (out to r = 5a and d = 10a) are kept only
// when --structure asks for them.
// Article: none; the article's screen shows no structure. Beyond it.
// Lesson: lessons/13-box-and-bulk.md
//
// Assumptions: one radius a; the interior is a rectangle of centres well
// away from the walls (the statistics' interior), and the walls' strips are
// taken only for y inside it, away from the corners.
#pragma once

#include <string>
#include <vector>

#include "beyond/blocking.hpp"
#include "beyond/cell_layout.hpp"
#include "stage1_data.hpp"

namespace gas {

// The width of the shells (pairs) and strips (walls), in radii.
inline constexpr double structure_bin_radii = 0.05;
// The value at contact: the cubic c0 + c1 s + c2 s^2 + c3 s^3 (s: distance
// from contact) whose bin means best fit (least squares) the first
// contact_bins bins, 0 ... 0.5a from contact. g(r) is smooth beyond contact
// but curves: at eta = 0.5 the straight line through the first two bins is
// 0.17 % low, a parabola through 6 bins 0.13 %, this cubic 0.02 %, and it
// has less noise than either (lesson 14).
inline constexpr int contact_bins = 10;
inline constexpr int contact_fit_degree = 3;
// How far the curves of --structure reach: g(r) to r = 5a, where it is 1
// within a few thousandths even at eta = 0.5; n(d) to d = 10a from the
// wall's limit, where the layers have died out (the interior starts at d =
// 11a).
inline constexpr double pair_curve_radii = 5;
inline constexpr double wall_profile_radii = 10;

// A rectangle of centres, x_min <= x <= x_max, y_min <= y <= y_max: the
// statistics' interior (empty on a table too small to have one).
struct Region {
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  bool contains(double x, double y) const {
    return x >= x_min && x <= x_max && y >= y_min && y <= y_max;
  }
  bool empty() const { return !(x_max > x_min && y_max > y_min); }
  double area() const { return empty() ? 0.0 : (x_max - x_min) * (y_max - y_min); }
};

// One bin of a curve, averaged over the snapshots.
struct CurveBin {
  double from = 0, to = 0;  // its edges: r (pairs) or d (walls), model lengths
  double value = 0;         // g (no unit) or n (centres per unit area), the mean
  double error =
      0;  // its blocking error (at the level of the contact value's); NaN until known
};

// The snapshots of a run and their averages.
class FluidStructure {
 public:
  FluidStructure() = default;  // nothing to measure: no snapshots
  // For `gas`, with the statistics' interior; `curves`: keep the whole
  // curves too (--structure), not only the bins near contact.
  FluidStructure(const Gas& gas, const Region& interior, bool curves);

  // Before an event at `time` (or before B rewrites the rows at `time`): the
  // snapshots due up to then are taken now, while every ball's row is still
  // the straight flight through them. The first `balls` events after a
  // restart set the spacing of the snapshots: the time they took.
  void catch_up(const Gas& gas, double time) {
    if (spacing_ > 0 && time < next_) return;  // nearly always
    take_snapshots(gas, time);
  }
  // Forgets the snapshots; the next ones after `time`.
  void restart(double time);

  // g(2a+) per snapshot and the density of centres at the walls' contact
  // (per unit area), fitted from the first contact_bins bins.
  const BlockingAnalysis& pair_contact() const { return pair_contact_; }
  const BlockingAnalysis& wall_contact_density() const { return wall_contact_; }
  // g(2a+) less the reference's g(2a) at the snapshot's own interior
  // density, per snapshot: what the interior's wandering density moves in
  // both cancels (like Z's deviation, lesson 14).
  const BlockingAnalysis& pair_contact_minus_theory() const {
    return pair_contact_minus_theory_;
  }
  // The curves (--structure): empty unless asked for.
  std::vector<CurveBin> pair_curve() const;
  std::vector<CurveBin> wall_profile() const;
  long long snapshots() const { return static_cast<long long>(pair_contact_.count()); }

 private:
  void take_snapshots(const Gas& gas, double time);
  void take_snapshot(const Gas& gas, double time);
  void sort_by_cell();
  // Adds, for each pair of centres i (in sorted_) and from ... to - 1 at
  // 2a ... reach_ apart, one to its shell for each of its balls inside.
  void count_pairs(std::size_t i, std::size_t from, std::size_t to);
  std::vector<CurveBin> curve(const std::vector<BlockingAnalysis>& bins,
                              double first_edge, const BlockingAnalysis& contact) const;

  Region interior_;
  double radius_ = 0, width_ = 0;  // a and A1
  double bin_ = 0;                 // the bins' width, structure_bin_radii a
  double reach_ = 0;               // pairs counted up to r = reach_
  std::size_t balls_ = 0;
  bool curves_ = false;
  // The snapshots' moments: every spacing_, from next_.
  double start_ = 0, spacing_ = 0, next_ = 0;
  std::size_t events_ = 0;  // since start_, until spacing_ is known
  // The fits' weights: value at contact = sum of weight_k x bin k.
  std::vector<double> pair_weights_, wall_weights_;
  BlockingAnalysis pair_contact_, wall_contact_, pair_contact_minus_theory_;
  // Per bin: g (pairs, from r = 2a) and n (walls, from d = 0), when curves_.
  std::vector<BlockingAnalysis> pair_bins_, wall_bins_;
  // Scratch, kept between snapshots.
  std::vector<Point> centres_;
  std::vector<double> pair_counts_, wall_counts_;
  // The centres sorted by cell (at least reach_ across): each cell's run in
  // sorted_ is cell_start_[cell] ... cell_start_[cell + 1] - 1; inside_: 1
  // for a centre in the interior, else 0.
  CellLayout cells_;
  std::vector<std::size_t> cell_start_, cell_of_;
  std::vector<Point> sorted_;
  std::vector<double> inside_;
};

// The weights w_k of the fit at contact: the polynomial c0 + c1 s + ... +
// c_degree s^degree (s in radii from contact) whose means over `bins` bins,
// each `width` radii wide, best match (least squares) the bins' values has
// c0 = sum of w_k x value_k. A bin's mean weights each s by base + s (the
// length of the circle of radius r = (2 + s) a: base 2 for the shells of
// g(r)), or equally (base infinite: the strips along a straight wall).
std::vector<double> contact_weights(int bins, int degree, double width, double base);

// The --structure file: a header line, then one line per bin, g(r) first:
// curve,from,to,value,error with curve "pair" or "wall" (data/README.md).
std::string structure_csv(const FluidStructure& structure);

}  // namespace gas
