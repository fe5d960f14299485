// Enskog's transport coefficients of hard discs. See beyond/enskog_transport.hpp
// and lessons/16-long-time-tail.md.
//
// Where each formula comes from (unit mass, k = 1, 2D, s = 2a, g = g(s)).
//
// What we could read: the abstracts of J. J. Erpenbeck and W. W. Wood, Phys.
// Rev. A 26, 1648 (1982), of M. Isobe, Phys. Rev. E 77, 021201 (2008), of
// B. J. Alder and T. E. Wainwright, Phys. Rev. A 1, 18 (1970), and of M. H.
// Ernst, E. H. Hauge and J. M. J. van Leeuwen, Phys. Rev. A 4, 2055 (1971),
// and the first page of D. M. Gass, J. Chem. Phys. 54, 1898 (1971), which
// derives Enskog's shear and bulk viscosities of discs (its abstract says
// so) in formulas we could not read. Nothing of Garzo and Dufty's
// d-dimensional Enskog theory (Phys. Rev. E 59, 5895 (1999)) or of Chapman
// and Cowling's book. So every formula below is derived here, in d
// dimensions, and the suite computes each coefficient again from the
// collision rule by Monte Carlo, in 2D and in 3D
// (tests/test_enskog_transport.cpp); in 3D the same integrals give Chapman
// and Cowling's dilute hard-sphere eta_0 = (5 / 16) sqrt(kT / pi) / s^2 and
// D_0 = (3 / 8) sqrt(kT / pi) / (n s^2), which we could read only as others
// quote them (the documentation of EntropyScaling.jl,
// docs/src/models/CE_models.md, with the reduced collision integrals 1 of
// rigid spheres; eta_0 also in jonasbue/MD_viscosity,
// simulation/analysis/viscosity.py).
//
// Collisions in equilibrium. A ball of velocity v1 meets partners of
// velocity v2 (w = v1 - v2) along the unit vector e from its centre to
// theirs at the rate n g s (w.e) de per unit time, for w.e > 0 (contact
// length s de, the density at contact g n), and leaves with v1 - (w.e) e.
//
// tau_E and D_E. At t = 0+ the velocity of a ball changes only by its
// collisions, so d<v1(0).v1(t)>/dt at 0+ = -n g s < integral (w.e)^2 (v1.e)
// de >. With v1 = V + w/2 the centre-of-mass part averages out, the angle
// integral of cos^3 over a half circle is 4/3, and <|w|^3> = 3 sqrt(pi/2)
// (2 kT)^(3/2) (w is Maxwellian with variance 2 kT a component); so the
// slope is -4 sqrt(pi) n g s kT^(3/2), and divided by <v^2> = 2 kT:
//   1 / tau_E = 2 sqrt(pi) n g s sqrt(kT),   D_E = kT tau_E = sqrt(kT / pi) / (2 n s g).
// This is exact for hard discs (only the equilibrium distribution at contact
// enters, and its factor g is exact), and it is Enskog's D in the first
// Sonine approximation, whose trial function is the velocity itself:
// Enskog's exponential has the exact initial slope (Erpenbeck and Wood's
// abstract). In 2D 1 / tau_E is also exactly Enskog's collision rate
// 2 s n g sqrt(pi kT) (beyond/kinetic_theory.hpp): Enskog's velocity
// forgets itself in one mean free time (in 3D in 1.5).
//
// eta_E and kappa_E, first Sonine approximation (a shear flow distorts the
// Maxwellian by v_x v_y alone). Three parts, each a collision integral:
//  - The dilute gas: under Boltzmann's collisions the average of v_x v_y
//    relaxes at the rate nu_s = <(v_x v_y) L (v_x v_y)> / <(v_x v_y)^2> (L
//    the linearised collision operator, nu_s = 2 sqrt(pi) n s sqrt(kT), the
//    same as 1 / tau_E at g = 1), and eta_0 = n kT / nu_s = sqrt(kT / pi) /
//    (2 s); in d dimensions
//    ((d + 2) / 8) Gamma(d / 2) pi^((1 - d) / 2) s^(1 - d) sqrt(kT), in 3D
//    (5 / 16) sqrt(kT / pi) / s^2. In 2D eta_0 / n = D_0: a dilute gas of
//    discs spreads momentum as fast as it spreads its balls.
//  - Transfer across contact: a collision hands the momentum (w.e) e across
//    the distance s e. For the distorted Maxwellian that adds to the balls'
//    own (kinetic) stress eta g times it (in d dimensions 2^d phi g / (d + 2),
//    phi the packed fraction), and Enskog's collision term, expanded in the
//    contact distance, raises the drive of the distortion by the same
//    factor. So the kinetic part is eta_k = (eta_0 / g)(1 + eta g) and the
//    transferred part eta g eta_k.
//  - The flow across contact: the partner's mean velocity differs by
//    s (e.grad) u, which changes the momentum handed over. In a compression
//    that is the bulk viscosity kappa_E = (pi / 2) n^2 g s^3 sqrt(kT / pi)
//    (d dimensions: Omega_d n^2 g s^(d+1) sqrt(kT / pi) / d^2, Omega_d the
//    unit sphere's area), in a shear d / (d + 2) of it, kappa_E / 2.
// Together, with kappa_E = (16 / pi) eta^2 g eta_0,
//   eta_E = (eta_0 / g)(1 + eta g)^2 + kappa_E / 2 = eta_0 (1 / g + 2 eta + (1 + 8 / pi)
//   eta^2 g).
// (At d = 3 the same parts give 1 / g + 0.8 b n + 0.7712 (b n)^2 g, b n =
// 4 phi, the form we remember from Chapman and Cowling but could not read.)
// The next Sonine approximations change eta_0 and D_0 by a few per cent;
// we do not compute them.
//
// The tail. The ball's velocity at time t is that of the fluid around it;
// the momentum it had at 0 is shared with the fluid, and a fraction
// (d - 1) / d of it goes into the shear modes (the transverse projector
// 1 - k_x^2 / k^2 averaged over directions), which decay as exp(-nu k^2 t),
// while the ball spreads as exp(-D k^2 t); per ball of fluid the velocity is
// the momentum over n. So
//   rho(t) = ((d - 1) / (d n)) integral d^dk / (2 pi)^d exp(-(D + nu) k^2 t)
//          = ((d - 1) / (d n)) (4 pi (D + nu) t)^(-d/2) = 1 / (8 pi n (D + nu) t) in 2D,
// mode coupling's amplitude (Ernst, Hauge and van Leeuwen, Phys. Rev. Lett.
// 25, 1254 (1970); J. R. Dorfman and E. G. D. Cohen, ibid. 1257: not read
// here). What we read agrees: Alder and Wainwright's abstract gives the decay
// as (viscosity times t)^(-d/2), from the flow round a moving volume element,
// and the 1971 abstract of Ernst, Hauge and van Leeuwen the coefficient in
// terms of the transport coefficients. The factor is derived here, and the
// suite integrates it both ways (in k, and as the overlap of two Gaussians).
//
// The sound speed. P = n kT Z(eta), the energy kT a ball (2D): at fixed
// entropy dT/dn = T Z / n, so dP/dn = kT (Z + eta Z') + n k Z T Z / n, and
// c^2 = kT (Z + eta Z' + Z^2) (2 kT in the dilute limit: c_p / c_v = 2).
//
// The heat capacity. Per ball c_v = 1 (2D), and c_p - c_v = T (dP/dT)_n^2 /
// (n^2 (dP/dn)_T) with (dP/dT)_n = n Z, (dP/dn)_T = kT (Z + eta Z'):
//   c_p = 1 + Z^2 / (Z + eta Z'),   gamma = c_p / c_v = c_p
// (c^2 = gamma (dP/dn)_T, the sound speed above; 2 in the dilute limit).
//
// The thermal conductivity lambda_E, first Sonine approximation (a gradient
// dT/dx distorts the Maxwellian by a psi alone, kT = 1 and dT/dx = 1 in what
// follows, psi = (v^2 / 2 - (d + 2) / 2) v_x). <psi^2> = (d + 2) / 2 and
// <v_x psi> = 0, so the heat flux of the distortion is n a <(v^2 / 2) v_x psi>
// = n a <psi^2>. Three parts again:
//  - The dilute gas: streaming drives the distortion by v_x (v^2 / 2 - d / 2)
//    (d ln f0 / dT at fixed n), the pressure gradient's pull by -v_x Z; with
//    Z = 1 the drive is psi. Collisions relax <psi> at nu_h = <psi L psi> /
//    <psi^2>, so a = -1 / nu_h and lambda_0 = n <psi^2> / nu_h. A collision
//    keeps the pair's mean velocity V and |w|, w = v1 - v2, and psi1 + psi2
//    = 2 V_x (V^2 / 2 + w^2 / 8 - (d + 2) / 2) + (V.w) w_x / 2; so it changes
//    by V.(M e_x) / 2, and v_x v_y by M_xy / 2, M = w' w' - w w, one traceless
//    tensor. Over V (variance 1/2) and directions (isotropy) the first square
//    is (d - 1)(d + 2) / (2 d) times the second, whence nu_h = ((d - 1) / d)
//    nu_s (any force law) and lambda_0 = (d (d + 2) / (2 (d - 1))) eta_0 (k /
//    m): 4 eta_0 = (2 / s) sqrt(kT / pi) in 2D, (75 / 64) sqrt(kT / pi) / s^2
//    in 3D.
//  - Transfer across contact: a collision hands ball 2 the energy (w.e)(V.e)
//    across s e. Over V, (V.e)(psi1 + psi2) = e_x (w^2 / 8 - (d + 2) / 4) +
//    (w.e) w_x / 4; against (w.e)^2 over w (Maxwellian, variance 2) the first
//    term averages to 0 and the second to 3 e_x^2 / 2. So (pairs counted from
//    both ends, half) the collisional flux is t times the kinetic one,
//      t = 3 Omega_d n g s^d / (2 d (d + 2)) = 3 2^(d-1) phi g / (d + 2),
//    (3 / 2) eta g in 2D, (3 / 5) b n g in 3D (b n = 4 phi): 3/2 of the
//    viscosity's. Enskog's collision term, with the partner's Maxwellian at
//    T + s e_x (and T - s e_x in the restoring collision), adds to the drive
//    a v_x part that cancels the pull's Z - 1 (collisions keep momentum) and
//    a psi part that the suite finds to be t psi, as for the viscosity. So
//    the kinetic part is lambda_k = (lambda_0 / g)(1 + t) and the transferred
//    part t lambda_k.
//  - The temperature difference across contact: the undistorted pair
//    straddling a plane, ball 1 at T - s e_x / 2 and ball 2 at T + s e_x / 2,
//    is weighed by 1 + (s e_x / 2)(v2^2 - v1^2) / 2 = 1 - (s e_x / 2)(V.w), and
//    over V (V.e)(V.w) = (w.e) / 2; with <(w.e)_+^3> = 4 / sqrt(pi) the energy
//    handed down the gradient is
//      lambda_c = Omega_d n^2 g s^(d+1) sqrt(kT / pi) / (2 d) = (d / 2) kappa_E,
//    (pi / 2) n^2 g s^3 sqrt(kT / pi) in 2D, kappa_E itself.
// Together, in 2D (lambda_c = (4 / pi) eta^2 g lambda_0),
//   lambda_E = (lambda_0 / g)(1 + 3 eta g / 2)^2 + lambda_c
//            = lambda_0 (1 / g + 3 eta + (9 / 4 + 4 / pi) eta^2 g),
// and at d = 3 lambda_0 (1 / g + (6 / 5) b n + (9 / 25 + 32 / (25 pi)) (b n)^2
// g), the form we remember from Chapman and Cowling (not read).
//
// Heat diffuses at D_T = lambda_E / (n c_p) (at constant pressure). A sound
// wave exp(i (k x - w t)) of the linearised equations (dn/dt = -n du/dx, n du/dt
// = -dP/dx + n nu_l d^2u/dx^2, n c_v dT/dt = -T (dP/dT)_n du/dx + lambda_E
// d^2T/dx^2) has, to order k^2, w = c k - i Gamma k^2 with
//   Gamma = (nu_l + (gamma - 1) D_T) / 2,  nu_l = (2 (d - 1) / d eta_E + kappa_E) / n
// (the stress of a compression along x: eta_E (2 - 2 / d) + kappa_E), in 2D
// nu_l = (eta_E + kappa_E) / n: the sound root of the cubic in w, expanded
// about c k (the suite finds the root numerically at small k). A sound wave
// of wave number k decays as exp(-Gamma k^2 t).
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
    e.shear_viscosity = e.bulk_viscosity = e.kinematic_viscosity = unknown;
    e.sound_speed = e.heat_capacity = e.heat_capacity_ratio = unknown;
    e.thermal_conductivity = e.thermal_diffusivity = e.sound_attenuation = unknown;
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
  // The viscosities: eta_0, the transfer factor eta g, kappa_E; nu_E = eta_E / (m n).
  const double dilute_viscosity = std::sqrt(kT / pi) / (2 * s);
  const double transfer = eta * g;
  const double kinetic_viscosity = dilute_viscosity * (1 + transfer) / g;
  e.bulk_viscosity = (pi / 2) * n * n * g * s * s * s * std::sqrt(kT / pi);
  e.shear_viscosity = kinetic_viscosity * (1 + transfer) + e.bulk_viscosity / 2;
  e.kinematic_viscosity = e.shear_viscosity / n;
  e.sound_speed = hard_disc_sound_speed(eta, kT);
  // Heat: c_p = 1 + Z^2 / (Z + eta Z'), gamma = c_p / c_v with c_v = 1.
  const double z = hard_disc_fluid_compressibility(eta);
  const double slope = hard_disc_fluid_compressibility_slope(eta);
  e.heat_capacity = 1 + z * z / (z + eta * slope);
  e.heat_capacity_ratio = e.heat_capacity;  // over c_v = 1
  // lambda_0 = 4 eta_0, the transfer factor 3 eta g / 2, and lambda_c =
  // (pi / 2) n^2 g s^3 sqrt(kT / pi) from the temperature difference across
  // contact (in 2D the same number as kappa_E).
  const double dilute_conductivity = 4 * dilute_viscosity;
  const double heat_transfer = 1.5 * eta * g;
  const double contact_conductivity =
      (pi / 2) * n * n * g * s * s * s * std::sqrt(kT / pi);
  e.thermal_conductivity =
      dilute_conductivity / g * (1 + heat_transfer) * (1 + heat_transfer) +
      contact_conductivity;
  e.thermal_diffusivity = e.thermal_conductivity / (n * e.heat_capacity);
  // Sound decays at Gamma = (nu_l + (gamma - 1) D_T) / 2, nu_l = (eta_E + kappa_E) / n.
  const double longitudinal = (e.shear_viscosity + e.bulk_viscosity) / n;
  e.sound_attenuation =
      (longitudinal + (e.heat_capacity_ratio - 1) * e.thermal_diffusivity) / 2;
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
