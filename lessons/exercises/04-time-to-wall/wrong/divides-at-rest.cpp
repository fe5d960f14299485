// A wrong answer to exercise 04, kept so that CI proves the tests catch it:
// the article's trap. It divides first and mends infinity afterwards; at
// rest exactly on a limit it divides 0 by 0, and NaN slips through
// std::max(0.0, NaN) as 0: "the wall is due now" for a ball at rest.
// Caught by at least 2 tests.
#include <algorithm>
#include <cmath>

#include "stage4_first_collision.hpp"

namespace gas {

double time_to_wall(double position, double velocity, double low, double high) {
  const double t = ((velocity > 0 ? high : low) - position) / velocity;
  if (std::isinf(t)) return never;
  return std::max(0.0, t);
}

}  // namespace gas
