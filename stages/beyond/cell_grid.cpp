// Stage 4 — first collision, by a grid of cells and a calendar of events. See
// beyond/cell_grid.hpp.
#include "beyond/cell_grid.hpp"

#include <algorithm>
#include <cmath>

#include "beyond/event_order.hpp"

namespace gas {

namespace {

constexpr std::uint64_t scan_event = std::uint64_t{1} << 63;

}  // namespace

// ---- the order of events

// The place of a ball's event in the calendar's order at equal times:
// crossings first (they change no row of R, only the grid's books, and may
// bring in an event that belongs before the collisions at that time), then
// the events of the scan in the scan's order.
std::uint64_t CellGrid::place(int ball, std::int32_t partner) const {
  switch (partner) {
    case cross_x:
      return static_cast<std::uint64_t>(ball) << 1;
    case cross_y:
      return static_cast<std::uint64_t>(ball) << 1 | 1;
    case horizontal_wall:
      return scan_event | scan_place(CollisionKind::horizontal_wall, ball, 0);
    case vertical_wall:
      return scan_event | scan_place(CollisionKind::vertical_wall, ball, 0);
    default:
      return scan_event | scan_place(CollisionKind::balls, std::min(ball, partner),
                                     std::max(ball, partner));
  }
}

// Does e come before f in the scan's order (time, then place)?
inline bool CellGrid::earlier(int ball, const Event& e, const Event& f) const {
  return e.time < f.time ||
         (e.time == f.time && place(ball, e.partner) < place(ball, f.partner));
}

// Keeps e as the earliest if it comes before it. (An event that never comes
// is no event.)
inline void CellGrid::keep_earlier(int ball, Event& earliest, Event e) const {
  if (e.time < never && earlier(ball, e, earliest)) earliest = e;
}

// The event the ball holds, and an event given it to hold.
inline CellGrid::Event CellGrid::held(int ball) const {
  return {record(ball).event_time, record(ball).partner};
}
inline void CellGrid::hold(int ball, const Event& e) {
  record(ball).event_time = e.time;
  record(ball).partner = e.partner;
}

std::uint64_t CellGrid::KeyPlaces::place(int ball) const {
  const Record& r = grid->record(ball);
  const std::int32_t key = r.key == its_event        ? r.partner
                           : r.key == its_crossing_x ? cross_x
                                                     : cross_y;
  return grid->place(ball, key);
}

// ---- the cells' lists of balls

void CellGrid::insert(int ball, int column, int line) {
  Record& r = record(ball);
  std::int32_t& first = head(column, line);
  r.column = static_cast<std::uint32_t>(column);
  r.line = static_cast<std::uint32_t>(line);
  next_in_cell_[static_cast<std::size_t>(ball)] = first;
  first = ball;
}

// (A cell holds a ball or two: its list is walked to find the one before.)
void CellGrid::remove(int ball) {
  const Record& r = record(ball);
  std::int32_t* link = &head(static_cast<int>(r.column), static_cast<int>(r.line));
  while (*link != ball) link = &next_in_cell_[static_cast<std::size_t>(*link)];
  *link = next_in_cell_[static_cast<std::size_t>(ball)];
}

// Gathers into `neighbours_` the balls of a block of cells, `across` cells by
// `down` from the cell (column, line); returns how many. (The frame of empty
// cells around the table lets the block reach one cell beyond an edge.) A
// cell's list is walked two steps without asking whether it has ended (the
// list's end, ball 0, leads on to ball 0 again, and the count moves on only
// for a ball): whether a cell holds none, one or two balls is a coin toss the
// processor would guess wrong. Only a third ball takes a branch.
// [anchor: grid-gather]
template <int across, int down>
std::size_t CellGrid::gather(int column, int line) {
  std::int32_t* out = neighbours_.data();
  const std::int32_t* next = next_in_cell_.data();
  std::size_t found = 0;
  // (Both loops written out by the compiler: their counts are known, and
  // counting them costs as much as the cells' own steps.)
#pragma GCC unroll 3
  for (int l = line; l < line + down; ++l) {
    const std::int32_t* heads = &head(column, l);
#pragma GCC unroll 3
    for (int c = 0; c < across; ++c) {
      std::int32_t k = heads[c];  // the cell's first ball, or 0
      out[found] = k;
      found += k != 0;
      k = next[k];  // its second, or 0
      out[found] = k;
      found += k != 0;
      for (k = next[k]; k != 0; k = next[k]) {  // a third and more: rare
        // (Room for this ball and two for each cell of the block.)
        if (neighbours_.size() < found + 1 + 2 * across * down) {
          neighbours_.resize(2 * (found + 1 + 2 * across * down));
          out = neighbours_.data();
        }
        out[found++] = k;
      }
    }
  }
  return found;
}
// [/anchor: grid-gather]

// ---- predictions

// Is the ball moving towards the table's edge along x (or y), its cell the
// last one that way? Then a wall is ahead of it, and no cell crossing.
// (Asked with & and |, not && and ||: the sign of the velocity is a coin
// toss the processor would guess wrong.)
bool CellGrid::edge_ahead(int ball, bool along_x) const {
  const Record& r = record(ball);
  const double velocity = along_x ? row(ball).vx : row(ball).vy;
  const int cell = along_x ? r.column : static_cast<int>(r.line);
  const int last = (along_x ? cells_.columns : cells_.rows) - 1;
  return ((velocity > 0) & (cell == last)) | ((velocity < 0) & (cell == 0));
}

// K of a wall's code.
inline CollisionKind CellGrid::wall_kind(std::int32_t wall) {
  return wall == horizontal_wall ? CollisionKind::horizontal_wall
                                 : CollisionKind::vertical_wall;
}

inline CellGrid::Event CellGrid::wall_event(int ball, std::int32_t wall) const {
  return {wall_time(*gas_, limits_, ball, wall_kind(wall)), wall};
}

// A meeting, computed as the scan computes it: time_of_contact(N3, N4) with
// N3 < N4.
inline CellGrid::Event CellGrid::pair_event(int ball, int other) const {
  // (N4 found without a branch, which is lower being a coin toss: the xor of
  // the two numbers, less one of them, is the other.)
  const int n3 = std::min(ball, other), n4 = ball ^ other ^ n3;
  return {pair_time(*gas_, n3, n4), other};
}

// The next time the centre leaves its cell: through the side ahead of it in
// x or in y, whichever comes first (none at the table's edge: the wall comes
// first).
CellGrid::Event CellGrid::next_crossing(int ball) const {
  const Record& r = record(ball);
  const Ball& row = this->row(ball);
  // The side ahead along x: the cell's right side if vx > 0, its left if
  // vx < 0; none if vx = 0 or at the table's edge. The same along y. Both
  // times are computed and the answer selected, not branched on: the signs
  // of vx and vy are coin tosses the processor would guess wrong. (A time
  // divided by vx = 0 is infinite or not a number, and never selected.)
  const bool right = row.vx > 0, up = row.vy > 0;
  const bool open_x = (row.vx != 0) & !edge_ahead(ball, true);
  const bool open_y = (row.vy != 0) & !edge_ahead(ball, false);
  const double to_x =
      row.since + ((r.column + right) * cells_.cell_width - row.x) / row.vx;
  const double to_y =
      row.since + ((static_cast<int>(r.line) + up) * cells_.cell_height - row.y) / row.vy;
  const double across = open_x ? to_x : never, down = open_y ? to_y : never;
  const bool x_first = across <= down;
  return {x_first ? across : down, x_first ? cross_x : cross_y};
}

// ---- asking memory early (the processor's prefetch: a hint, which changes
// no result)
//
// Each of these is always written out where it is called. GCC 12 finds a
// function that only prefetches free of any effect and may drop a call to
// it whole: so it once did with the look ahead's asks for the first balls
// of cells, and 10^5 balls ran 25 % slower. A prefetch written out in its
// caller stays.

namespace {

// A block of `bytes` asked for: both ends, as it may span two cache lines.
[[gnu::always_inline]] inline void ask_early(const void* from, std::size_t bytes) {
  __builtin_prefetch(from);
  __builtin_prefetch(static_cast<const char*>(from) + bytes - 1);
}

}  // namespace

// A ball's row of R (40 bytes).
[[gnu::always_inline]] inline void CellGrid::ask_row_early(int ball) const {
  ask_early(&row(ball), sizeof(Ball));
}

// The 3 x 3 cells around the cell of record r.
inline CellGrid::Block CellGrid::block_around(const Record& r) const {
  return {cell_index(r.column - 1, static_cast<int>(r.line) - 1), 3, 3};
}

// The heads of a block's cells (`across` in a row, `down` rows).
[[gnu::always_inline]] inline void CellGrid::ask_heads_early(const Block& block) const {
  for (int l = 0; l < block.down; ++l)
    ask_early(&head_[block.first + lines_of_cells(l)],
              static_cast<std::size_t>(block.across) * sizeof(std::int32_t));
}

// For the first ball of each of a block's cells (heads in the cache), its
// link to the next and its row. (An empty cell's 0 asks for ball 1's row:
// no branch on a coin toss.)
[[gnu::always_inline]] inline void CellGrid::ask_first_balls_early(
    const Block& block) const {
  for (int l = 0; l < block.down; ++l) {
    const std::int32_t* heads = &head_[block.first + lines_of_cells(l)];
    for (int c = 0; c < block.across; ++c) {
      const std::int32_t k = heads[c];
      __builtin_prefetch(&next_in_cell_[static_cast<std::size_t>(k)]);
      ask_row_early(k + (k == 0));
    }
  }
}

// The rows of the first `count` balls gathered, asked for at once before
// the predictions read them one after another: each may wait for main
// memory, and the waits overlap.
[[gnu::always_inline]] inline void CellGrid::ask_rows_early(std::size_t count) const {
  for (std::size_t i = 0; i < count; ++i) ask_row_early(neighbours_[i]);
}

// A ball's event made afresh (its row of R is new, or the partner of the
// meeting it held has collided): the earliest of the walls along its cell's
// edges that it moves towards and the balls of the 3 x 3 cells around it
// (but `skip`, and only those numbered from `lowest`).
void CellGrid::predict(int ball, int skip, int lowest) {
  Record& r = record(ball);
  Event earliest;  // none yet
  if (edge_ahead(ball, false))
    keep_earlier(ball, earliest, wall_event(ball, horizontal_wall));
  if (edge_ahead(ball, true))
    keep_earlier(ball, earliest, wall_event(ball, vertical_wall));
  const std::size_t found = gather<3, 3>(r.column - 1, static_cast<int>(r.line) - 1);
  // Set aside the ball itself, `skip` and those below `lowest`, again by
  // arithmetic rather than by a branch.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < found; ++i) {
    const std::int32_t k = neighbours_[i];
    neighbours_[kept] = k;
    kept += static_cast<std::size_t>((k != ball) & (k != skip) & (k >= lowest));
  }
  ask_rows_early(kept);
  for (std::size_t i = 0; i < kept; ++i)
    keep_earlier(ball, earliest, pair_event(ball, neighbours_[i]));
  hold(ball, earliest);
}

