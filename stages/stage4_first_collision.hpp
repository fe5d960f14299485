// Stage 4 — first collision.
//
// What this stage does: looks at every ball and every pair of balls and finds
// the earliest coming collision: its time TC, its kind K and the balls N1, N2.
// Article: "Gas on the display", stage 4, "first collision" (start with a
// large TC, check each ball against the walls, then every pair N3 < N4 by the
// quadratic "the distance of the centres becomes 2a").
// Lesson: lessons/4-first-collision.md
//
// Assumptions: the balls fly freely (stage 1's centre_at) until the collision
// found here; nothing in this stage changes the gas.
#pragma once

#include <limits>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"

namespace gas {

// K, the kind of a collision.
enum class CollisionKind {
  none = 0,             // K = 0: nothing will ever collide (e.g. one ball at rest)
  horizontal_wall = 1,  // K = 1: the wall y = 0 or y = A2; vy changes sign
  vertical_wall = 2,    // K = 2: the wall x = 0 or x = A1; vx changes sign
  balls = 3,            // K = 3: ball N1 meets ball N2
};

inline constexpr double never = std::numeric_limits<double>::infinity();

// The result of stage 4.
// [anchor: collision]
struct Collision {
  double time = never;                       // TC, model time of the collision
  CollisionKind kind = CollisionKind::none;  // K
  int first = 0;                             // N1, numbered 1..N as in the scene
  int second = 0;                            // N2 for K = 3, else 0
};
// [/anchor: collision]

// How long until a centre at `position`, moving at `velocity`, reaches the
// limit it is moving towards (`low` if moving down, `high` if moving up).
// Never divides by zero: a centre at rest along this axis reaches no wall.
// A centre already at or beyond that limit reaches it now (0).
double time_to_wall(double position, double velocity, double low, double high);

// The model time at which the centres of balls p and q come 2a apart while
// approaching each other, or `never`. Balls that already touch or overlap
// (round-off) and are approaching collide at once; balls moving apart, or
// at rest relative to each other, never collide.
double time_of_contact(const Ball& p, const Ball& q, double diameter);

// The earliest collision of the gas, scanning as the article does: for each
// ball the walls (K = 1, then K = 2), then every pair N3 < N4 (K = 3). A
// collision wins only if it is strictly earlier than the best so far, so of
// simultaneous collisions the first one scanned is taken. TC is never earlier
// than gas.time.
Collision find_first_collision(const Gas& gas, const CentreLimits& limits);

}  // namespace gas
