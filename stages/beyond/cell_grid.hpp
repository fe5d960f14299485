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
// Each ball keeps one event: the earliest of its meetings and walls that it
// predicted (its next crossing is worked out again from its row and cell
// when needed). An event calendar (beyond/event_calendar.*) holds every ball
// once, keyed by the earlier of that event and its next crossing. After a
// collision its two balls predict afresh. The other balls may still hold a
// meeting with one of them, now worthless; rather than hunt those down, a
// ball whose meeting comes up checks it: unless the partner's row is older
// than its own (then it cannot have changed since), the meeting's time
// worked out again from the two rows as they are now must be the time it
// holds, bit for bit. If it is not, the partner has collided since, and the
// ball predicts afresh (lazy invalidation). A ball needs no other event:
// every meeting it did not keep is no earlier than the one it keeps, so it
// predicts again before any of them is due. The work per collision does not
// grow with N.
//
// Where things live in memory matters as much as the work, once there are
// more balls than the processor's caches hold (some 10^4): every event
// happens somewhere else on the table, so what it needs comes from main
// memory, a wait worth hundreds of arithmetic steps. So the grid keeps its
// books small: a ball's event and its cell in one record of 16 bytes, four to
// a cache line; the links of the cells' lists in an array of 4-byte numbers
// (which at 10^5 balls still fits in a processor's second-level cache); all
// in large pages (beyond/large_pages.hpp); the rows of R it reads from the
// gas.
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
// predictions are stage 4's time_to_wall and time_of_contact on the same rows
// of R (a crossing never rewrites a row), and events are ordered as the scan
// meets them (beyond/event_order.hpp), crossings first.
// Lesson: lessons/10-scaling.md
//
// Assumptions: between two calls of `first`, the gas changes only by the
// collision passed to `update` (stage 5's apply_collision); after anything
// else that rewrites rows of R (the B key, a new scene), call `rebuild`.
// Every centre stays on the table (stage 5 keeps it there), and no row was
// written after the present moment gas.time (stage 2 refuses such a SINCE).
#pragma once

#include <cstdint>
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
  // How much wider than 2a a cell is at least, as a fraction of 2a. Two balls
  // in cells that are not neighbours are then more than 2a (1 + margin)
  // apart; the margin is far above the rounding of any centre (~1e-16 of the
  // table's size, and of |v| T), so the grid's idea of which cell holds a
  // centre can never be wrong by enough to hide a collision.
  static constexpr double margin = 1.0 / 1024;

 private:
  // An event: a meeting with the ball `partner`, or an event of the ball
  // alone, coded by a `partner` of 0 or less.
  struct Event {
    double time = never;  // model time
    std::int32_t partner = horizontal_wall;
  };
  static constexpr std::int32_t horizontal_wall = 0;  // K = 1
  static constexpr std::int32_t vertical_wall = -1;   // K = 2
  static constexpr std::int32_t cross_x = -2;  // leaves its cell through a side x = const
  static constexpr std::int32_t cross_y = -3;  // ... through a side y = const

  // What a ball's key in the calendar is.
  enum Key : std::uint32_t { its_event = 0, its_crossing_x = 1, its_crossing_y = 2 };

  // A ball as the grid keeps it: its event, its cell, its key; four records
  // to a cache line. (Cells have at most 2^16 - 1 columns and 2^14 - 1
  // lines: see rebuild.)
  struct Record {
    double event_time = never;               // its earliest meeting or wall predicted
    std::int32_t partner = horizontal_wall;  // ... with: a ball, or a wall's code
    std::uint32_t column : 16 = 0;           // its cell's column ...
    std::uint32_t line : 14 = 0;             // ... and line
    // Which is its key: the event, or its next crossing.
    std::uint32_t key : 2 = its_event;
  };
  static_assert(sizeof(Record) == 16, "a record is 16 bytes");

  const Ball& row(int ball) const {  // its row of R
    return gas_->balls[static_cast<std::size_t>(ball - 1)];
  }
  Record& record(int ball) { return records_[static_cast<std::size_t>(ball)]; }
  const Record& record(int ball) const {
    return records_[static_cast<std::size_t>(ball)];
  }
  // How far apart in cell_index `lines` lines of cells are.
  std::size_t lines_of_cells(int lines) const {
    return static_cast<std::size_t>(lines) * static_cast<std::size_t>(cells_.columns + 2);
  }
  // Cells are numbered row by row in a frame one cell wider on every side.
  std::size_t cell_index(int column, int line) const {
    return lines_of_cells(line + 1) + static_cast<std::size_t>(column + 1);
  }
  std::int32_t& head(int column, int line) { return head_[cell_index(column, line)]; }
  const std::int32_t& head(int column, int line) const {
    return head_[cell_index(column, line)];
  }

  std::uint64_t place(int ball, std::int32_t partner) const;
  bool earlier(int ball, const Event& e, const Event& f) const;
  Event held(int ball) const;
  void hold(int ball, const Event& e);
  bool partner_unchanged(int ball, int partner) const;

  void predict(int ball, int skip, int lowest);
  void ask_row_early(int ball) const;
  // A block of cells: `across` cells by `down` lines from the cell `first`
  // (a cell_index).
  struct Block {
    std::size_t first;
    int across, down;
  };
  Block block_around(const Record& r) const;
  Block block_ahead(int ball) const;
  void ask_heads_early(const Block& block) const;
  void ask_first_balls_early(const Block& block) const;
  void ask_rows_early(std::size_t count) const;
  void keep_earlier(int ball, Event& earliest, Event e) const;
  Event pair_event(int ball, int other) const;
  static CollisionKind wall_kind(std::int32_t wall);
  Event wall_event(int ball, std::int32_t wall) const;
  bool edge_ahead(int ball, bool along_x) const;
  Event next_crossing(int ball) const;
  void cross(int ball, bool along_x);
  double choose_key(int ball);
  void schedule(int ball);
  void insert(int ball, int column, int line);
  void remove(int ball);
  template <int across, int down>
  std::size_t gather(int column, int line);

  CentreLimits limits_;
  CellLayout cells_;                 // the cells over the table (beyond/cell_layout.hpp)
  const Gas* gas_ = nullptr;         // the gas of the last call (its rows of R)
  LargePageVector<Record> records_;  // by ball number 1..N (0 unused)
  LargePageVector<std::int32_t> next_in_cell_;  // by ball: the next in its cell; 0 ends
                                                // (and next_in_cell_[0] stays 0)
  LargePageVector<std::int32_t> head_;          // by cell_index: a ball in the cell, or 0
  std::vector<std::int32_t> neighbours_;        // gather's answer: balls of a block
  EventCalendar calendar_;  // every ball with an event, keyed by the earlier of
                            // its event and its next crossing
  // The calendar's question on a tie of times: the place of a ball's key.
  struct KeyPlaces final : EventCalendar::Places {
    explicit KeyPlaces(const CellGrid* of) : grid(of) {}
    const CellGrid* grid;
    std::uint64_t place(int ball) const override;
    void prefetch(int ball, int step) const override;
  };
};

}  // namespace gas
