// The push on the walls' middles. See beyond/wall_push.hpp and
// lessons/14-error-bars.md.
//
// The derivation (unit mass, k = 1, 2D).
//
// The low-frequency part. By the fluctuation-dissipation theorem the total
// force F on the two middles has, at zero frequency, the spectrum
// integral C_F(t) dt over all t = 2 kT Re Z(0), Re Z(0) the power the fluid
// takes from the middles moved inward at unit speed, very slowly (the
// classical limit of H. B. Callen and T. A. Welton, Phys. Rev. 83, 34
// (1951): Nyquist's noise of a resistance). Slowly: the gas stays uniform
// and is squeezed as a whole, at the rate eps = 2 l / A (l one middle's
// length, A = L1 L2 the centres' box 0 <= x <= L1, 0 <= y <= L2). The flow
// that does it, w = grad phi + curl psi (w_x = phi_x + psi_y, w_y = phi_y -
// psi_x), written as waves across, k = q pi / L2, z = x - L1 / 2:
//   phi = sum_q Y_q(x) cos(k y), with div w = -eps and the middles' unit
//     speed inward through the walls: Y_0' = s_0 - eps x, and for q >= 1
//     Y_q = -(s_q / k) E, E = cosh(k z) / sinh(H), O = sinh(k z) / sinh(H),
//     H = k L1 / 2, s_q the middles' projection over the wave's norm
//     (side_wave of beyond/box_modes.hpp);
//   psi = sum_q X_q(x) sin(k y): no flow through the walls (X = 0 there)
//     and, mirrors, no shear stress on them; Stokes's equations then give
//     X_q = s_q (z E - (L1 / 2) coth(H) O).
// The power is the viscous dissipation, the integral of
//   eta_s ((d_x w_x - d_y w_y)^2 + (d_y w_x + d_x w_y)^2) + zeta (div w)^2:
// (eta_s + zeta) eps^2 A for q = 0, and for each q >= 1
//   eta_s (L2 / 2) s_q^2 k^4 integral over z of (2 z O - b E)^2 + (2 z E - b O)^2,
// b = L1 coth(H). The sum over q grows as the logarithm of the highest wave
// number (the shear at the middles' ends): it stops at k = 1 / a, a
// ball's size, as the waves of beyond/box_modes do.
//
// The ringing part. Each sound wave (m, q) of the box presses on the walls
// with <F^2> = n kT c^2 (P_q^2 / |phi|^2) (1 + (-1)^m)^2 (P_q the middle's
// projection, the same on both walls; odd m push the two walls in turn and
// cancel in F) and rings as cos(c k t) exp(-Gamma k^2 t). Its share of the
// zero-frequency spectrum is already in Re Z(0); what the ringing adds in a
// run of length W is its averaged_ringing less that share,
// 2 alpha / ((alpha^2 + omega^2) W).
//
// So, with P = F / (2 l):
//   Var(P over W) = (2 kT Re Z(0) / W + sum over waves <F^2> (ringing
//                   - 2 alpha / ((alpha^2 + omega^2) W))) / (2 l)^2.
#include "beyond/wall_push.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace gas {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

// integral over -L1/2 <= z <= L1/2 of (2 z O - b E)^2 + (2 z E - b O)^2 for
// wave number k. Written out, (4 z^2 + b^2) cosh(2 k z) - 4 b z sinh(2 k z)
// over sinh(H)^2; integrated term by term, with d = b - L1 (which is
// 2 L1 / (e^(2H) - 1)) and e4 = e^(-2H) / sinh(H)^2 taken apart so that the
// large terms, which cancel, never appear:
//   2 ((2 coth H / K) d^2 - 2 b L1 e4 / K + (4 / K^2)(2 d coth H - L1 e4)
//      + 16 coth H / K^3),   K = 2 k.
// (Checked against Simpson's rule to 1e-14; for H beyond a few, 4 coth H /
// k^3, the potential flow's dissipation halved.)
double shear_integral(double k, double side) {
  const double h_scaled = k * side / 2, twice_k = 2 * k;  // H, K
  const double coth = 1 / std::tanh(h_scaled);
  const double b = side * coth;
  const double d = 2 * side / std::expm1(2 * h_scaled);  // b - L1
  const double e4 = 4 * std::exp(-4 * h_scaled) / std::pow(std::expm1(-2 * h_scaled), 2);
  return 2 * ((2 * coth / twice_k) * d * d - 2 * b * side * e4 / twice_k +
              (4 / (twice_k * twice_k)) * (2 * d * coth - side * e4) +
              16 * coth / std::pow(twice_k, 3));
}

}  // namespace

