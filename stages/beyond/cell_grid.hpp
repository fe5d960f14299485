// Stage 4 — first collision, by a grid of cells and a calendar of events
// (beyond the article).
//
// What this file does: cuts the table into cells at least 2a wide (laid out
// by beyond/cell_layout.hpp) and keeps every ball in the cell that holds its
// centre. Two balls in cells that are not neighbours are more than 2a apart,
// so a ball is predicted only against the balls of the 3 x 3 cells around
// its own. A ball leaving its cell is an event too, a "cell crossing": the
// ball moves to the next cell and is predicted against the balls that have
// just become its neighbours. A ball hears of a wall only in the cells along
// that wall.
//
// Each ball keeps a short list of its predictions (the walls ahead of it, its
// next crossing, the meetings it predicted), and an event calendar
// (beyond/event_calendar.*) holds every ball once, keyed by the earliest
// prediction in its list. After a collision the lists of its balls are made
// afresh. The other balls may still hold predictions of meetings with them,
// now worthless; rather than hunt those down, every ball counts its
// collisions, a prediction of a meeting remembers the count its partner had,
// and a prediction whose count is out of date is dropped when it comes up
// (lazy invalidation). The work per collision does not grow with N.
//
// Where things live in memory matters as much as the work, once there are
// more balls than the processor's caches hold (some 10^4): every event
// happens somewhere else on the table, so what it needs comes from main
// memory, a wait worth hundreds of arithmetic steps. So the grid keeps its
// books small: a ball's cell and first predictions in one record of a cache
// line, the collision counts and the cells' lists in arrays of 4-byte
// numbers, all in large pages (beyond/large_pages.hpp). And it keeps them in
// the order of the cells, not of the scene's numbers: it gives every ball a
// seat, its own number for it, counting cell by cell (in strips four cells
// high, column after column), and keeps a copy of each ball's row of R at its
// seat. The balls a ball is compared with, those of the 3 x 3 cells around
// it, then sit a few seats from it, and their books share the cache lines
// that the event has fetched already. As the balls wander, their seats are
// dealt afresh now and then (every `reseat_collisions` collisions a ball,
// by `rebuild`). The scene's numbers stay what everyone else sees: in the
// collisions the grid gives, and in the order of ties.
//
// And a processor guesses which way each `if` goes, long before it knows;
// a wrong guess throws away some fifteen steps of work. Whether a cell holds
// a ball, whether a neighbour's number is the lower, which way a ball moves:
// these are coin tosses, so where they are asked for every neighbour the
// grid answers them by arithmetic (a count moved on by 0 or 1, a value
// selected) instead of by a branch.
//
// Beyond the article: the article scans every wall and every pair for each
// collision. The answer here is the scan's, bit for bit, ties included: the
// predictions are stage 4's wall_time and pair_time on copies of the same
// rows of R (a crossing never rewrites a row), and events are ordered as the
// scan meets them (beyond/event_order.hpp, by the scene's numbers), crossings
// first. Dealing the seats afresh changes no answer: the predictions made
// then are those the grid held, each pair's time being computed from the
// same two rows.
// Lesson: lessons/10-scaling.md
//
// Assumptions: between two calls of `first`, the gas changes only by the
// collision passed to `update` (stage 5's apply_collision); after anything
// else that rewrites rows of R (the B key, a new scene), call `rebuild`.
// Every centre stays on the table (stage 5 keeps it there).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "beyond/cell_layout.hpp"
#include "beyond/event_calendar.hpp"
#include "beyond/large_pages.hpp"
#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

class CellGrid final : public FirstCollisionFinder {
 public:
  // Lays out the cells, puts every ball in its cell at gas.time, and predicts
  // every ball's walls, neighbours and first crossing.
  void rebuild(const Gas& gas, const CentreLimits& limits) override;

  // The first collision, as find_first_collision(gas, limits) gives it.
  // Carries out (only in the grid's books) every cell crossing before it.
  Collision first(const Gas& gas) override;

  // After stage 5 carried out `done` (rows of N1, and N2 for K = 3, rewritten):
  // those balls are predicted afresh.
  void update(const Gas& gas, const Collision& done) override;

  const char* name() const override { return "grid"; }

  // The layout, for tests and the benchmark.
  int columns() const { return cells_.columns; }
  int rows() const { return cells_.rows; }
  double cell_width() const { return cells_.cell_width; }
  double cell_height() const { return cells_.cell_height; }
  // The longest list of predictions a ball holds now, for tests.
  std::uint32_t longest_list() const;
  // How much wider than 2a a cell is at least, as a fraction of 2a. Two balls
  // in cells that are not neighbours are then more than 2a (1 + margin)
  // apart; the margin is far above the rounding of any centre (~1e-16 of the
  // table's size, and of |v| T), so the grid's idea of which cell holds a
  // centre can never be wrong by enough to hide a collision.
  static constexpr double margin = 1.0 / 1024;

  // How many predictions a record holds itself; a longer list (rare: a ball
  // predicts a meeting only with the balls it approaches) goes on in
  // `more_predictions_`.
  static constexpr std::uint32_t predictions_kept = 3;

  // The seats are dealt afresh after this many collisions a ball (a ball
  // takes part in two collisions for each): by then a ball has wandered a
  // few cells from where it was seated. A deal costs about what a third of a
  // collision a ball does (every ball predicted afresh), so 3 to 4 % of the
  // time, also where all the books fit in the caches anyway (N = 10^3).
  static constexpr std::uint64_t reseat_collisions = 8;

