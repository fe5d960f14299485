// Stage 4 — first collision, by a grid of cells and a queue of events
// (beyond the article).
//
// What this file does: cuts the table into cells at least 2a wide and keeps
// every ball in the cell that holds its centre. Two balls in cells that are
// not neighbours are more than 2a apart, so a ball is predicted only against
// the balls of the 3 x 3 cells around its own. A ball leaving its cell is an
// event too, a "cell crossing": the ball moves to the next cell and is
// predicted against the balls that have just become its neighbours. A ball
// hears of a wall only in the cells along that wall.
//
// Each ball keeps a short list of its predictions (the walls ahead of it, its
// next crossing, the meetings it predicted), and a priority queue — a binary
// heap, earliest on top — holds every ball once, keyed by the earliest
// prediction in its list. After a collision the lists of its balls are made
// afresh. The other balls may still hold predictions of meetings with them,
// now worthless; rather than hunt those down, every ball counts its
// collisions, a prediction of a meeting remembers the count its partner had,
// and a prediction whose count is out of date is dropped when it comes to the
// top (lazy invalidation). The work per collision no longer grows with N,
// but for the heap's log N.
// Beyond the article: the article scans every wall and every pair for each
// collision. The answer here is the scan's, bit for bit, ties included: the
// predictions are stage 4's time_to_wall and time_of_contact on the same rows
// of R (a crossing never rewrites a row), and the queue is ordered as the
// scan meets events (stage4_event_order.hpp), crossings first.
// Lesson: lessons/10-scaling.md
//
// Assumptions: between two calls of `first`, the gas changes only by the
// collision passed to `update` (stage 5's apply_collision); after anything
// else that rewrites rows of R (the B key, a new scene), call `rebuild`.
// Every centre stays on the table (stage 5 keeps it there).
#pragma once

#include <cstdint>
#include <vector>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

class CellGrid {
 public:
  // Lays out the cells, puts every ball in its cell at gas.time, and predicts
  // every ball's walls, neighbours and first crossing.
  void rebuild(const Gas& gas, const CentreLimits& limits);

  // The first collision, as find_first_collision(gas, limits) gives it.
  // Carries out (only in the grid's books) every cell crossing before it.
  Collision first(const Gas& gas);

  // After stage 5 carried out `done` (rows of N1, and N2 for K = 3, rewritten):
  // those balls are predicted afresh.
  void update(const Gas& gas, const Collision& done);

  // The layout, for tests and the benchmark.
  int columns() const { return columns_; }
  int rows() const { return rows_; }
  double cell_width() const { return cell_width_; }
  double cell_height() const { return cell_height_; }

  // How much wider than 2a a cell is at least, as a fraction of 2a. Two balls
  // in cells that are not neighbours are then more than 2a (1 + margin)
  // apart; the margin is far above the rounding of any centre (~1e-16 of the
  // table's size, and of |v| T), so the grid's idea of which cell holds a
  // centre can never be wrong by enough to hide a collision.
  static constexpr double margin = 1.0 / 1024;

 private:
  // One prediction in a ball's list: a meeting with the ball `partner`
  // (predicted when the partner had had `partner_count` collisions), or an
  // event of the ball alone, coded by a `partner` of 0 or less.
  struct Prediction {
    double time = never;
    std::int32_t partner = 0;
    std::uint32_t partner_count = 0;
  };
  static constexpr std::int32_t horizontal_wall = 0;  // K = 1
  static constexpr std::int32_t vertical_wall = -1;   // K = 2
  static constexpr std::int32_t cross_x = -2;  // leaves its cell through a side x = const
  static constexpr std::int32_t cross_y = -3;  // ... through a side y = const

  // An entry of the heap: a ball and the time of its earliest prediction.
  struct Entry {
    double time = never;
    std::int32_t ball = 0;
  };

  std::uint64_t place(int ball, const Prediction& p) const;
  bool before(const Entry& a, const Entry& b) const;
  bool current(const Prediction& p) const;

  void predict(const Gas& gas, int ball, int skip, int lowest);
  void add_pair(const Gas& gas, int ball, int other);
  void add_wall(const Gas& gas, int ball, std::int32_t wall);
  Prediction next_crossing(const Gas& gas, int ball) const;
  void cross(const Gas& gas, int ball, bool along_x);
  void choose_earliest(int ball);
  void refresh(int ball);
  void sift_up(std::size_t position);
  void sift_down(std::size_t position);
  void insert(int ball, int column, int row);
  void remove(int ball);

  CentreLimits limits_;
  int columns_ = 1, rows_ = 1;
  double cell_width_ = 0, cell_height_ = 0;
  // Per ball, indexed by its number 1..N (index 0 unused):
  std::vector<std::vector<Prediction>> predictions_;  // its list
  std::vector<Prediction> earliest_;                  // the earliest of its list: its key
  std::vector<std::uint32_t> count_;   // its collisions so far (wraps after 2^32:
                                       // harmless unless a prediction waits that long)
  std::vector<std::size_t> position_;  // its entry in the heap
  std::vector<int> column_, row_;      // its cell
  std::vector<int> next_in_cell_, previous_in_cell_;  // the cell's list; 0 ends it
  std::vector<int> head_;    // head_[row * columns + column]: a ball in the cell, or 0
  std::vector<Entry> heap_;  // every ball once, the earliest key on top
};

}  // namespace gas
