// The Lyapunov exponent on the screen and in --csv. See
// beyond/lyapunov_screen.hpp.
#include "beyond/lyapunov_screen.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace gas {

PrecisionHorizons precision_horizons(const Gas& gas, const LyapunovFigures& f) {
  const double lambda = f.per_collision_per_ball;
  if (!(lambda > 0)) return {};
  const double distance = horizon_distance_radii * gas.radius;
  auto horizon = [&](int digits) {
    return precision_horizon(lambda, distance, coordinate_ulp(gas, digits));
  };
  return {horizon(std::numeric_limits<float>::digits),
          horizon(std::numeric_limits<double>::digits),
          horizon(std::numeric_limits<long double>::digits)};
}

namespace {

// "1.2345 +- 0.0012"; while the error is not known, the reason in its place
// ("1.2345 +- not yet"), or the value alone.
std::string with_error(double value, double error, const char* why_no_error) {
  if (!std::isnan(error)) return fmt::format("{:.5g} +- {:.2g}", value, error);
  if (why_no_error != nullptr) return fmt::format("{:.5g} +- {}", value, why_no_error);
  return fmt::format("{:.5g}", value);
}

}  // namespace

// [anchor: lyapunov-lines]
std::vector<std::string> lyapunov_lines(const Gas& gas, const LyapunovFigures& f) {
  if (f.warming_up || std::isnan(f.exponent.value)) {
    return {"Lyapunov exponent: warming up (the change turns to grow fastest)"};
  }
  const PrecisionHorizons h = precision_horizons(gas, f);
  const char* const why = f.exponent.why_no_error;
  return {
      fmt::format(
          "Lyapunov: {} per unit time, {} per collision per ball",
          with_error(f.exponent.value, f.exponent.error, why),
          with_error(f.per_collision_per_ball, f.per_collision_per_ball_error, why)),
      fmt::format("  horizon to a/100 (collisions per ball): float {:.2g} double {:.2g} "
                  "long double {:.2g}",
                  h.single, h.twice, h.extended)};
}
// [/anchor: lyapunov-lines]

std::string lyapunov_csv_header() {
  return ",lyapunov,lyapunov_error";
}

std::string lyapunov_csv_row(const LyapunovFigures& f) {
  return fmt::format(",{:.17g},{:.17g}", f.exponent.value, f.exponent.error);
}

}  // namespace gas
