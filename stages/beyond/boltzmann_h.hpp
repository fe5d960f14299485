// Boltzmann's H (beyond the article): how far the gas's speeds are from the
// Maxwell-Boltzmann distribution, as one number that falls to zero.
//
// What this file does: measures a histogram of speeds (fractions of the balls,
// or of ball-time, in equal bins) against the 2D Maxwell-Boltzmann
// distribution at the same energy, by the relative entropy
//
//   H = sum_i p_i ln(p_i / q_i)  >= 0,
//
// p_i the measured fraction in bin i, q_i the Maxwell-Boltzmann probability
// of the same bin, q_i = exp(-v_lo^2 / 2kT) - exp(-v_hi^2 / 2kT) (unit mass,
// k = 1; the last bin runs to infinity). H is zero exactly when the histogram
// is Maxwell-Boltzmann's and positive otherwise (Gibbs' inequality); a term
// with p_i = 0 adds nothing.
// Article: none; the article shows no distributions. Everything here is
// beyond it.
// Lesson: lessons/12-statistics-screen.md
//
// Why this is Boltzmann's H. Boltzmann's H = integral of f ln f over the
// velocity plane (f the density of velocities). For a distribution that is the
// same in every direction, f(v) = P(v) / (2 pi v), P the density of speeds
// (2 pi v is the length of the circle of speed v: the Jacobian from the plane
// to speeds). Then, with P_MB(v) = (v / kT) exp(-v^2 / 2kT) at the same
// energy (the same mean v^2 = 2 kT),
//
//   H_Boltzmann - H_Boltzmann(Maxwell-Boltzmann) = integral P ln(P / P_MB) dv,
//
// because ln f_MB = -ln(2 pi kT) - v^2 / 2kT is a constant plus a multiple of
// v^2, whose mean both distributions share. So the relative entropy of the
// speeds is Boltzmann's H measured from its equilibrium value, and the
// H-theorem says it falls to 0. The histogram version is the coarse-grained
// H: binning can only lower it (it is never above the fine-grained one).
//
// A finite gas never reaches 0: N speeds drawn from Maxwell-Boltzmann fill
// the bins with multinomial noise, and 2 N H is then distributed like
// chi-squared with (bins - 1) degrees of freedom, so H fluctuates about
// (bins - 1) / (2 N) (`boltzmann_h_noise_floor`, which says why).
#pragma once

#include <cstddef>
#include <span>

namespace gas {

// H of a histogram of speeds: fractions[i] is the fraction of balls (or of
// ball-time) with speed in [i w, (i+1) w), w = bin_width; fraction_beyond the
// fraction at speed >= fractions.size() * w. The fractions, with
// fraction_beyond, should sum to 1 (they are divided by their sum, so counts
// work as well). kT = E / N, the energy per ball (unit mass, 2D). H has no
// units and is >= 0; NaN if kT or bin_width is not positive, the histogram is
// empty, or a fraction is negative.
double boltzmann_h(std::span<const double> fractions, double fraction_beyond,
                   double bin_width, double kT);

// H of the speeds of the balls now: their histogram in `bins` bins of width
// `bin_width` (faster ones in one more bin beyond), against Maxwell-Boltzmann
// at kT = mean(v^2) / 2, the gas's own energy per ball. NaN if there are no
// speeds, all are 0, or bins < 1 or bin_width <= 0.
double boltzmann_h_of_speeds(std::span<const double> speeds, std::size_t bins,
                             double bin_width);

// The H that N speeds drawn from Maxwell-Boltzmann show on average, from the
// noise alone, when kT is their own mean v^2 / 2 (as in the gas, whose energy
// is fixed, and in boltzmann_h_of_speeds). For many balls in every bin,
// 2 N H = 2 N sum p ln(p / q) ~ sum N (p - q)^2 / q, Pearson's chi-squared
// of the counts (the second-order term; the first, sum (p - q), is 0); its
// degrees of freedom are the categories, bins + 1 with the one beyond, less
// one for their sum N, less one for the energy, a second linear constraint
// on the counts (sum of counts times each bin's v^2 = 2 N kT, to first order):
// mean (bins - 1) / (2 N), standard deviation sqrt(2 (bins - 1)) / (2 N)
// (`boltzmann_h_noise_spread`). Bins that expect only a few balls make it
// rougher; for a handful of balls (fewer than a few per bin) it is no guide.
double boltzmann_h_noise_floor(std::size_t bins, std::size_t balls);
double boltzmann_h_noise_spread(std::size_t bins, std::size_t balls);

}  // namespace gas
