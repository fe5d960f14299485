// Exercise 07 — YOUR collide_balls (stage 5, new coordinates: the formula VI).
//
// The task: lessons/exercises/07-collide-balls/instructions.md. The tests:
// test_collide_balls.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in
// stages/stage5_new_coordinates.cpp. ([[maybe_unused]] only keeps the
// compiler quiet while the body is a placeholder; delete it when you like.)
#include "stage5_new_coordinates.hpp"

namespace gas {

void collide_balls([[maybe_unused]] Ball& p, [[maybe_unused]] Ball& q) {
  // TODO: the new velocities of p and q, two balls in contact, by the
  // article's VI. (Placeholder: nothing changes, as if they passed through.)
}

}  // namespace gas
