// Stage 4 — first collision: the three ways to find it, and which to use.
//
// What this file does: puts the article's scan (stage4_first_collision.*),
// the table of next events (beyond/event_table.*) and the cell grid
// (beyond/cell_grid.*) behind one small interface — predict from scratch,
// give the first collision, take note of a collision carried out — and picks
// one for a scene by its number of balls.
// Beyond the article: the article has only the scan. All three give the same
// TC, K, N1, N2, bit for bit, ties included (suite `strategies`); they differ
// only in how long they take (data/reports/speed-against-error.md).
// Lesson: lessons/10-scaling.md
//
// Assumptions: as for the table and the grid — between two calls of `first`
// the gas changes only by the collision passed to `update`; anything else
// that rewrites rows of R asks for `rebuild`.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <variant>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "beyond/cell_grid.hpp"
#include "beyond/event_table.hpp"
#include "stage4_first_collision.hpp"

namespace gas {

// The ways to do stage 4.
enum class Strategy {
  scan,   // the article's: every wall and every pair, for each collision
  table,  // a table of each ball's next event; after a collision only its balls
  grid,   // cells at least 2a wide, a queue of events, cell crossings
};

// The way stage 4 is done for a scene of `ball_count` balls. A handful keeps
// the article's scan, so that `--trace` on the teaching scenes follows the
// article (for so few balls any way takes well under a microsecond a
// collision); then the table, while it is the fastest for a sparse gas; then
// the grid. The crossovers, measured by gas-benchmark, are in
// data/reports/speed-against-error.md (section 1).
// [anchor: strategy-for]
inline constexpr std::size_t most_balls_for_scan = 8;
inline constexpr std::size_t most_balls_for_table = 12;
inline Strategy strategy_for(std::size_t ball_count) {
  if (ball_count <= most_balls_for_scan) return Strategy::scan;
  if (ball_count <= most_balls_for_table) return Strategy::table;
  return Strategy::grid;
}
// [/anchor: strategy-for]

// "scan", "table", "grid"; and back (nothing for any other name).
const char* strategy_name(Strategy strategy);
std::optional<Strategy> strategy_named(std::string_view name);

// The article's scan as a way of stage 4: it keeps nothing between calls.
class ArticleScan {
 public:
  void rebuild(const Gas&, const CentreLimits& limits) { limits_ = limits; }
  Collision first(const Gas& gas) const { return find_first_collision(gas, limits_); }
  void update(const Gas&, const Collision&) {}

 private:
  CentreLimits limits_;
};

// Stage 4 done one of the three ways.
class FirstCollisionFinder {
 public:
  explicit FirstCollisionFinder(Strategy strategy = Strategy::scan);
  Strategy strategy() const { return strategy_; }

  // Predicts from scratch (at the start, and after the B key).
  void rebuild(const Gas& gas, const CentreLimits& limits);
  // The first collision: TC, K, N1, N2, as find_first_collision gives it.
  Collision first(const Gas& gas);
  // After stage 5 carried out `done`.
  void update(const Gas& gas, const Collision& done);

 private:
  Strategy strategy_;
  std::variant<ArticleScan, EventTable, CellGrid> way_;
};

}  // namespace gas
