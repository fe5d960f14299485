// Stage 4 — first collision, by a grid of cells and a calendar of events:
// the plain algorithm. See beyond/plain_grid.hpp.
#include "beyond/plain_grid.hpp"

#include <algorithm>

namespace gas {

// ---- predictions

// A wall, as the scan computes it.
Event PlainGrid::wall_event(int ball, EventKind wall) const {
  return {wall_time(*gas_, limits_, ball, static_cast<CollisionKind>(wall)), wall, 0};
}

// A meeting, as the scan computes it: time_of_contact(N3, N4) with N3 < N4.
Event PlainGrid::meeting(int ball, int other) const {
  return {pair_time(*gas_, std::min(ball, other), std::max(ball, other)),
          EventKind::meeting, other};
}

// The ball's event becomes e if e comes first. (An event that never comes
// is none.)
void PlainGrid::keep_earlier(int ball, const Event& e) {
  if (e.time < never && earlier(ball, e, books(ball).event)) books(ball).event = e;
}

// [anchor: plain-predict]
// A ball's event made afresh (its column of R is new, or the partner of the
// meeting it held has collided): the earliest of its two walls and its
// meetings with the balls of the 3 x 3 cells around its own, but `skip`.
void PlainGrid::predict(int ball, int skip) {
  Books& b = books(ball);
  b.event = Event{};  // none yet
  keep_earlier(ball, wall_event(ball, EventKind::horizontal_wall));
  keep_earlier(ball, wall_event(ball, EventKind::vertical_wall));
  const int last_row = std::min(cells_.rows - 1, b.cell_row + 1);
  const int last_column = std::min(cells_.columns - 1, b.cell_column + 1);
  for (int row = std::max(0, b.cell_row - 1); row <= last_row; ++row) {
    for (int column = std::max(0, b.cell_column - 1); column <= last_column; ++column) {
      for (const int other : cell(column, row))
        if (other != ball && other != skip) keep_earlier(ball, meeting(ball, other));
    }
  }
}
// [/anchor: plain-predict]

// The next time the ball's centre leaves its cell: through the side ahead
// of it along x or along y, whichever comes first (x on a tie). None at the
// table's edge: there the wall comes first.
Event PlainGrid::next_crossing(int ball) const {
  const Ball& r = R(ball);
  const Books& b = books_[static_cast<std::size_t>(ball)];
  Event along_x, along_y;  // none yet
  if (r.vx > 0 && b.cell_column < cells_.columns - 1)
    along_x.time = r.since + ((b.cell_column + 1) * cells_.cell_width - r.x) / r.vx;
  if (r.vx < 0 && b.cell_column > 0)
    along_x.time = r.since + (b.cell_column * cells_.cell_width - r.x) / r.vx;
  if (r.vy > 0 && b.cell_row < cells_.rows - 1)
    along_y.time = r.since + ((b.cell_row + 1) * cells_.cell_height - r.y) / r.vy;
  if (r.vy < 0 && b.cell_row > 0)
    along_y.time = r.since + (b.cell_row * cells_.cell_height - r.y) / r.vy;
  along_x.kind = EventKind::crossing_x;
  along_y.kind = EventKind::crossing_y;
  return along_y.time < along_x.time ? along_y : along_x;
}

// The ball's key: the earlier of its event and its next crossing (the
// crossing first at equal times), put in the calendar. (A key that never
// comes takes the ball off the calendar.)
void PlainGrid::schedule(int ball) {
  Books& b = books(ball);
  const Event crossing = next_crossing(ball);
  b.key = crossing.time <= b.event.time ? crossing : b.event;
  calendar_.schedule(ball, b.key.time);
}

// [anchor: plain-cross]
// A crossing: the ball moves to the next cell in the books and is offered
// the balls of the cells that have just become its neighbours (the cell
// column, or cell row, one further on). The event it held stays, unless one
// of these comes first.
void PlainGrid::cross(int ball, EventKind crossing) {
  Books& b = books(ball);
  const bool along_x = crossing == EventKind::crossing_x;
  const int step = (along_x ? R(ball).vx : R(ball).vy) > 0 ? 1 : -1;
  std::erase(cell(b.cell_column, b.cell_row), ball);
  (along_x ? b.cell_column : b.cell_row) += step;
  cell(b.cell_column, b.cell_row).push_back(ball);
  for (int side = -1; side <= 1; ++side) {
    const int column = b.cell_column + (along_x ? step : side);
    const int row = b.cell_row + (along_x ? side : step);
    if (column < 0 || column >= cells_.columns || row < 0 || row >= cells_.rows) continue;
    for (const int other : cell(column, row)) keep_earlier(ball, meeting(ball, other));
  }
  schedule(ball);
}
// [/anchor: plain-cross]

// ---- the three calls

void PlainGrid::rebuild(const Gas& gas, const CentreLimits& limits) {
  gas_ = &gas;
  limits_ = limits;
  cells_ = grid_cells(gas.width, gas.height, gas.radius, gas.balls.size());
  const int count = static_cast<int>(gas.balls.size());
  books_.assign(gas.balls.size() + 1, Books{});
  balls_in_cell_.assign(static_cast<std::size_t>(cells_.columns * cells_.rows), {});
  for (int ball = 1; ball <= count; ++ball) {
    const Point centre = centre_at(R(ball), gas.time);
    books(ball).cell_column = cells_.column_of(centre.x);
    books(ball).cell_row = cells_.row_of(centre.y);
    cell(books(ball).cell_column, books(ball).cell_row).push_back(ball);
  }
  calendar_.reset(gas.balls.size());
  for (int ball = 1; ball <= count; ++ball) {
    predict(ball, 0);
    schedule(ball);
  }
}

// [anchor: plain-first]
Collision PlainGrid::first(const Gas& gas) {
  gas_ = &gas;
  // The ball whose key is the earliest; none: nothing will ever collide.
  const KeyPlaces places(this);
  for (int ball = calendar_.earliest(places); ball != 0;
       ball = calendar_.earliest(places)) {
    const Event key = books(ball).key;
    switch (key.kind) {
      case EventKind::crossing_x:
      case EventKind::crossing_y:
        cross(ball, key.kind);
        break;
      case EventKind::meeting:
        if (meeting(ball, key.partner).time != key.time) {
          // The partner has collided since: the meeting is not what it was.
          predict(ball, 0);
          schedule(ball);
          break;
        }
        return due_from({key.time, CollisionKind::balls, std::min(ball, key.partner),
                         std::max(ball, key.partner)},
                        gas.time);
      default:  // a wall
        return due_from({key.time, static_cast<CollisionKind>(key.kind), ball, 0},
                        gas.time);
    }
  }
  return Collision{};  // K = 0
}
// [/anchor: plain-first]

// [anchor: plain-update]
void PlainGrid::update(const Gas& gas, const Collision& done) {
  if (done.kind == CollisionKind::none) return;
  gas_ = &gas;
  // Both balls predict afresh; the pair itself is N1's. (Meetings that other
  // balls hold with them are found out of date when they come up.)
  predict(done.first, 0);
  schedule(done.first);
  if (done.kind == CollisionKind::balls) {
    predict(done.second, done.first);
    schedule(done.second);
  }
}
// [/anchor: plain-update]

std::uint64_t PlainGrid::KeyPlaces::place(int ball) const {
  return grid_place(ball, grid->books_[static_cast<std::size_t>(ball)].key);
}

}  // namespace gas
