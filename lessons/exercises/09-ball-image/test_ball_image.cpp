// Exercise 09, ball_image: the provided tests (suite exercise-09).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage6_output.cpp. Don't change this file to make a
// test pass: change your ball_image.cpp.
//
// The screen of these tests is stage 3's character screen of 60 x 24
// characters, border included: the inside is columns 1..58 and rows 1..22,
// a column is 1 unit of the table wide and a row 2 units tall, so the
// inside covers 0 <= x <= 58, 0 <= y <= 44. Cell middles are at
// x = 0.5, 1.5, ... and y = 1, 3, 5, ...; all the numbers are exact in
// binary, so "within the radius" is decided without rounding.
#include <doctest/doctest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "exercise_test.hpp"
#include "stage3_screen.hpp"
#include "stage6_output.hpp"

namespace {

using gas::Cell;
using gas::Point;

gas::TextScreen screen() {
  return gas::prepare_character_screen(60, 24);
}

// Cells as sorted (row, column) pairs, to compare sets of cells.
std::vector<std::pair<int, int>> sorted(const std::vector<Cell>& cells) {
  std::vector<std::pair<int, int>> pairs;
  for (const Cell& c : cells) pairs.emplace_back(c.row, c.column);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::string text(const std::vector<Cell>& cells) {
  std::ostringstream out;
  for (const auto& [row, column] : sorted(cells))
    out << " [" << column << ' ' << row << ']';
  return cells.empty() ? " (none)" : out.str();
}

// What the image must be: the centre's own cell, and every inside cell
// whose middle is within `radius` of the centre (found by looking at all of
// them).
std::vector<Cell> disc(const gas::TextScreen& s, Point centre, double radius) {
  std::vector<Cell> cells{s.cell_of(centre)};
  for (int row = 1; row < s.rows - 1; ++row) {
    for (int column = 1; column < s.columns - 1; ++column) {
      const Cell cell{column, row};
      const Point m = s.middle_of(cell);
      const double dx = m.x - centre.x, dy = m.y - centre.y;
      if (!(cell == cells[0]) && dx * dx + dy * dy <= radius * radius)
        cells.push_back(cell);
    }
  }
  return cells;
}

bool check_image(const gas::TextScreen& s, Point centre, double radius) {
  CAPTURE(centre);
  CAPTURE(radius);
  const std::vector<Cell> image = gas::ball_image(s, centre, radius);
  const std::vector<Cell> wanted = disc(s, centre, radius);
  INFO("wanted [column row]:" << text(wanted));
  INFO("got:" << text(image));
  CHECK(sorted(image) == sorted(wanted));
  return sorted(image) == sorted(wanted);
}

}  // namespace

TEST_SUITE("exercise-09") {
  TEST_CASE(
      "exercise-09 a ball smaller than a character is one glyph: its centre's cell") {
    const gas::TextScreen s = screen();
    INFO(
        "always draw the centre's own cell, even when no cell middle is within the "
        "radius");
    for (const Point centre : {Point{10.5, 11}, Point{10, 10}, Point{33.9, 40.1}}) {
      CAPTURE(centre);
      const std::vector<Cell> image = gas::ball_image(s, centre, 0.2);
      REQUIRE(image.size() == 1);
      CHECK(image[0] == s.cell_of(centre));
    }
  }

  TEST_CASE("exercise-09 the centre's cell comes first and no cell comes twice") {
    const gas::TextScreen s = screen();
    const Point centre{20.3, 21.7};
    const std::vector<Cell> image = gas::ball_image(s, centre, 3);
    REQUIRE_FALSE(image.empty());
    CHECK(image[0] == s.cell_of(centre));
    std::vector<std::pair<int, int>> cells = sorted(image);
    INFO("got:" << text(image));
    CHECK(std::adjacent_find(cells.begin(), cells.end()) == cells.end());
  }

  TEST_CASE("exercise-09 a ball covers the cells whose middles are within its radius") {
    const gas::TextScreen s = screen();
    // A big ball: about 10 columns wide and 5 rows high (a row is twice as
    // tall as a column is wide), so it looks round.
    check_image(s, {30.25, 22.5}, 5);
    INFO("a middle exactly at the radius counts: <=, not <");
    // Radius 2 from a cell's middle: the middles 2 to the left, right, above
    // and below lie exactly on the circle.
    check_image(s, {10.5, 11}, 2);
  }

  TEST_CASE("exercise-09 a ball at a wall or past it stays inside the border") {
    const gas::TextScreen s = screen();
    INFO(
        "cells beyond the table are not drawn: cell_of keeps every point inside the "
        "border");
    // Touching the bottom-left corner, and a hair beyond the top-right one.
    check_image(s, {4, 4}, 4);
    check_image(s, {58.25, 44.5}, 3);
    for (const Cell& cell : gas::ball_image(s, {58.25, 44.5}, 3)) {
      CAPTURE(cell);
      CHECK(s.inside(cell));
    }
  }

  TEST_CASE("exercise-09 300 generated balls on screens of every size") {
    // Screens of 3 to 100 columns and 3 to 40 rows (stage 3's character
    // screen: a column 1 unit wide, a row 2 tall), centres anywhere on the
    // table and a little beyond, radii from 0.1 to 12. The numbers are
    // random, so no cell middle lies on a circle but by a chance too small
    // to matter.
    gas::exercises::Draw draw(901);
    for (int n = 1; n <= 300; ++n) {
      const gas::TextScreen s =
          gas::prepare_character_screen(draw.integer(3, 100), draw.integer(3, 40));
      const double width = s.columns - 2, height = 2.0 * (s.rows - 2);
      const Point centre{draw.uniform(-1, width + 1), draw.uniform(-1, height + 1)};
      CAPTURE(n);
      INFO("a screen of " << s.columns << " x " << s.rows << " characters");
      if (!check_image(s, centre, draw.magnitude(-1, 1.08))) break;
    }
  }
}
