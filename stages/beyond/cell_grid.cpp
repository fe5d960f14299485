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

// ---- a ball's list of predictions: the record's first few, then the rest

// (The earliest stays at the front: the list's key. The rare overflow is a
// call of its own, so that the common case is small enough to be written
// into its callers.)
inline void CellGrid::add(int ball, Prediction p) {
  Record& r = record(ball);
  if (r.listed > 0 && earlier(ball, p, r.first[0])) std::swap(p, r.first[0]);
  if (r.listed < predictions_kept) {
    r.first[r.listed] = p;
  } else {
    add_more(ball, p);
  }
  ++r.listed;
}

void CellGrid::add_more(int ball, const Prediction& p) {
  more_predictions_[ball].push_back(p);
}

// Drops the predictions for which `dropped` says so (the others close up),
// and moves the earliest of the rest to the front.
template <typename Dropped>
void CellGrid::drop(int ball, Dropped dropped) {
  Record& r = record(ball);
  const std::uint32_t listed = r.listed;
  // The rest of the list, if it is longer than the record holds (looked up
  // once, not for each prediction).
  std::vector<Prediction>* more =
      listed > predictions_kept ? &more_predictions_.at(ball) : nullptr;
  auto at = [&](std::uint32_t i) -> Prediction& {
    return i < predictions_kept ? r.first[i] : (*more)[i - predictions_kept];
  };
  std::uint32_t kept = 0;
  for (std::uint32_t i = 0; i < listed; ++i) {
    const Prediction p = at(i);
    if (dropped(p)) continue;
    Prediction& slot = at(kept++);
    slot = p;
    if (earlier(ball, slot, r.first[0])) std::swap(slot, r.first[0]);
  }
  r.listed = kept;
  if (more != nullptr) {
    if (kept > predictions_kept) {
      more->resize(kept - predictions_kept);
    } else {
      more_predictions_.erase(ball);
    }
  }
}

// The whole list dropped.
void CellGrid::forget(int ball) {
  if (record(ball).listed > predictions_kept) more_predictions_.erase(ball);
  record(ball).listed = 0;
}

// The ball's key: the earliest of its list, or `never`.
CellGrid::Prediction CellGrid::key(int ball) const {
  const Record& r = record(ball);
  return r.listed > 0 ? r.first[0] : Prediction{};
}

std::uint32_t CellGrid::longest_list() const {
  std::uint32_t longest = 0;
  for (const Record& r : records_) longest = std::max(longest, r.listed);
  return longest;
}

// ---- the order of events, and which predictions still hold

// The place of a ball's prediction in the calendar's order at equal times:
// crossings first (they change no row of R, only the grid's books, and may
// bring in a prediction that belongs before the collisions at that time),
// then the events of the scan in the scan's order.
std::uint64_t CellGrid::place(int ball, const Prediction& p) const {
  switch (p.partner) {
    case cross_x:
      return static_cast<std::uint64_t>(ball) << 1;
    case cross_y:
      return static_cast<std::uint64_t>(ball) << 1 | 1;
    case horizontal_wall:
      return scan_event | scan_place(CollisionKind::horizontal_wall, ball, 0);
    case vertical_wall:
      return scan_event | scan_place(CollisionKind::vertical_wall, ball, 0);
    default:
      return scan_event | scan_place(CollisionKind::balls, std::min(ball, p.partner),
                                     std::max(ball, p.partner));
  }
}

// Does p come before q in the scan's order (time, then place)?
inline bool CellGrid::earlier(int ball, const Prediction& p, const Prediction& q) const {
  return p.time < q.time || (p.time == q.time && place(ball, p) < place(ball, q));
}

// Made when the partner had the collisions it still has? (A ball's own
// events are dropped with its list when it collides.)
inline bool CellGrid::current(const Prediction& p) const {
  return p.partner <= 0 || count_[static_cast<std::size_t>(p.partner)] == p.partner_count;
}

// ---- the cells' lists of balls

void CellGrid::insert(int ball, int column, int line) {
  Record& r = record(ball);
  std::int32_t& first = head(column, line);
  r.column = column;
  r.line = line;
  next_in_cell_[static_cast<std::size_t>(ball)] = first;
  first = ball;
}

// (A cell holds a ball or two: its list is walked to find the one before.)
void CellGrid::remove(int ball) {
  std::int32_t* link = &head(record(ball).column, record(ball).line);
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
  const int cell = along_x ? r.column : r.line;
  const int last = (along_x ? cells_.columns : cells_.rows) - 1;
  return ((velocity > 0) & (cell == last)) | ((velocity < 0) & (cell == 0));
}

