// A wrong answer to exercise 07, kept so that CI proves the tests catch it.
// The velocities are right, but it also sets both balls' `since` to 0, as
// if a collision started their clocks again: their columns of R now say they were
// at x, y at time 0, and every later centre is computed from the wrong
// moment.
#include "stage5_new_coordinates.hpp"

namespace gas {

void collide_balls(Ball& p, Ball& q) {
  const double dx = q.x - p.x, dy = q.y - p.y;
  const double wx = q.vx - p.vx, wy = q.vy - p.vy;
  const double vi = (dx * wx + dy * wy) / (dx * dx + dy * dy);
  p.vx += vi * dx;
  q.vx -= vi * dx;
  p.vy += vi * dy;
  q.vy -= vi * dy;
  p.since = 0;
  q.since = 0;
}

}  // namespace gas
