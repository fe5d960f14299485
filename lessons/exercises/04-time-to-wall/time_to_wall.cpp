// Exercise 04 — YOUR time_to_wall (stage 4, first collision: the walls).
//
// The task: lessons/exercises/04-time-to-wall/instructions.md. The tests:
// test_time_to_wall.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in
// stages/stage4_first_collision.cpp. ([[maybe_unused]] only keeps the
// compiler quiet while the body is a placeholder; delete it when you like.)
#include <algorithm>
#include <limits>

#include "stage4_first_collision.hpp"

namespace gas {

double time_to_wall([[maybe_unused]] double position, [[maybe_unused]] double velocity,
                    [[maybe_unused]] double low, [[maybe_unused]] double high) {
  // TODO: how long until `position`, moving at `velocity`, reaches the limit
  // it moves towards (`high` moving up, `low` moving down); `never` at rest.
  return std::numeric_limits<double>::quiet_NaN();  // placeholder: "not a number yet"
}

}  // namespace gas
