// The report's two pictures: what they show, from the figures measured.
//
//   throughput.svg              collisions per second against N (log-log):
//                               each way of stage 4, dense and sparse, and the
//                               program's runs of section 5
//   number-types-distance.svg   the distance from the 113-bit run against
//                               collisions per ball (log y), for each number type
//
// plots.hpp draws them with gnuplot.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "engine.hpp"
#include "plots.hpp"
#include "program_runs.hpp"

namespace gas::benchmark {

// One sample of section 2: how far a number type's run is from the 113-bit
// run of the same scene at a moment.
struct DistanceRow {
  std::string scene, type;
  double collisions_per_ball, time, error;  // error: the largest distance, in radii
};

// Collisions per second against N: a panel for each area fraction (the first
// one, the dense gas of the large scenes, with the program's runs).
Picture throughput_figure(const std::filesystem::path& out,
                          const std::vector<Throughput>& throughput,
                          const std::vector<double>& fractions,
                          const ProgramFigures& program);

// The distance from the 113-bit run, the default scene and the crowd side by
// side.
Picture distance_figure(const std::filesystem::path& out,
                        const std::vector<DistanceRow>& rows);

// Draws the picture: the markdown that shows it, or says why there is none.
std::string picture_markdown(const Picture& picture, const std::string& caption);

}  // namespace gas::benchmark