// The ball's key, marked in its record: the earlier of its event and its
// next crossing (the crossing first at equal times). schedule also moves the
// key to its day in the calendar.
double CellGrid::choose_key(int ball) {
  Record& r = record(ball);
  const Event crossing = next_crossing(ball);
  if (crossing.time <= r.event_time) {
    r.key = crossing.partner == cross_x ? its_crossing_x : its_crossing_y;
    return crossing.time;
  }
  r.key = its_event;
  return r.event_time;
}
void CellGrid::schedule(int ball) {
  calendar_.schedule(ball, choose_key(ball));
}

// A crossing: the ball moves to the next cell in the books, is predicted
// against the balls of the cells that have just become its neighbours,
// learns of the wall if the new cell lies along it, and gets its next
// crossing. The event it held stays, unless one of these comes first.
void CellGrid::cross(int ball, bool along_x) {
  const Record& r = record(ball);
  const int step = (along_x ? row(ball).vx : row(ball).vy) > 0 ? 1 : -1;
  const int column = r.column + (along_x ? step : 0);
  const int line = static_cast<int>(r.line) + (along_x ? 0 : step);
  remove(ball);
  insert(ball, column, line);
  Event earliest = held(ball);
  // The new neighbours: the column (or row of cells) one further on.
  const std::size_t found = along_x ? gather<1, 3>(column + step, line - 1)
                                    : gather<3, 1>(column - 1, line + step);
  ask_rows_early(found);
  for (std::size_t i = 0; i < found; ++i)
    keep_earlier(ball, earliest, pair_event(ball, neighbours_[i]));
  if (edge_ahead(ball, along_x))
    keep_earlier(ball, earliest,
                 wall_event(ball, along_x ? vertical_wall : horizontal_wall));
  hold(ball, earliest);
  schedule(ball);
}

