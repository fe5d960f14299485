// What the sections of gas-benchmark share. See report_common.hpp.
#include "report_common.hpp"

#include <cmath>
#include <numbers>

#include "beyond/random_placement.hpp"
#include "engine.hpp"
#include "program/console.hpp"
#include "stage2_input.hpp"
#include "time_stepped.hpp"

namespace gas::benchmark {

Sizes sizes_for(bool smoke) {
  if (smoke) {
    return {.ball_counts = {7, 16, 64, 200},
            .seconds_per_point = 0.02,
            .most_balls_scan = 64,
            .most_balls_table = 200,
            .most_balls_sparse = 64,
            .seconds_default_scene = 0.05,
            .default_scene_rounds = 4,
            .drift_collisions = 3000,
            .horizon_events = 300,
            .distance_samples = 10,
            .reversal_k = {1, 2},
            .h_theorem_k = {5},
            .lyapunov_samples = 100,
            .lyapunov_seeds = 3,
            .stepped_balls = 100,
            .stepped_end = 5,
            .stepped_dt = {0.5, 0.1},
            .program_rounds = 1,
            .program_time_limit = 60};
  }
  return {.ball_counts = {2,    3,    4,    5,     7,     10,    12,    16,  24,
                          32,   48,   64,   96,    128,   192,   256,   384, 512,
                          1000, 2000, 5000, 10000, 20000, 50000, 100000},
          .seconds_per_point = 1.0,
          .most_balls_scan = 2000,
          .most_balls_table = 20000,
          .most_balls_sparse = 2000,
          .seconds_default_scene = 4.0,
          .default_scene_rounds = 40,
          .drift_collisions = 1'000'000,
          .horizon_events = 6000,
          .distance_samples = 200,
          .reversal_k = {1, 2, 3, 5, 8, 12, 20, 30, 50},
          .h_theorem_k = {5, 8, 10, 12, 15, 20},
          .lyapunov_samples = 2000,
          .lyapunov_seeds = 20,
          .stepped_balls = 2000,
          .stepped_end = 100,
          .stepped_dt = {0.5, 0.25, 0.1, 0.05, 0.02, 0.01},
          .program_rounds = 3,
          .program_time_limit = 600};
}

Gas random_gas(std::size_t count, double fraction, std::uint64_t seed) {
  const double area = static_cast<double>(count) * std::numbers::pi / fraction;
  const double height = std::sqrt(area * 3 / 4), width = area / height;
  return gas::parse_scene(
      fmt::format("a 1\nT0 1\nA1 {:.17g}\nA2 {:.17g}\nrandom {} {} 1\n", width, height,
                  count, seed),
      fmt::format("random-{}", count));
}

Gas default_gas() {
  return gas::parse_scene(gas::default_scene_text, gas::default_scene_name);
}

Gas crowd_gas() {
  return gas::read_scene_file(std::string(GAS_SOURCE_DIR) + "/data/crowd.scene");
}

Gas h_theorem_gas() {
  return gas::read_scene_file(std::string(GAS_SOURCE_DIR) + "/data/h-theorem.scene");
}

double cpu_since(double start) {
  return cpu_seconds() - start;
}

}  // namespace gas::benchmark
