// Stage 4 — first collision, by a grid of cells and a queue of events. See
// stage4_cell_grid.hpp.
#include "stage4_cell_grid.hpp"

#include <algorithm>
#include <cmath>

#include "stage4_event_order.hpp"

namespace gas {

namespace {

// How many cells along a side of `length`: as many as fit with each at least
// `smallest` long, and at least one.
double cells_along(double length, double smallest) {
  return std::max(1.0, std::floor(length / smallest));
}

// The cell of a coordinate, among `cells` cells of width `width` from 0.
int cell_of(double coordinate, double width, int cells) {
  const double cell = std::floor(coordinate / width);
  return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(cells - 1)));
}

constexpr std::uint64_t scan_event = std::uint64_t{1} << 63;

}  // namespace

// The place of a ball's prediction in the queue's order at equal times:
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

// The heap's order: time, then the place in the scan (rarely needed).
inline bool CellGrid::before(const Entry& a, const Entry& b) const {
  if (a.time != b.time) return a.time < b.time;
  return place(a.ball, earliest_[static_cast<std::size_t>(a.ball)]) <
         place(b.ball, earliest_[static_cast<std::size_t>(b.ball)]);
}

// Made when the partner had the collisions it still has? (A ball's own
// events are dropped with its list when it collides.)
inline bool CellGrid::current(const Prediction& p) const {
  return p.partner <= 0 || count_[static_cast<std::size_t>(p.partner)] == p.partner_count;
}

void CellGrid::sift_up(std::size_t position) {
  const Entry entry = heap_[position];
  while (position > 0) {
    const std::size_t parent = (position - 1) / 2;
    if (!before(entry, heap_[parent])) break;
    heap_[position] = heap_[parent];
    position_[static_cast<std::size_t>(heap_[position].ball)] = position;
    position = parent;
  }
  heap_[position] = entry;
  position_[static_cast<std::size_t>(entry.ball)] = position;
}

void CellGrid::sift_down(std::size_t position) {
  const Entry entry = heap_[position];
  const std::size_t size = heap_.size();
  while (true) {
    std::size_t child = 2 * position + 1;
    if (child >= size) break;
    if (child + 1 < size && before(heap_[child + 1], heap_[child])) ++child;
    if (!before(heap_[child], entry)) break;
    heap_[position] = heap_[child];
    position_[static_cast<std::size_t>(heap_[position].ball)] = position;
    position = child;
  }
  heap_[position] = entry;
  position_[static_cast<std::size_t>(entry.ball)] = position;
}

void CellGrid::insert(int ball, int column, int row) {
  const auto b = static_cast<std::size_t>(ball);
  const auto cell = static_cast<std::size_t>(row * columns_ + column);
  column_[b] = column;
  row_[b] = row;
  previous_in_cell_[b] = 0;
  next_in_cell_[b] = head_[cell];
  if (head_[cell] != 0) previous_in_cell_[static_cast<std::size_t>(head_[cell])] = ball;
  head_[cell] = ball;
}

void CellGrid::remove(int ball) {
  const auto b = static_cast<std::size_t>(ball);
  const auto cell = static_cast<std::size_t>(row_[b] * columns_ + column_[b]);
  const int before_it = previous_in_cell_[b], after_it = next_in_cell_[b];
  if (before_it != 0) {
    next_in_cell_[static_cast<std::size_t>(before_it)] = after_it;
  } else {
    head_[cell] = after_it;
  }
  if (after_it != 0) previous_in_cell_[static_cast<std::size_t>(after_it)] = before_it;
}

void CellGrid::add_wall(const Gas& gas, int ball, std::int32_t wall) {
  const double time = wall_time(gas, limits_, ball,
                                wall == horizontal_wall ? CollisionKind::horizontal_wall
                                                        : CollisionKind::vertical_wall);
  if (time < never)
    predictions_[static_cast<std::size_t>(ball)].push_back({time, wall, 0});
}

void CellGrid::add_pair(const Gas& gas, int ball, int other) {
  const double time = pair_time(gas, std::min(ball, other), std::max(ball, other));
  if (time < never) {
    predictions_[static_cast<std::size_t>(ball)].push_back(
        {time, other, count_[static_cast<std::size_t>(other)]});
  }
}

