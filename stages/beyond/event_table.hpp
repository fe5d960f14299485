// Stage 4 — first collision, by a table of next events (beyond the article).
//
// What this file does: keeps, for every ball, the earliest event it takes
// part in (a wall, or a meeting with another ball) and finds TC, K, N1, N2
// as the earliest entry of that table. After a collision only the balls that
// collided have new columns of R, so only the predictions involving them are
// made again: each of them against the walls and every other ball (the other
// balls' entries improve if the new prediction is earlier), and, in full, any
// ball whose entry named one of them as its partner (that prediction is gone).
// About 2N predictions per collision instead of the scan's N(N + 1)/2.
// Beyond the article: the article scans every wall and every pair for each
// collision. The answer here is the scan's, bit for bit, ties included: the
// same formulas (stage 4's time_to_wall and time_of_contact) and the scan's
// order (beyond/event_order.hpp).
// Lesson: lessons/10-scaling.md
//
// Assumptions: between two calls of `first`, the gas changes only by the
// collision passed to `update` (stage 5's apply_collision); after anything
// else that rewrites columns of R (the B key, a new scene), call `rebuild`.
#pragma once

#include <cstdint>
#include <vector>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

class EventTable final : public FirstCollisionFinder {
 public:
  // Predicts every ball's earliest event from scratch: N(N + 1)/2 predictions.
  void rebuild(const Gas& gas, const CentreLimits& limits) override;

  // The first collision, as find_first_collision(gas, limits) gives it.
  Collision first(const Gas& gas) override;

  // After stage 5 carried out `done` (rows of N1, and N2 for K = 3, rewritten):
  // makes again the predictions that involve those balls.
  void update(const Gas& gas, const Collision& done) override;

  const char* name() const override { return "table"; }

 private:
  // A ball's earliest event: a wall (partner 0) or a meeting with `partner`.
  struct Entry {
    double time = never;
    std::uint64_t place = 0;  // the event's place in the scan (scan_place)
    CollisionKind kind = CollisionKind::none;
    int partner = 0;
  };

  void offer(int ball, double time, CollisionKind kind, int partner);
  void predict_walls(const Gas& gas, int ball);

  CentreLimits limits_;
  std::vector<Entry> next_;  // next_[i - 1]: the earliest event of ball i
};

}  // namespace gas
