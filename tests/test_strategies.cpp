// The ways of stage 4 — the article's scan, the table of next events, the
// plain cell grid with its event calendar, and the tuned grid — give the
// same collisions.
//
// Not "nearly the same": the table and the grids compute every prediction
// with stage 4's own time_to_wall and time_of_contact on the same rows of R,
// and take the earliest by the scan's order (time, then walls of ball 1,
// walls of ball 2, ..., pairs N3 < N4 in order). So the sequences of
// (TC, K, N1, N2) agree to the last bit of TC, for as long as the runs go —
// not just for the ~100 collisions a chaotic gas lets two *different*
// computations agree (suite `high-precision`). Any difference, even in one
// bit, would show at once and then grow: these comparisons would fail
// within a few collisions of it.
//
// - first(): on hand-made ties, and on random states whose balls were
//   written at different moments, each way gives find_first_collision's
//   answer, also after an update.
// - Whole runs through stage 7 (take_step): every scene in data/, lattices
//   full of exact ties, random gases up to 20000 balls, a cluster whose
//   lists outgrow the grid's records, with the B key and
//   display steps that leave found collisions waiting.
// - The grids' layout: cells at least 2a (1 + margin) wide, and not a cell
//   per pixel of a huge, nearly empty table; the tuned grid's bound on the
//   cells along a side.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "beyond/cell_grid.hpp"
#include "beyond/cell_layout.hpp"
#include "beyond/event_table.hpp"
#include "beyond/plain_grid.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "program/console.hpp"
#include "stage2_input.hpp"
#include "stage7_control.hpp"
#include "support.hpp"

namespace {

using gas::Ball;
using gas::Collision;
using gas::CollisionKind;
using gas::Gas;
using gas::Strategy;
using gas::testing::source_path;
using gas::testing::table_with;

constexpr Strategy all_strategies[] = {Strategy::scan, Strategy::table,
                                       Strategy::plain_grid, Strategy::grid};

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

std::string describe(const Collision& c) {
  return fmt::format("TC={:.17g} ({:#018x}) K={} N1={} N2={}", c.time, bits(c.time),
                     static_cast<int>(c.kind), c.first, c.second);
}

bool same(const Collision& a, const Collision& b) {
  return bits(a.time) == bits(b.time) && a.kind == b.kind && a.first == b.first &&
         a.second == b.second;
}

// The first collision each way finds for one state of the gas.
Collision first_by(Strategy strategy, const Gas& gas) {
  const auto finder = gas::make_finder(strategy);
  finder->rebuild(gas, gas::centre_limits(gas));
  return finder->first(gas);
}

void check_same_first(const Gas& gas) {
  const Collision scan = gas::find_first_collision(gas, gas::centre_limits(gas));
  for (const Strategy strategy : all_strategies) {
    CAPTURE(std::string(gas::strategy_name(strategy)));
    const Collision found = first_by(strategy, gas);
    CHECK_MESSAGE(same(found, scan), describe(found)
                                         << " but the scan found " << describe(scan));
  }
}

// A run through stage 7: `count` collisions (fewer if the gas stops
// colliding), with the keys `keys` pressed before the steps they stand at
// ('.' for none; a step is one display step, often ending on a collision).
struct Run {
  std::vector<Collision> collisions;
  Gas end;
};

Run run(const Gas& start, Strategy strategy, std::size_t count,
        const std::string& keys = "") {
  gas::Control control = gas::start_control(start, gas::make_finder(strategy));
  REQUIRE(std::string(control.finder->name()) == gas::strategy_name(strategy));
  Run result;
  for (std::size_t step = 0; result.collisions.size() < count; ++step) {
    if (step < keys.size()) gas::press_key(control, keys[step]);
    if (control.next.kind == CollisionKind::none && !control.must_find_collision) break;
    const gas::Step taken = gas::take_step(control, gas::never, nullptr);
    result.collisions.insert(result.collisions.end(), taken.collisions.begin(),
                             taken.collisions.end());
  }
  if (result.collisions.size() > count) result.collisions.resize(count);
  result.end = control.gas;
  return result;
}

// Runs every strategy in `which` and requires the very same collisions as
// the first; returns how many were compared.
std::size_t check_same_runs(const Gas& gas, std::size_t count,
                            std::vector<Strategy> which = {Strategy::scan,
                                                           Strategy::table,
                                                           Strategy::plain_grid,
                                                           Strategy::grid},
                            const std::string& keys = "") {
  const Run reference = run(gas, which.front(), count, keys);
  for (std::size_t w = 1; w < which.size(); ++w) {
    CAPTURE(std::string(gas::strategy_name(which[w])));
    const Run other = run(gas, which[w], count, keys);
    REQUIRE(other.collisions.size() == reference.collisions.size());
    std::size_t agree = 0;
    while (agree < reference.collisions.size() &&
           same(reference.collisions[agree], other.collisions[agree]))
      ++agree;
    CHECK_MESSAGE(agree == reference.collisions.size(),
                  "the runs part at collision "
                      << agree + 1 << ": "
                      << std::string(gas::strategy_name(which.front())) << " "
                      << describe(reference.collisions[agree]) << ", "
                      << std::string(gas::strategy_name(which[w])) << " "
                      << describe(other.collisions[agree]));
    // And the rows of R at the end, bit for bit.
    bool rows_agree = true;
    for (std::size_t i = 0; i < reference.end.balls.size(); ++i) {
      const Ball& p = reference.end.balls[i];
      const Ball& q = other.end.balls[i];
      rows_agree = rows_agree && bits(p.x) == bits(q.x) && bits(p.y) == bits(q.y) &&
                   bits(p.vx) == bits(q.vx) && bits(p.vy) == bits(q.vy) &&
                   bits(p.since) == bits(q.since);
    }
    CHECK(rows_agree);
  }
  return reference.collisions.size();
}

// A lattice of balls with whole-number centres and velocities along the axes:
// many events fall at exactly the same time (walls of several balls, pairs
// head-on, a ball struck from two sides), so the order of ties decides.
Gas lattice(int columns, int rows, std::uint64_t seed) {
  Gas gas;
  gas.radius = 1;
  gas.display_step = 1;
  gas.width = 6.0 * columns;
  gas.height = 6.0 * rows;
  std::mt19937_64 random(seed);
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const auto pick = random() % 6;
      const double speed = static_cast<double>(1 + random() % 3);
      Ball ball{3.0 + 6 * i, 3.0 + 6 * j, 0, 0, 0};
      if (pick == 0) ball.vx = speed;
      if (pick == 1) ball.vx = -speed;
      if (pick == 2) ball.vy = speed;
      if (pick == 3) ball.vy = -speed;
      if (pick == 4) ball.vx = ball.vy = speed;  // along a diagonal: corners
      gas.balls.push_back(ball);                 // pick 5: at rest
    }
  }
  return gas;
}

