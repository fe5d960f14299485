// Stage 3 of the article, "screen preparation": the limits of the centres
// (the article's G1, G2) and the layout of the table on a text grid — size,
// proportions, border, the mapping between table points and character cells,
// and clearing the inside. Hand-made tables and random ones (fixed seed).
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>

#include "stage3_screen.hpp"

namespace {

using gas::Cell;
using gas::Gas;
using gas::TextScreen;

Gas table(double width, double height, double radius = 1) {
  Gas gas;
  gas.width = width;
  gas.height = height;
  gas.radius = radius;
  return gas;
}

// The border is '+' at the corners, '-' along the top and bottom, '|' down
// the sides; everything inside it is `inside`.
void check_frame(const TextScreen& s, char inside = ' ') {
  REQUIRE(s.lines.size() == static_cast<std::size_t>(s.rows));
  std::string edge(static_cast<std::size_t>(s.columns), '-');
  std::string middle(static_cast<std::size_t>(s.columns), inside);
  edge.front() = edge.back() = '+';
  middle.front() = middle.back() = '|';
  CHECK(s.lines.front() == edge);
  CHECK(s.lines.back() == edge);
  for (int row = 1; row < s.rows - 1; ++row) {
    CHECK(s.lines[static_cast<std::size_t>(row)] == middle);
  }
}

// What every layout must satisfy, for a table requested on columns x rows.
void check_layout(const Gas& gas, const TextScreen& s, int columns, int rows) {
  CAPTURE(gas.width);
  CAPTURE(gas.height);
  CAPTURE(columns);
  CAPTURE(rows);
  // Fits in the requested grid, with at least one cell inside the border.
  CHECK(s.columns <= columns);
  CHECK(s.rows <= rows);
  CHECK(s.columns >= 3);
  CHECK(s.rows >= 3);
  // A character is twice as tall as wide, so a row covers twice the model
  // length of a column: one common scale keeps the table's proportions.
  CHECK(s.row_height == 2 * s.column_width);
  const int inside_columns = s.columns - 2, inside_rows = s.rows - 2;
  // The inside cells cover the table, with less than one cell to spare.
  // Why 1e-9: the layout forgives a length that exceeds a whole number of
  // cells by under 1e-9 of a cell (a rounding of its division), so the cells
  // may fall short of the table by that much, i.e. by under 1e-9 of its
  // length; a wrong scale is off by whole cells.
  CHECK(inside_columns * s.column_width >= gas.width * (1 - 1e-9));
  CHECK(inside_rows * s.row_height >= gas.height * (1 - 1e-9));
  CHECK((inside_columns - 1) * s.column_width < gas.width);
  CHECK((inside_rows - 1) * s.row_height < gas.height);
  // As large as the grid allows: one direction uses all the room there is.
  CHECK((s.columns == columns || s.rows == rows));
  check_frame(s);
}

}  // namespace

