// Tangent dynamics (beyond the article): how an infinitesimal change of the
// gas's state is carried along the exact motion, flight by flight and
// collision by collision.
//
// What this file does: keeps, for every ball, a small change of its state —
// dq (of the centre) and dp (of the velocity; mass 1) — and moves it with the
// ball: during a free flight dq grows by dp t; at a wall both are reflected;
// at a collision of two balls the linearised collision map below mixes the
// two balls' changes. This is how the physics literature computes the
// Lyapunov exponents of hard discs (C. Dellago, H. A. Posch and W. G. Hoover,
// "Lyapunov instability in a system of hard disks in equilibrium and
// nonequilibrium steady states", Phys. Rev. E 53, 1485 (1996)); the map is
// derived in lesson 15 and checked by finite differences of stage 5 itself
// (tests/test_lyapunov.cpp).
// Article: none; the article's stage 5 carries out the collisions this
// follows. Everything here is beyond it.
// Lesson: lessons/15-chaos.md
//
// Assumptions: unit mass, equal radii; the change of a ball is kept, like its
// row of R, as of the moment `since` it was last written, so that a collision
// costs O(1) whatever N (the flight in between is one multiplication).
#pragma once

#include <cstdint>
#include <vector>

#include "stage1_data.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

// The change of one ball's state: dq at model time `since`, and dp.
// [anchor: ball-tangent]
struct BallTangent {
  double qx = 0, qy = 0;  // dq: the change of the centre, at time `since`
  double px = 0, py = 0;  // dp: the change of the velocity
  double since = 0;       // model time at which qx, qy were written
};
// [/anchor: ball-tangent]

// Free flight: dq at `time` (dq + dp (time - since)); no collision in between.
inline Point tangent_dq_at(const BallTangent& t, double time) {
  const double flight = time - t.since;
  return {t.qx + t.px * flight, t.qy + t.py * flight};
}

// Brings the change of a ball to `time` along its free flight.
void move_tangent_to(BallTangent& t, double time);

// The reflection at a wall (K = 1: y flips; K = 2: x flips), for a change
// written at the moment of the bounce: both dq and dp are reflected, because
// the earlier or later bounce of the changed ball exactly makes up for the
// wall's being reached sooner or later (lesson 15).
void reflect_tangent(BallTangent& t, CollisionKind kind);

// The linearised collision map of two balls at contact, for changes written
// at the moment of the collision. `qi`, `qj`: the centres at contact;
// `vi`, `vj`: the velocities just before. With n = (qi - qj) / |qi - qj|,
// v_ij = vi - vj, dq_ij = dq_i - dq_j, dp_ij = dp_i - dp_j:
//   dt_c  = -(dq_ij . n) / (v_ij . n)          the collision's time shift
//   dn    = (dq_ij + v_ij dt_c) / |qi - qj|    the turn of the normal
//   dq_i' = dq_i - (dq_ij . n) n,   dq_j' = dq_j + (dq_ij . n) n
//   dp_i' = dp_i - (dp_ij . n) n - (v_ij . dn) n - (v_ij . n) dn,
//   dp_j' = dp_j + (the same).
void collide_tangents(BallTangent& i, BallTangent& j, Point qi, Point qj, Point vi,
                      Point vj);

// The changes of every ball, carried along a running gas through stage 7's
// hook (the caller forwards before_collision; beyond/lyapunov.hpp does).
class TangentDynamics {
 public:
  // A change of unit Euclidean norm (all 4N components) in a direction drawn
  // from `seed` (the same seed, the same direction), written at the gas's T.
  TangentDynamics(const Gas& gas, std::uint64_t seed);

  // Before stage 5 carries out `collision`: the balls' changes brought to TC
  // and mapped through it (from the gas as it is before: the centres at TC
  // and the old velocities).
  void before_collision(const Gas& gas, const Collision& collision);

  // The Euclidean norm of the whole change at `time` (no collision between
  // the balls' last collisions and `time`); walks the balls once.
  double norm_at(double time) const;
  // Every change brought to `time` and multiplied by `factor` (Benettin's
  // renormalisation); walks the balls once.
  void scale_at(double time, double factor);
  // A fresh change drawn from `seed`, of unit norm, at `time`.
  void restart(double time, std::uint64_t seed);
  // Every change brought to `time`, its dp reversed (the key B reverses every
  // velocity: the same change, seen by the reversed gas).
  void reverse_at(double time);

  const std::vector<BallTangent>& balls() const { return balls_; }
  std::vector<BallTangent>& balls() { return balls_; }

 private:
  std::vector<BallTangent> balls_;  // ball i is balls_[i - 1], as in the gas
};

}  // namespace gas