// [anchor: middles-friction]
double middles_friction(const Viscosities& viscosities, double radius, double width,
                        double height, const WallMiddles& middles,
                        double max_wave_number) {
  const double side1 = width - 2 * radius, side2 = height - 2 * radius;  // L1, L2
  const double v0 = middles.from - radius, v1 = middles.to - radius;     // centres' box
  if (!(side1 > 0 && side2 > 0 && v1 > v0)) return unknown;
  const double k_max = max_wave_number > 0 ? max_wave_number : 1 / radius;
  // Squeeze the whole gas.
  const double area = side1 * side2;
  const double squeeze = 2 * (v1 - v0) / area;  // eps at unit speed
  double friction = (viscosities.shear + viscosities.bulk) * squeeze * squeeze * area;
  // Shear it near the middles' ends, wave by wave across.
  for (int q = 1; q * pi / side2 <= k_max; ++q) {
    const double k = q * pi / side2;
    const WaveSide across = side_wave(q, side2, v0, v1);
    const double s = across.projection / across.norm;
    friction += viscosities.shear * (side2 / 2) * s * s * std::pow(k, 4) *
                shear_integral(k, side1);
  }
  return friction;
}
// [/anchor: middles-friction]

// [anchor: middles-push-wander]
double middles_push_wander(const BoxHydrodynamics& fluid, const Viscosities& viscosities,
                           double radius, double width, double height,
                           const WallMiddles& middles, double duration,
                           double max_wave_number) {
  const double side1 = width - 2 * radius, side2 = height - 2 * radius;
  const double v0 = middles.from - radius, v1 = middles.to - radius;
  if (!(duration > 0 && fluid.sound_speed > 0 && fluid.sound_attenuation > 0))
    return unknown;
  const double friction =
      middles_friction(viscosities, radius, width, height, middles, max_wave_number);
  if (!std::isfinite(friction)) return unknown;
  const double k_max = max_wave_number > 0 ? max_wave_number : 1 / radius;
  // The sound waves that push both middles at once: m even.
  double ringing = 0;
  for (int m = 0; m * pi / side1 <= k_max; m += 2) {
    const WaveSide along = side_wave(m, side1, 0, side1);  // only its norm
    for (int q = 0;; ++q) {
      if (m == 0 && q == 0) continue;  // the whole gas: fixed
      const double k2 = std::pow(m * pi / side1, 2) + std::pow(q * pi / side2, 2);
      if (k2 > k_max * k_max) break;
      const WaveSide across = side_wave(q, side2, v0, v1);
      const double force = fluid.density * fluid.kT * fluid.sound_speed *
                           fluid.sound_speed * 4 * across.projection * across.projection /
                           (along.norm * across.norm);  // <F^2>
      const double alpha = fluid.sound_attenuation * k2;
      const double omega = fluid.sound_speed * std::sqrt(k2);
      ringing += force * (averaged_ringing(alpha, omega, duration) -
                          2 * alpha / ((alpha * alpha + omega * omega) * duration));
    }
  }
  const double variance = 2 * fluid.kT * friction / duration + ringing;  // of F
  const double length = 2 * (v1 - v0);
  return std::sqrt(std::max(variance, 0.0)) / length;
}
// [/anchor: middles-push-wander]

}  // namespace gas
