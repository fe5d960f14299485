// The box's sound and heat. See beyond/box_modes.hpp and lessons/14-error-bars.md.
//
// The derivation (unit mass, k = 1, 2D: c_v = 1 a ball, c_p = gamma).
//
// Waves. The centres move in the box 0 <= u <= L1, 0 <= v <= L2 (u = x - a,
// L1 = A1 - 2a). The waves phi(u, v) = cos(m pi u / L1) cos(q pi v / L2), k^2
// = (m pi / L1)^2 + (q pi / L2)^2, have no slope at the walls: nothing flows
// through a mirror. They are orthogonal, with norm |phi|^2 = integral phi^2
// = (L1 / 2, or L1 for m = 0) times (L2 / 2, or L2 for q = 0). The wave
// m = q = 0 is the whole gas, whose count and energy are fixed: it is left
// out.
//
// What each wave holds. Far from the walls, over lengths much longer than a
// ball, the density's fluctuations are uncorrelated from place to place:
// <dn(r) dn(r')> = n S(0) delta(r - r'). A wave's amplitude a = integral dn
// phi / |phi|^2 then has <a^2> = n S(0) / |phi|^2, and the interior's count
// N_int = integral over the interior of n moves by a P, P = integral over
// the interior of phi (for the box's mirror symmetry, only even m and q
// give P != 0; the sum takes them all). The energy's combination that moves
// kT_int = E_int / N_int is X = de - kT dn (a ball's kinetic energy
// averages kT in 2D, and hard discs have no other energy): dkT_int =
// X_int / N_int. Its fluctuations: thermodynamics splits any fluctuation
// into the pressure's dP, which travels as sound, and the heat's dq = de -
// h dn (h = kT (1 + Z), the enthalpy a ball), which only spreads; the two
// are uncorrelated, <dP^2> = n kT c^2 and <dq^2> = n kT^2 c_p per unit area.
// With dn = dP / c^2 - (alpha_P / c_p) dq (alpha_P = Z / (kT (Z + eta Z')),
// the expansion at constant pressure) the density's share of heat is 1 -
// 1 / gamma and of sound 1 / gamma; and X = dq / c_p + (kT Z / c^2) dP holds
// n kT^2 / gamma of heat and n kT^2 (1 - 1 / gamma) of sound per unit area
// (both sum to n kT^2 for an ideal gas, where X is a sum of independent v^2
// / 2 - kT).
//
// How each wave forgets. Linear hydrodynamics: the heat part of a wave
// decays as exp(-D_T k^2 t), the sound part rings as cos(c k t) exp(-Gamma
// k^2 t). (A small term in sin(c k t), of order Gamma k / c, is left out;
// the whole sound part is some 3 % of eta_int's variance over W = 270 on
// data/large-1000.scene.)
//
// The time average. For a correlation C(t) the average over W has the
// variance (2 / W^2) integral_0^W (W - t) C(t) dt: for C = exp(-t / tau)
// that is (2 tau / W)(1 - (tau / W)(1 - exp(-W / tau))), for C = cos(omega
// t) exp(-alpha t) with s = alpha - i omega the real part of (2 / W^2)(W /
// s - (1 - exp(-s W)) / s^2). Both tend to 1 (the static variance) as W ->
// 0 and fall as 1 / W for long runs.
//
// Then, over the waves, with pi a^2 / A_int turning a count into an area
// fraction:
//   Var(eta_int) = (pi a^2 / A_int)^2 sum n S(0) (P^2 / |phi|^2)
//                  ((1 - 1/gamma) heat + (1/gamma) sound),
//   Var(kT_int)  = (n A_int)^-2 sum n kT^2 (P^2 / |phi|^2)
//                  ((1/gamma) heat + (1 - 1/gamma) sound),
// heat and sound each the time average's factor above for that wave.
//
// The two together. <dn X> = <dP^2> kT Z / c^4 - <dq^2> alpha_P / c_p^2 =
// n kT Z S(0) / gamma (sound - heat) per unit area (kT / c^2 = S(0) /
// gamma, alpha_P kT = Z S(0)): heat moves the count and the energy
// opposite ways, sound the same way. For hard discs gamma - 1 = Z^2 S(0)
// (c_p - c_v = T (dP/dT)_n^2 / (n^2 (dP/dn)_T), with (dP/dT)_n = n Z and
// (dP/dn)_T = kT / S(0)), so wave by wave heat's correlation is exactly
// -1 and sound's +1, and with H and A the sums of P^2 / |phi|^2 times heat
// and times sound,
//   Corr(eta_int, kT_int) = sqrt(gamma - 1) (A - H)
//                           / sqrt(((gamma - 1) H + A) (H + (gamma - 1) A)).
#include "beyond/box_modes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace gas {

namespace {

constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
constexpr double pi = std::numbers::pi;

// exp(z) - 1 for complex z = x + i y without losing the small ones: the
// real part expm1(x) cos y - 2 sin^2(y / 2), the imaginary exp(x) sin y.
// One sine and cosine, of y / 2: cos y = 1 - 2 sin^2(y / 2), sin y = 2
// sin(y / 2) cos(y / 2) (the sums over the waves call this some 10^4 times
// for every row of the statistics).
std::complex<double> complex_expm1(std::complex<double> z) {
  const double x = z.real(), y = z.imag();
  const double sine = std::sin(y / 2), cosine = std::cos(y / 2);
  const double versine = 2 * sine * sine;  // 1 - cos y
  const double e = std::expm1(x);
  return {e * (1 - versine) - versine, (1 + e) * 2 * sine * cosine};
}

}  // namespace

