// The hard-disc fluid (beyond the article): the reference equation of state
// the statistics screen compares the gas with, and Henderson's beside it.
//
// What this file does: gives the compressibility factor Z = P A / (N kT) of
// the bulk hard-disc FLUID as a function of the area fraction eta = N pi a^2 /
// A, up to eta = 0.70 (where the fluid ends: the liquid-hexatic coexistence
// starts at eta ~ 0.700), its slope dZ/deta, and the contact value g(2a) of
// the pair correlation that follows from Z by the 2D virial theorem,
// Z = 1 + 2 eta g(2a). It also says how far Henderson's simple formula, the
// article-era approximation, is from it. Checked: the virial coefficients
// B2 ... B10 (Z is their series to 2e-9 at eta = 0.1 and to 5e-5, what the
// series leaves out, at 0.3) and simulations at
// eta = 0.67 ... 0.70 (within 0.06 %); see hard_disc_fluid.cpp.
// Article: none; the article ("Gas on the display") predicts no pressure.
// Everything here is beyond it.
// Lesson: lessons/13-box-and-bulk.md
//
// The reference (sources checked, and how, in hard_disc_fluid.cpp):
// J. Kolafa and M. Rottner, "Simulation-based equation of state of the hard
// disk fluid and prediction of higher-order virial coefficients", Mol. Phys.
// 104, 3435 (2006), arXiv:cond-mat/0608356: a polynomial in x = eta / (1 - eta)
// built from their molecular-dynamics pressures (finite-size effects treated
// in the paper) and the known virial coefficients B2 ... B10.
//
// Assumptions: a bulk fluid in equilibrium, N -> infinity (no walls, no
// finite-size correction); k = 1 and unit mass do not enter (Z has no units).
#pragma once

#include <span>

namespace gas {

// The largest area fraction the fluid reference is given for: eta = 0.70, the
// end of the stable fluid (Engel et al., Phys. Rev. E 87, 042134 (2013): the
// liquid-hexatic coexistence spans about 0.700 ... 0.716). Above it the
// functions below say "not known" (NaN).
inline constexpr double fluid_area_fraction_limit = 0.70;

// One term c x^power of the reference, x = eta / (1 - eta): Z = sum of terms.
struct FluidTerm {
  int power = 0;
  double coefficient = 0;
};

// The terms of the Kolafa-Rottner equation of state, lowest power first (the
// lesson prints them; the tests expand them into virial coefficients).
std::span<const FluidTerm> hard_disc_fluid_terms();

// Z = P A / (N kT) of the bulk hard-disc fluid at area fraction eta, 0 <= eta
// <= 0.70 (A is the whole area, eta = N pi a^2 / A); NaN outside.
double hard_disc_fluid_compressibility(double area_fraction);

// dZ / deta of the same (no units); NaN outside 0 <= eta <= 0.70. With it
// the isothermal compressibility of the fluid, and so its density
// fluctuations, follow: d(eta Z)/deta = Z + eta dZ/deta = (dP/drho) / kT.
double hard_disc_fluid_compressibility_slope(double area_fraction);

// d^2Z / deta^2 of the same (no units); NaN outside 0 <= eta <= 0.70. With
// the slope it gives how P = Z n kT curves in the density, d^2(eta Z)/deta^2
// = 2 Z' + eta Z'', which sets how much a closed box's interior differs
// from the open bulk (beyond/kinetic_theory.hpp, fixed_count_shift).
double hard_disc_fluid_compressibility_curvature(double area_fraction);

// The bulk fluid's pressure (a force per unit length: the table is a plane)
// at area fraction eta and temperature kT, for discs of radius a:
// P = Z n kT with n = eta / (pi a^2). NaN outside 0 <= eta <= 0.70.
double hard_disc_fluid_pressure(double area_fraction, double kT, double radius);

// The contact value g(2a) of the fluid's pair correlation, from the 2D virial
// theorem Z = 1 + 2 eta g(2a): g(2a) = (Z - 1) / (2 eta). It is what Enskog's
// collision rate needs. At eta = 0 it is 1 (the limit); NaN outside 0...0.70.
double hard_disc_fluid_contact_value(double area_fraction);

// dg(2a)/deta of the same: Z' / (2 eta) - (Z - 1) / (2 eta^2), with the
// theory's uncertainty |dg/deta| x (eta's error) when eta is measured. At
// eta = 0 the limit, dZ/deta's series: b3 / 2 = 1.564; NaN outside 0...0.70.
double hard_disc_fluid_contact_value_slope(double area_fraction);

// Henderson's Z = (1 + eta^2 / 8) / (1 - eta)^2 against the reference:
// Z_Henderson / Z_reference - 1 (a fraction: 0.022 is 2.2 % too high). NaN
// outside 0 <= eta <= 0.70. At 0.5 it is +0.45 %, at 0.65 +2.2 %, at 0.69
// +8.1 %, at 0.70 +14 %: Henderson is a low-density formula.
double henderson_relative_error(double area_fraction);

}  // namespace gas
