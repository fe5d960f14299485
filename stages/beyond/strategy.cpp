// Stage 4 — the ways to find the first collision. See beyond/strategy.hpp.
#include "beyond/strategy.hpp"

#include "beyond/cell_grid.hpp"
#include "beyond/event_table.hpp"
#include "beyond/plain_grid.hpp"

namespace gas {

const char* strategy_name(Strategy strategy) {
  switch (strategy) {
    case Strategy::scan:
      return "scan";
    case Strategy::table:
      return "table";
    case Strategy::plain_grid:
      return "plain-grid";
    case Strategy::grid:
      return "grid";
  }
  return "?";
}

std::optional<Strategy> strategy_named(std::string_view name) {
  for (const Strategy strategy :
       {Strategy::scan, Strategy::table, Strategy::plain_grid, Strategy::grid}) {
    if (name == strategy_name(strategy)) return strategy;
  }
  return std::nullopt;
}

std::unique_ptr<FirstCollisionFinder> make_finder(Strategy strategy) {
  switch (strategy) {
    case Strategy::scan:
      return std::make_unique<ArticleScan>();
    case Strategy::table:
      return std::make_unique<EventTable>();
    case Strategy::plain_grid:
      return std::make_unique<PlainGrid>();
    case Strategy::grid:
      return std::make_unique<CellGrid>();
  }
  return std::make_unique<ArticleScan>();
}

Control start_control_for(Gas gas, std::optional<Strategy> strategy) {
  const Strategy chosen = strategy.value_or(strategy_for(gas.balls.size()));
  return start_control(std::move(gas), make_finder(chosen));
}

}  // namespace gas