WaveSide side_wave(int m, double length, double from, double to) {
  if (m == 0) return {to - from, length};
  const double k = m * pi / length;
  return {(std::sin(k * to) - std::sin(k * from)) / k, length / 2};
}

// [anchor: averaged-decay]
double averaged_decay(double tau, double duration) {
  const double x = duration / tau;
  // (2 / x)(1 - (1 - exp(-x)) / x), with 1 - exp(-x) = -expm1(-x).
  return (2 / x) * (1 + std::expm1(-x) / x);
}

double averaged_ringing(double alpha, double omega, double duration) {
  const std::complex<double> s(alpha, -omega);
  const double w = duration;
  // 1 / s as conj(s) / |s|^2: a division by a real number (the library's
  // complex division guards against overflows that cannot happen here, at
  // some cost).
  const std::complex<double> inverse = std::conj(s) / std::norm(s);
  const std::complex<double> integral =
      w * inverse + complex_expm1(-s * w) * inverse * inverse;
  return 2 * integral.real() / (w * w);
}
// [/anchor: averaged-decay]

double corrected_by_batches(double theory_whole, double theory_batch,
                            double theory_batches, double batches, double batch_error) {
  if (!(batches >= 2)) return unknown;
  const double expected =
      (theory_batch * theory_batch - theory_batches * theory_batches) / (batches - 1);
  return std::sqrt(theory_whole * theory_whole + batch_error * batch_error - expected);
}

// [anchor: interior-wander]
InteriorWander interior_wander(const BoxHydrodynamics& fluid, double radius, double width,
                               double height, const Region& interior, double duration,
                               double max_wave_number) {
  InteriorWander wander;
  const double side1 = width - 2 * radius, side2 = height - 2 * radius;  // L1, L2
  if (interior.empty() || !(duration > 0) || !(side1 > 0 && side2 > 0)) return wander;
  if (!(fluid.thermal_diffusivity > 0 && fluid.sound_speed > 0 &&
        fluid.sound_attenuation > 0 && fluid.heat_capacity_ratio > 0))
    return wander;
  const double k_max = max_wave_number > 0 ? max_wave_number : 1 / radius;
  // The interior in the centres' box.
  const double u0 = interior.x_min - radius, u1 = interior.x_max - radius;
  const double v0 = interior.y_min - radius, v1 = interior.y_max - radius;
  double heat_sum = 0, sound_sum = 0;  // H and A: the waves' weights times heat, sound
  const int m_max = static_cast<int>(k_max * side1 / pi);
  const int q_max = static_cast<int>(k_max * side2 / pi);
  // The interior's side along y, for each q once (not once per wave).
  std::vector<WaveSide> along_ys;
  for (int q = 0; q <= q_max; ++q) along_ys.push_back(side_wave(q, side2, v0, v1));
  for (int m = 0; m <= m_max; ++m) {
    const WaveSide along_x = side_wave(m, side1, u0, u1);
    for (int q = 0; q <= q_max; ++q) {
      if (m == 0 && q == 0) continue;  // the whole gas: fixed
      const double k2 = std::pow(m * pi / side1, 2) + std::pow(q * pi / side2, 2);
      if (k2 > k_max * k_max) break;
      const WaveSide& along_y = along_ys[static_cast<std::size_t>(q)];
      const double weight = std::pow(along_x.projection * along_y.projection, 2) /
                            (along_x.norm * along_y.norm);  // P^2 / |phi|^2
      // Find how much of each part the average over W keeps.
      const double heat = averaged_decay(1 / (fluid.thermal_diffusivity * k2), duration);
      const double sound = averaged_ringing(fluid.sound_attenuation * k2,
                                            fluid.sound_speed * std::sqrt(k2), duration);
      heat_sum += weight * heat;
      sound_sum += weight * sound;
    }
  }
  // Var(N_int) and Var(X_int) of the averages, in units of n S(0) and n kT^2.
  const double g = fluid.heat_capacity_ratio;
  const double count = ((g - 1) * heat_sum + sound_sum) / g;
  const double energy = (heat_sum + (g - 1) * sound_sum) / g;
  const double n = fluid.density;
  const double area = interior.area();
  wander.area_fraction =
      pi * radius * radius / area * std::sqrt(n * fluid.structure_factor * count);
  wander.kT = std::sqrt(n * fluid.kT * fluid.kT * energy) / (n * area);
  wander.correlation =
      std::sqrt(g - 1) * (sound_sum - heat_sum) / (g * std::sqrt(count * energy));
  return wander;
}
// [/anchor: interior-wander]

double following_wander(const InteriorWander& wander, double eta, double kT,
                        double eta_power, double kT_power) {
  const double by_eta = eta_power * wander.area_fraction / eta;
  const double by_kT = kT_power * wander.kT / kT;
  // (Never below zero: a correlation of -1 and equal shares cancel exactly.)
  return std::sqrt(std::max(
      0.0, by_eta * by_eta + by_kT * by_kT + 2 * wander.correlation * by_eta * by_kT));
}

}  // namespace gas
