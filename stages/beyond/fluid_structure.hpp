// The structure of the fluid at one moment (beyond the article): how the
// balls crowd each other, and how they crowd a wall, at contact.
//
// What this file does: from the centres at one moment it measures two
// contact values that the theory of the hard-disc fluid predicts — the pair
// correlation g(r) just outside contact, r = 2a, among the balls of the
// interior (its value there is the g(2a) of the virial theorem and of
// Enskog's collision rate), and the density of centres against the walls
// x = 0 and x = A1, whose value at contact the contact theorem ties to the
// pressure: kT n(contact) = P. Each is read from two thin shells or strips
// and extrapolated to contact along a straight line. One call walks the
// balls once (with cells 2.5a wide for the pairs); the statistics take one
// snapshot every N collisions and average them (beyond/gas_statistics).
// Article: none; the article's screen shows no structure. Beyond it.
// Lesson: lessons/11-kinetic-theory.md
//
// Assumptions: one radius a; the interior is a rectangle of centres well
// away from the walls (the statistics' interior), and the strips at the
// walls x = 0 and x = A1 are taken only for y inside it, away from the
// corners.
#pragma once

#include "stage1_data.hpp"

namespace gas {

// The width of the shells and strips, in radii: thin enough that a straight
// line through two of them reaches contact within about the noise (where
// g(r) curves, at eta = 0.5, it ends some 0.3 % low: lesson 11), wide enough
// to hold balls at every snapshot.
inline constexpr double contact_shell_radii = 0.05;

// A rectangle of centres, x_min <= x <= x_max, y_min <= y <= y_max: the
// statistics' interior (empty on a table too small to have one).
struct Region {
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  bool contains(double x, double y) const {
    return x >= x_min && x <= x_max && y >= y_min && y <= y_max;
  }
  bool empty() const { return !(x_max > x_min && y_max > y_min); }
  double area() const { return empty() ? 0.0 : (x_max - x_min) * (y_max - y_min); }
};

// Contact values at one moment; NaN where there is nothing to measure (no
// interior, no ball in it).
struct ContactSnapshot {
  double pair_contact = 0;  // g(2a+): pairs at 2a ... 2a + 2 shells, extrapolated
  double wall_contact_density =
      0;  // centres per area at the walls x = 0, A1, extrapolated
};

// The contact values of the gas at `time`, for the interior (of the centres).
ContactSnapshot contact_snapshot(const Gas& gas, double time, const Region& interior);

}  // namespace gas
