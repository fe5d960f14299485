// Exercise 11 — YOUR mean_speed (beyond the article: the figure its stage 6
// suggests printing).
//
// The task: lessons/exercises/11-mean-speed/instructions.md. The tests:
// test_mean_speed.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in stages/stage1_data.cpp.
// ([[maybe_unused]] only keeps the compiler quiet while the body is a
// placeholder; delete it when you like.)
#include <cmath>
#include <limits>

#include "stage1_data.hpp"

namespace gas {

double mean_speed([[maybe_unused]] const Gas& gas) {
  // TODO: the average over the balls of the speed sqrt(vx^2 + vy^2); 0 for
  // a gas without balls.
  return std::numeric_limits<double>::quiet_NaN();  // placeholder: "not a number yet"
}

}  // namespace gas
