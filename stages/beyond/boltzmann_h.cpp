// Boltzmann's H (beyond the article). See beyond/boltzmann_h.hpp for the
// definition and why it is Boltzmann's H measured from equilibrium.
#include "beyond/boltzmann_h.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace gas {

namespace {
constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
}  // namespace

// [anchor: boltzmann-h]
double boltzmann_h(std::span<const double> fractions, double fraction_beyond,
                   double bin_width, double kT) {
  if (!(kT > 0) || !(bin_width > 0) || !(fraction_beyond >= 0)) return unknown;
  double total = fraction_beyond;
  for (const double p : fractions) {
    if (!(p >= 0)) return unknown;
    total += p;
  }
  if (!(total > 0)) return unknown;
  // q_i = F(v_hi) - F(v_lo), F(v) = 1 - exp(-v^2 / 2kT) the Maxwell-Boltzmann
  // fraction slower than v; written with the tails exp(-v^2 / 2kT) so that
  // small q_i far out keep their digits.
  auto tail = [&](double v) { return std::exp(-v * v / (2 * kT)); };
  double h = 0;
  auto add = [&](double p, double q) {
    if (p > 0) h += p * std::log(p / q);  // p ln(p/q) -> 0 as p -> 0
  };
  for (std::size_t i = 0; i < fractions.size(); ++i) {
    const double lo = static_cast<double>(i) * bin_width;
    add(fractions[i] / total, tail(lo) - tail(lo + bin_width));
  }
  add(fraction_beyond / total, tail(static_cast<double>(fractions.size()) * bin_width));
  // Each term can be negative, the sum cannot (Gibbs' inequality); rounding
  // can leave -1e-17 when p = q. Only that is rounded away: a larger negative
  // H would be a mistake in the q_i, and is left for the tests to see.
  return (h < 0 && h > -1e-12) ? 0 : h;
}
// [/anchor: boltzmann-h]

double boltzmann_h_of_speeds(std::span<const double> speeds, std::size_t bins,
                             double bin_width) {
  if (speeds.empty() || bins < 1 || !(bin_width > 0)) return unknown;
  std::vector<double> counts(bins, 0.0);
  double beyond = 0;
  double squares = 0;
  for (const double v : speeds) {
    if (!(v >= 0)) return unknown;  // a speed, not a velocity component
    squares += v * v;
    const double bin = std::floor(v / bin_width);
    if (bin < static_cast<double>(bins)) {
      counts[static_cast<std::size_t>(bin)] += 1;
    } else {
      beyond += 1;
    }
  }
  const double kT = squares / static_cast<double>(speeds.size()) / 2;
  return boltzmann_h(counts, beyond, bin_width, kT);
}

// [anchor: h-noise]
double boltzmann_h_noise_floor(std::size_t bins, std::size_t balls) {
  if (balls == 0 || bins < 2) return unknown;
  return static_cast<double>(bins - 1) / (2 * static_cast<double>(balls));
}

double boltzmann_h_noise_spread(std::size_t bins, std::size_t balls) {
  if (balls == 0 || bins < 2) return unknown;
  return std::sqrt(2 * static_cast<double>(bins - 1)) / (2 * static_cast<double>(balls));
}
// [/anchor: h-noise]

}  // namespace gas