Gas scene_text(const std::string& text) {
  return gas::parse_scene(text, "test.scene");
}

}  // namespace

TEST_SUITE("strategies") {
  TEST_CASE("strategies: the names and the choice by the number of balls") {
    for (const Strategy strategy : all_strategies) {
      CHECK(gas::strategy_named(gas::strategy_name(strategy)) == strategy);
    }
    CHECK_FALSE(gas::strategy_named("Scan").has_value());
    CHECK_FALSE(gas::strategy_named("").has_value());
    CHECK(gas::strategy_for(1) == Strategy::scan);
    CHECK(gas::strategy_for(7) ==
          Strategy::scan);  // the default scene: the article's way
    CHECK(gas::strategy_for(gas::most_balls_for_scan) == Strategy::scan);
    CHECK(gas::strategy_for(gas::most_balls_for_scan + 1) == Strategy::table);
    CHECK(gas::strategy_for(gas::most_balls_for_table) == Strategy::table);
    CHECK(gas::strategy_for(gas::most_balls_for_table + 1) == Strategy::grid);
    CHECK(gas::strategy_for(100000) == Strategy::grid);
    // Stage 7 alone knows only the article's scan; make_finder makes each way.
    const Gas seven = gas::parse_scene(gas::default_scene_text, gas::default_scene_name);
    CHECK(std::string(gas::start_control(seven).finder->name()) == "scan");
    for (const Strategy strategy : all_strategies) {
      CHECK(std::string(
                gas::start_control(seven, gas::make_finder(strategy)).finder->name()) ==
            gas::strategy_name(strategy));
    }
  }

  TEST_CASE("strategies: ties go to the first event the scan meets") {
    // The hand-made ties of suite stage4, each way.
    check_same_first(table_with({{10, 20, 0, 3}, {7, 5, -2, 0}}));  // ball 1's wall
    check_same_first(table_with({{7, 5, -2, 0}, {10, 20, 0, 3}}));  // K = 2 of ball 1
    check_same_first(table_with({{36, 26, 1, 1}}));                 // a corner: K = 1
    check_same_first(
        table_with({{10, 15, 0, 0}, {10, 21, 0, -1}, {30, 5, 0, -1}}));  // walls first
    check_same_first(
        table_with({{20, 15, 0, 0}, {28, 15, -1, 0}, {12, 15, 1, 0}}));  // (1, 2) first
    // The same pair tie with the balls numbered the other way round.
    check_same_first(table_with({{12, 15, 1, 0}, {28, 15, -1, 0}, {20, 15, 0, 0}}));
    // Nothing ever collides: K = 0 every way.
    check_same_first(table_with({{20, 15, 0, 0}}));
    // A collision a hair in the past is due now (T = 10).
    check_same_first(table_with({{39 - 1e-7, 15, 1, 0, 9}}, 10));
    check_same_first(table_with({{10, 15, 0, 0, 9.5}, {12, 15, -1, 0, 9.5}}, 10));
  }

  TEST_CASE("strategies: random states with rows written at different moments") {
    // Up to 60 balls on a 40 x 30 table (radius 1), each row written at its
    // own moment between 0 and 1, the present T = 1; velocities random, some
    // whole numbers so that ties happen.
    std::mt19937_64 random(2024);
    std::uniform_real_distribution<double> unit(0, 1);
    int compared = 0;
    for (int trial = 0; trial < 200; ++trial) {
      std::vector<Ball> balls;
      const int wanted = 1 + static_cast<int>(random() % 60);
      for (int tries = 0; tries < 2000 && static_cast<int>(balls.size()) < wanted;
           ++tries) {
        const bool whole = random() % 3 == 0;
        Ball ball{
            whole ? static_cast<double>(2 + random() % 37) : 1.5 + 37 * unit(random),
            whole ? static_cast<double>(2 + random() % 27) : 1.5 + 27 * unit(random),
            whole ? static_cast<double>(static_cast<int>(random() % 5) - 2)
                  : 4 * unit(random) - 2,
            whole ? static_cast<double>(static_cast<int>(random() % 5) - 2)
                  : 4 * unit(random) - 2,
            1.0};
        bool free = true;
        for (const Ball& other : balls)
          free = free && std::hypot(other.x - ball.x, other.y - ball.y) >= 2;
        if (!free) continue;
        // Written earlier, at `since`, on the same flight.
        ball.since = whole ? 1.0 : unit(random);
        ball.x -= ball.vx * (1 - ball.since);
        ball.y -= ball.vy * (1 - ball.since);
        balls.push_back(ball);
      }
      CAPTURE(trial);
      const Gas gas = table_with(balls, 1.0);
      check_same_first(gas);
      // And after one collision carried out by stage 5 and told to each way.
      const gas::CentreLimits limits = gas::centre_limits(gas);
      const Collision c = gas::find_first_collision(gas, limits);
      if (c.kind == CollisionKind::none) continue;
      Gas after = gas;
      after.time = c.time;
      gas::apply_collision(after, limits, c);
      const Collision expected = gas::find_first_collision(after, limits);
      for (const Strategy strategy : all_strategies) {
        CAPTURE(std::string(gas::strategy_name(strategy)));
        const auto finder = gas::make_finder(strategy);
        finder->rebuild(gas, limits);
        REQUIRE(same(finder->first(gas), c));
        finder->update(after, c);
        const Collision found = finder->first(after);
        CHECK_MESSAGE(same(found, expected),
                      describe(found) << " but the scan found " << describe(expected));
      }
      ++compared;
    }
    CHECK(compared > 150);
  }

  TEST_CASE("strategies: every scene in data/ gives the same collisions every way") {
    namespace fs = std::filesystem;
    std::vector<std::string> scenes;
    for (const char* folder : {"data", "data/edge", "data/hard"}) {
      for (const auto& entry : fs::directory_iterator(source_path(folder))) {
        if (entry.path().extension() == ".scene")
          scenes.push_back(fs::relative(entry.path(), source_path("")).generic_string());
      }
    }
    REQUIRE(scenes.size() >= 20);
    std::size_t compared = 0;
    for (const std::string& scene : scenes) {
      CAPTURE(scene);
      const Gas gas = gas::read_scene_file(source_path(scene));
      // The scan only where it is quick: up to 200 balls.
      std::vector<Strategy> which = {Strategy::table, Strategy::plain_grid,
                                     Strategy::grid};
      if (gas.balls.size() <= 200) which.insert(which.begin(), Strategy::scan);
      if (gas.balls.size() > 2000)
        which = {Strategy::plain_grid, Strategy::grid};  // the table is slow there
      // Not the million: its tuned grid takes the same paths as at 10^5 (the
      // look-ahead from 16384 balls, the large pages), and setting up two
      // grids of 10^6 balls takes minutes in the sanitizers' build.
      if (gas.balls.size() > 100000) continue;
      compared += check_same_runs(gas, 3000, which);
    }
    MESSAGE(
        fmt::format("{} collisions compared over {} scenes", compared, scenes.size()));
  }

  TEST_CASE(
      "strategies: the default scene for 10^5 collisions and the crowd for 2x10^4") {
    const Gas seven = gas::parse_scene(gas::default_scene_text, gas::default_scene_name);
    CHECK(check_same_runs(seven, 100000) == 100000);
    const Gas crowd = gas::read_scene_file(source_path("data/crowd.scene"));
    CHECK(check_same_runs(crowd, 20000) == 20000);
  }

  TEST_CASE("strategies: lattices full of exact ties") {
    for (const std::uint64_t seed : {1, 2, 3}) {
      CAPTURE(seed);
      CHECK(check_same_runs(lattice(12, 9, seed), 5000) == 5000);
    }
    // Many more cells than balls across: ties of crossings with collisions.
    CHECK(check_same_runs(lattice(30, 4, 7), 5000) == 5000);
  }

  TEST_CASE("strategies: the B key and display steps that leave collisions waiting") {
    Gas crowd = gas::read_scene_file(source_path("data/crowd.scene"));
    crowd.display_step = 0.37;  // most steps end before the collision found
    const std::string keys = std::string(500, '.') + "B" + std::string(300, '.') + "B>>" +
                             std::string(200, '.') + "<B";
    CHECK(check_same_runs(
              crowd, 6000,
              {Strategy::scan, Strategy::table, Strategy::plain_grid, Strategy::grid},
              keys) == 6000);
  }

  TEST_CASE("strategies: random gases of 300 and 1000 balls at area fraction 0.3") {
    // 300 balls: every way, 3000 collisions (the scan is slow here).
    const Gas three_hundred = scene_text("a 1\nT0 1\nA1 56\nA2 56\nrandom 300 11 1\n");
    CHECK(check_same_runs(three_hundred, 3000) == 3000);
    // 1000 balls: the table and the grids, 3x10^4 collisions (30 per ball).
    const Gas thousand = scene_text("a 1\nT0 1\nA1 102\nA2 102\nrandom 1000 12 1\n");
    CHECK(check_same_runs(thousand, 30000,
                          {Strategy::table, Strategy::plain_grid, Strategy::grid}) ==
          30000);
  }

  TEST_CASE(
      "strategies: a held meeting whose partner changed at the moment of its own row") {
    // Ball 1 bounces off the wall x = a at T = 1 and, from its new row, the
    // grid's ball 1 predicts meeting ball 2 at T = 1.5 (gap 3, closing at
    // 2). At the same T = 1 ball 2 is struck by ball 3 and turns away: the
    // meeting held by ball 1 is out of date, though both rows were written at
    // T = 1. The grid must not take equal moments for "unchanged" (it does
    // not: the quick answer needs the partner's row strictly older); the
    // scan's third collision is 1 and 2 at 1 + 5 / (sqrt(11) + 6), not 1.5.
    Gas gas = table_with({{2, 10, -1, 0, 0}, {5, 10, -1, 0, 0}, {4, 13, 0, -1, 0}}, 0);
    gas.display_step = 0.25;  // T0
    const Run scan = run(gas, Strategy::scan, 3);
    REQUIRE(scan.collisions.size() == 3);
    CHECK(scan.collisions[0].kind == CollisionKind::vertical_wall);
    CHECK(scan.collisions[0].time == 1);
    CHECK(scan.collisions[1].kind == CollisionKind::balls);
    CHECK(scan.collisions[1].time == 1);
    CHECK(scan.collisions[2].first == 1);
    CHECK(scan.collisions[2].second == 2);
    // (Within 1e-12: a few roundings of numbers near 1.5.)
    CHECK(scan.collisions[2].time ==
          doctest::Approx(1 + 5 / (std::sqrt(11.0) + 6)).epsilon(1e-12));
    CHECK(check_same_runs(gas, 3) == 3);
  }

  TEST_CASE("strategies: a crowded cell and a gas of 20000") {
    // 48 balls packed in a corner of a 1000 x 1000 table: the grid makes no
    // more than 4 x 48 + 16 cells, ~70 wide, so all 48 start in one cell and
    // each compares itself with dozens (its list of a cell walked past two).
    Gas cluster;
    cluster.radius = 1;
    cluster.width = cluster.height = 1000;
    cluster.display_step = 100;  // T0: the gas spreads out, collisions grow rare
    std::mt19937_64 random(5);
    for (int i = 0; i < 48; ++i) {
      const double vx = static_cast<double>(static_cast<int>(random() % 9) - 4) / 4;
      const double vy = static_cast<double>(static_cast<int>(random() % 9) - 4) / 4;
      cluster.balls.push_back({2 + 2.5 * (i % 8), 2 + 2.5 * (i / 8), vx, vy, 0});
    }
    gas::CellGrid grid;
    grid.rebuild(cluster, gas::centre_limits(cluster));
    CHECK(grid.cells().cell_width > 2.5 * 8);  // all in one cell
    CHECK(check_same_runs(cluster, 3000) == 3000);
    // 20000 balls: more pages in the calendar than the lattices and the
    // small gases use, and a calendar laid out from a random start.
    const Gas big = scene_text("a 1\nT0 1\nA1 458\nA2 458\nrandom 20000 13 1\n");
    CHECK(check_same_runs(big, 2000,
                          {Strategy::table, Strategy::plain_grid, Strategy::grid}) ==
          2000);
  }

  TEST_CASE(
      "strategies: the grids' cells are at least 2a (1 + margin) wide and not too "
      "many") {
    // Both grids lay out their cells alike.
    const auto layouts = [](const Gas& gas) {
      gas::PlainGrid plain;
      plain.rebuild(gas, gas::centre_limits(gas));
      gas::CellGrid tuned;
      tuned.rebuild(gas, gas::centre_limits(gas));
      return std::vector<gas::CellLayout>{plain.cells(), tuned.cells()};
    };
    struct Table {
      double radius, width, height;
      std::size_t balls;
    };
    for (const Table t :
         {Table{4, 256, 192, 7}, Table{1, 102, 102, 1000}, Table{1, 4.1, 1000, 10},
          Table{1, 1e6, 1e6, 3}, Table{0.5, 1e75, 2, 2}}) {
      CAPTURE(t.width);
      Gas gas;
      gas.radius = t.radius;
      gas.width = t.width;
      gas.height = t.height;
      for (std::size_t i = 0; i < t.balls; ++i)
        gas.balls.push_back({t.radius + static_cast<double>(i % 2) * 2 * t.radius,
                             t.radius + static_cast<double>(i / 2) * 2 * t.radius, 1, 1,
                             0});
      const double smallest = 2 * t.radius * (1 + gas::grid_margin);
      for (const gas::CellLayout& cells : layouts(gas)) {
        CHECK(cells.columns >= 1);
        CHECK(cells.rows >= 1);
        if (cells.columns > 1) CHECK(cells.cell_width >= smallest);
        if (cells.rows > 1) CHECK(cells.cell_height >= smallest);
        CHECK(cells.cell_width * cells.columns == doctest::Approx(t.width));
        // No more cells than 4 per ball and 16 more.
        CHECK(static_cast<double>(cells.columns) * cells.rows <= 4.0 * t.balls + 16);
      }
    }
    // The default scene: 31 x 23 cells would fit, but 7 balls need no more than
    // 4 x 7 + 16 = 44 cells.
    Gas seven = gas::parse_scene(gas::default_scene_text, gas::default_scene_name);
    for (const gas::CellLayout& cells : layouts(seven)) {
      CHECK(cells.columns == 7);
      CHECK(cells.rows == 5);
    }
  }

  TEST_CASE(
      "strategies: the cell layout gives cells at least as long as asked and clamps a "
      "point's cell to the table") {
    const gas::CellLayout cells = gas::lay_out_cells(100, 30, 8, 1000);
    CHECK(cells.columns == 12);  // 100 / 8 = 12.5
    CHECK(cells.rows == 3);      // 30 / 8 = 3.75
    CHECK(cells.cell_width == 100.0 / 12);
    CHECK(cells.cell_height == 10);
    CHECK(cells.column_of(0) == 0);
    CHECK(cells.column_of(51) == 6);
    CHECK(cells.row_of(29.5) == 2);
    // A rounding off the table is in the cell at its edge.
    CHECK(cells.column_of(-1e-12) == 0);
    CHECK(cells.column_of(100) == 11);
    CHECK(cells.row_of(30 + 1e-12) == 2);
    // 1000 x 1000 cells would fit, but 100 are asked for at most: both sides
    // get fewer, in proportion, so each cell is only larger.
    const gas::CellLayout capped = gas::lay_out_cells(1000, 1000, 1, 100);
    CHECK(capped.columns == 10);
    CHECK(capped.rows == 10);
    CHECK(capped.cell_width == 100);
    // A table narrower than one cell: one cell, as wide as the table.
    const gas::CellLayout one = gas::lay_out_cells(5, 50, 8, 100);
    CHECK(one.columns == 1);
    CHECK(one.cell_width == 5);
    CHECK(one.rows == 6);
    // At most so many along each side, when asked: the cells only longer.
    const gas::CellLayout narrow = gas::lay_out_cells(1000, 900, 1, 1e6, 250, 300);
    CHECK(narrow.columns == 250);
    CHECK(narrow.rows == 300);
    CHECK(narrow.cell_width == 4);
  }

  TEST_CASE("strategies: a table longer than a grid record can number its columns") {
    // 20000 balls in one line of cells 200000 a long: 4 x 20000 + 16 cells
    // would be allowed, 99900 fit, but the tuned grid's record numbers cell
    // columns in 13 bits: it lays out 8191, each only longer, and still finds
    // every collision (and so does the plain grid, with 80016). The balls move in pairs
    // towards each other, 10 apart, at speed 1: the first 10000 collisions are the pairs
    // (1, 2), (3, 4), ..., all at T = 4 exactly, in the scan's order of ties.
    std::string text = "a 1\nT0 50\nA1 200000\nA2 3\nN 20000\n";
    for (int i = 0; i < 20000; ++i)
      text += fmt::format("ball {} 1.5 {} 0\n", 5 + 10 * i, i % 2 == 0 ? 1 : -1);
    const Gas line = scene_text(text);
    gas::CellGrid grid;
    grid.rebuild(line, gas::centre_limits(line));
    CHECK(grid.cells().columns == gas::CellGrid::most_cells_along);
    CHECK(grid.cells().columns == 8191);
    CHECK(grid.cells().rows == 1);
    for (const Strategy strategy : {Strategy::plain_grid, Strategy::grid}) {
      CAPTURE(std::string(gas::strategy_name(strategy)));
      const Run run_of_grid = run(line, strategy, 10000);
      REQUIRE(run_of_grid.collisions.size() == 10000);
      int as_expected = 0;
      for (int k = 0; k < 10000; ++k) {
        const Collision& c = run_of_grid.collisions[static_cast<std::size_t>(k)];
        as_expected += c.kind == CollisionKind::balls && c.time == 4 &&
                       c.first == 2 * k + 1 && c.second == 2 * k + 2;
      }
      CHECK(as_expected == 10000);
    }
  }
}

