// Exercise 08 — YOUR shift_time (stage 5, new coordinates: the step T1).
//
// The task: lessons/exercises/08-shift-time/instructions.md. The tests:
// test_shift_time.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in
// stages/stage5_new_coordinates.cpp. ([[maybe_unused]] only keeps the
// compiler quiet while the body is a placeholder; delete it when you like.)
#include "stage5_new_coordinates.hpp"

namespace gas {

void shift_time(Gas& gas, [[maybe_unused]] Picture& picture, double new_time) {
  gas.time = new_time;  // T = T + T1: given, so that gas-student's clock runs
  // TODO: remember the centres drawn so far as the old ones (RS), and put
  // the centres at the new time into picture.centres.
}

}  // namespace gas
