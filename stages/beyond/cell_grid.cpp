// Stage 4 — first collision, by a grid of cells and a calendar of events:
// the tuned grid. See beyond/cell_grid.hpp (the steps, numbered there) and,
// for the algorithm, beyond/plain_grid.hpp; the look ahead is in
// beyond/grid_look_ahead.cpp.
#include "beyond/cell_grid.hpp"

#include <algorithm>
#include <cassert>

namespace gas {

// ---- a ball's event and key (step 1: packed in its record)

inline Event CellGrid::held(int ball) const {
  const Record& r = record(ball);
  return {r.event_time, static_cast<EventKind>(r.event), r.partner};
}

inline void CellGrid::hold(int ball, const Event& e) {
  Record& r = record(ball);
  r.event_time = e.time;
  r.partner = e.partner;
  r.event = static_cast<std::uint32_t>(e.kind);
}

// The event that is the ball's key: its event, or its next crossing (whose
// time the calendar holds; its place needs only its kind).
Event CellGrid::key_event(int ball) const {
  const Record& r = record(ball);
  if (r.key == r.event) return held(ball);
  return {never, static_cast<EventKind>(r.key), 0};
}

std::uint64_t CellGrid::KeyPlaces::place(int ball) const {
  return grid_place(ball, grid->key_event(ball));
}

// Keeps e as the earliest if it comes before it. (An event that never comes
// is no event.)
inline void CellGrid::keep_earlier(int ball, Event& earliest, const Event& e) {
  if (e.time < never && earlier(ball, e, earliest)) earliest = e;
}

// ---- the cells' chains of balls (step 1)

void CellGrid::insert(int ball, int cell_column, int cell_row) {
  assert(cell_column >= 0 && cell_column < cells_.columns && cell_row >= 0 &&
         cell_row < cells_.rows);
  Record& r = record(ball);
  std::int32_t& first = head(cell_column, cell_row);
  r.cell_column = static_cast<std::uint32_t>(cell_column);
  r.cell_row = static_cast<std::uint32_t>(cell_row);
  assert(static_cast<int>(r.cell_column) == cell_column &&
         static_cast<int>(r.cell_row) == cell_row);  // the 13 bits hold them
  next_in_cell_[static_cast<std::size_t>(ball)] = first;
  first = ball;
}

// (A cell holds a ball or two: its chain is walked to find the one before.)
void CellGrid::remove(int ball) {
  const Record& r = record(ball);
  std::int32_t* link =
      &head(static_cast<int>(r.cell_column), static_cast<int>(r.cell_row));
  while (*link != ball) link = &next_in_cell_[static_cast<std::size_t>(*link)];
  *link = next_in_cell_[static_cast<std::size_t>(ball)];
}

// Gathers into `neighbours_` the balls of a block of cells, `across` cells
// by `down` cell rows from the cell (cell_column, cell_row); returns how
// many. (The frame lets the block reach one cell beyond an edge.) A cell's
// chain is walked two links without asking whether it has ended (its end,
// ball 0, links to ball 0 again, and the count moves on only for a ball);
// only a third ball takes a branch. Both loops are written out by the
// compiler (step 3).
// [anchor: grid-gather]
template <int across, int down>
std::size_t CellGrid::gather(int cell_column, int cell_row) {
  assert(in_frame(cell_column, cell_row) &&
         in_frame(cell_column + across - 1, cell_row + down - 1));
  std::int32_t* out = neighbours_.data();
  const std::int32_t* next = next_in_cell_.data();
  std::size_t found = 0;
#pragma GCC unroll 3
  for (int row = cell_row; row < cell_row + down; ++row) {
    const std::int32_t* heads = &head(cell_column, row);
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
// last one that way? Then a wall is ahead of it, and no cell crossing
// (steps 2 and 3: asked with & and |).
inline bool CellGrid::edge_ahead(int ball, bool along_x) const {
  const Record& r = record(ball);
  const double velocity = along_x ? R(ball).vx : R(ball).vy;
  const int cell = static_cast<int>(along_x ? r.cell_column : r.cell_row);
  const int last = (along_x ? cells_.columns : cells_.rows) - 1;
  return ((velocity > 0) & (cell == last)) | ((velocity < 0) & (cell == 0));
}

inline Event CellGrid::wall_event(int ball, EventKind wall) const {
  return {wall_time(*gas_, limits_, ball, static_cast<CollisionKind>(wall)), wall, 0};
}

// A meeting, computed as the scan computes it: time_of_contact(N3, N4) with
// N3 < N4. (N4 without a branch: the xor of the two numbers, less one of
// them, is the other.)
inline Event CellGrid::pair_event(int ball, int other) const {
  const int n3 = std::min(ball, other), n4 = ball ^ other ^ n3;
  return {pair_time(*gas_, n3, n4), EventKind::meeting, other};
}

// The next time the centre leaves its cell, as the plain grid finds it:
// through the side ahead of it along x or along y, whichever comes first
// (x on a tie); none at the table's edge. Both times are computed and the
// answer selected (step 3). (A time divided by a velocity of 0 is infinite
// or not a number, and never selected.)
Event CellGrid::next_crossing(int ball) const {
  const Record& r = record(ball);
  const Ball& b = R(ball);
  const bool right = b.vx > 0, up = b.vy > 0;
  const bool open_x = (b.vx != 0) & !edge_ahead(ball, true);
  const bool open_y = (b.vy != 0) & !edge_ahead(ball, false);
  const double to_x =
      b.since +
      ((static_cast<int>(r.cell_column) + right) * cells_.cell_width - b.x) / b.vx;
  const double to_y =
      b.since + ((static_cast<int>(r.cell_row) + up) * cells_.cell_height - b.y) / b.vy;
  const double along_x = open_x ? to_x : never, along_y = open_y ? to_y : never;
  const bool x_first = along_x <= along_y;
  return {x_first ? along_x : along_y,
          x_first ? EventKind::crossing_x : EventKind::crossing_y, 0};
}

// Step 4.
inline bool CellGrid::partner_unchanged(int ball, int partner) const {
  return R(partner).since < R(ball).since;
}

// The plain grid's predict: the earliest of the walls ahead (step 2) and the
// balls of the 3 x 3 cells around, but `skip`.
void CellGrid::predict(int ball, int skip) {
  const Record& r = record(ball);
  Event earliest;  // none yet
  if (edge_ahead(ball, false))
    keep_earlier(ball, earliest, wall_event(ball, EventKind::horizontal_wall));
  if (edge_ahead(ball, true))
    keep_earlier(ball, earliest, wall_event(ball, EventKind::vertical_wall));
  const std::size_t found =
      gather<3, 3>(static_cast<int>(r.cell_column) - 1, static_cast<int>(r.cell_row) - 1);
  // Set aside the ball itself and `skip`, again by arithmetic (step 3).
  std::size_t kept = 0;
  for (std::size_t i = 0; i < found; ++i) {
    const std::int32_t k = neighbours_[i];
    neighbours_[kept] = k;
    kept += static_cast<std::size_t>((k != ball) & (k != skip));
  }
  for (std::size_t i = 0; i < kept; ++i)
    keep_earlier(ball, earliest, pair_event(ball, neighbours_[i]));
  hold(ball, earliest);
}

// The ball's key, marked in its record and put in the calendar: the earlier
// of its event and its next crossing (the crossing first at equal times).
void CellGrid::schedule(int ball) {
  Record& r = record(ball);
  const Event crossing = next_crossing(ball);
  const bool crosses = crossing.time <= r.event_time;
  r.key = crosses ? static_cast<std::uint32_t>(crossing.kind) : r.event;
  calendar_.schedule(ball, crosses ? crossing.time : r.event_time);
}

// The plain grid's cross: into the next cell, offered the cells that have
// just become its neighbours (through the frame: no test at the edges), and
// the wall if the new cell lies along it (step 2).
void CellGrid::cross(int ball, bool along_x) {
  const Record& r = record(ball);
  const int step = (along_x ? R(ball).vx : R(ball).vy) > 0 ? 1 : -1;
  const int column = static_cast<int>(r.cell_column) + (along_x ? step : 0);
  const int row = static_cast<int>(r.cell_row) + (along_x ? 0 : step);
  remove(ball);
  insert(ball, column, row);
  Event earliest = held(ball);
  const std::size_t found = along_x ? gather<1, 3>(column + step, row - 1)
                                    : gather<3, 1>(column - 1, row + step);
  for (std::size_t i = 0; i < found; ++i)
    keep_earlier(ball, earliest, pair_event(ball, neighbours_[i]));
  if (edge_ahead(ball, along_x))
    keep_earlier(ball, earliest,
                 wall_event(ball, along_x ? EventKind::vertical_wall
                                          : EventKind::horizontal_wall));
  hold(ball, earliest);
  schedule(ball);
}

// ---- the three calls

void CellGrid::rebuild(const Gas& gas, const CentreLimits& limits) {
  limits_ = limits;
  const auto n = gas.balls.size();
  cells_ = grid_cells(gas.width, gas.height, gas.radius, n, most_cells_along);
  // The columns of R, read at random places like the books: moved into large
  // pages too (step 5).
  ask_large_pages(gas.balls.data(), n * sizeof(Ball));
  records_.assign(n + 1, Record{});
  next_in_cell_.assign(n + 1, 0);
  head_.assign(cell_index(cells_.columns, cells_.rows) + 1, 0);  // the frame included
  neighbours_.assign(2 * 9, 0);  // two for each of 3 x 3 cells; more if need be
  gas_ = &gas;
  const int count = static_cast<int>(n);
  for (int ball = 1; ball <= count; ++ball) {
    const Point centre = centre_at(R(ball), gas.time);
    insert(ball, cells_.column_of(centre.x), cells_.row_of(centre.y));
  }
  calendar_.reset(n);
  looking_ahead_ = n >= look_ahead_from;
  for (int ball = 1; ball <= count; ++ball) {
    predict(ball, 0);
    schedule(ball);
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
    const auto key = static_cast<EventKind>(r.key);
    if (key == EventKind::crossing_x || key == EventKind::crossing_y) {
      cross(ball, key == EventKind::crossing_x);
    } else if (key == EventKind::meeting) {
      if (!partner_unchanged(ball, r.partner) &&
          pair_event(ball, r.partner).time != r.event_time) {
        // The partner has collided since: the meeting is not what it was.
        predict(ball, 0);
        schedule(ball);
      } else {
        return due_from({r.event_time, CollisionKind::balls, std::min(ball, r.partner),
                         std::max(ball, r.partner)},
                        gas.time);
      }
    } else {  // a wall
      return due_from({r.event_time, static_cast<CollisionKind>(key), ball, 0}, gas.time);
    }
  }
  return Collision{};  // K = 0
}
// [/anchor: grid-first]

// [anchor: grid-update]
void CellGrid::update(const Gas& gas, const Collision& done) {
  if (done.kind == CollisionKind::none) return;
  gas_ = &gas;
  predict(done.first, 0);
  schedule(done.first);
  if (done.kind == CollisionKind::balls) {
    predict(done.second, done.first);  // the pair itself is N1's
    schedule(done.second);
  }
}
// [/anchor: grid-update]

}  // namespace gas
