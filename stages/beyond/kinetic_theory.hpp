// Kinetic theory (beyond the article): the statistics screen's physics, what
// the averages of beyond/gas_statistics.hpp are compared with.
//
// What this file does: predicts, from the number of balls, their radius, the
// table and the energy alone, what kinetic theory says the gas should show —
// the 2D Maxwell-Boltzmann speeds, the pressure of the hard-disc fluid (the
// reference equation of state of beyond/hard_disc_fluid.hpp, and Henderson's
// of 1975 beside it), the collision rate and the mean free path.
// Article: "Gas on the display", stage 6, the third screen ("print some
// properties of the gas, the mean speed for example"). The theory is beyond
// the article.
// Lesson: lessons/12-statistics-screen.md; Henderson's: lessons/13-box-and-bulk.md
//
// Assumptions: unit mass and k = 1, so kT is an energy per ball (in 2D,
// E = N kT); every formula is for equilibrium and for the bulk fluid, far
// from any wall (the measured side compares like with like: lesson 13).
#pragma once

#include <cstddef>

#include "beyond/gas_statistics.hpp"
#include "stage1_data.hpp"

namespace gas {

// What kinetic theory predicts for a gas, from N, a, A1, A2 and E only.
// [anchor: kinetic-theory]
struct KineticTheory {
  double kT = 0;                  // E / N: two degrees of freedom per ball, unit mass
  double mean_speed = 0;          // <v> of N balls at fixed E (fixed_energy_mean_speed)
  double maxwell_mean_speed = 0;  // its limit for many balls: sqrt(pi kT / 2)
  double rms_speed = 0;           // sqrt(<v^2>) = sqrt(2 kT), fixed by E alone
  double area_fraction = 0;       // eta = N pi a^2 / (A1 A2)
  double contact_value = 0;    // g(2a) of the reference fluid at eta: (Z - 1) / (2 eta)
  double compressibility = 0;  // Z of the bulk fluid at eta: the reference
  double henderson = 0;        // Z at eta by Henderson: (1 + eta^2 / 8) / (1 - eta)^2
};
// [/anchor: kinetic-theory]

// The predictions of the bulk fluid (its equation of state, Enskog's rate)
// hold for a gas of many balls: the closed box's 1 / N is taken into them
// (fixed_count_shift, below), but with a few balls the walls take so large
// a share that there is no interior to speak of (lesson 14). Below this
// many balls the screen says so instead of showing a number.
inline constexpr std::size_t kinetic_theory_fewest_balls = 100;

KineticTheory kinetic_theory(const Gas& gas);
// The same, with the gas's kinetic energy E already summed (kinetic_energy):
// a frame sums it once for stage 6 and for these.
KineticTheory kinetic_theory(const Gas& gas, double energy);

// The 2D Maxwell-Boltzmann distribution of speeds at temperature kT (unit
// mass): the density f(v) = (v / kT) exp(-v^2 / (2 kT)) and its integral
// F(v) = 1 - exp(-v^2 / (2 kT)), the fraction of balls slower than v.
double maxwell_density(double speed, double kT);
double maxwell_fraction_below(double speed, double kT);

// The mean speed of one of N balls whose total kinetic energy E = N kT is
// fixed (unit mass; walls, so the momentum is not): <v> = sqrt(2 N kT)
// Gamma(3/2) Gamma(N) / Gamma(N + 1/2), which tends to Maxwell's
// sqrt(pi kT / 2) as N grows (lesson 12 derives it). NaN for N = 0.
double fixed_energy_mean_speed(std::size_t balls, double kT);

// Enskog's collision rate per ball per unit time of the bulk fluid at area
// fraction eta (radius a, unit mass, k = 1): 2 (2a) n g(2a) sqrt(pi kT),
// n = eta / (pi a^2), g(2a) the reference's contact value; and the mean free
// path, Maxwell's mean speed over that rate, 1 / (2 sqrt 2 (2a) n g(2a)).
// NaN where the reference has no value (eta beyond the fluid).
double enskog_collision_rate(double eta, double radius, double kT);
double enskog_mean_free_path(double eta, double radius);

// The interior of a closed box of N balls against the open bulk at the same
// density (Lebowitz and Percus, "Thermodynamic properties of small systems",
// Phys. Rev. 124, 1673 (1961): averages at fixed N differ from those of an
// open system by a series in 1/N whose terms follow from the open system's
// own averages). An open box's count N would wander by Var N = N S(0), S(0)
// = 1 / (Z + eta Z') the compressibility, and its interior is the bulk: the
// push of its collisions per unit area, w = P - n kT, is the bulk's w(n) on
// average. The closed box is the open one at one N; averaging over N,
//   w_open = w_N + w''(n) Var(N) (dn/dN)^2 / 2,   n_open = n_N + ...,
// and as w_N = w(n_N) + O(1/N), the closed box's w lies below the curve
// w(n) at its own measured n by Var(N) (dn/dN)^2 w''(n) / 2. With dn/dN =
// n / N (a ball more raises the whole profile in proportion) and w = kT n
// (Z - 1), w'' = kT pi a^2 (2 Z' + eta Z''), so Z = 1 + w / (n kT) shifts by
//   dZ = -eta (2 Z' + eta Z'') / (2 N (Z + eta Z')),
// some -0.85 / N at eta = 0.3 (-0.0033 at N = 256, 0.18 % of Z). At low
// density it is -2 eta / N: each ball has N - 1 partners, not N. The
// collisions inside follow w too, so Enskog's rate (and one over the free
// path) carries the same factor 1 + dZ / (Z - 1). Checked on build/gas
// against seeds at N = 256 and 1024 (data/reports/kinetic-seeds.md).
// The expansion holds for a fluid far from its transition: above eta = 0.6
// the reference's curvature turns (Z'' < 0 from 0.67 as the hexatic phase
// nears, where the count's fluctuations are no longer small), and no shift
// is applied there (fixed_count_area_fraction_limit): the theory is the
// open bulk's. NaN outside the fluid range; 0 for no balls.
inline constexpr double fixed_count_area_fraction_limit = 0.6;
double fixed_count_shift(double area_fraction, std::size_t balls);
// Z of the interior of a closed box of N balls: the reference plus the shift.
double fixed_count_compressibility(double area_fraction, std::size_t balls);
// The factor 1 + dZ / (Z - 1) on Enskog's rate (1 - 1 / N at eta = 0).
double fixed_count_rate_factor(double area_fraction, std::size_t balls);

// How long a figure of the box must be averaged before its own samples can
// tell its error (beyond/blocking.hpp, rule 2; lesson 14): 1 / (D k^2) for
// the heat mode of wavelength L, the table's longer side (k = 2 pi / L; the
// longest, k = pi / L, is odd and leaves the middle's average alone), with
// D = lambda <v> (lambda: Enskog's mean free path at eta = N pi a^2 / (A1
// A2), <v> = sqrt(pi kT / 2)). That D is a rough one, 4.4 times below
// Enskog's thermal diffusivity D_T at eta = 0.3 (1.8 at 0.1, 15 at 0.5;
// beyond/enskog_transport.hpp): so this is some 4 relaxation times of that
// heat mode at eta = 0.3, and batches that long hold (lesson 14). Some 370
// time units for data/large-1000.scene, 3000 for large-10000. NaN for fewer
// than 2 balls or a gas at rest.
double table_heat_time(const Gas& gas);

// The time a ball takes for speeds_batch_collisions collisions
// (beyond/gas_statistics.hpp), at Enskog's rate at eta = N pi a^2 / (A1 A2)
// and kT = E / N: the mean speed's shortest batch (lesson 14), some 28 time
// units for data/large-1000.scene. NaN for fewer than 2 balls or a gas at
// rest.
double speeds_batch_time(const Gas& gas);

// The Henderson equation of state of hard discs and its contact value g(2a),
// as functions of the area fraction.
double henderson_compressibility(double area_fraction);
double henderson_contact_value(double area_fraction);

}  // namespace gas