// The next time the centre leaves its cell: through the side ahead of it in
// x or in y, whichever comes first (none at the table's edge: the wall comes
// before).
CellGrid::Prediction CellGrid::next_crossing(const Gas& gas, int ball) const {
  const auto b = static_cast<std::size_t>(ball);
  const Ball& row = gas.balls[b - 1];
  double across = never, down = never;
  if (row.vx > 0 && column_[b] < columns_ - 1)
    across = row.since + ((column_[b] + 1) * cell_width_ - row.x) / row.vx;
  if (row.vx < 0 && column_[b] > 0)
    across = row.since + (column_[b] * cell_width_ - row.x) / row.vx;
  if (row.vy > 0 && row_[b] < rows_ - 1)
    down = row.since + ((row_[b] + 1) * cell_height_ - row.y) / row.vy;
  if (row.vy < 0 && row_[b] > 0)
    down = row.since + (row_[b] * cell_height_ - row.y) / row.vy;
  if (across <= down) return {across, cross_x, 0};
  return {down, cross_y, 0};
}

// A ball's list made afresh (its row of R is new): the walls along its cell's
// edges that it moves towards, the balls of the 3 x 3 cells around it (but
// `skip`, and only those numbered from `lowest`), its next crossing.
void CellGrid::predict(const Gas& gas, int ball, int skip, int lowest) {
  const auto b = static_cast<std::size_t>(ball);
  predictions_[b].clear();
  const Ball& row = gas.balls[b - 1];
  const int column = column_[b], line = row_[b];
  if ((row.vy > 0 && line == rows_ - 1) || (row.vy < 0 && line == 0))
    add_wall(gas, ball, horizontal_wall);
  if ((row.vx > 0 && column == columns_ - 1) || (row.vx < 0 && column == 0))
    add_wall(gas, ball, vertical_wall);
  for (int r = std::max(0, line - 1); r <= std::min(rows_ - 1, line + 1); ++r) {
    for (int c = std::max(0, column - 1); c <= std::min(columns_ - 1, column + 1); ++c) {
      for (int k = head_[static_cast<std::size_t>(r * columns_ + c)]; k != 0;
           k = next_in_cell_[static_cast<std::size_t>(k)]) {
        if (k != ball && k != skip && k >= lowest) add_pair(gas, ball, k);
      }
    }
  }
  const Prediction crossing = next_crossing(gas, ball);
  if (crossing.time < never) predictions_[b].push_back(crossing);
}

// The ball's key: the earliest current prediction of its list (the others,
// out of date, are dropped on the way).
void CellGrid::choose_earliest(int ball) {
  const auto b = static_cast<std::size_t>(ball);
  std::vector<Prediction>& list = predictions_[b];
  std::erase_if(list, [&](const Prediction& p) { return !current(p); });
  Prediction earliest;
  for (const Prediction& p : list) {
    if (p.time < earliest.time ||
        (p.time == earliest.time && place(ball, p) < place(ball, earliest)))
      earliest = p;
  }
  earliest_[b] = earliest;
}

// The same, and the ball's entry moved to its place in the heap.
void CellGrid::refresh(int ball) {
  choose_earliest(ball);
  const std::size_t position = position_[static_cast<std::size_t>(ball)];
  heap_[position].time = earliest_[static_cast<std::size_t>(ball)].time;
  if (position > 0 && before(heap_[position], heap_[(position - 1) / 2])) {
    sift_up(position);
  } else {
    sift_down(position);
  }
}

