// Stage 5 — new coordinates.
//
// What this stage does: shifts time by T1 — a whole display step T0, or only
// up to the first collision TC — remembers the old centres (RS) so that stage
// 6 can erase them, computes the new centres, and, when the step ends on a
// collision, gives the colliding balls their new velocities.
// Article: "Gas on the display", stage 5, "new coordinates" (T1 = T0 if
// TC > T + T0, T1 = TC - T if TC < T + T0, and TC = T + T0 left open: the
// glossary of lessons/README.md; new velocities of N1 (K != 3) or of N1 and
// N2 (K = 3) by the formula for VI).
// Lesson: lessons/5-new-coordinates.md
//
// Assumptions: the physics moves from collision to collision (stage 1's Ball
// keeps the moment it was written), so T1 only decides where the picture is
// taken: any T0 gives the same collisions, bit for bit.
#pragma once

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

// T1, the time to the next picture: the display step T0 if the first
// collision comes later than T + T0, else just up to the collision, T1 = TC - T.
// (At TC = T + T0 exactly, which the article leaves open, the step ends on
// the collision: lessons/README.md, glossary.) Stage 7's loop asks this one
// function where each step ends.
// [anchor: step-length]
struct StepEnd {
  double time = 0;            // T + T1, the model time of the next picture
  bool on_collision = false;  // T1 = TC - T: the step ends on the first collision
};

inline StepEnd step_end(double now, double display_step, double collision_time) {
  // TC > T + T0: no collision in this step, T1 = T0.
  if (collision_time > now + display_step) return {now + display_step, false};
  // Else T1 = TC - T: the step ends at exactly TC (T + (TC - T) may round to
  // either side of it).
  return {collision_time, true};
}
// [/anchor: step-length]

// The centres a picture shows: the old ones (RS) and the new ones.
// [anchor: picture]
struct Picture {
  std::vector<Point> old_centres;  // RS(2, N): the centres drawn last time
  std::vector<Point> centres;      // the centres at T, to draw now
};
// [/anchor: picture]

// Shifts the clock to `new_time` (T + T1): the centres drawn so far become the
// old ones, and the centres at the new time are computed.
// [anchor: shift-time-declaration]
void shift_time(Gas& gas, Picture& picture, double new_time);
// [/anchor: shift-time-declaration]

// The new velocities of two balls in contact, by the article's VI formula.
// Requires p != q. Only the components along the line of centres change.
// [anchor: collide-balls-declaration]
void collide_balls(Ball& p, Ball& q);
// [/anchor: collide-balls-declaration]

// Carries out a collision found by stage 4 at its time TC: moves the ball(s)
// involved to TC and gives them their new velocities. A ball hitting a wall is
// put exactly on its limit, so round-off never lets a ball through a wall.
void apply_collision(Gas& gas, const CentreLimits& limits, const Collision& collision);

// The B key: every velocity reversed, at the present time.
void reverse_velocities(Gas& gas);

}  // namespace gas
