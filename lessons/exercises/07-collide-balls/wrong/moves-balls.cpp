// A wrong answer to exercise 07, kept so that CI proves the tests catch it.
// The velocities are right, but it also moves the balls a hair along their
// new velocities "so that they no longer touch", and writes them at that
// moment: x, y and since change, and the run's collisions with them.
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
  const double hair = 1e-9;
  for (Ball* ball : {&p, &q}) {
    ball->x += ball->vx * hair;
    ball->y += ball->vy * hair;
    ball->since += hair;
  }
}

}  // namespace gas
