// Exercise 09 — YOUR ball_image (stage 6, output: a ball on the text screen).
//
// The task: lessons/exercises/09-ball-image/instructions.md. The tests:
// test_ball_image.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in stages/stage6_output.cpp.
// ([[maybe_unused]] only keeps the compiler quiet while the body is a
// placeholder; delete it when you like.)
#include <vector>

#include "stage6_output.hpp"

namespace gas {

std::vector<Cell> ball_image([[maybe_unused]] const TextScreen& screen,
                             [[maybe_unused]] Point centre,
                             [[maybe_unused]] double radius) {
  // TODO: the cells the ball covers: first the cell of its centre, then
  // every other cell whose middle is within `radius` of the centre.
  return {};  // placeholder: no cells, an invisible ball
}

}  // namespace gas
