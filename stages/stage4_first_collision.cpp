// Stage 4 — first collision. See stage4_first_collision.hpp.
#include "stage4_first_collision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gas {

// The article avoids dividing by zero by first asking whether the ball gets
// past the limit by TC at all ("x + vx (TC - T) < G1"). A ball at rest
// along x never does, so the division is never reached. Here the same
// question is asked of the sign of the velocity: only a centre moving towards
// a wall has a time to it.
#ifndef GAS_STUDENT_TIME_TO_WALL  // see lessons/exercises/04-time-to-wall
// [anchor: time-to-wall]
double time_to_wall(double position, double velocity, double low, double high) {
  if (velocity > 0) return std::max(0.0, (high - position) / velocity);
  if (velocity < 0) return std::max(0.0, (low - position) / velocity);
  return never;  // at rest along this axis: no wall, no division
}
// [/anchor: time-to-wall]
#endif

// The article's quadratic, with d = r2 - r1 and w = v2 - v1 at a common time:
//   |d + w t|^2 = (2a)^2,  i.e.  (w.w) t^2 + 2 (d.w) t + (d.d - 4a^2) = 0.
// Call b = d.w, c = d.d - 4a^2. The balls approach only if b < 0; the
// (quarter) discriminant is D = b^2 - (w.w) c. The smaller root is
//   t = (-b - sqrt(D)) / (w.w)                  (as printed in textbooks)
//     = c / (-b + sqrt(D))                      (the same number, times its conjugate)
// The first form subtracts two nearly equal numbers whenever c is small
// (balls close together: every collision a moment after another), and loses
// the digits of t; the second only adds two positive numbers. So we use the
// second.
#ifndef GAS_STUDENT_TIME_OF_CONTACT  // see lessons/exercises/05-time-of-contact
// [anchor: time-of-contact]
double time_of_contact(const Ball& p, const Ball& q, double diameter) {
  // Both centres at the later of the two balls' times.
  const double start = std::max(p.since, q.since);
  const Point rp = centre_at(p, start);
  const Point rq = centre_at(q, start);
  const double dx = rq.x - rp.x, dy = rq.y - rp.y;  // d = r2 - r1
  const double wx = q.vx - p.vx, wy = q.vy - p.vy;  // w = v2 - v1
  const double b = dx * wx + dy * wy;               // d.w
  if (b >= 0) return never;                         // moving apart, or side by side
  // The balls approach if d.w < 0 — by more than round-off: the velocities
  // are known to about epsilon times their size, and a d.w below that
  // floor is noise. (Two touching balls whose velocities differ in the last
  // bit would otherwise "collide" for ever at one instant: the change VI
  // makes is too small to alter a single bit. Lesson 4 tells the story.)
  const double noise =
      4 * std::numeric_limits<double>::epsilon() * (std::fabs(dx) + std::fabs(dy)) *
      (std::fabs(p.vx) + std::fabs(p.vy) + std::fabs(q.vx) + std::fabs(q.vy));
  if (b >= -noise) return never;  // no relative motion worth the name
  const double c = dx * dx + dy * dy - diameter * diameter;
  if (c <= 0) return start;  // touching or overlapping: now
  const double ww = wx * wx + wy * wy;
  const double discriminant = b * b - ww * c;        // D
  if (discriminant <= 0) return never;               // they miss (D < 0) or graze (D = 0)
  return start + c / (std::sqrt(discriminant) - b);  // the smaller root
}
// [/anchor: time-of-contact]
#endif

#ifndef GAS_STUDENT_FIND_FIRST_COLLISION  // see lessons/exercises/06-find-first-collision
// [anchor: find-first-collision]
Collision find_first_collision(const Gas& gas, const CentreLimits& limits) {
  Collision first;  // TC = "a large number", K = 0, N1 = N2 = 0
  const int n = static_cast<int>(gas.balls.size());

  // Find the earliest wall collision: each ball against the walls.
  for (int i = 1; i <= n; ++i) {
    const double horizontal = wall_time(gas, limits, i, CollisionKind::horizontal_wall);
    const double vertical = wall_time(gas, limits, i, CollisionKind::vertical_wall);
    if (horizontal < first.time)
      first = {horizontal, CollisionKind::horizontal_wall, i, 0};
    if (vertical < first.time) first = {vertical, CollisionKind::vertical_wall, i, 0};
  }

  // Find an earlier collision of two balls: every pair N3 < N4.
  for (int n3 = 1; n3 < n; ++n3) {
    for (int n4 = n3 + 1; n4 <= n; ++n4) {
      const double contact = pair_time(gas, n3, n4);
      if (contact < first.time) first = {contact, CollisionKind::balls, n3, n4};
    }
  }

  // Round-off can place a collision a hair before the present; it is due now.
  return due_from(first, gas.time);
}
// [/anchor: find-first-collision]
#endif

}  // namespace gas
