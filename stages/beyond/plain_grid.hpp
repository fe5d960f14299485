// Stage 4 — first collision, by a grid of cells and a calendar of events
// (beyond the article): the plain algorithm.
//
// What this file does: cuts the table into cells at least 2a wide
// (beyond/cell_layout.hpp) and keeps every ball in the cell that holds its
// centre. Two balls in cells that are not neighbours are more than 2a apart,
// so a ball is predicted only against the balls of the 3 x 3 cells around
// its own, and against its two walls. A ball leaving its cell is an event
// too, a "cell crossing": the ball moves to the next cell in the grid's books
// and is predicted against the balls that have just become its neighbours.
//
// Each ball keeps one event: the earliest wall or meeting it predicted. Its
// key in the event calendar (beyond/event_calendar.*) is the earlier of that
// event and its next crossing, and the calendar gives the ball whose key is
// the earliest. After a collision its two balls predict afresh. Other balls
// may still hold a meeting with one of them, now worthless; rather than hunt
// those down, a ball whose meeting comes up checks it: the meeting's time
// worked out again from the two balls' columns of R as they are now must be
// the time it holds, bit for bit. If it is not, the partner has collided
// since, and the ball predicts afresh ("lazy invalidation"). A ball needs no
// other event: every meeting it did not keep is no earlier than the one it
// keeps, so it predicts again before any of them is due. The work per
// collision does not grow with N.
//
// Beyond the article: the article scans every wall and every pair for each
// collision. The answer here is the scan's, bit for bit, ties included: the
// predictions are stage 4's wall_time and pair_time on the same columns of R
// (a crossing never rewrites one), and events are ordered as the scan meets
// them (beyond/event_order.hpp), crossings first. The grid that the program
// runs, beyond/cell_grid.*, is this one with measured speed-ups.
// Lesson: lessons/10-scaling.md
//
// Assumptions: between two calls of `first`, the gas changes only by the
// collision passed to `update` (stage 5's apply_collision); after anything
// else that rewrites columns of R (the B key, a new scene), call `rebuild`.
// Every centre stays on the table (stage 5 keeps it there).
#pragma once

#include <vector>

#include "beyond/cell_layout.hpp"
#include "beyond/event_calendar.hpp"
#include "beyond/event_order.hpp"
#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

class PlainGrid final : public FirstCollisionFinder {
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

  const char* name() const override { return "plain-grid"; }

  // The layout, for tests.
  const CellLayout& cells() const { return cells_; }

 private:
  // What the grid keeps of a ball.
  struct Books {
    Event event;  // the earliest wall or meeting it predicted
    Event key;    // its key in the calendar: `event`, or its next crossing
    int cell_column = 0, cell_row = 0;  // the cell that holds its centre
  };

  const Ball& R(int ball) const {  // its column of R
    return gas_->balls[static_cast<std::size_t>(ball - 1)];
  }
  Books& books(int ball) { return books_[static_cast<std::size_t>(ball)]; }
  std::vector<int>& cell(int cell_column, int cell_row) {
    return balls_in_cell_[static_cast<std::size_t>(cell_row * cells_.columns +
                                                   cell_column)];
  }

  Event wall_event(int ball, EventKind wall) const;
  Event meeting(int ball, int other) const;
  void keep_earlier(int ball, const Event& e);
  void predict(int ball, int skip);
  Event next_crossing(int ball) const;
  void schedule(int ball);
  void cross(int ball, EventKind crossing);

  CentreLimits limits_;
  CellLayout cells_;                             // the cells over the table
  const Gas* gas_ = nullptr;                     // the gas of the last call
  std::vector<Books> books_;                     // by ball number 1..N (0 unused)
  std::vector<std::vector<int>> balls_in_cell_;  // by cell, row after row
  EventCalendar calendar_;                       // every ball with a key

  // The calendar's question on a tie of times: the place of a ball's key.
  struct KeyPlaces final : EventCalendar::Places {
    explicit KeyPlaces(const PlainGrid* of) : grid(of) {}
    const PlainGrid* grid;
    std::uint64_t place(int ball) const override;
  };
};

}  // namespace gas
