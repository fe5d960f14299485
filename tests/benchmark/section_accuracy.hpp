// Sections 2 and 3 of the report: accuracy against cost for the number
// type, and time reversal. Float, double and long double against a 113-bit
// reference (cost, energy drift, overlaps, how long each follows the exact
// motion) beside the horizon the Lyapunov exponent predicts; and forward k
// collisions per ball, B, back as long: the return error against k, and how
// far back the exponent predicts B to bring the gas.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "lyapunov_horizon.hpp"
#include "report_common.hpp"
#include "report_pictures.hpp"

namespace gas::benchmark {

struct TypeFigures {
  std::string scene;
  std::string type;
  int bits = 0;
  double nanoseconds = 0;  // per collision, in the reference kernel
  long long drift_collisions = 0;
  double energy_drift = 0;     // |E - E0| / E0 after drift_collisions
  double largest_overlap = 0;  // deepest overlap seen (sampled), / 2a
  int horizon_events = -1;     // collisions in agreement with the 113-bit run
  double horizon_per_ball = -1;
  double trusted_per_ball = -1;  // collisions per ball until an error of a / 100
};

struct NumberTypeFigures {
  std::vector<TypeFigures> types;
  std::vector<DistanceRow> distances;  // each type's distance from the 113-bit run
  // The Lyapunov exponent of each scene, and the horizons it predicts; the
  // same along the run from T = 0.
  std::vector<ExponentFigures> exponents;
  std::vector<Horizons> along;
  // The exponent's error bar against independent seeds: how many, the mean
  // of lambda / v_rms, and the spread of (lambda_s - mean) / error_s.
  std::size_t seeds = 0;
  double seeds_mean = 0, seeds_spread = 0;
};

struct ReversalRow {
  std::string scene, type;
  int per_ball;
  double time;   // T at which B is pressed
  double error;  // largest distance from the start after 2T, in radii
};

// Section 2, writing lyapunov.csv, number-types.csv and
// number-types-distance.csv into `out`; its text (`picture`: the distance
// picture's markdown).
NumberTypeFigures measure_number_types(const Sizes& sizes,
                                       const std::filesystem::path& out);
std::string number_types_section(const Sizes& sizes, const NumberTypeFigures& figures,
                                 const std::string& picture);

// Section 3, writing time-reversal.csv; its text.
std::vector<ReversalRow> measure_time_reversal(const Sizes& sizes,
                                               const std::filesystem::path& out);
std::string time_reversal_section(const Sizes& sizes,
                                  const std::vector<ReversalRow>& rows,
                                  const NumberTypeFigures& types);

}  // namespace gas::benchmark
