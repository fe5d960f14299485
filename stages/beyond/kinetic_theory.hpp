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
// Lesson: lessons/11-kinetic-theory.md
//
// Assumptions: unit mass and k = 1, so kT is an energy per ball (in 2D,
// E = N kT); every formula is for equilibrium and for the bulk fluid, far
// from any wall (the measured side compares like with like: lesson 11).
#pragma once

#include "beyond/gas_statistics.hpp"
#include "stage1_data.hpp"

namespace gas {

// What kinetic theory predicts for a gas, from N, a, A1, A2 and E only.
// [anchor: kinetic-theory]
struct KineticTheory {
  double kT = 0;               // E / N: two degrees of freedom per ball, unit mass
  double mean_speed = 0;       // 2D Maxwell-Boltzmann: <v> = sqrt(pi kT / 2)
  double rms_speed = 0;        // sqrt(<v^2>) = sqrt(2 kT), fixed by E alone
  double area_fraction = 0;    // eta = N pi a^2 / (A1 A2)
  double contact_value = 0;    // g(2a) of the reference fluid: (Z - 1) / (2 eta)
  double compressibility = 0;  // Z of the bulk fluid at eta: the reference
  double henderson = 0;        // Z at eta by Henderson: (1 + eta^2 / 8) / (1 - eta)^2
  double collision_rate = 0;   // per ball, Enskog: 2 (2a) n g(2a) sqrt(pi kT)
  double mean_free_path = 0;   // <v> / collision rate
};
// [/anchor: kinetic-theory]

KineticTheory kinetic_theory(const Gas& gas);

// The 2D Maxwell-Boltzmann distribution of speeds at temperature kT (unit
// mass): the density f(v) = (v / kT) exp(-v^2 / (2 kT)) and its integral
// F(v) = 1 - exp(-v^2 / (2 kT)), the fraction of balls slower than v.
double maxwell_density(double speed, double kT);
double maxwell_fraction_below(double speed, double kT);

// The Henderson equation of state of hard discs and its contact value g(2a),
// as functions of the area fraction.
double henderson_compressibility(double area_fraction);
double henderson_contact_value(double area_fraction);

}  // namespace gas
