// The hard-disc fluid's equation of state (beyond the article). See
// beyond/hard_disc_fluid.hpp and lessons/13-box-and-bulk.md.
//
// Where the numbers come from, and what was checked.
//
// The formula is Kolafa and Rottner's (Mol. Phys. 104, 3435 (2006),
// arXiv:cond-mat/0608356), their fit to MD data up to reduced density
// rho sigma^2 = 0.90 (eta = 0.707):
//
//   Z = sum_i C_i x^i,   x = eta / (1 - eta),
//
// with the fifteen coefficients below. We could not read the paper itself
// (nor its equation and table numbers): the coefficients were taken from a
// public transcription of that fit, and then checked against two sources that
// are independent of the transcription:
//
// 1. The virial coefficients. Expanding the series in eta gives
//    Z = 1 + sum_n b_n eta^(n-1), b_n = B_n / (pi a^2)^(n-1) for discs of
//    radius a (b_n = 2^(n-1) B_n / B_2^(n-1)). The expansion gives b2 = 2,
//    b3 = 3.12801775 (exact: 16/3 - 4 sqrt(3)/pi = 3.1280177516), and
//    b4 ... b10 within the error bars of N. Clisby and B. M. McCoy, J. Stat.
//    Phys. 122, 15 (2006), Table 1 (B_n / B_2^(n-1) for D = 2: 0.53223180,
//    0.33355604(1), 0.1988425(42), 0.1148728(43), 0.0649930(34),
//    0.0362193(35), 0.0199537(80)). This fixes C_0 ... C_9.
// 2. Simulation data at the top of the fluid range, where the fitted
//    coefficients C_10 ... C_57 dominate (from the open data of B. Li et al.,
//    J. Chem. Phys. 157, 234111 (2022), repository "HistoricDisks", files
//    DigitizedData/Engel_2013 and DigitizedData/ThisWork; pressures given as
//    beta P (2a)^2, so Z = beta P (2a)^2 pi / (4 eta)):
//      eta = 0.698, N = 1024^2 (Engel et al., Phys. Rev. E 87, 042134 (2013)):
//        Z = 10.31746(3); this formula 10.32043, +0.029 %
//      eta = 0.700, N = 1024^2 (same): Z = 10.30600(10); formula +0.053 %
//      eta = 0.670, N = 870 (Li et al. 2022): Z = 9.36234(3); formula +0.001 %
//      eta = 0.680, N = 870 (same): Z = 9.83276(4); formula -0.041 % (N = 870
//        is about 0.1 % low there: N = 224 is 0.26 % lower still)
//    tests/test_hard_disc_fluid.cpp checks these.
// Between eta ~ 0.35 and 0.67 no simulation table was found to check against;
// there the formula interpolates smoothly between two ends that are checked.
#include "beyond/hard_disc_fluid.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace gas {

namespace {

constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

// Kolafa and Rottner (2006), the fit to rho sigma^2 <= 0.90: C_0 = 1 and
// C_1 = 2 make Z = 1 + 2 eta + ... (B2); the rest as transcribed (see above).
constexpr std::array<FluidTerm, 15> kolafa_rottner = {{
    {0, 1.0},
    {1, 2.0},
    {2, 1.12801775},
    {3, 0.00181895291},
    {4, -0.0526134737},
    {5, 0.0504960168},
    {6, -0.0325537792},
    {7, 0.0134578632},
    {8, 0.00140888182},
    {9, -0.00834273601},
    {10, 0.00694127367},
    {11, -0.00262254723},
    {12, 0.000355746352},
    {22, -5.24672938e-9},
    {57, 5.88054639e-23},
}};

bool in_fluid_range(double eta) {
  return eta >= 0 && eta <= fluid_area_fraction_limit;
}

}  // namespace

std::span<const FluidTerm> hard_disc_fluid_terms() {
  return kolafa_rottner;
}

// [anchor: reference-eos]
double hard_disc_fluid_compressibility(double area_fraction) {
  if (!in_fluid_range(area_fraction)) return unknown;
  const double x = area_fraction / (1 - area_fraction);
  double z = 0;
  for (const FluidTerm& term : kolafa_rottner) {
    z += term.coefficient * std::pow(x, term.power);
  }
  return z;
}
// [/anchor: reference-eos]

double hard_disc_fluid_pressure(double area_fraction, double kT, double radius) {
  return hard_disc_fluid_compressibility(area_fraction) * area_fraction * kT /
         (std::numbers::pi * (radius * radius));
}

double hard_disc_fluid_compressibility_slope(double area_fraction) {
  if (!in_fluid_range(area_fraction)) return unknown;
  const double one_minus = 1 - area_fraction;
  const double x = area_fraction / one_minus;
  double dz_dx = 0;
  for (const FluidTerm& term : kolafa_rottner) {
    if (term.power > 0) {
      dz_dx += term.power * term.coefficient * std::pow(x, term.power - 1);
    }
  }
  return dz_dx / (one_minus * one_minus);  // dx/deta = 1 / (1 - eta)^2
}

double hard_disc_fluid_compressibility_curvature(double area_fraction) {
  if (!in_fluid_range(area_fraction)) return unknown;
  // Z(x(eta)) with dx/deta = (1 + x)^2 and d^2x/deta^2 = 2 (1 + x)^3:
  // Z'' = Z_xx (1 + x)^4 + 2 Z_x (1 + x)^3.
  const double x = area_fraction / (1 - area_fraction);
  double dz_dx = 0, d2z_dx2 = 0;
  for (const FluidTerm& term : kolafa_rottner) {
    const double c = term.coefficient;
    const int k = term.power;
    if (k > 0) dz_dx += k * c * std::pow(x, k - 1);
    if (k > 1) d2z_dx2 += k * (k - 1) * c * std::pow(x, k - 2);
  }
  const double one_plus = 1 + x;
  return d2z_dx2 * std::pow(one_plus, 4) + 2 * dz_dx * std::pow(one_plus, 3);
}

double hard_disc_fluid_contact_value(double area_fraction) {
  if (!in_fluid_range(area_fraction)) return unknown;
  if (area_fraction == 0) return 1;  // the limit: Z = 1 + 2 eta + ...
  return (hard_disc_fluid_compressibility(area_fraction) - 1) / (2 * area_fraction);
}

double hard_disc_fluid_contact_value_slope(double area_fraction) {
  if (!in_fluid_range(area_fraction)) return unknown;
  const double eta = area_fraction;
  // At eta = 0 the limit: Z = 1 + C_1 x + C_2 x^2 + ... with x = eta + eta^2
  // + ..., so Z = 1 + 2 eta + (C_1 + C_2) eta^2 + ... and g = 1 + (C_1 +
  // C_2) eta / 2 + ...
  if (eta == 0)
    return (kolafa_rottner[1].coefficient + kolafa_rottner[2].coefficient) / 2;
  return hard_disc_fluid_compressibility_slope(eta) / (2 * eta) -
         (hard_disc_fluid_compressibility(eta) - 1) / (2 * eta * eta);
}

double henderson_relative_error(double area_fraction) {
  if (!in_fluid_range(area_fraction)) return unknown;
  const double eta = area_fraction;
  const double henderson = (1 + eta * eta / 8) / ((1 - eta) * (1 - eta));
  return henderson / hard_disc_fluid_compressibility(eta) - 1;
}

}  // namespace gas
