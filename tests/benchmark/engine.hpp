// The engine: the stages' event loop with nothing drawn, and how fast it runs.
//
// Stage 4 (one way or another), the clock to TC, stage 5's apply_collision,
// and the finder told of it: what take_step does when every step ends on a
// collision, without the picture. Section 1 of the report times it for each
// way of stage 4; section 5 sets it beside the program that users run.
#pragma once

#include <memory>
#include <utility>

#include "beyond/strategy.hpp"
#include "stage1_data.hpp"
#include "stage4_first_collision.hpp"
#include "stage5_new_coordinates.hpp"

namespace gas::benchmark {

struct EventLoop {
  Gas gas;
  CentreLimits limits;
  std::unique_ptr<FirstCollisionFinder> finder;

  EventLoop(const Gas& start, Strategy strategy);
  // The next collision, carried out; K = 0 if there is none.
  Collision step();
  // Every collision up to model time `end`, and the clock to it; returns how
  // many there were.
  long long run_to(double end);
};

// One measurement of the engine's speed.
struct Throughput {
  Strategy strategy;
  double fraction;  // area fraction of the gas
  std::size_t balls;
  double setup_seconds;  // predicting from scratch (rebuild)
  long long collisions;
  double seconds;
  double per_second() const { return static_cast<double>(collisions) / seconds; }
  double nanoseconds() const { return 1e9 * seconds / static_cast<double>(collisions); }
};

// Runs collisions in batches that double while they are quick, until the
// budget of processor time is spent or `most` have run; returns how many ran
// and how long they took.
std::pair<long long, double> run_for(EventLoop& loop, double budget, long long most);

// The engine's collisions per second on `gas` with `strategy`: after a
// warm-up of a collision per ball (at most a quarter of the budget), the best
// of three rounds of a third of the budget each, in processor time.
Throughput measure_throughput(const Gas& gas, Strategy strategy, double budget);

}  // namespace gas::benchmark