void CellGrid::add_wall(int ball, std::int32_t wall) {
  const double time = wall_time(*gas_, limits_, ball,
                                wall == horizontal_wall ? CollisionKind::horizontal_wall
                                                        : CollisionKind::vertical_wall);
  if (time < never) add(ball, {time, wall, 0});
}

// A meeting, computed as the scan computes it: time_of_contact(N3, N4) with
// N3 < N4.
void CellGrid::add_pair(int ball, int other) {
  // (N4 found without a branch, which is lower being a coin toss: the xor of
  // the two numbers, less one of them, is the other.)
  const int n3 = std::min(ball, other), n4 = ball ^ other ^ n3;
  const double time = pair_time(*gas_, n3, n4);
  if (time < never) add(ball, {time, other, count_[static_cast<std::size_t>(other)]});
}

// The next time the centre leaves its cell: through the side ahead of it in
// x or in y, whichever comes first (none at the table's edge: the wall comes
// first).
CellGrid::Prediction CellGrid::next_crossing(int ball) const {
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
  const double to_y = row.since + ((r.line + up) * cells_.cell_height - row.y) / row.vy;
  const double across = open_x ? to_x : never, down = open_y ? to_y : never;
  const bool x_first = across <= down;
  return {x_first ? across : down, x_first ? cross_x : cross_y, 0};
}

// A ball's list made afresh (its row of R is new): the walls along its cell's
// edges that it moves towards, the balls of the 3 x 3 cells around it (but
// `skip`, and only those numbered from `lowest`), its next crossing.
void CellGrid::predict(int ball, int skip, int lowest) {
  forget(ball);
  if (edge_ahead(ball, false)) add_wall(ball, horizontal_wall);
  if (edge_ahead(ball, true)) add_wall(ball, vertical_wall);
  const std::size_t found = gather<3, 3>(record(ball).column - 1, record(ball).line - 1);
  // Set aside the ball itself, `skip` and those below `lowest`, again by
  // arithmetic rather than by a branch.
  std::size_t kept = 0;
  for (std::size_t i = 0; i < found; ++i) {
    const std::int32_t k = neighbours_[i];
    neighbours_[kept] = k;
    kept += static_cast<std::size_t>((k != ball) & (k != skip) & (k >= lowest));
  }
  for (std::size_t i = 0; i < kept; ++i) add_pair(ball, neighbours_[i]);
  const Prediction crossing = next_crossing(ball);
  if (crossing.time < never) add(ball, crossing);
}

// The ball's key moved to its day in the calendar.
void CellGrid::schedule(int ball) {
  calendar_.schedule(ball, key(ball).time);
}

// A crossing: the ball moves to the next cell in the books, is predicted
// against the balls of the cells that have just become its neighbours, learns
// of the wall if the new cell lies along it, and gets its next crossing.
void CellGrid::cross(int ball, bool along_x) {
  const Record& r = record(ball);
  const int step = (along_x ? row(ball).vx : row(ball).vy) > 0 ? 1 : -1;
  const int column = r.column + (along_x ? step : 0);
  const int line = r.line + (along_x ? 0 : step);
  remove(ball);
  insert(ball, column, line);
  drop(ball,
       [](const Prediction& p) { return p.partner == cross_x || p.partner == cross_y; });
  // The new neighbours: the column (or row of cells) one further on.
  const std::size_t found = along_x ? gather<1, 3>(column + step, line - 1)
                                    : gather<3, 1>(column - 1, line + step);
  for (std::size_t i = 0; i < found; ++i) add_pair(ball, neighbours_[i]);
  if (edge_ahead(ball, along_x))
    add_wall(ball, along_x ? vertical_wall : horizontal_wall);
  const Prediction crossing = next_crossing(ball);
  if (crossing.time < never) add(ball, crossing);
  schedule(ball);
}

// ---- the three calls

void CellGrid::rebuild(const Gas& gas, const CentreLimits& limits) {
  limits_ = limits;
  const auto n = gas.balls.size();
  // Cells at least 2a (1 + margin) wide, and not many more cells than balls
  // (a huge table with a few balls needs few cells).
  cells_ = lay_out_cells(gas.width, gas.height, 2 * gas.radius * (1 + margin),
                         4.0 * static_cast<double>(n) + 16);

  // The rows of R, read at random places like the books: in large pages too.
  ask_large_pages(gas.balls.data(), n * sizeof(Ball));
  records_.assign(n + 1, Record{});
  more_predictions_.clear();
  count_.assign(n + 1, 0);
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
  // Each pair once, in the list of its lower-numbered ball.
  calendar_.reset(n);
  for (int ball = 1; ball <= count; ++ball) {
    predict(ball, 0, ball + 1);
    schedule(ball);
  }
}

