// A wrong answer to exercise 04, kept so that CI proves the tests catch it.
// Right for the limits 1 and 9 of the first tests, and only for those: it
// never looks at `low` and `high`.
#include <algorithm>

#include "stage4_first_collision.hpp"

namespace gas {

double time_to_wall(double position, double velocity, double, double) {
  if (velocity > 0) return std::max(0.0, (9 - position) / velocity);
  if (velocity < 0) return std::max(0.0, (1 - position) / velocity);
  return never;
}

}  // namespace gas
