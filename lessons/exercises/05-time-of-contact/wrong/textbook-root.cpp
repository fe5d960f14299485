// A wrong answer to exercise 05, kept so that CI proves the tests catch it:
// the trap of this exercise. Everything is right but the root, taken in the
// textbook form (-b - sqrt(D)) / (w.w), which cancels when the balls nearly
// touch.
// Caught by at least 2 tests.
#include <algorithm>
#include <cmath>

#include "stage4_first_collision.hpp"

namespace gas {

double time_of_contact(const Ball& p, const Ball& q, double diameter) {
  const double start = std::max(p.since, q.since);
  const Point rp = centre_at(p, start);
  const Point rq = centre_at(q, start);
  const double dx = rq.x - rp.x, dy = rq.y - rp.y;
  const double wx = q.vx - p.vx, wy = q.vy - p.vy;
  const double b = dx * wx + dy * wy;
  if (b >= 0) return never;
  const double c = dx * dx + dy * dy - diameter * diameter;
  if (c <= 0) return start;
  const double ww = wx * wx + wy * wy;
  const double discriminant = b * b - ww * c;
  if (discriminant <= 0) return never;
  return start + (-b - std::sqrt(discriminant)) / ww;
}

}  // namespace gas
