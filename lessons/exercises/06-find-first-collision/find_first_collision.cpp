// Exercise 06 — YOUR find_first_collision (stage 4, first collision: the scan).
//
// The task: lessons/exercises/06-find-first-collision/instructions.md. The
// tests: test_find_first_collision.cpp beside this file. Once you have
// edited it, this definition stands in for the reference one
// in stages/stage4_first_collision.cpp. ([[maybe_unused]] only keeps the
// compiler quiet while the body is a placeholder; delete it when you like.)
#include <algorithm>

#include "stage4_first_collision.hpp"

namespace gas {

Collision find_first_collision([[maybe_unused]] const Gas& gas,
                               [[maybe_unused]] const CentreLimits& limits) {
  // TODO: the earliest collision TC, its kind K and its balls N1, N2: each
  // ball against the walls (time_to_wall), then every pair (time_of_contact).
  return Collision{};  // placeholder: K = 0, TC = never, "nothing ever collides"
}

}  // namespace gas
