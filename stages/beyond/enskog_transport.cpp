// Enskog's transport coefficients of hard discs. See beyond/enskog_transport.hpp
// and lessons/16-long-time-tail.md.
//
// Where each formula comes from (unit mass, k = 1, 2D, s = 2a, g = g(s)).
//
// tau_E and D_E. At t = 0+ the velocity of a ball changes only by its
// collisions. A ball of velocity v1 meets partners of velocity v2 (relative
// velocity w = v1 - v2) along the unit vector e from its centre to theirs at
// the rate n g s (w.e) de per unit time, for w.e > 0 (contact length s de,
// the density at contact g n), and each such collision changes v1 by
// -(w.e) e. In equilibrium v1 and v2 are independent Maxwellians, so
// d<v1(0).v1(t)>/dt at 0+ = -n g s < integral (w.e)^2 (v1.e) de >. With
// v1 = V + w/2 the centre-of-mass part averages out, the angle integral of
// cos^3 over a half circle is 4/3, and <|w|^3> = 3 sqrt(pi/2) (2 kT)^(3/2)
// (w is Maxwellian with variance 2 kT a component); so the slope is
// -4 sqrt(pi) n g s kT^(3/2), and divided by <v^2> = 2 kT:
//   1 / tau_E = 2 sqrt(pi) n g s sqrt(kT),   D_E = kT tau_E = sqrt(kT / pi) / (2 n s g).
// This is exact for hard discs (only the equilibrium distribution at contact
// enters, and its factor g is exact), and it is Enskog's D in the first
// Sonine approximation: Enskog's exponential has the exact initial slope
// (J. J. Erpenbeck and W. W. Wood, Phys. Rev. A 26, 1648 (1982), the
// abstract). The same steps in 3D give Chapman and Cowling's
// D = 3 sqrt(kT / pi) / (8 n s^2 g). In 2D 1 / tau_E is also exactly
// Enskog's collision rate 2 s n g sqrt(pi kT) (beyond/kinetic_theory.hpp):
// Enskog's velocity forgets itself in one mean free time (in 3D in 1.5).
//
// eta_E. Enskog's shear viscosity in d dimensions has the form
//   eta_E / eta_0 = (1 / g) (1 + 2^d phi g / (d + 2))^2 + (d / (d + 2)) kappa / eta_0,
// phi the packed fraction, eta_0 the dilute (Boltzmann) viscosity in the same
// approximation, kappa the bulk viscosity (V. Garzo and J. W. Dufty, Phys.
// Rev. E 59, 5895 (1999), at restitution 1). In 3D it is Chapman and
// Cowling's 1/g + 3.2 phi + 12.34 phi^2 g exactly, with kappa = (4/9)
// sqrt(pi) n^2 s^4 g sqrt(kT). kappa we derived again for any d: the
// momentum carried across the contact distance by collisions in a flow of
// gradient du is, to first order, m n^2 g s^(d+1) sqrt(kT / pi) times the
// angle integral of e_i e_j e_k e_l over the unit sphere (area Omega_d), whose
// trace part gives kappa = Omega_d n^2 g s^(d+1) sqrt(kT / pi) / d^2 (in 3D
// the value above; in 2D (pi/2) n^2 g s^3 sqrt(kT / pi) = (16 / pi) phi^2 g eta_0).
// With eta_0 = sqrt(kT / pi) / (2 s) in 2D, d = 2 gives (D. M. Gass,
// J. Chem. Phys. 54, 1898 (1971), for discs)
//   eta_E = eta_0 (1 / g + 2 eta + (1 + 8 / pi) eta^2 g),
// eta the area fraction. The tests check the 3D reduction and the dilute limit.
//
// The tail. A ball's momentum, shared with the fluid around it, spreads as
// the fluid's shear modes (d - 1 of its d directions) by diffusion of
// momentum, nu t, while the ball itself wanders by D t; the overlap of the two
// spreads, a Gaussian of variance 2 (D + nu) t in each direction, gives
//   rho(t) = ((d - 1) / (d n)) (4 pi (D + nu) t)^(-d/2) = 1 / (8 pi n (D + nu) t) in 2D
// (M. H. Ernst, E. H. Hauge and J. M. J. van Leeuwen, Phys. Rev. Lett. 25,
// 1254 (1970); J. R. Dorfman and E. G. D. Cohen, ibid. 1257: mode coupling;
// B. J. Alder and T. E. Wainwright, Phys. Rev. A 1, 18 (1970): the vortex).
//
// The sound speed. P = n kT Z(eta), the energy kT a ball (2D): at fixed
// entropy dT/dn = T Z / n, so dP/dn = kT (Z + eta Z') + n k Z T Z / n, and
// c^2 = kT (Z + eta Z' + Z^2) (2 kT in the dilute limit: c_p / c_v = 2).
#include "beyond/enskog_transport.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "beyond/hard_disc_fluid.hpp"

namespace gas {

namespace {
constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
constexpr double pi = std::numbers::pi;
}  // namespace

// [anchor: enskog-transport]
EnskogTransport enskog_transport(double area_fraction, double radius, double kT) {
  EnskogTransport e;
  const double eta = area_fraction;
  if (!(eta > 0 && eta <= fluid_area_fraction_limit)) {
    e.density = e.contact_value = e.velocity_time = e.diffusion = unknown;
    e.shear_viscosity = e.kinematic_viscosity = e.sound_speed = unknown;
    e.tail_coefficient = unknown;
    return e;
  }
  const double s = 2 * radius;  // the diameter
  const double n = eta / (pi * radius * radius);
  const double g = hard_disc_fluid_contact_value(eta);
  e.density = n;
  e.contact_value = g;
  // tau_E from the exact initial slope, D_E = kT tau_E.
  e.velocity_time = 1 / (2 * std::sqrt(pi) * n * g * s * std::sqrt(kT));
  e.diffusion = kT * e.velocity_time;
  // Enskog's shear viscosity of discs (Gass), and nu_E = eta_E / (m n).
  const double dilute_viscosity = std::sqrt(kT / pi) / (2 * s);
  e.shear_viscosity = dilute_viscosity * (1 / g + 2 * eta + (1 + 8 / pi) * eta * eta * g);
  e.kinematic_viscosity = e.shear_viscosity / n;
  e.sound_speed = hard_disc_sound_speed(eta, kT);
  // Mode coupling: rho(t) = 1 / (8 pi n (D + nu) t).
  e.tail_coefficient = 1 / (8 * pi * n * (e.diffusion + e.kinematic_viscosity));
  return e;
}
// [/anchor: enskog-transport]

double EnskogTransport::vacf(double t) const {
  return std::exp(-t / velocity_time);
}

double EnskogTransport::diffusion_by(double t) const {
  return -diffusion * std::expm1(-t / velocity_time);
}

double EnskogTransport::tail(double t) const {
  return tail_coefficient / t;
}

double hard_disc_sound_speed(double area_fraction, double kT) {
  const double z = hard_disc_fluid_compressibility(area_fraction);
  const double slope = hard_disc_fluid_compressibility_slope(area_fraction);
  return std::sqrt(kT * (z + area_fraction * slope + z * z));
}

}  // namespace gas
