// Section 1 of the report: throughput. Collisions per second against N for
// each way of stage 4 (the engine: the stages' event loop, nothing drawn),
// where they cross over, and the default scene as the program runs it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine.hpp"
#include "report_common.hpp"

namespace gas::benchmark {

// The default scene as the program runs it (take_step with its own T0 = 1,
// every display step a picture computed) with one way of stage 4.
struct ProgramSpeed {
  std::string how;  // the way's name, or "chosen by N"
  long long steps = 0, collisions = 0;
  double seconds = 0;
};

struct ThroughputFigures {
  std::vector<Throughput> all;  // every way, N and density measured
  // The default scene, every way: summed over the rounds; and each round's
  // ratio of display steps per second, the way the program chooses (the
  // scan, for 7 balls) over the scan: the same code timed twice.
  std::vector<ProgramSpeed> default_scene;
  std::vector<double> chosen_over_scan;
  int default_rounds = 0;

  // Nanoseconds a collision of way `s` at N and area fraction; 0 if not run.
  double cost(Strategy s, std::size_t n, double fraction) const;
};

// Measures, writing throughput.csv and default-scene.csv into `out`.
ThroughputFigures measure_throughputs(const Sizes& sizes,
                                      const std::filesystem::path& out);

// The section's text, from its heading on (`picture`: the markdown of its
// picture); and its rows of the Targets table.
std::string throughput_section(const Sizes& sizes, const ThroughputFigures& figures,
                               const std::string& picture);
std::string throughput_targets(const ThroughputFigures& figures,
                               const std::string& reads);

}  // namespace gas::benchmark
