// Stage 5 — new coordinates. See stage5_new_coordinates.hpp.
#include "stage5_new_coordinates.hpp"

namespace gas {

#ifndef GAS_STUDENT_SHIFT_TIME  // see lessons/exercises/08-shift-time
// [anchor: shift-time]
void shift_time(Gas& gas, Picture& picture, double new_time) {
  gas.time = new_time;                          // T = T + T1
  picture.old_centres.swap(picture.centres);    // remember the old coordinates (RS)
  picture.centres = centres_at(gas, gas.time);  // the coordinates after T1
  if (picture.old_centres.size() != picture.centres.size()) {
    picture.old_centres = picture.centres;  // the first picture has no past
  }
}
// [/anchor: shift-time]
#endif

// The article's VI with d = r2 - r1, w = v2 - v1:
//   VI = (d.w) / 4a^2,  v1' = v1 + VI d,  v2' = v2 - VI d.
// It exchanges the balls' velocity components along d and leaves the rest.
// At contact |d|^2 = 4a^2; we divide by the |d|^2 of the actual centres, which
// round-off may leave a hair off 4a^2, because only then is the kinetic energy
// exactly what it was (lesson 5 derives it).
#ifndef GAS_STUDENT_COLLIDE_BALLS  // see lessons/exercises/07-collide-balls
// [anchor: collide-balls]
void collide_balls(Ball& p, Ball& q) {
  const double dx = q.x - p.x, dy = q.y - p.y;                  // d = r2 - r1
  const double wx = q.vx - p.vx, wy = q.vy - p.vy;              // w = v2 - v1
  const double vi = (dx * wx + dy * wy) / (dx * dx + dy * dy);  // VI
  p.vx += vi * dx;
  q.vx -= vi * dx;
  p.vy += vi * dy;
  q.vy -= vi * dy;
}
// [/anchor: collide-balls]
#endif

namespace {

// Moves one ball along its flight to model time `time` and records it there.
// [anchor: move-to]
void move_to(Ball& ball, double time) {
  const Point centre = centre_at(ball, time);
  ball.x = centre.x;
  ball.y = centre.y;
  ball.since = time;
}
// [/anchor: move-to]

}  // namespace

// [anchor: apply-collision]
void apply_collision(Gas& gas, const CentreLimits& limits, const Collision& collision) {
  Ball& first = gas.balls[static_cast<std::size_t>(collision.first - 1)];  // N1
  move_to(first, collision.time);
  switch (collision.kind) {
    case CollisionKind::horizontal_wall:  // K = 1: vy changes sign
      first.y = first.vy > 0 ? limits.y_max : limits.y_min;
      first.vy = -first.vy;
      break;
    case CollisionKind::vertical_wall:  // K = 2: vx changes sign
      first.x = first.vx > 0 ? limits.x_max : limits.x_min;
      first.vx = -first.vx;
      break;
    case CollisionKind::balls: {  // K = 3: N1 and N2 by VI
      Ball& second = gas.balls[static_cast<std::size_t>(collision.second - 1)];
      move_to(second, collision.time);
      collide_balls(first, second);
      break;
    }
    case CollisionKind::none:
      break;
  }
}
// [/anchor: apply-collision]

void reverse_velocities(Gas& gas) {
  for (Ball& ball : gas.balls) {
    move_to(ball, gas.time);
    ball.vx = -ball.vx;
    ball.vy = -ball.vy;
  }
}

}  // namespace gas
