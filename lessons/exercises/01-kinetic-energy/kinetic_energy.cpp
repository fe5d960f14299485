// Exercise 01 — YOUR kinetic_energy (stage 1, variables and data).
//
// The task: lessons/exercises/01-kinetic-energy/instructions.md. The tests:
// test_kinetic_energy.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in stages/stage1_data.cpp.
// ([[maybe_unused]] only keeps the compiler quiet while the body is a
// placeholder; delete it when you like.)
#include <limits>

#include "stage1_data.hpp"

namespace gas {

double kinetic_energy([[maybe_unused]] const Gas& gas) {
  // TODO: add up (vx^2 + vy^2) / 2 over every ball of gas.balls.
  return std::numeric_limits<double>::quiet_NaN();  // placeholder: "not a number yet"
}

}  // namespace gas
