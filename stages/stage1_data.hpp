// Stage 1 — variables and data.
//
// What this stage does: declares everything the program knows about the gas —
// the balls, their radius, the table, the clock — and the few helpers that
// only restate what a ball's state means (where it is at a given moment).
// Article: "Gas on the display", stage 1, "variables and data" (N, a, T, T0,
// A1, A2, the arrays R(4, N) and RS(2, N)).
// Lesson: lessons/1-variables-and-data.md
//
// Assumptions: all balls are discs of one radius and one mass (the mass never
// appears: it cancels from every formula the article uses); collisions are
// perfectly elastic; the table is the rectangle 0 <= x <= A1, 0 <= y <= A2
// whose four sides are the walls. Units are the scene file's own, lengths and
// time alike (the default scene's 256 x 192 borrows the numbers of the
// article's example screen: lessons/README.md, glossary).
#pragma once

#include <vector>

namespace gas {

// A ball's column of the article's R(4, N) — R(1..4, i) for ball i — plus
// the moment it was written.
//
// The article keeps x, y, vx, vy of every ball at the common time T and moves
// every ball at every step. We write a ball's column of R only when that ball
// collides, and remember when: its centre at any later moment is
// (x + vx * (time - since), y + vy * (time - since)) until its next collision.
// A free flight is then one multiplication, not a sum of many small steps,
// and the display step T0 cannot change the physics (lesson 1 and 5).
// [anchor: ball]
struct Ball {
  double x = 0;      // R(1, i): centre x at time `since`
  double y = 0;      // R(2, i): centre y at time `since`
  double vx = 0;     // R(3, i): velocity along x
  double vy = 0;     // R(4, i): velocity along y
  double since = 0;  // model time at which x and y were written
};
// [/anchor: ball]

// A point of the plane: a ball's centre at some moment. RS(2, N) is a list of
// these.
struct Point {
  double x = 0;
  double y = 0;
};

// [anchor: gas]
struct Gas {
  double radius = 0;        // a, the radius of every ball
  double width = 0;         // A1: the walls x = 0 and x = A1
  double height = 0;        // A2: the walls y = 0 and y = A2
  std::vector<Ball> balls;  // R(4, N); N = balls.size(), ball i is balls[i - 1]
  double time = 0;          // T, the model time shown on the screen
  double display_step = 0;  // T0, how far T moves between two pictures
};
// [/anchor: gas]

// Where a ball's centre is at model time `time` (no collision in between).
// [anchor: centre-at]
inline Point centre_at(const Ball& ball, double time) {
  const double flight = time - ball.since;
  return {ball.x + ball.vx * flight, ball.y + ball.vy * flight};
}
// [/anchor: centre-at]

// The centres of all balls at model time `time`: the positions stage 6 draws.
std::vector<Point> centres_at(const Gas& gas, double time);

// Kinetic energy (unit mass): sum of (vx^2 + vy^2) / 2.
// [anchor: kinetic-energy-declaration]
double kinetic_energy(const Gas& gas);
// [/anchor: kinetic-energy-declaration]

// Total momentum (unit mass): the sum of the velocities.
Point total_momentum(const Gas& gas);

// Mean speed: the average of sqrt(vx^2 + vy^2); 0 for no balls.
// [anchor: mean-speed-declaration]
double mean_speed(const Gas& gas);
// [/anchor: mean-speed-declaration]

}  // namespace gas