// The calendar's look ahead (beyond/event_calendar.hpp): what the event of
// `ball` will read. Step 0: its record and row of R. Step 1 (the record in
// the cache by then): the heads of its 3 x 3 cells, and for the partner of
// its key its count, record, row and calendar entry. Step 2 (those in the
// cache): for the first ball of each of those cells its link, count and
// row, and the partner's page in the calendar and the heads of its 3 x 3
// cells (most are the ball's own). (Tried: a step 3 for the
// cells' second balls; not faster.)
void CellGrid::KeyPlaces::prefetch(int ball, int step) const {
  const auto both_ends = [](const void* from, std::size_t bytes) {
    __builtin_prefetch(from);
    __builtin_prefetch(static_cast<const char*>(from) + bytes - 1);
  };
  if (step == 0) {
    __builtin_prefetch(&grid->record(ball));
    both_ends(&grid->row(ball), sizeof(Ball));
    return;
  }
  const Record& r = grid->record(ball);
  if (step == 2) {
    if (r.first[0].partner > 0) {
      grid->calendar_.prefetch(r.first[0].partner, 1);
      const Record& q = grid->record(r.first[0].partner);
      for (int l = q.line - 1; l <= q.line + 1; ++l)
        both_ends(&grid->head_[grid->cell_index(q.column - 1, l)],
                  3 * sizeof(std::int32_t));
    }
    for (int l = r.line - 1; l <= r.line + 1; ++l) {
      const std::int32_t* heads = &grid->head_[grid->cell_index(r.column - 1, l)];
      for (int c = 0; c < 3; ++c) {
        // (An empty cell's 0 asks for ball 1's row: no branch on a coin toss.)
        const std::int32_t k = heads[c];
        __builtin_prefetch(&grid->next_in_cell_[static_cast<std::size_t>(k)]);
        __builtin_prefetch(&grid->count_[static_cast<std::size_t>(k)]);
        both_ends(&grid->row(k + (k == 0)), sizeof(Ball));
      }
    }
    return;
  }
  for (int l = r.line - 1; l <= r.line + 1; ++l)
    both_ends(&grid->head_[grid->cell_index(r.column - 1, l)], 3 * sizeof(std::int32_t));
  const std::int32_t partner = r.first[0].partner;
  if (partner > 0) {
    __builtin_prefetch(&grid->count_[static_cast<std::size_t>(partner)]);
    __builtin_prefetch(&grid->record(partner));
    grid->calendar_.prefetch(partner, 0);
    both_ends(&grid->row(partner), sizeof(Ball));
  }
}

// [anchor: grid-first]
Collision CellGrid::first(const Gas& gas) {
  gas_ = &gas;
  // The ball whose next event is the earliest; none: nothing will ever collide.
  const KeyPlaces places(this);
  for (int ball = calendar_.earliest(places); ball != 0;
       ball = calendar_.earliest(places)) {
    const Prediction p = key(ball);
    if (!current(p)) {  // its partner has collided since: dropped
      drop(ball, [&](const Prediction& q) { return !current(q); });
      schedule(ball);
    } else if (p.partner == cross_x || p.partner == cross_y) {
      cross(ball, p.partner == cross_x);
    } else if (p.partner > 0) {
      return due_from({p.time, CollisionKind::balls, std::min(ball, p.partner),
                       std::max(ball, p.partner)},
                      gas.time);
    } else {
      const CollisionKind wall = p.partner == horizontal_wall
                                     ? CollisionKind::horizontal_wall
                                     : CollisionKind::vertical_wall;
      return due_from({p.time, wall, ball, 0}, gas.time);
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
  // The collision counted: predictions of meetings with these balls are out
  // of date.
  ++count_[static_cast<std::size_t>(done.first)];
  if (pair) ++count_[static_cast<std::size_t>(done.second)];
  predict(done.first, 0, 1);
  schedule(done.first);
  if (pair) {
    predict(done.second, done.first, 1);  // the pair itself is in N1's list
    schedule(done.second);
  }
}
// [/anchor: grid-update]

}  // namespace gas
