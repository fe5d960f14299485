// Exercise 03 — YOUR TextScreen::cell_of (stage 3, screen preparation).
//
// The task: lessons/exercises/03-cell-of/instructions.md. The tests:
// test_cell_of.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in stages/stage3_screen.cpp.
// ([[maybe_unused]] only keeps the compiler quiet while the body is a
// placeholder; delete it when you like.)
#include <algorithm>
#include <cmath>

#include "stage3_screen.hpp"

namespace gas {

Cell TextScreen::cell_of([[maybe_unused]] Point p) const {
  // TODO: the column and the row of the character whose area holds p, kept
  // inside the border. Column 1 starts at x = 0; row 1 is the top row.
  return {1, 1};  // placeholder: the top-left cell inside the border
}

}  // namespace gas
