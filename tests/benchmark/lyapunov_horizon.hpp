// The precision horizon the Lyapunov exponent predicts, for the report's
// sections 2 (the number type) and 3 (time reversal).
//
// The stages run a scene with the exponent's observer on stage 7's hook
// (stages/beyond/lyapunov.hpp); from lambda, per collision a ball, follows
// how many collisions a ball an error of one unit in the last place of the
// coordinates takes to grow to a hundredth of a radius, in float, double and
// long double: ln(d / eps) / lambda (lessons/15-chaos.md). The report sets
// these beside the horizons it measures against the 113-bit run and by B.
#pragma once

#include <string>

#include "stage1_data.hpp"

namespace gas::benchmark {

struct ExponentFigures {
  std::string scene;
  double per_time = 0, per_time_error = 0;     // lambda per unit model time
  double per_ball = 0, per_ball_error = 0;     // e-folds per collision a ball
  long long samples = 0;                       // renormalisations averaged
  double single = 0, twice = 0, extended = 0;  // predicted horizons, collisions a ball
};

// Runs `gas` with the stages (the program's way of stage 4) until the
// exponent has `samples` renormalisations, and predicts the horizons to a
// hundredth of a radius.
ExponentFigures measure_exponent(const std::string& scene, const Gas& gas,
                                 long long samples);

// The same horizons from the growth along the very stretch the report
// measures: a change of norm 1, in a direction drawn at random, followed
// from T = 0 along the stages' run of `gas` (no average: this one path);
// the collisions a ball after which it has grown by a / (100 eps), for
// float, double and long double (NaN if not within `most_per_ball`).
struct Horizons {
  double single = 0, twice = 0, extended = 0;
};
Horizons horizons_along_the_run(const Gas& gas, double most_per_ball);

}  // namespace gas::benchmark
