// Stage 4 — first collision: the order of the article's scan, as a key.
//
// What this file does: gives every event stage 4 can find a key — its time,
// then its place in the article's scan. (Each event's time comes from the
// scan's own expressions: wall_time and pair_time in stage 4.) A program that
// keeps its predictions from one collision to the next (beyond/event_table.*,
// the grids of beyond/plain_grid.* and beyond/cell_grid.*) and takes the event
// with the smallest key finds exactly the collision the scan finds: the same
// TC to the last bit, and the same K, N1, N2 when events tie. And it names the
// events a grid keeps for a ball, the scan's and the crossing of a cell's
// side, with their order at equal times.
// Beyond the article: the article scans afresh for every collision and needs
// no such key; it is what lets a faster program promise the same answer.
// Lesson: lessons/10-scaling.md
//
// Assumptions: at most 2^31 - 1 balls (the numbers N1, N2 are ints).
#pragma once

#include <algorithm>
#include <cstdint>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

// The scan (find_first_collision) meets the events in this order: the walls
// of ball 1 (K = 1, then K = 2), the walls of ball 2, ..., then the pairs
// N3 < N4 in the order (1, 2), (1, 3), ..., (2, 3), ... Of simultaneous
// events it keeps the first one met, because a later one must be *strictly*
// earlier to replace it. So the scan's answer is the event with the smallest
// (time, place in the scan); scan_place numbers the places.
// [anchor: scan-place]
inline std::uint64_t scan_place(CollisionKind kind, int first, int second) {
  const auto n1 = static_cast<std::uint64_t>(first);
  const auto n2 = static_cast<std::uint64_t>(second);
  if (kind == CollisionKind::balls) return std::uint64_t{1} << 62 | n1 << 31 | n2;
  return n1 << 1 | (kind == CollisionKind::vertical_wall ? 1 : 0);  // walls: before pairs
}

// Does the event (time a, place pa) come before the event (time b, place pb)?
inline bool comes_before(double a, std::uint64_t pa, double b, std::uint64_t pb) {
  return a < b || (a == b && pa < pb);
}
// [/anchor: scan-place]

// What a grid keeps for a ball: K's kinds of event, and the crossing of a
// side of its cell (which changes no column of R, only the grid's books).
// [anchor: grid-event]
enum class EventKind : std::uint8_t {
  none = 0,             // no event: nothing lies ahead of the ball
  horizontal_wall = 1,  // K = 1
  vertical_wall = 2,    // K = 2
  meeting = 3,          // K = 3, with `partner`
  crossing_x = 4,       // its centre leaves its cell through a side x = const
  crossing_y = 5,       // ... through a side y = const
};

inline bool is_crossing(EventKind kind) {
  return kind == EventKind::crossing_x || kind == EventKind::crossing_y;
}

// One event of a ball: what, when (model time), and with which ball.
struct Event {
  double time = never;
  EventKind kind = EventKind::none;
  int partner = 0;  // the other ball of a meeting; 0 for any other kind
};

// The place of an event of `ball` among events at the same time: crossings
// first (they rewrite no column of R, and may bring in an event that belongs
// before the collisions at that time), by ball; then the scan's events, in
// the scan's order.
inline std::uint64_t grid_place(int ball, const Event& e) {
  constexpr std::uint64_t after_crossings = std::uint64_t{1} << 63;
  const auto n = static_cast<std::uint64_t>(ball);
  switch (e.kind) {
    case EventKind::crossing_x:
      return n << 1;
    case EventKind::crossing_y:
      return n << 1 | 1;
    case EventKind::meeting:
      return after_crossings | scan_place(CollisionKind::balls, std::min(ball, e.partner),
                                          std::max(ball, e.partner));
    default:  // a wall (no event never comes, and is never compared)
      return after_crossings | scan_place(static_cast<CollisionKind>(e.kind), ball, 0);
  }
}

// Does e come before f, both events of `ball`? (No event comes after all.)
inline bool earlier(int ball, const Event& e, const Event& f) {
  return comes_before(e.time, grid_place(ball, e), f.time, grid_place(ball, f));
}
// [/anchor: grid-event]

}  // namespace gas
