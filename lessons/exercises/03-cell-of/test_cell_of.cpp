// Exercise 03, TextScreen::cell_of: the provided tests (suite exercise-03).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage3_screen.cpp. Don't change this file to make a
// test pass: change your cell_of.cpp.
//
// The screen of these tests: 12 columns by 7 rows, border included, so the
// inside is columns 1..10 and rows 1..5. A column is 2 units of the table
// wide and a row 4 units tall, so the inside covers the table
// 0 <= x <= 20, 0 <= y <= 20. All the numbers are exact in binary.
//
//          x: 0   2   4  ...  18  20
//   row 1    y from 16 to 20   (the top of the table)
//   row 5    y from  0 to  4   (the bottom)
#include <doctest/doctest.h>
#include <fmt/format.h>

#include "exercise_test.hpp"
#include "stage3_screen.hpp"

namespace {

using gas::Cell;

gas::TextScreen grid() {
  gas::TextScreen screen;
  screen.columns = 12;
  screen.rows = 7;
  screen.column_width = 2;
  screen.row_height = 4;
  return screen;
}

}  // namespace

TEST_SUITE("exercise-03") {
  TEST_CASE("exercise-03 the bottom-left corner of the table is the bottom-left cell") {
    const gas::TextScreen screen = grid();
    INFO("y grows upwards on the table but rows grow downwards on the screen");
    CHECK(screen.cell_of({0.5, 0.5}) == Cell{1, 5});
    CHECK(screen.cell_of({0, 0}) == Cell{1, 5});
  }

  TEST_CASE("exercise-03 columns count from x = 0 and rows from the top of the table") {
    const gas::TextScreen screen = grid();
    CHECK(screen.cell_of({3, 1}) == Cell{2, 5});         // x in [2, 4): column 2
    CHECK(screen.cell_of({5, 9}) == Cell{3, 3});         // y in [8, 12): row 3
    CHECK(screen.cell_of({19.5, 19.5}) == Cell{10, 1});  // the top-right cell
    CHECK(screen.cell_of({11, 17}) == Cell{6, 1});
  }

  TEST_CASE("exercise-03 a point on a cell's left or lower edge belongs to that cell") {
    const gas::TextScreen screen = grid();
    INFO("a cell holds its left and lower edges: column k holds 2(k-1) <= x < 2k");
    CHECK(screen.cell_of({4, 8}) == Cell{3, 3});
    CHECK(screen.cell_of({2, 4}) == Cell{2, 4});
    CHECK(screen.cell_of({18, 12}) == Cell{10, 2});
  }

  TEST_CASE("exercise-03 points on the far walls or beyond them stay inside the border") {
    const gas::TextScreen screen = grid();
    INFO("clamp the column to 1..columns-2 and the row to 1..rows-2");
    // The top-right corner of the table lies on the border's lines.
    CHECK(screen.cell_of({20, 20}) == Cell{10, 1});
    CHECK(screen.cell_of({20, 0}) == Cell{10, 5});
    // Beyond the table (round-off, or a ball's image near a wall).
    CHECK(screen.cell_of({25, -3}) == Cell{10, 5});
    CHECK(screen.cell_of({-1, 30}) == Cell{1, 1});
    CHECK(screen.cell_of({-0.5, 10}) == Cell{1, 3});
  }

  TEST_CASE("exercise-03 the middle of every cell lies in that cell") {
    const gas::TextScreen screen = grid();
    // middle_of (stage 3, beside cell_of) goes the other way: from a cell to
    // the point at its middle.
    for (int row = 1; row <= 5; ++row) {
      for (int column = 1; column <= 10; ++column) {
        const Cell cell{column, row};
        CAPTURE(cell);
        CHECK(screen.cell_of(screen.middle_of(cell)) == cell);
      }
    }
  }

  TEST_CASE("exercise-03 500 generated points on screens of every size") {
    // Screens of 3 to 120 columns and 3 to 60 rows, cells 1/8 to 8 units
    // wide and tall, and points on a grid of 1/64 of a cell (edges
    // included) from a cell beyond one side of the table to one beyond
    // the other: every number exact in binary, so each point lies in one
    // cell for sure. The cell wanted is found by looking at every column
    // and every row, not by a formula.
    gas::exercises::Draw draw(301);
    for (int n = 1; n <= 500; ++n) {
      gas::TextScreen screen;
      screen.columns = draw.integer(3, 120);
      screen.rows = draw.integer(3, 60);
      screen.column_width = draw.integer(1, 64) / 8.0;
      screen.row_height = draw.integer(1, 64) / 8.0;
      const int last_column = screen.columns - 2, last_row = screen.rows - 2;
      const double x =
          draw.integer(-64, 64 * (last_column + 1)) / 64.0 * screen.column_width;
      const double y = draw.integer(-64, 64 * (last_row + 1)) / 64.0 * screen.row_height;
      Cell wanted{1, last_row};  // left of or below the table
      for (int column = 1; column <= last_column; ++column)
        if (x >= (column - 1) * screen.column_width) wanted.column = column;
      for (int from_bottom = 0; from_bottom < last_row; ++from_bottom)
        if (y >= from_bottom * screen.row_height) wanted.row = last_row - from_bottom;
      const Cell got = screen.cell_of({x, y});
      CAPTURE(n);
      INFO(fmt::format(
          "cell_of(({}, {})) on a screen of {} x {} characters, border included, each "
          "{} wide and {} tall",
          gas::exercises::digits(x), gas::exercises::digits(y), screen.columns,
          screen.rows, gas::exercises::digits(screen.column_width),
          gas::exercises::digits(screen.row_height)));
      CHECK(got == wanted);
      if (!(got == wanted)) break;
    }
  }
}
