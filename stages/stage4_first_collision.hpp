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

#include <algorithm>
#include <cstddef>
#include <limits>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"

namespace gas {

// K, the kind of a collision.
// [anchor: collision-kind]
enum class CollisionKind {
  none = 0,             // K = 0: nothing will ever collide (e.g. one ball at rest)
  horizontal_wall = 1,  // K = 1: the wall y = 0 or y = A2; vy changes sign
  vertical_wall = 2,    // K = 2: the wall x = 0 or x = A1; vx changes sign
  balls = 3,            // K = 3: ball N1 meets ball N2
};

inline constexpr double never = std::numeric_limits<double>::infinity();
// [/anchor: collision-kind]

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
// [anchor: time-to-wall-declaration]
double time_to_wall(double position, double velocity, double low, double high);
// [/anchor: time-to-wall-declaration]

// The model time at which the centres of balls p and q come 2a apart while
// approaching each other, or `never`. Balls that already touch or overlap
// (round-off) and are approaching collide at once; balls moving apart, or
// at rest relative to each other, never collide.
// [anchor: time-of-contact-declaration]
double time_of_contact(const Ball& p, const Ball& q, double diameter);
// [/anchor: time-of-contact-declaration]

// The scan's time for ball `number` (1..N) to reach a wall of kind K = 1
// (y = a or y = A2 - a) or K = 2 (x = a or x = A1 - a): its time plus
// time_to_wall along that axis. Every way of stage 4 computes a wall's time
// with this one expression, so all of them get the same bits.
// [anchor: wall-time]
inline double wall_time(const Gas& gas, const CentreLimits& limits, int number,
                        CollisionKind kind) {
  const Ball& ball = gas.balls[static_cast<std::size_t>(number - 1)];
  return kind == CollisionKind::horizontal_wall
             ? ball.since + time_to_wall(ball.y, ball.vy, limits.y_min, limits.y_max)
             : ball.since + time_to_wall(ball.x, ball.vx, limits.x_min, limits.x_max);
}
// [/anchor: wall-time]

// The scan's time for balls N3 < N4 to meet: time_of_contact(N3, N4), in that
// order (the order of the arguments matters to the last bit, through the sums
// in its round-off floor), for every way of stage 4 alike.
inline double pair_time(const Gas& gas, int n3, int n4) {
  return time_of_contact(gas.balls[static_cast<std::size_t>(n3 - 1)],
                         gas.balls[static_cast<std::size_t>(n4 - 1)], 2 * gas.radius);
}

// The last line of the scan: round-off can place a collision a hair before
// the present T; it is due now.
inline Collision due_from(Collision first, double now) {
  if (first.kind != CollisionKind::none) first.time = std::max(first.time, now);
  return first;
}

// The earliest collision of the gas: the balls in the article's order, by
// number, each against its walls (K = 1, then K = 2: this order within a
// ball is ours, the article gives none), then every pair N3 < N4 (K = 3), the
// article's double loop. A collision wins only if it is strictly earlier
// than the best so far, so of simultaneous collisions the first one scanned
// is taken. (The article's wall test lets the last one scanned win a tie:
// of two balls reaching a wall at one TC it keeps the later-numbered; lesson
// 4 says why we keep the first.) TC is never earlier than gas.time.
// [anchor: find-first-collision-declaration]
Collision find_first_collision(const Gas& gas, const CentreLimits& limits);
// [/anchor: find-first-collision-declaration]

// Stage 4 as stage 7 calls it: "a first-collision finder". The article's
// scan is one (ArticleScan, below); faster ones that keep their predictions
// from one collision to the next live beyond the article
// (stages/beyond/strategy.hpp, lesson 10). Every finder gives the scan's TC,
// K, N1, N2 to the last bit, ties included.
// [anchor: first-collision-finder]
class FirstCollisionFinder {
 public:
  virtual ~FirstCollisionFinder() = default;
  // Predicts from scratch: at the start, and after anything but a collision
  // rewrote columns of R (the B key).
  virtual void rebuild(const Gas& gas, const CentreLimits& limits) = 0;
  // The first collision: TC, K, N1, N2, as find_first_collision gives it.
  virtual Collision first(const Gas& gas) = 0;
  // Told after stage 5 carried out `done` (N1's column of R, and N2's, rewritten).
  virtual void update(const Gas& gas, const Collision& done) = 0;
  // Its name, for messages: "scan", "table", "grid".
  virtual const char* name() const = 0;
};

// The article's scan as a finder: it keeps nothing between collisions and
// scans every wall and every pair each time.
class ArticleScan final : public FirstCollisionFinder {
 public:
  void rebuild(const Gas&, const CentreLimits& limits) override { limits_ = limits; }
  Collision first(const Gas& gas) override { return find_first_collision(gas, limits_); }
  void update(const Gas&, const Collision&) override {}
  const char* name() const override { return "scan"; }

 private:
  CentreLimits limits_;  // G1, G2 and the lower limits, from stage 3
};
// [/anchor: first-collision-finder]

}  // namespace gas
