// A wrong answer to exercise 07, kept so that CI proves the tests catch it.
// The velocities are right, but it also does what stage 5's name, "new
// coordinates", seems to ask: it moves both balls on by their new
// velocities, x += vx and y += vy. The balls jump, and the run's collisions
// change with them.
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
  for (Ball* ball : {&p, &q}) {
    ball->x += ball->vx;
    ball->y += ball->vy;
  }
}

}  // namespace gas
