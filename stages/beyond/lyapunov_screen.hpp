// The Lyapunov exponent on the statistics screen and in --csv (beyond the
// article).
//
// What this file does: lays out what beyond/lyapunov.hpp measures as two
// lines of the statistics screen — the exponent per unit time and per
// collision per ball (walls' and pairs'), and the precision horizon it
// predicts for float, double and long double — and as the last block of
// --csv's columns, `lyapunov,lyapunov_error` (per unit model time).
// Article: "Gas on the display", stage 6, the third screen ("print some
// properties of the gas"); the exponent is beyond the article.
// Lesson: lessons/15-chaos.md
#pragma once

#include <string>
#include <vector>

#include "beyond/lyapunov.hpp"
#include "stage1_data.hpp"

namespace gas {

// The distance the screen's horizon is counted to: a hundredth of a radius,
// as the benchmark's "trusted" (data/reports/speed-against-error.md).
inline constexpr double horizon_distance_radii = 0.01;

// The precision horizon of each number type, in collisions per ball, for the
// exponent measured (NaN while it is not known).
struct PrecisionHorizons {
  double single = not_known;    // float
  double twice = not_known;     // double
  double extended = not_known;  // long double
};
PrecisionHorizons precision_horizons(const Gas& gas, const LyapunovFigures& figures);

// The screen's lines: the exponent, and the horizons.
std::vector<std::string> lyapunov_lines(const Gas& gas, const LyapunovFigures& figures);

// --csv: the block appended at the end of the header (",lyapunov,lyapunov_error")
// and of each row.
std::string lyapunov_csv_header();
std::string lyapunov_csv_row(const LyapunovFigures& figures);

}  // namespace gas
