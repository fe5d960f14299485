// The check of overlaps through cells. See beyond/overlap_cells.hpp.
#include "beyond/overlap_cells.hpp"

#include <algorithm>
#include <cmath>

#include "beyond/cell_layout.hpp"

namespace gas {
namespace {

// How much wider than `closest` a cell is, as a fraction. Two centres that
// the comparison finds closer than `closest` are at most a few parts in 10^16
// farther apart than that; and the number (x - left) / width whose floor is a
// centre's cell is rounded, in its subtraction and its division, by at most
// 2^-52 of the cells along the side, 2^20 at most (below): 2^-32 of a cell,
// twice that for two centres. A margin of 1e-6 of a cell, far above, keeps
// two such centres in the same or neighbouring cells.
constexpr double cell_margin = 1e-6;
// The most cells along a side (see cell_margin).
constexpr double most_cells_a_side = 0x1.0p20;

}  // namespace

// [anchor: first-overlap-by-cells]
std::optional<Overlap> first_overlap_by_cells(const std::vector<Point>& centres,
                                              double closest) {
  if (centres.size() < 2) return std::nullopt;
  // The box around every centre, and cells over it.
  double left = centres[0].x, right = left, bottom = centres[0].y, top = bottom;
  for (const Point& p : centres) {
    left = std::min(left, p.x);
    right = std::max(right, p.x);
    bottom = std::min(bottom, p.y);
    top = std::max(top, p.y);
  }
  const double smallest = closest * (1 + cell_margin);
  const CellLayout layout = lay_out_cells(
      std::max(right - left, smallest), std::max(top - bottom, smallest), smallest,
      2 * static_cast<double>(centres.size()) + 16, most_cells_a_side, most_cells_a_side);
  CellLists cells(layout, centres.size());

  // Each ball in the order of the file against the balls before it nearby:
  // the first ball closer to one of them ends the search, with the first of
  // those it is closer to.
  for (std::size_t j = 0; j < centres.size(); ++j) {
    const Point& p = centres[j];
    std::optional<std::size_t> earliest;
    cells.visit_near(p.x - left, p.y - bottom, [&](std::size_t i) {
      const double dx = p.x - centres[i].x;
      const double dy = p.y - centres[i].y;
      if (dx * dx + dy * dy < closest * closest && (!earliest || i < *earliest))
        earliest = i;
      return true;
    });
    if (earliest) return Overlap{j, *earliest};
    cells.file(j, p.x - left, p.y - bottom);
  }
  return std::nullopt;
}
// [/anchor: first-overlap-by-cells]

}  // namespace gas
