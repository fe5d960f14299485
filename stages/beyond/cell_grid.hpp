// Stage 4 — first collision, by a grid of cells and a calendar of events:
// the tuned grid, which the program runs (beyond the article).
//
// What this file does: the plain grid's algorithm (beyond/plain_grid.hpp: cells
// at least 2a wide, one event a ball, cell crossings, lazy invalidation, the
// event calendar), collision for collision, made faster by the steps below.
// Below some 10^4 balls everything a collision reads is in the processor's
// caches and its cost is the count of its instructions; beyond, every event
// happens somewhere else on the table, what it reads comes from main memory,
// and each such read waits as long as hundreds of arithmetic steps. So the
// steps save instructions, memory and waits. Each is described here once;
// lesson 11 quotes them, and the benchmark's report measures what they buy
// together (data/reports/speed-against-error.md, "What the tuning buys").
//
// Beyond the article: the answer is the scan's, bit for bit, ties included,
// as the plain grid's is (suite `strategies` runs both beside the scan).
// Lesson: lessons/11-memory.md; the algorithm: lessons/10-scaling.md
//
// Assumptions: those of the plain grid; and no column of R was written
// after the present moment gas.time (stage 2 refuses such a SINCE: step 4
// rests on it).
//
// The steps:
//
// [anchor: step-record]
// 1. Books of 16 bytes. A ball's event (time, partner, kind), its key's kind
//    and its cell share one record of 16 bytes, four to a cache line: the
//    kinds in 3 bits each, the cell's column and cell row in 13 bits each
//    (so at most 8191 cells along a side; a larger table gets wider cells).
//    The cells' lists are chains of 4-byte links (a head for each cell, a
//    next for each ball), 400 KB at 10^5 balls, which stay in the
//    processor's second-level cache; and a frame of empty cells around the
//    table lets a block of 3 x 3 cells be read without a test at the edges.
// [/anchor: step-record]
//
// [anchor: step-walls]
// 2. Walls only along the edges. A ball meets the wall x = A1 only from
//    the last column of cells (its centre must reach A1 - a, well inside
//    it), so a ball predicts a wall only in an edge cell, moving towards
//    it, and learns of it when it crosses into one.
// [/anchor: step-walls]
//
// [anchor: step-arithmetic]
// 3. Coin tosses answered by arithmetic. At each `if` the processor
//    guesses the way long before it knows it, and a wrong guess throws
//    away some fifteen steps of work. Whether a cell holds a ball or two,
//    which of two balls has the lower number, which way a ball moves: these
//    are coin tosses, asked for every neighbour of every event. The grid
//    answers them with a count moved on by 0 or 1, or a value selected: a
//    cell's chain is walked two links without asking where it ends
//    (`gather`), N3 < N4 found by min and xor (`pair_event`), the sides
//    ahead of a ball selected (`next_crossing`), and the gathering's loops
//    written out by the compiler, their counts known.
// [/anchor: step-arithmetic]
//
// [anchor: step-quick-check]
// 4. The quick check of a meeting. A meeting that comes up is worked out
//    again only if the partner's column of R is not older than the ball's
//    own. Columns of R are written only by stage 5, at the present; the ball
//    predicted after its own was written; so a partner's column older than
//    the ball's has not changed since. (Equal moments prove nothing: two
//    columns rewritten by one collision.)
// [/anchor: step-quick-check]
//
// [anchor: step-large-pages]
// 5. Large pages. Every address read is translated to a place in the
//    machine's memory, page by page, and the processor keeps only some two
//    thousand translations at hand: 8 MiB of ordinary 4 KiB pages, less
//    than the books and the columns of R of 10^5 balls. The books and the
//    calendar ask for 2 MiB pages, and when the grid starts it asks the
//    system to move the gas's columns of R into such pages at once
//    (beyond/large_pages.hpp).
// [/anchor: step-large-pages]
//
// [anchor: step-look-ahead]
// 6. The calendar's look ahead (from 16384 balls, `look_ahead_from`; with
//    fewer the books are in the caches and it costs more than it saves).
//    Each event reads a chain of cache lines, each line's address read from
//    the line before: the ball's calendar entry, its record, its cells'
//    heads, their balls' links and columns of R. The calendar knows which
//    balls come next: those on the pages of the next few days (a day holds
//    about two events). So each time today moves on a day, the grid asks
//    memory early (the processor's prefetch: a hint, which changes no
//    result) for one link of the chain of each ball some days ahead, a
//    link further a day later:
//      10 days ahead: the line of the calendar's pages;
//       6, 5 days ahead: the calendar entries of a page's first two balls;
//       4 days ahead: the ball's record and column of R;
//       3 days ahead: the heads of the cells its event will gather (3 x 3
//                     for a meeting or a wall, the three cells beyond for a
//                     crossing); for a meeting, the partner's record,
//                     column of R and calendar entry;
//       2 days ahead: the first ball of each of those cells (its link and
//                     column of R); the partner's page in the calendar and
//                     the heads of its 3 x 3 cells;
//       1 day ahead:  the first balls of the partner's cells.
//    No stage waits for memory itself: each reads only lines asked for a
//    day before. (The prefetching helpers are always written out where
//    they are called: a function that only prefetches seems to GCC to do
//    nothing, and a call of it may be dropped with no warning; a test
//    counts the prefetches in the built program.)
// [/anchor: step-look-ahead]
#pragma once

#include <cstdint>
#include <vector>