// A quick answer, without working the meeting out again: the partner's row
// is older than the ball's own. Rows are only rewritten by stage 5, at the
// collision's time TC, never before the present; the ball predicted its
// event after its own row was written; so a row of the partner's rewritten
// since would be written no earlier than the ball's. (Equal times prove
// nothing: two rows rewritten by one collision, or at one moment.)
inline bool CellGrid::partner_unchanged(int ball, int partner) const {
  return row(partner).since < row(ball).since;
}

// ---- the three calls

void CellGrid::rebuild(const Gas& gas, const CentreLimits& limits) {
  limits_ = limits;
  const auto n = gas.balls.size();
  // Cells at least 2a (1 + margin) wide, and not many more cells than balls
  // (a huge table with a few balls needs few cells), nor more columns and
  // lines than a record's 16 and 14 bits number (a wider cell only holds
  // more balls).
  cells_ = lay_out_cells(gas.width, gas.height, 2 * gas.radius * (1 + margin),
                         4.0 * static_cast<double>(n) + 16, 0xFFFF, 0x3FFF);

  // The rows of R, read at random places like the books: in large pages too.
  ask_large_pages(gas.balls.data(), n * sizeof(Ball));
  records_.assign(n + 1, Record{});
  next_in_cell_.assign(n + 1, 0);
  head_.assign(static_cast<std::size_t>(cells_.columns + 2) *
                   static_cast<std::size_t>(cells_.rows + 2),
               0);
  neighbours_.assign(2 * 9, 0);  // two for each of 3 x 3 cells; more if need be
  gas_ = &gas;
  const int count = static_cast<int>(n);
  for (int ball = 1; ball <= count; ++ball) {
    const Point centre = centre_at(row(ball), gas.time);
    insert(ball, cells_.column_of(centre.x), cells_.row_of(centre.y));
  }
  // Each pair once, by its lower-numbered ball.
  calendar_.reset(n);
  for (int ball = 1; ball <= count; ++ball) {
    predict(ball, 0, ball + 1);
    schedule(ball);
  }
}

