// Kinetic theory's predictions. See beyond/kinetic_theory.hpp and
// lessons/12-statistics-screen.md for where each formula comes from.
#include "beyond/kinetic_theory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "beyond/hard_disc_fluid.hpp"

namespace gas {

// [anchor: maxwell-speeds]
// 2D Maxwell-Boltzmann (unit mass, k = 1): a velocity is two independent
// normal components of variance kT, so its speed has the Rayleigh density
// f(v) = (v / kT) exp(-v^2 / (2 kT)), mean sqrt(pi kT / 2), mean square 2 kT.
double maxwell_density(double speed, double kT) {
  return speed / kT * std::exp(-speed * speed / (2 * kT));
}

double maxwell_fraction_below(double speed, double kT) {
  return -std::expm1(-speed * speed / (2 * kT));
}
// [/anchor: maxwell-speeds]

// [anchor: fixed-energy]
// N balls of unit mass in a box, total kinetic energy E fixed (the walls do
// not keep the momentum, so nothing else is): the 2N velocity components lie
// on the sphere sum v_i^2 = 2E in 2N dimensions, and in equilibrium every
// point of it is as likely (the microcanonical measure; the positions do not
// depend on the velocities for hard discs). k coordinates of a point
// uniform on the sphere of radius R in d dimensions have the density
// (1 - |u|^2 / R^2)^((d - k) / 2 - 1) (the surface measure of the sphere cut
// at u); one ball's velocity u is k = 2 of the d = 2N coordinates, so its
// density is (1 - u^2 / R^2)^(N - 2), R^2 = 2E, and with s = v^2 / R^2 its speed
// has density (N - 1) (1 - s)^(N - 2) in s. So <v> = R <sqrt s> = R (N - 1)
// B(3/2, N - 1) = R Gamma(3/2) Gamma(N) / Gamma(N + 1/2). N = 1: <v> = R.
double fixed_energy_mean_speed(std::size_t balls, double kT) {
  if (balls == 0) return std::numeric_limits<double>::quiet_NaN();
  const auto n = static_cast<double>(balls);
  const double radius = std::sqrt(2 * n * kT);  // R = sqrt(2E)
  return radius * std::sqrt(std::numbers::pi) / 2 *
         std::exp(std::lgamma(n) - std::lgamma(n + 0.5));
}
// [/anchor: fixed-energy]

// [anchor: henderson]
// D. Henderson, "A simple equation of state for hard discs", Molecular
// Physics 30, 971 (1975): Z = P A / (N kT) = (1 + eta^2 / 8) / (1 - eta)^2.
// Against the reference (beyond/hard_disc_fluid.hpp) it is within 0.03 % up
// to eta = 0.3, 0.45 % high at 0.5, 2.2 % at 0.65 and 8 % at 0.69: the
// article-era approximation, shown beside the reference.
double henderson_compressibility(double eta) {
  return (1 + eta * eta / 8) / ((1 - eta) * (1 - eta));
}

// The virial theorem for hard discs of diameter s = 2a (2D):
// Z = 1 + (pi / 2) n s^2 g(s) = 1 + 2 eta g(s), so Henderson's Z gives
// g(s) = (Z - 1) / (2 eta) = (1 - 7 eta / 16) / (1 - eta)^2.
double henderson_contact_value(double eta) {
  return (1 - 7 * eta / 16) / ((1 - eta) * (1 - eta));
}
// [/anchor: henderson]

// [anchor: enskog]
// Enskog's collision rate per ball in 2D: a ball meets the others at contact
// distance s = 2a across a "cross-section" of length 2s, at the mean relative
// speed sqrt(pi kT) (that of two Maxwellian velocities), and the density at
// contact is g(s) times the mean: rate = 2 s n g(s) sqrt(pi kT). (The dilute
// rate with Enskog's factor g, derived in these lines; the kinetic-theory
// suite checks it against the rate the program measures inside the table.)
double enskog_collision_rate(double eta, double radius, double kT) {
  const double density = eta / (std::numbers::pi * radius * radius);
  return 2 * (2 * radius) * density * hard_disc_fluid_contact_value(eta) *
         std::sqrt(std::numbers::pi * kT);
}

// Maxwell's mean speed over it: sqrt(pi kT / 2) / rate = 1 / (2 sqrt 2 s n g).
double enskog_mean_free_path(double eta, double radius) {
  const double density = eta / (std::numbers::pi * radius * radius);
  return 1 / (2 * std::numbers::sqrt2 * (2 * radius) * density *
              hard_disc_fluid_contact_value(eta));
}
// [/anchor: enskog]

// [anchor: fixed-count]
// The closed box's interior against the open bulk: kinetic_theory.hpp
// derives dZ = -eta (2 Z' + eta Z'') / (2 N (Z + eta Z')).
double fixed_count_shift(double area_fraction, std::size_t balls) {
  if (balls == 0) return 0;
  if (area_fraction > fixed_count_area_fraction_limit &&
      area_fraction <= fluid_area_fraction_limit)
    return 0;
  const double eta = area_fraction, z = hard_disc_fluid_compressibility(eta);
  const double slope = hard_disc_fluid_compressibility_slope(eta);
  const double curvature = hard_disc_fluid_compressibility_curvature(eta);
  return -eta * (2 * slope + eta * curvature) /
         (2 * static_cast<double>(balls) * (z + eta * slope));
}

double fixed_count_compressibility(double area_fraction, std::size_t balls) {
  return hard_disc_fluid_compressibility(area_fraction) +
         fixed_count_shift(area_fraction, balls);
}

double fixed_count_rate_factor(double area_fraction, std::size_t balls) {
  if (balls == 0) return 1;
  // At eta = 0, dZ / (Z - 1) -> -(2 Z'(0)) / (2 N) / Z'(0) = -1 / N.
  if (area_fraction == 0) return 1 - 1 / static_cast<double>(balls);
  return 1 + fixed_count_shift(area_fraction, balls) /
                 (hard_disc_fluid_compressibility(area_fraction) - 1);
}
// [/anchor: fixed-count]

namespace {

// The state a time of the table is worked out at: eta = N pi a^2 / (A1 A2)
// and kT = E / N; kT = 0 (no such time) for fewer than 2 balls or a gas at
// rest.
struct TableState {
  double eta = 0, kT = 0;
};

TableState table_state(const Gas& gas) {
  const std::size_t n = gas.balls.size();
  const double kT = n > 0 ? kinetic_energy(gas) / static_cast<double>(n) : 0.0;
  if (n < 2 || !(kT > 0)) return {};
  return {static_cast<double>(n) * std::numbers::pi * gas.radius * gas.radius /
              (gas.width * gas.height),
          kT};
}

}  // namespace

double table_heat_time(const Gas& gas) {
  const TableState s = table_state(gas);
  if (!(s.kT > 0)) return std::numeric_limits<double>::quiet_NaN();
  const double diffusivity =
      enskog_mean_free_path(s.eta, gas.radius) * std::sqrt(std::numbers::pi * s.kT / 2);
  const double wave = std::max(gas.width, gas.height) / (2 * std::numbers::pi);  // 1 / k
  return wave * wave / diffusivity;
}

double speeds_batch_time(const Gas& gas) {
  const TableState s = table_state(gas);
  if (!(s.kT > 0)) return std::numeric_limits<double>::quiet_NaN();
  return speeds_batch_collisions / enskog_collision_rate(s.eta, gas.radius, s.kT);
}

KineticTheory kinetic_theory(const Gas& gas) {
  return kinetic_theory(gas, kinetic_energy(gas));
}

KineticTheory kinetic_theory(const Gas& gas, double energy) {
  KineticTheory t;
  const auto n_balls = static_cast<double>(gas.balls.size());
  if (gas.balls.empty()) return t;
  const double pi = std::numbers::pi;
  t.kT = energy / n_balls;
  t.mean_speed = fixed_energy_mean_speed(gas.balls.size(), t.kT);
  t.maxwell_mean_speed = std::sqrt(pi * t.kT / 2);
  t.rms_speed = std::sqrt(2 * t.kT);
  const double table = gas.width * gas.height;
  t.area_fraction = n_balls * pi * gas.radius * gas.radius / table;
  t.compressibility = hard_disc_fluid_compressibility(t.area_fraction);
  t.contact_value = hard_disc_fluid_contact_value(t.area_fraction);
  t.henderson = henderson_compressibility(t.area_fraction);
  return t;
}

}  // namespace gas