  // The seat of ball `number` (1..N) now, for tests.
  int seat_of(int number) const { return seat_[static_cast<std::size_t>(number)]; }

 private:
  // One prediction in a ball's list: a meeting with the ball at seat
  // `partner` (predicted when the partner had had `partner_count`
  // collisions), or an event of the ball alone, coded by a `partner` of 0 or
  // less.
  struct Prediction {
    double time = never;
    std::int32_t partner = 0;
    std::uint32_t partner_count = 0;
  };
  static constexpr std::int32_t horizontal_wall = 0;  // K = 1
  static constexpr std::int32_t vertical_wall = -1;   // K = 2
  static constexpr std::int32_t cross_x = -2;  // leaves its cell through a side x = const
  static constexpr std::int32_t cross_y = -3;  // ... through a side y = const

  // A ball as the grid keeps it: its cell and its list, in one cache line.
  struct alignas(64) Record {
    std::uint32_t listed = 0;            // the length of its list of predictions,
    Prediction first[predictions_kept];  // ... the first of them (the
                                         // earliest in first[0]: its key)
    std::int32_t column = 0, line = 0;   // its cell
  };
  static_assert(sizeof(Record) == 64, "a record is one cache line");

  // Everything below is by seat (1..N; 0 unused), but for `seat_`.
  const Ball& row(int seat) const {  // its row of R (the grid's copy)
    return rows_[static_cast<std::size_t>(seat)];
  }
  int number(int seat) const {  // its number in the scene (N1, N2)
    return number_[static_cast<std::size_t>(seat)];
  }
  Record& record(int seat) { return records_[static_cast<std::size_t>(seat)]; }
  const Record& record(int seat) const {
    return records_[static_cast<std::size_t>(seat)];
  }
  // Cells are numbered in strips `strip_lines` cells high, column after
  // column within a strip, in a frame one cell wider on every side: the
  // 3 x 3 cells around a cell lie in one or two runs of a dozen numbers.
  static constexpr int strip_shift = 2;
  static constexpr int strip_lines = 1 << strip_shift;
  std::size_t cell_index(int column, int line) const {
    const auto framed_column = static_cast<std::size_t>(column + 1);
    const auto framed_line = static_cast<std::size_t>(line + 1);
    return (framed_line >> strip_shift) * strip_size_ + (framed_column << strip_shift) +
           (framed_line & (strip_lines - 1));
  }
  std::int32_t& head(int column, int line) { return head_[cell_index(column, line)]; }

  // A ball's list of predictions.
  void add(int seat, Prediction p);  // (keeps the earliest at the front)
  template <typename Dropped>
  void drop(int seat, Dropped dropped);
  void forget(int seat);
  Prediction key(int seat) const;

  std::uint64_t place(int seat, const Prediction& p) const;
  bool current(const Prediction& p) const;
  bool earlier(int seat, const Prediction& p, const Prediction& q) const;

  void seat_in_cell_order(const Gas& gas);
  void predict(int seat, int skip, int lowest);
  void add_pair(int seat, int other);
  void add_wall(int seat, std::int32_t wall);
  bool edge_ahead(int seat, bool along_x) const;
  Prediction next_crossing(int seat) const;
  void cross(int seat, bool along_x);
  void schedule(int seat);
  void insert(int seat, int column, int line);
  void remove(int seat);
  template <int across, int down>
  std::size_t gather(int column, int line);

  CentreLimits limits_;
  CellLayout cells_;                 // the cells over the table (beyond/cell_layout.hpp)
  std::size_t strip_size_ = 0;       // cells in a strip, the frame's included
  double radius_ = 0;                // a
  LargePageVector<Record> records_;  // by seat
  LargePageVector<Ball> rows_;       // by seat: a copy of its row of R
  LargePageVector<std::int32_t> number_;  // by seat: the ball's number in the scene
  LargePageVector<std::int32_t> seat_;    // by number 1..N: the ball's seat
  // By seat, for the few whose list is longer than the record holds: the
  // rest of it. (Not a list for every ball: 24 bytes a ball, for 10^6 balls
  // more than the rows of R themselves.)
  std::unordered_map<std::int32_t, std::vector<Prediction>> more_predictions_;
  LargePageVector<std::uint32_t> count_;        // by seat: its collisions so far (wraps
                                                // after 2^32: harmless unless a
                                                // prediction waits that long)
  LargePageVector<std::int32_t> next_in_cell_;  // by seat: the next in its cell; 0 ends
                                                // (and next_in_cell_[0] stays 0)
  LargePageVector<std::int32_t> head_;          // by cell_index: a ball in the cell, or 0
  std::vector<std::int32_t> neighbours_;        // gather's answer: balls of a block
  EventCalendar calendar_;  // every ball with an event, keyed by the earliest
  // The calendar's question on a tie of times: the place of a ball's key.
  struct KeyPlaces final : EventCalendar::Places {
    explicit KeyPlaces(const CellGrid* of) : grid(of) {}
    const CellGrid* grid;
    std::uint64_t place(int seat) const override {
      return grid->place(seat, grid->key(seat));
    }
  };
  std::uint64_t collisions_since_seating_ = 0;  // ball collisions since the last deal
};

}  // namespace gas