// The block of cells a ball's next event will gather: for a meeting or a
// wall, the 3 x 3 cells around its own; for a crossing, the three cells it
// will newly neighbour (the column or line of cells that cross gathers).
CellGrid::Block CellGrid::block_ahead(int ball) const {
  const Record& r = record(ball);
  const int column = r.column, line = static_cast<int>(r.line);
  if (r.key == its_crossing_x) {
    const int step = row(ball).vx > 0 ? 2 : -2;
    return {cell_index(column + step, line - 1), 1, 3};
  }
  if (r.key == its_crossing_y) {
    const int step = row(ball).vy > 0 ? 2 : -2;
    return {cell_index(column - 1, line + step), 3, 1};
  }
  return block_around(r);
}

// The calendar's look ahead (beyond/event_calendar.hpp): what the event of
// `ball` will read, one step a day. Step 0: its record and row of R. Step 1
// (the record in the cache by then): the heads of the cells its event will
// gather (block_ahead), and, if its key is a meeting, the partner's record,
// row and calendar entry. Step 2 (those in the cache): the first ball of
// each of those cells (its link to the next, its row); the partner's page in
// the calendar and the heads of its 3 x 3 cells. Step 3: the first balls of
// the partner's cells, for its prediction after the collision (most were
// asked for already, as the ball's own). (Tried: a step for the cells'
// second balls; not faster.)
void CellGrid::KeyPlaces::prefetch(int ball, int step) const {
  if (step == 0) {
    __builtin_prefetch(&grid->record(ball));
    grid->ask_row_early(ball);
    return;
  }
  // (Nothing of the record read before this line: at step 0 it is not yet in
  // the cache, and a read would wait for it.)
  const Record& r = grid->record(ball);
  const std::int32_t partner = r.key == its_event ? r.partner : 0;
  switch (step) {
    case 1:
      grid->ask_heads_early(grid->block_ahead(ball));
      // (A crossing also takes the ball out of its own cell's list, which
      // starts at its cell's head.)
      if (r.key != its_event)
        __builtin_prefetch(&grid->head(r.column, static_cast<int>(r.line)));
      if (partner > 0) {
        __builtin_prefetch(&grid->record(partner));
        grid->ask_row_early(partner);
        grid->calendar_.prefetch(partner, 0);
      }
      return;
    case 2:
      grid->ask_first_balls_early(grid->block_ahead(ball));
      if (partner > 0) {
        grid->calendar_.prefetch(partner, 1);
        grid->ask_heads_early(grid->block_around(grid->record(partner)));
      }
      return;
    default:
      if (partner > 0)
        grid->ask_first_balls_early(grid->block_around(grid->record(partner)));
      return;
  }
}

