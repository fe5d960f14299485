// Stage 4 — first collision: the tuned grid's look ahead (beyond the
// article). Step 6 of beyond/cell_grid.hpp says what it asks memory for,
// and when; here it is done.
//
// Every helper here only prefetches, and is always written out where it is
// called ([[gnu::always_inline]], down to KeyPlaces::new_day, which the
// calendar calls through its interface): GCC takes a function that only
// prefetches for one without effect, and may drop a call of it. And no loop
// here is unrolled (#pragma GCC unroll 1), so that each prefetch written
// here is one instruction in new_day for each place it is written out: a
// test counts them in the built program (tests/test_grid_look_ahead.cpp).
#include <cassert>

#include "beyond/cell_grid.hpp"

namespace gas {

namespace {

// The look ahead's stages, in days before a ball's day (step 6).
constexpr std::int32_t pages_ahead = 10;          // the line of pages
constexpr std::int32_t first_entries_ahead = 6;   // a page's first ball's entry
constexpr std::int32_t second_entries_ahead = 5;  // ... and its second's
constexpr std::int32_t books_ahead = 4;           // ask_for_books
constexpr std::int32_t cells_ahead = 3;           // ask_for_cells
constexpr std::int32_t first_balls_ahead = 2;     // ask_for_first_balls
constexpr std::int32_t partner_balls_ahead = 1;   // ask_for_partner_balls

// A block of `bytes` asked for: both ends, as it may span two cache lines.
[[gnu::always_inline]] inline void ask_early(const void* from, std::size_t bytes) {
  __builtin_prefetch(from);
  __builtin_prefetch(static_cast<const char*>(from) + bytes - 1);
}

}  // namespace

// `across` cells by `down` cell rows from the cell (cell_column, cell_row),
// inside the frame.
CellGrid::Block CellGrid::block(int cell_column, int cell_row, int across,
                                int down) const {
  assert(in_frame(cell_column, cell_row) &&
         in_frame(cell_column + across - 1, cell_row + down - 1));
  return {cell_index(cell_column, cell_row), across, down};
}

// The block of cells a ball's next event will gather: for a crossing, the
// three cells it is about to neighbour (two cells on: inside the frame, as
// a ball crosses only where no edge is ahead); else the 3 x 3 around it.
CellGrid::Block CellGrid::block_ahead(int ball) const {
  const Record& r = record(ball);
  const int column = static_cast<int>(r.cell_column), row = static_cast<int>(r.cell_row);
  switch (static_cast<EventKind>(r.key)) {
    case EventKind::crossing_x:
      return block(column + (R(ball).vx > 0 ? 2 : -2), row - 1, 1, 3);
    case EventKind::crossing_y:
      return block(column - 1, row + (R(ball).vy > 0 ? 2 : -2), 3, 1);
    default:
      return block(column - 1, row - 1, 3, 3);
  }
}

// A ball's column of R (40 bytes).
[[gnu::always_inline]] inline void CellGrid::ask_for_R(int ball) const {
  ask_early(&R(ball), sizeof(Ball));
}

// The heads of a block's cells, a cell row at a time.
[[gnu::always_inline]] inline void CellGrid::ask_for_heads(const Block& b) const {
#pragma GCC unroll 1
  for (int row = 0; row < b.down; ++row)
    ask_early(&head_[b.first + cell_rows_apart(row)],
              static_cast<std::size_t>(b.across) * sizeof(std::int32_t));
}

// The first ball of each of a block's cells (the heads in the cache): its
// link to the next and its column of R. (An empty cell's 0 asks for ball
// 1's: no branch on a coin toss.)
[[gnu::always_inline]] inline void CellGrid::ask_for_balls(const Block& b) const {
#pragma GCC unroll 1
  for (int row = 0; row < b.down; ++row) {
    const std::int32_t* heads = &head_[b.first + cell_rows_apart(row)];
#pragma GCC unroll 1
    for (int c = 0; c < b.across; ++c) {
      const std::int32_t k = heads[c];
      __builtin_prefetch(&next_in_cell_[static_cast<std::size_t>(k)]);
      ask_for_R(k + (k == 0));
    }
  }
}

// 4 days ahead: the ball's record and column of R.
[[gnu::always_inline]] inline void CellGrid::ask_for_books(int ball) const {
  __builtin_prefetch(&record(ball));
  ask_for_R(ball);
}

// 3 days ahead (its record in the cache): the heads of the cells its event
// will gather, and for a crossing its own cell's head too (it leaves that
// cell's chain); for a meeting, the partner's record, column of R and
// calendar entry.
[[gnu::always_inline]] inline void CellGrid::ask_for_cells(int ball) const {
  const Record& r = record(ball);
  ask_for_heads(block_ahead(ball));
  const auto key = static_cast<EventKind>(r.key);
  if (is_crossing(key))
    __builtin_prefetch(&head_[cell_index(static_cast<int>(r.cell_column),
                                         static_cast<int>(r.cell_row))]);
  if (key == EventKind::meeting) {
    __builtin_prefetch(&record(r.partner));
    ask_for_R(r.partner);
    __builtin_prefetch(calendar_.entry_address(r.partner));
  }
}

// 2 days ahead: the first ball of each of those cells; for a meeting, the
// partner's page in the calendar and the heads of its 3 x 3 cells.
[[gnu::always_inline]] inline void CellGrid::ask_for_first_balls(int ball) const {
  const Record& r = record(ball);
  ask_for_balls(block_ahead(ball));
  if (static_cast<EventKind>(r.key) == EventKind::meeting) {
    const Record& p = record(r.partner);
    __builtin_prefetch(calendar_.page_address(calendar_.key_day(r.partner)));
    ask_for_heads(block(static_cast<int>(p.cell_column) - 1,
                        static_cast<int>(p.cell_row) - 1, 3, 3));
  }
}

// 1 day ahead: the first balls of the partner's cells, for its prediction
// after the collision.
[[gnu::always_inline]] inline void CellGrid::ask_for_partner_balls(int ball) const {
  const Record& r = record(ball);
  if (static_cast<EventKind>(r.key) == EventKind::meeting) {
    const Record& p = record(r.partner);
    ask_for_balls(block(static_cast<int>(p.cell_column) - 1,
                        static_cast<int>(p.cell_row) - 1, 3, 3));
  }
}

// `ask` for each ball whose key falls on `day`. (An empty page's ball 0 has
// an entry too, whose next is 0.)
template <void (CellGrid::*ask)(int) const>
[[gnu::always_inline]] inline void CellGrid::ask_for_day(std::int32_t day) const {
  for (int ball = calendar_.first_on_page(day); ball != 0;
       ball = calendar_.next_on_page(ball)) {
    if (calendar_.key_day(ball) == day) (this->*ask)(ball);
  }
}

// Each stage reads only what the stage before asked for, a day earlier.
// [anchor: grid-look-ahead]
[[gnu::always_inline]] inline void CellGrid::look_ahead() const {
  const std::int32_t today = calendar_.today();
  __builtin_prefetch(calendar_.page_address(today + pages_ahead));
  __builtin_prefetch(
      calendar_.entry_address(calendar_.first_on_page(today + first_entries_ahead)));
  __builtin_prefetch(calendar_.entry_address(
      calendar_.next_on_page(calendar_.first_on_page(today + second_entries_ahead))));
  ask_for_day<&CellGrid::ask_for_books>(today + books_ahead);
  ask_for_day<&CellGrid::ask_for_cells>(today + cells_ahead);
  ask_for_day<&CellGrid::ask_for_first_balls>(today + first_balls_ahead);
  ask_for_day<&CellGrid::ask_for_partner_balls>(today + partner_balls_ahead);
}
// [/anchor: grid-look-ahead]

void CellGrid::KeyPlaces::new_day() const {
  if (grid->looking_ahead_) grid->look_ahead();
}

}  // namespace gas