// A crossing: the ball moves to the next cell in the books, is predicted
// against the balls of the cells that have just become its neighbours, learns
// of the wall if the new cell lies along it, and gets its next crossing.
void CellGrid::cross(const Gas& gas, int ball, bool along_x) {
  const auto b = static_cast<std::size_t>(ball);
  const Ball& row = gas.balls[b - 1];
  const int step = (along_x ? row.vx : row.vy) > 0 ? 1 : -1;
  const int column = column_[b] + (along_x ? step : 0);
  const int line = row_[b] + (along_x ? 0 : step);
  remove(ball);
  insert(ball, column, line);
  std::vector<Prediction>& list = predictions_[b];
  std::erase_if(list, [](const Prediction& p) {
    return p.partner == cross_x || p.partner == cross_y;
  });
  // The new neighbours: the column (or row of cells) one further on.
  for (int i = -1; i <= 1; ++i) {
    const int c = along_x ? column + step : column + i;
    const int r = along_x ? line + i : line + step;
    if (c < 0 || c >= columns_ || r < 0 || r >= rows_) continue;
    for (int k = head_[static_cast<std::size_t>(r * columns_ + c)]; k != 0;
         k = next_in_cell_[static_cast<std::size_t>(k)]) {
      add_pair(gas, ball, k);
    }
  }
  if (along_x && (step > 0 ? column == columns_ - 1 : column == 0))
    add_wall(gas, ball, vertical_wall);
  if (!along_x && (step > 0 ? line == rows_ - 1 : line == 0))
    add_wall(gas, ball, horizontal_wall);
  const Prediction crossing = next_crossing(gas, ball);
  if (crossing.time < never) list.push_back(crossing);
  refresh(ball);
}

void CellGrid::rebuild(const Gas& gas, const CentreLimits& limits) {
  limits_ = limits;
  const auto n = gas.balls.size();
  // Cells at least 2a (1 + margin) wide, and not many more cells than balls
  // (a huge table with a few balls needs few cells).
  const double smallest = 2 * gas.radius * (1 + margin);
  const double most = 4.0 * static_cast<double>(n) + 16;
  double columns = std::min(cells_along(gas.width, smallest), most);
  double rows = std::min(cells_along(gas.height, smallest), most);
  if (columns * rows > most) {
    const double shrink = std::sqrt(most / (columns * rows));
    columns = std::max(1.0, std::floor(columns * shrink));
    rows = std::max(1.0, std::floor(rows * shrink));
  }
  columns_ = static_cast<int>(columns);
  rows_ = static_cast<int>(rows);
  cell_width_ = gas.width / columns_;
  cell_height_ = gas.height / rows_;

  predictions_.assign(n + 1, {});
  earliest_.assign(n + 1, Prediction{});
  count_.assign(n + 1, 0);
  position_.assign(n + 1, 0);
  column_.assign(n + 1, 0);
  row_.assign(n + 1, 0);
  next_in_cell_.assign(n + 1, 0);
  previous_in_cell_.assign(n + 1, 0);
  head_.assign(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_), 0);
  const int count = static_cast<int>(n);
  for (int ball = 1; ball <= count; ++ball) {
    const Point centre =
        centre_at(gas.balls[static_cast<std::size_t>(ball - 1)], gas.time);
    insert(ball, cell_of(centre.x, cell_width_, columns_),
           cell_of(centre.y, cell_height_, rows_));
  }
  // Each pair once, in the list of its lower-numbered ball.
  heap_.clear();
  for (int ball = 1; ball <= count; ++ball) {
    predict(gas, ball, 0, ball + 1);
    choose_earliest(ball);
    heap_.push_back({earliest_[static_cast<std::size_t>(ball)].time, ball});
    position_[static_cast<std::size_t>(ball)] = heap_.size() - 1;
  }
  for (std::size_t position = heap_.size() / 2; position-- > 0;) sift_down(position);
}

// [anchor: grid-first]
Collision CellGrid::first(const Gas& gas) {
  while (!heap_.empty()) {
    const int ball = heap_.front().ball;
    const Prediction p = earliest_[static_cast<std::size_t>(ball)];
    if (!(p.time < never)) break;  // nothing will ever collide
    if (!current(p)) {             // its partner has collided since: dropped
      refresh(ball);
    } else if (p.partner == cross_x || p.partner == cross_y) {
      cross(gas, ball, p.partner == cross_x);
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
  ++count_[static_cast<std::size_t>(done.first)];  // predictions of meetings with
  if (pair) ++count_[static_cast<std::size_t>(done.second)];  // them: out of date
  predict(gas, done.first, 0, 1);
  refresh(done.first);
  if (pair) {
    predict(gas, done.second, done.first, 1);  // the pair itself is in N1's list
    refresh(done.second);
  }
}
// [/anchor: grid-update]

}  // namespace gas
