// Stage 4 — the three ways to find the first collision. See beyond/strategy.hpp.
#include "beyond/strategy.hpp"

namespace gas {

const char* strategy_name(Strategy strategy) {
  switch (strategy) {
    case Strategy::scan:
      return "scan";
    case Strategy::table:
      return "table";
    case Strategy::grid:
      return "grid";
  }
  return "?";
}

std::optional<Strategy> strategy_named(std::string_view name) {
  for (const Strategy strategy : {Strategy::scan, Strategy::table, Strategy::grid}) {
    if (name == strategy_name(strategy)) return strategy;
  }
  return std::nullopt;
}

FirstCollisionFinder::FirstCollisionFinder(Strategy strategy) : strategy_(strategy) {
  switch (strategy) {
    case Strategy::scan:
      way_.emplace<ArticleScan>();
      break;
    case Strategy::table:
      way_.emplace<EventTable>();
      break;
    case Strategy::grid:
      way_.emplace<CellGrid>();
      break;
  }
}

void FirstCollisionFinder::rebuild(const Gas& gas, const CentreLimits& limits) {
  std::visit([&](auto& way) { way.rebuild(gas, limits); }, way_);
}

Collision FirstCollisionFinder::first(const Gas& gas) {
  return std::visit([&](auto& way) { return way.first(gas); }, way_);
}

void FirstCollisionFinder::update(const Gas& gas, const Collision& done) {
  std::visit([&](auto& way) { way.update(gas, done); }, way_);
}

}  // namespace gas
