// Exercise 05 — YOUR time_of_contact (stage 4, first collision: two balls).
//
// The task: lessons/exercises/05-time-of-contact/instructions.md. The tests:
// test_time_of_contact.cpp beside this file. Once you have
// edited it, this definition stands in for the reference one
// in stages/stage4_first_collision.cpp. ([[maybe_unused]] only keeps the
// compiler quiet while the body is a placeholder; delete it when you like.)
#include <algorithm>
#include <cmath>
#include <limits>

#include "stage4_first_collision.hpp"

namespace gas {

double time_of_contact([[maybe_unused]] const Ball& p, [[maybe_unused]] const Ball& q,
                       [[maybe_unused]] double diameter) {
  // TODO: the model time at which the centres of p and q come `diameter`
  // apart while approaching each other, or `never`.
  return std::numeric_limits<double>::quiet_NaN();  // placeholder: "not a number yet"
}

}  // namespace gas
