// Stage 3 — screen preparation: the layout of the table on the text grid.
// See stage3_screen.hpp.
#include "stage3_screen.hpp"

#include <algorithm>
#include <cmath>

namespace gas {
namespace {

// The border of '+', '-' and '|' around an empty inside.
void draw_border(TextScreen& screen) {
  const auto width = static_cast<std::size_t>(screen.columns);
  std::string edge(width, '-');
  std::string middle(width, ' ');
  edge.front() = edge.back() = '+';
  middle.front() = middle.back() = '|';
  screen.lines.assign(static_cast<std::size_t>(screen.rows), middle);
  screen.lines.front() = edge;
  screen.lines.back() = edge;
}

}  // namespace

// Lay the table out on the grid: one model length per column, twice that per
// row, as large as the grid allows; then draw the border.
// [anchor: prepare-screen]
TextScreen prepare_screen(const Gas& gas, int columns, int rows) {
  const int inside_columns = columns - 2;
  const int inside_rows = rows - 2;
  const double column_width =
      std::max(gas.width / inside_columns, gas.height / (cell_aspect * inside_rows));
  TextScreen screen;
  screen.column_width = column_width;
  screen.row_height = cell_aspect * column_width;
  // Cells needed to cover a length; the 1e-9 keeps a length of exactly k
  // cells, divided with a rounding error, from asking for a (k+1)-th.
  const auto cells_across = [](double length, double cell, int most) {
    return std::clamp(static_cast<int>(std::ceil(length / cell - 1e-9)), 1, most);
  };
  screen.columns = 2 + cells_across(gas.width, screen.column_width, inside_columns);
  screen.rows = 2 + cells_across(gas.height, screen.row_height, inside_rows);
  draw_border(screen);
  return screen;
}
// [/anchor: prepare-screen]

TextScreen prepare_character_screen(int columns, int rows) {
  TextScreen screen;
  screen.columns = columns;
  screen.rows = rows;
  screen.column_width = 1;
  screen.row_height = cell_aspect;
  draw_border(screen);
  return screen;
}

void clear_inside(TextScreen& screen) {
  for (int row = 1; row < screen.rows - 1; ++row) {
    for (int column = 1; column < screen.columns - 1; ++column)
      screen.at({column, row}) = ' ';
  }
}

#ifndef GAS_STUDENT_CELL_OF  // see lessons/exercises/03-cell-of
Cell TextScreen::cell_of(Point p) const {
  // Column 1 starts at x = 0; row 1 is the top of the table, y = rows * height.
  const double column = std::floor(p.x / column_width);
  const double row_from_bottom = std::floor(p.y / row_height);
  const int last_column = columns - 2;
  const int last_row = rows - 2;
  Cell cell;
  cell.column = 1 + static_cast<int>(std::clamp(column, 0.0, last_column - 1.0));
  cell.row =
      last_row - static_cast<int>(std::clamp(row_from_bottom, 0.0, last_row - 1.0));
  return cell;
}
#endif

Point TextScreen::middle_of(Cell cell) const {
  const int last_row = rows - 2;
  return {(cell.column - 1 + 0.5) * column_width,
          (last_row - cell.row + 0.5) * row_height};
}

}  // namespace gas
