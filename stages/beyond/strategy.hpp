// Stage 4 — first collision: the ways to find it, and which to use.
//
// What this file does: names the ways — the article's scan
// (stage4_first_collision.*), the table of next events (beyond/event_table.*),
// the plain cell grid (beyond/plain_grid.*) and the tuned one
// (beyond/cell_grid.*), each a FirstCollisionFinder, stage 4's small
// interface — picks one for a scene by its number of balls, and makes it for
// stage 7.
// Beyond the article: the article has only the scan. All give the same
// TC, K, N1, N2, bit for bit, ties included (suite `strategies`); they differ
// only in how long they take (data/reports/speed-against-error.md).
// Lesson: lessons/10-scaling.md
//
// Assumptions: as for the table and the grids — between two calls of `first`
// the gas changes only by the collision passed to `update`; anything else
// that rewrites columns of R asks for `rebuild`.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <string_view>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"
#include "stage7_control.hpp"

namespace gas {

// The ways to do stage 4.
enum class Strategy {
  scan,        // the article's: every wall and every pair, for each collision
  table,       // a table of each ball's next event; after a collision only its balls
  plain_grid,  // cells at least 2a wide, a calendar of events, cell crossings
  grid,        // the same, tuned: measured steps that save instructions and waits
};

// The way stage 4 is done for a scene of `ball_count` balls. A handful keeps
// the article's scan, so that `--trace` on the teaching scenes follows the
// article (for so few balls any way takes well under a microsecond a
// collision); then the table, while it is the fastest for a sparse gas; then
// the tuned grid. The crossovers, measured by gas-benchmark, are in
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

// "scan", "table", "plain-grid", "grid"; and back (nothing for any other
// name).
const char* strategy_name(Strategy strategy);
std::optional<Strategy> strategy_named(std::string_view name);

// A finder that does stage 4 the given way, for stage 7's Control
// (start_control takes it).
std::unique_ptr<FirstCollisionFinder> make_finder(Strategy strategy);

// Stage 7's loop set up for `gas` with stage 4 done the given way, or, by
// default, the way strategy_for picks for its number of balls (what the
// program does).
Control start_control_for(Gas gas, std::optional<Strategy> strategy = std::nullopt);

}  // namespace gas
