// Stage 4 — first collision: the order of the article's scan, as a key.
//
// What this file does: gives every event stage 4 can find a key — its time,
// then its place in the article's scan. (Each event's time comes from the
// scan's own expressions: wall_time and pair_time in stage 4.) A program that keeps its
// predictions from one collision to the next (beyond/event_table.*, beyond/cell_grid.*)
// and takes the event with the smallest key finds exactly the collision the scan finds:
// the same TC to the last bit, and the same K, N1, N2 when events tie.
// Beyond the article: the article scans afresh for every collision and needs
// no such key; it is what lets a faster program promise the same answer.
// Lesson: lessons/10-scaling.md
//
// Assumptions: at most 2^31 - 1 balls (the numbers N1, N2 are ints).
#pragma once

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

}  // namespace gas