TEST_SUITE("console") {
  TEST_CASE(
      "parse_options: --strategy scan, table, plain-grid or grid and nothing else") {
    CHECK_FALSE(gas::parse_options({}).strategy.has_value());
    CHECK(gas::parse_options({"--strategy", "table"}).strategy == Strategy::table);
    CHECK(gas::parse_options({"--strategy=grid"}).strategy == Strategy::grid);
    CHECK(gas::parse_options({"--strategy", "scan"}).strategy == Strategy::scan);
    CHECK_THROWS_WITH_AS(gas::parse_options({"--strategy", "heap"}),
                         "--strategy takes scan, table, plain-grid or grid, not 'heap'",
                         gas::UsageError);
    CHECK_THROWS_WITH_AS(gas::parse_options({"--strategy"}), "--strategy needs a value",
                         gas::UsageError);
  }

  TEST_CASE("the program: --strategy changes nothing that is printed") {
    // The crowd's frames, and lesson 10's run of 1000 balls with --trace.
    for (const std::vector<std::string>& arguments :
         {std::vector<std::string>{"data/crowd.scene", "--frames", "40", "--cols", "40",
                                   "--rows", "14"},
          std::vector<std::string>{"data/large-1000.scene", "--trace", "--frames", "2",
                                   "--cols", "16", "--rows", "7"}}) {
      CAPTURE(arguments.front());
      const auto chosen = gas::testing::run_program(arguments);
      REQUIRE(chosen.status == 0);
      for (const char* strategy : {"scan", "table", "plain-grid", "grid"}) {
        std::vector<std::string> with = arguments;
        with.insert(with.end(), {"--strategy", strategy});
        const auto run = gas::testing::run_program(with);
        CHECK(run.status == 0);
        CHECK(run.out == chosen.out);
      }
    }
  }
}
