// Stage 3 — screen preparation.
//
// What this stage does: lays the table out on a grid of text characters,
// draws the table's border, and computes the limits that the balls' centres
// must stay within (the article's G1, G2).
// Article: "Gas on the display", stage 3, "screen preparation" (a graphics
// screen of integer points, e.g. 1 <= x <= 256, 1 <= y <= 192; limits "of the
// type" G1 = A1 - 2a - 1, G2 = A2 - 2a - 1).
// Lesson: lessons/3-screen-preparation.md
//
// Assumptions: the screen is a terminal of fixed-width characters, each about
// twice as tall as it is wide; y grows upwards on the table, as in physics.
#pragma once

#include <string>
#include <vector>

#include "stage1_data.hpp"

namespace gas {

// The box a ball's centre must stay in (the article's G1, G2, on a table whose
// walls are the lines x = 0, x = A1, y = 0, y = A2).
//
// The article calls its G1 = A1 - 2a - 1 ("of the type") a limit of the
// centres; our reading of it (lesson 8's, not the article's words): a pixel
// screen that spends a pixel on the border line and draws a ball from its
// corner. On our table the centre of a ball of radius a touches a wall when
// it is a away from it.
// [anchor: centre-limits]
struct CentreLimits {
  double x_min = 0;  // a
  double x_max = 0;  // A1 - a   (the article's G1)
  double y_min = 0;  // a
  double y_max = 0;  // A2 - a   (the article's G2)
};

inline CentreLimits centre_limits(const Gas& gas) {
  return {gas.radius, gas.width - gas.radius, gas.radius, gas.height - gas.radius};
}
// [/anchor: centre-limits]

// A character cell: column 0 and row 0 are the top-left corner of the grid.
struct Cell {
  int column = 0;
  int row = 0;
  bool operator==(const Cell&) const = default;
};

// How much taller a terminal's character cell is than it is wide. Balls are
// drawn round by giving a row twice the model length of a column.
inline constexpr double cell_aspect = 2.0;

// The text screen: the table inside a border of '+', '-' and '|'.
// [anchor: text-screen]
struct TextScreen {
  int columns = 0;                 // grid width, border included
  int rows = 0;                    // grid height, border included
  double column_width = 0;         // model length across one character
  double row_height = 0;           // model length down one character
  std::vector<std::string> lines;  // lines[row][column], border included

  // The cell whose area holds point p of the table (clamped to the inside).
  Cell cell_of(Point p) const;
  // The table point at the middle of a cell.
  Point middle_of(Cell cell) const;
  // Is the cell inside the border?
  bool inside(Cell cell) const {
    return cell.column > 0 && cell.column < columns - 1 && cell.row > 0 &&
           cell.row < rows - 1;
  }
  char& at(Cell cell) {
    return lines[static_cast<std::size_t>(cell.row)]
                [static_cast<std::size_t>(cell.column)];
  }
};
// [/anchor: text-screen]

// The smallest grid (border included) that `prepare_screen` accepts.
inline constexpr int smallest_columns = 8;
inline constexpr int smallest_rows = 5;

// Lays out the table in a grid of at most `columns` x `rows` characters,
// keeping its proportions, and draws the border around an empty inside.
// Requires columns >= smallest_columns and rows >= smallest_rows.
TextScreen prepare_screen(const Gas& gas, int columns, int rows);

// The article's third way: a character screen with no table drawn, for
// figures only — a border around the whole `columns` x `rows` grid.
TextScreen prepare_character_screen(int columns, int rows);

// Wipes the inside of the border (the border stays).
void clear_inside(TextScreen& screen);

}  // namespace gas
