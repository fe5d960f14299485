// Enskog's transport coefficients of the hard-disc fluid, and the long-time
// tail they predict (beyond the article).
//
// What this file does: gives, for the bulk hard-disc fluid at area fraction
// eta and temperature kT, what the velocity autocorrelation function is
// compared with (beyond/velocity_autocorrelation.hpp): Enskog's decay time
// tau_E of a ball's velocity, the diffusion coefficient D_E = kT tau_E, the
// shear and bulk viscosities and the kinematic viscosity nu_E, the speed of
// sound, the heat capacity c_p and the ratio c_p / c_v, the thermal
// conductivity lambda_E and diffusivity D_T, the damping of sound, and the
// mode-coupling tail rho(t) = 1 / (8 pi n (D_E + nu_E) t).
// Every formula is derived in enskog_transport.cpp (and in the lesson); the
// suite computes each coefficient again from the collision rule itself, by
// Monte Carlo integration in two and three dimensions
// (tests/test_enskog_transport.cpp). Which papers we could read, and which
// we could not, enskog_transport.cpp says beside each formula.
// Article: none; the article ("Gas on the display", 1989) has no
// transport theory. Everything here is beyond it.
// Lesson: lessons/16-long-time-tail.md
//
// Assumptions: unit mass and k = 1 (kT is an energy per ball, E = N kT in
// 2D); discs of radius a, diameter s = 2a; number density n = eta / (pi a^2);
// g(s), the contact value, from the reference equation of state
// (beyond/hard_disc_fluid.hpp), so eta at most 0.70. Enskog's theory in its
// first (Sonine) approximation: the one whose exponential has the exact
// initial slope (enskog_transport.cpp).
#pragma once

namespace gas {

// Enskog's predictions for one state of the bulk fluid.
struct EnskogTransport {
  double density = 0;              // n, balls per unit area
  double contact_value = 0;        // g(2a) of the reference fluid
  double velocity_time = 0;        // tau_E: Enskog's rho(t) = exp(-t / tau_E)
  double diffusion = 0;            // D_E = kT tau_E, area per unit time
  double shear_viscosity = 0;      // eta_E, momentum per unit length (2D)
  double bulk_viscosity = 0;       // kappa_E, the same unit
  double kinematic_viscosity = 0;  // nu_E = eta_E / n (unit mass), area per unit time
  double sound_speed = 0;          // c, adiabatic, length per unit time
  double heat_capacity = 0;        // c_p per ball at constant pressure, in units of k
  double heat_capacity_ratio = 0;  // gamma = c_p / c_v (c_v = 1 in 2D), no unit
  // lambda_E: the heat flux (energy per unit length and time) per unit
  // temperature gradient, in units of k per unit time (2D, k = 1).
  double thermal_conductivity = 0;
  double thermal_diffusivity = 0;  // D_T = lambda_E / (n c_p), area per unit time
  // Gamma: a sound wave of wave number k decays as exp(-Gamma k^2 t); area
  // per unit time.
  double sound_attenuation = 0;
  // The mode-coupling tail rho(t) = tail_coefficient / t (a time).
  double tail_coefficient = 0;

  // Enskog's velocity autocorrelation function exp(-t / tau_E), and its
  // running integral kT times: D_E (1 - exp(-t / tau_E)).
  double vacf(double t) const;
  double diffusion_by(double t) const;
  // The tail 1 / (8 pi n (D_E + nu_E) t) (infinite at t = 0).
  double tail(double t) const;
};

// Enskog's transport coefficients of the bulk hard-disc fluid at area
// fraction eta (0 < eta <= 0.70), for discs of radius `radius`, at kT.
// Outside 0 < eta <= 0.70 every field is NaN.
EnskogTransport enskog_transport(double area_fraction, double radius, double kT);

// The adiabatic speed of sound of the hard-disc fluid, P = n kT Z(eta):
// c^2 = kT (Z + eta dZ/deta + Z^2) (unit mass); NaN outside 0 <= eta <= 0.70.
double hard_disc_sound_speed(double area_fraction, double kT);

}  // namespace gas