// [anchor: grid-first]
Collision CellGrid::first(const Gas& gas) {
  gas_ = &gas;
  // The ball whose key is the earliest; none: nothing will ever collide.
  const KeyPlaces places(this);
  for (int ball = calendar_.earliest(places); ball != 0;
       ball = calendar_.earliest(places)) {
    const Record& r = record(ball);
    if (r.key != its_event) {
      cross(ball, r.key == its_crossing_x);
    } else if (r.partner > 0) {
      if (!partner_unchanged(ball, r.partner) &&
          pair_event(ball, r.partner).time != r.event_time) {
        // The partner has collided since: its meeting is not what it was.
        predict(ball, 0, 1);
        schedule(ball);
      } else {
        return due_from({r.event_time, CollisionKind::balls, std::min(ball, r.partner),
                         std::max(ball, r.partner)},
                        gas.time);
      }
    } else {
      return due_from({r.event_time, wall_kind(r.partner), ball, 0}, gas.time);
    }
  }
  return Collision{};  // K = 0
}
// [/anchor: grid-first]

// [anchor: grid-update]
void CellGrid::update(const Gas& gas, const Collision& done) {
  if (done.kind == CollisionKind::none) return;
  const bool pair = done.kind == CollisionKind::balls;
  gas_ = &gas;
  // Both balls predict afresh. (Meetings that other balls hold with them are
  // found out of date when they come up.) So that the waits for memory
  // overlap, N2's cells are asked for before N1 predicts, and N1's page in
  // the calendar before N2 predicts; N1's key goes on it after. (The order in
  // which keys go into the calendar changes nothing: it orders them by the
  // keys alone.)
  if (pair) ask_heads_early(block_around(record(done.second)));
  predict(done.first, 0, 1);
  const double first_key = choose_key(done.first);
  if (pair) {
    calendar_.ask_day_early(first_key);
    predict(done.second, done.first, 1);  // the pair itself is N1's
    schedule(done.second);
  }
  calendar_.schedule(done.first, first_key);
}
// [/anchor: grid-update]

}  // namespace gas
