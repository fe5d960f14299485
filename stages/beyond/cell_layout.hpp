// Stage 4 — first collision, and stage 2's 'random' line: the table cut into
// cells (beyond the article).
//
// What this file does: lays equal cells over the table, each at least a given
// length across, and finds the cell that holds a point. With cells at least 2a
// across, two centres in cells that are not neighbours are more than 2a apart,
// so a ball needs to be compared only with the balls of the 3 x 3 cells around
// its own. Three parts of the program rest on that: the cell grids of stage 4
// (beyond/plain_grid.*, beyond/cell_grid.*), the placement of the balls of a 'random'
// line (beyond/random_placement.*) and the pairs of the fluid's structure
// (beyond/fluid_structure.*). All lay out their cells here; the placement
// files the centres of one moment in CellLists (the structure sorts its
// centres by cell itself, each pair met once).
// Beyond the article: the article compares every ball with every other.
// Lesson: lessons/10-scaling.md (the grid); lessons/2-input.md (the
// 'random' line).
//
// Assumptions: the table's sides and the least length are positive. The
// helpers are inline: the grid asks for cells in its hot loop.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace gas {

// How many cells along a side of `length`: as many as fit with each at least
// `smallest` long, and at least one.
inline double cells_along(double length, double smallest) {
  return std::max(1.0, std::floor(length / smallest));
}

// The cell of a coordinate among `cells` cells of length `length` from 0. A
// coordinate a rounding off the table (below 0, or at its far edge) is in the
// cell at that edge.
inline int cell_of(double coordinate, double length, int cells) {
  const double cell = std::floor(coordinate / length);
  return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(cells - 1)));
}

// Cells over a table A1 x A2: `columns` across x, `rows` along y, each
// cell_width x cell_height, numbered from 0 at the corner x = y = 0.
struct CellLayout {
  int columns = 1, rows = 1;
  double cell_width = 0, cell_height = 0;

  int column_of(double x) const { return cell_of(x, cell_width, columns); }
  int row_of(double y) const { return cell_of(y, cell_height, rows); }
};

// Cells at least `smallest` across on a table `width` x `height`, but not many
// more than `most` of them (a huge table with few balls needs few cells): if
// there would be more, both sides get fewer cells, in proportion, so each cell
// is only larger. And at most `most_columns` across and `most_rows` along y
// (a cell grid that numbers them in a few bits asks for that).
inline CellLayout lay_out_cells(double width, double height, double smallest, double most,
                                double most_columns = HUGE_VAL,
                                double most_rows = HUGE_VAL) {
  double columns = std::min({cells_along(width, smallest), most, most_columns});
  double rows = std::min({cells_along(height, smallest), most, most_rows});
  if (columns * rows > most) {
    const double shrink = std::sqrt(most / (columns * rows));
    columns = std::max(1.0, std::floor(columns * shrink));
    rows = std::max(1.0, std::floor(rows * shrink));
  }
  return CellLayout{static_cast<int>(columns), static_cast<int>(rows), width / columns,
                    height / rows};
}

// How much wider than 2a a grid's cell is at least, as a fraction of 2a. Two
// balls in cells that are not neighbours are then more than 2a (1 + margin)
// apart; the margin is far above the rounding of any centre (~1e-16 of the
// table's size, and of |v| T), so a grid's idea of which cell holds a centre
// can never be wrong by enough to hide a collision.
inline constexpr double grid_margin = 1.0 / 1024;

// The cells of a grid of stage 4 (beyond/plain_grid.*, beyond/cell_grid.*)
// for `balls` balls of radius `radius`: at least 2a (1 + margin) wide, and
// not many more cells than balls (a huge table with a few balls needs few
// cells), nor more than `most_along` along a side (wider cells only hold
// more balls).
inline CellLayout grid_cells(double width, double height, double radius,
                             std::size_t balls, double most_along = HUGE_VAL) {
  return lay_out_cells(width, height, 2 * radius * (1 + grid_margin),
                       4.0 * static_cast<double>(balls) + 16, most_along, most_along);
}

// Points filed by cell, for the two passes that look at a moment's centres
// (the 'random' line's placement, and the structure of the fluid): each
// cell keeps a chain of the numbers of the points in it, and a query visits
// the points of the 3 x 3 cells around a place.
class CellLists {
 public:
  // For up to `points` points, on cells `layout`.
  CellLists(const CellLayout& layout, std::size_t points)
      : layout_(layout),
        head_(static_cast<std::size_t>(layout.columns) *
                  static_cast<std::size_t>(layout.rows),
              0),
        next_(points, 0) {}

  // Files point number `index` (0 ...), at (x, y).
  void file(std::size_t index, double x, double y) {
    const std::size_t cell = cell_index(layout_.column_of(x), layout_.row_of(y));
    next_[index] = head_[cell];
    head_[cell] = index + 1;
  }

  // Calls visit(index) for every point filed in the 3 x 3 cells around (x, y)
  // until it returns false; false if it stopped.
  template <typename Visit>
  bool visit_near(double x, double y, Visit visit) const {
    const int column = layout_.column_of(x), row = layout_.row_of(y);
    for (int r = std::max(0, row - 1); r <= std::min(layout_.rows - 1, row + 1); ++r) {
      for (int c = std::max(0, column - 1);
           c <= std::min(layout_.columns - 1, column + 1); ++c) {
        for (std::size_t k = head_[cell_index(c, r)]; k != 0; k = next_[k - 1])
          if (!visit(k - 1)) return false;
      }
    }
    return true;
  }

 private:
  std::size_t cell_index(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(layout_.columns) +
           static_cast<std::size_t>(column);
  }

  CellLayout layout_;
  std::vector<std::size_t> head_;  // by cell: a point's number + 1; 0: empty
  std::vector<std::size_t> next_;  // by point: the next in its cell, + 1; 0 ends
};

}  // namespace gas