#include "beyond/cell_layout.hpp"
#include "beyond/event_calendar.hpp"
#include "beyond/event_order.hpp"
#include "beyond/large_pages.hpp"
#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

class CellGrid final : public FirstCollisionFinder {
 public:
  // Lays out the cells, puts every ball in its cell at gas.time, and predicts
  // every ball's event and key.
  void rebuild(const Gas& gas, const CentreLimits& limits) override;

  // The first collision, as find_first_collision(gas, limits) gives it.
  // Carries out (only in the grid's books) every cell crossing before it.
  Collision first(const Gas& gas) override;

  // After stage 5 carried out `done` (the columns of R of N1, and N2 for
  // K = 3, rewritten): those balls predict afresh.
  void update(const Gas& gas, const Collision& done) override;

  const char* name() const override { return "grid"; }

  // The layout, for tests.
  const CellLayout& cells() const { return cells_; }

  // Cells along a side at most: as many as a record's 13 bits number (step 1).
  static constexpr int most_cells_along = (1 << 13) - 1;
  // The look ahead's least number of balls (step 6).
  static constexpr std::size_t look_ahead_from = 1 << 14;

 private:
  // A ball as the grid keeps it (step 1).
  // [anchor: grid-record]
  struct Record {
    double event_time = never;           // its event: when,
    std::int32_t partner = 0;            // with which ball (a meeting's), else 0,
    std::uint32_t event : 3 = 0;         // what (an EventKind);
    std::uint32_t key : 3 = 0;           // its key: `event`, or a crossing (an EventKind)
    std::uint32_t cell_column : 13 = 0;  // its cell
    std::uint32_t cell_row : 13 = 0;
  };
  static_assert(sizeof(Record) == 16, "a record is 16 bytes");
  // [/anchor: grid-record]

  const Ball& R(int ball) const {  // its column of R
    return gas_->balls[static_cast<std::size_t>(ball - 1)];
  }
  Record& record(int ball) { return records_[static_cast<std::size_t>(ball)]; }
  const Record& record(int ball) const {
    return records_[static_cast<std::size_t>(ball)];
  }
  // Cells are numbered row after row in a frame one cell wider on every side.
  std::size_t cell_rows_apart(int rows) const {  // how far apart in cell_index
    return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cells_.columns + 2);
  }
  std::size_t cell_index(int cell_column, int cell_row) const {
    return cell_rows_apart(cell_row + 1) + static_cast<std::size_t>(cell_column + 1);
  }
  std::int32_t& head(int cell_column, int cell_row) {
    return head_[cell_index(cell_column, cell_row)];
  }
  bool in_frame(int cell_column, int cell_row) const {
    return cell_column >= -1 && cell_column <= cells_.columns && cell_row >= -1 &&
           cell_row <= cells_.rows;
  }

  Event held(int ball) const;
  void hold(int ball, const Event& e);
  Event key_event(int ball) const;
  static void keep_earlier(int ball, Event& earliest, const Event& e);
  Event wall_event(int ball, EventKind wall) const;
  Event pair_event(int ball, int other) const;
  bool edge_ahead(int ball, bool along_x) const;
  Event next_crossing(int ball) const;
  bool partner_unchanged(int ball, int partner) const;
  template <int across, int down>
  std::size_t gather(int cell_column, int cell_row);
  void predict(int ball, int skip);
  void schedule(int ball);
  void cross(int ball, bool along_x);
  void insert(int ball, int cell_column, int cell_row);
  void remove(int ball);

  // The look ahead (step 6; beyond/grid_look_ahead.cpp).
  struct Block {  // `across` cells by `down` cell rows from the cell_index `first`
    std::size_t first;
    int across, down;
  };
  Block block(int cell_column, int cell_row, int across, int down) const;
  Block block_ahead(int ball) const;
  void look_ahead() const;
  template <void (CellGrid::*ask)(int) const>
  void ask_for_day(std::int32_t day) const;
  void ask_for_books(int ball) const;
  void ask_for_cells(int ball) const;
  void ask_for_first_balls(int ball) const;
  void ask_for_partner_balls(int ball) const;
  void ask_for_heads(const Block& block) const;
  void ask_for_balls(const Block& block) const;
  void ask_for_R(int ball) const;

  CentreLimits limits_;
  CellLayout cells_;                 // the cells over the table (beyond/cell_layout.hpp)
  const Gas* gas_ = nullptr;         // the gas of the last call (its columns of R)
  LargePageVector<Record> records_;  // by ball number 1..N (0 unused)
  LargePageVector<std::int32_t> next_in_cell_;  // by ball: the next in its cell; 0 ends
                                                // (and next_in_cell_[0] stays 0)
  LargePageVector<std::int32_t> head_;          // by cell_index: a ball in the cell, or 0
  std::vector<std::int32_t> neighbours_;        // gather's answer: balls of a block
  EventCalendar calendar_;      // every ball with a key (beyond/event_calendar.hpp)
  bool looking_ahead_ = false;  // does the calendar look ahead (enough balls)?

  // What the calendar asks the grid: the place of a ball's key on a tie of
  // times; and, each new day, to look ahead.
  struct KeyPlaces final : EventCalendar::Places {
    explicit KeyPlaces(const CellGrid* of) : grid(of) {}
    const CellGrid* grid;
    std::uint64_t place(int ball) const override;
    void new_day() const override;
  };
};

}  // namespace gas
