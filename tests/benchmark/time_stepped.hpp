// The gas as most newcomers first write it: a fixed time step.
//
// Every step moves every ball by v dt; a ball past a wall's limit and moving
// outwards has that velocity component reversed; two balls found
// overlapping and approaching exchange their velocity components along the
// line of centres (the article's VI). Nothing is predicted, so a collision is
// seen only after the balls have run into each other — up to |v| dt deep —
// and one that starts and ends within a step (a graze, or a fast ball through
// a slow one) is never seen at all.
//
// It lives only in the benchmark (section 4 of the report), to show what the
// event-driven stages buy. It uses a grid of cells 2a wide to find the
// overlapping pairs, so that the comparison is between the two methods, not
// between a scan and a grid.
#pragma once

#include <ctime>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "report_common.hpp"
#include "stage1_data.hpp"

namespace gas::benchmark {

// The processor time this thread has used, in seconds: what the benchmark
// measures, so that other programs sharing the machine (which take turns on
// its cores) do not count.
inline double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

// What a run measured, by either method.
struct GasRecord {
  double seconds = 0;             // processor time, one core
  long long ball_collisions = 0;  // K = 3 carried out
  long long wall_collisions = 0;  // K = 1, 2 carried out
  double wall_impulse = 0;        // sum of 2 |v across the wall| (unit mass)
  double energy_error = 0;        // |E(end) - E(0)| / E(0)
  double largest_overlap = 0;     // deepest overlap seen, as a fraction of 2a
  long long steps = 0;            // time steps (0 for the event-driven run)
};

// Runs `start` with the time step `dt` until model time `end`.
GasRecord run_time_stepped(const Gas& start, double dt, double end);

// Section 4 of the report: the event-driven stages and the fixed time step
// on the same gas. The event-driven run carries, beside its record, the
// spread of its figures between ten equal stretches of its time (how much a
// run this long is worth statistically).
struct TimeStepFigures {
  Gas gas;                      // the start of every run
  GasRecord events;             // the stages, event-driven
  double collision_spread = 0;  // relative standard error of its collision count
  double impulse_spread = 0;    // ... of its wall impulse
  std::vector<std::pair<double, GasRecord>> stepped;  // dt in diameters, the run
};

// Measures, writing time-stepping.csv into `out`; the section's text.
TimeStepFigures measure_time_steps(const Sizes& sizes, const std::filesystem::path& out);
std::string time_steps_section(const Sizes& sizes, const TimeStepFigures& figures);

}  // namespace gas::benchmark