TEST_SUITE("stage3") {
  TEST_CASE("stage3 centre limits are a and A - a") {
    const gas::CentreLimits l = gas::centre_limits(table(40, 30, 1.5));
    CHECK(l.x_min == 1.5);
    CHECK(l.x_max == 38.5);
    CHECK(l.y_min == 1.5);
    CHECK(l.y_max == 28.5);
  }

  TEST_CASE("stage3 a wide table on an 80 x 24 terminal") {
    // 100 x 50 in 78 x 22 inside cells: width needs 100/78 per column,
    // height 50/(2*22) per column; the larger, 100/78, sets the scale. The
    // table then takes 78 columns and 50 / (2*100/78) = 19.5 -> 20 rows.
    const Gas gas = table(100, 50);
    const TextScreen s = gas::prepare_screen(gas, 80, 24);
    CHECK(s.columns == 80);
    CHECK(s.rows == 22);
    // Why 1e-15: one division, one rounding.
    CHECK(s.column_width == doctest::Approx(100.0 / 78).epsilon(1e-15));
    check_layout(gas, s, 80, 24);
  }

  TEST_CASE("stage3 a tall table is limited by the rows") {
    // 30 x 60 in 38 x 18 inside cells: the height sets the scale,
    // 60 / (2*18) per column, so 18 rows and 30 / (60/36) = 18 columns.
    const Gas gas = table(30, 60);
    const TextScreen s = gas::prepare_screen(gas, 40, 20);
    CHECK(s.rows == 20);
    CHECK(s.columns == 20);
    check_layout(gas, s, 40, 20);
  }

  TEST_CASE("stage3 random tables and grids") {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> length(1, 1000);
    std::uniform_int_distribution<int> columns(gas::smallest_columns, 200);
    std::uniform_int_distribution<int> rows(gas::smallest_rows, 80);
    for (int i = 0; i < 300; ++i) {
      const Gas gas = table(length(rng), length(rng));
      const int c = columns(rng), r = rows(rng);
      check_layout(gas, gas::prepare_screen(gas, c, r), c, r);
    }
  }

  TEST_CASE("stage3 cells and table points") {
    const Gas gas = table(100, 50);
    const TextScreen s = gas::prepare_screen(gas, 80, 24);
    const int last_column = s.columns - 2, last_row = s.rows - 2;

    SUBCASE("the corners of the table are the corner cells inside the border") {
      // y grows upwards: the bottom of the table is the last inside row.
      CHECK(s.cell_of({0, 0}) == Cell{1, last_row});
      CHECK(s.cell_of({gas.width, 0}) == Cell{last_column, last_row});
      CHECK(s.cell_of({0, gas.height}) == Cell{1, 1});
      CHECK(s.cell_of({gas.width, gas.height}) == Cell{last_column, 1});
    }

    SUBCASE("the middle of a point's cell is in that cell and near the point") {
      std::mt19937_64 rng(32);
      std::uniform_real_distribution<double> x(0, gas.width), y(0, gas.height);
      for (int i = 0; i < 1000; ++i) {
        const gas::Point p{x(rng), y(rng)};
        const Cell cell = s.cell_of(p);
        CHECK(s.inside(cell));
        const gas::Point m = s.middle_of(cell);
        CHECK(s.cell_of(m) == cell);
        // Half a cell away at most (the cell is the one holding p); the
        // factor 1 + 1e-12 only absorbs the roundings of floor and products.
        CHECK(std::abs(m.x - p.x) <= s.column_width / 2 * (1 + 1e-12));
        CHECK(std::abs(m.y - p.y) <= s.row_height / 2 * (1 + 1e-12));
      }
    }

    SUBCASE("every inside cell's middle maps back to it") {
      for (int row = 1; row <= last_row; ++row) {
        for (int column = 1; column <= last_column; ++column) {
          CHECK(s.cell_of(s.middle_of({column, row})) == Cell{column, row});
        }
      }
    }

    SUBCASE("larger y is a smaller row and larger x a larger column") {
      std::mt19937_64 rng(33);
      std::uniform_real_distribution<double> x(0, gas.width), y(0, gas.height);
      for (int i = 0; i < 1000; ++i) {
        const gas::Point p{x(rng), y(rng)}, q{x(rng), y(rng)};
        const Cell cp = s.cell_of(p), cq = s.cell_of(q);
        if (q.y >= p.y + s.row_height) CHECK(cq.row < cp.row);
        if (q.y >= p.y) CHECK(cq.row <= cp.row);
        if (q.x >= p.x + s.column_width) CHECK(cq.column > cp.column);
        if (q.x >= p.x) CHECK(cq.column >= cp.column);
      }
    }
  }

  TEST_CASE("stage3 clear_inside empties the inside and keeps the border") {
    const Gas gas = table(60, 40);
    TextScreen s = gas::prepare_screen(gas, 50, 20);
    for (int row = 1; row < s.rows - 1; ++row) {
      for (int column = 1; column < s.columns - 1; ++column) s.at({column, row}) = 'o';
    }
    check_frame(s, 'o');
    gas::clear_inside(s);
    check_frame(s);
    CHECK(s.lines == gas::prepare_screen(gas, 50, 20).lines);
  }
}
