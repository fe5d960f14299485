// What the sections of gas-benchmark share: the sizes of a full run or a
// smoke run, the gases they run, and the CSV files they write beside the
// report.
#pragma once

#include <fmt/format.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "stage1_data.hpp"

namespace gas::benchmark {

// The sizes of each section: the full report, or a smoke run of seconds.
struct Sizes {
  std::vector<std::size_t> ball_counts;
  double seconds_per_point = 0;       // processor time of one throughput measurement
  std::size_t most_balls_scan = 0;    // the scan only up to here (it takes too long)
  std::size_t most_balls_table = 0;   // the table only up to here (its rebuild is N^2)
  std::size_t most_balls_sparse = 0;  // the sparse gases only up to here
  double seconds_default_scene = 0;   // per way, the default scene in take_step
  int default_scene_rounds = 0;       // ... in rounds of all ways in turn
  long long drift_collisions = 0;     // section 2: the energy-drift run
  int horizon_events = 0;             // section 2: events compared with the reference
  int distance_samples = 0;           // section 2: moments the distance is measured at
  std::vector<int> reversal_k;        // section 3: collisions per ball forward
  std::vector<int> h_theorem_k;       // section 3: the same for the H-theorem scene
  long long lyapunov_samples = 0;     // sections 2, 3: renormalisations of the exponent
  int lyapunov_seeds = 0;             // section 2: independent gases for its error bar
  std::size_t stepped_balls = 0;      // section 4
  double stepped_end = 0;             // section 4: model time of each run
  std::vector<double> stepped_dt;     // section 4: steps, in diameters per mean speed
  int program_rounds = 0;             // section 5: timed runs of each command
  double program_time_limit = 0;      // section 5: wall seconds before a run is stopped
};

Sizes sizes_for(bool smoke);

// The two densities of section 1: the benchmark's gas, and a sparse one like
// the teaching scenes (the crowd covers 0.049 of its table).
constexpr double dense = 0.3, sparse = 0.05;

// N balls of radius 1 at random places (the scene keyword 'random') on a
// 4:3 table whose area makes the given area fraction; speeds 0.5 to 1.5.
Gas random_gas(std::size_t count, double fraction, std::uint64_t seed);
Gas default_gas();
Gas crowd_gas();
Gas h_theorem_gas();

// Processor time of this thread since `start` (a cpu_seconds() reading): all
// the measurements use it, so that other programs on the machine, taking
// turns on its cores, are not counted against ours.
double cpu_since(double start);

// A CSV file beside the report: a header line, then a row at a time.
class Csv {
 public:
  Csv(const std::filesystem::path& path, const std::string& header) : file_(path) {
    if (!file_) throw std::runtime_error(fmt::format("{}: cannot write", path.string()));
    file_ << header << '\n';
  }
  template <class... Args>
  void row(fmt::format_string<Args...> format, Args&&... args) {
    file_ << fmt::format(format, std::forward<Args>(args)...) << '\n';
  }

 private:
  std::ofstream file_;
};

}  // namespace gas::benchmark
