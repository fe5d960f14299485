// How far the time-averaged mean speed wanders. See
// beyond/speed_relaxation.hpp and lessons/14-error-bars.md.
//
// Everything below is derived here (unit mass, k = 1, 2D, s = 2a, g = g(s));
// we read no paper on it. tests/test_speed_relaxation.cpp checks each closed
// form by quadrature and each matrix element by Monte Carlo over colliding
// pairs, the way tests/test_enskog_transport.cpp samples them.
//
// 1. The static variance. In 2D x = v^2 / (2 kT) is exponential, density
// e^-x, under Maxwell's distribution, so the isotropic Sonine polynomials
// are the Laguerre polynomials L_p(x), orthonormal under e^-x. With
// |v| = sqrt(2 kT x) and the integral of x^(1/2) L_p(x) e^-x over x,
// Gamma(3/2) (-1/2)_p / p! (L_p's sum of powers, then Chu-Vandermonde),
//   |v| = sqrt(kT) sum_p c_p L_p(x),   c_p = sqrt(pi / 2) (-1/2)_p / p!:
// c_0 = sqrt(pi / 2) (<|v|> = sqrt(pi kT / 2)), c_1 = -c_0 / 2, c_2 = -c_0 /
// 8, ... At fixed energy the projection onto {1, v^2} = {L_0, L_1} is fixed,
// and what wanders is psi = sqrt(kT) sum_{p >= 2} c_p L_p, so
//   <psi^2> = <v^2> - <|v|>^2 - cov(|v|, v^2)^2 / var(v^2)
//           = 2 kT - pi kT / 2 - (sqrt(pi / 2) kT^(3/2))^2 / (4 kT^2)
//           = (2 - 5 pi / 8) kT = 0.0365 kT,
// using <|v|^3> = 3 sqrt(pi / 2) kT^(3/2), var(v^2) = 4 kT^2. The mean speed
// of N balls at fixed E is (1 / N) sum_i |v_i|; to leading order in 1 / N its
// variance is <psi^2> / N, 1 / 11.7 of the 2 - pi / 2 it would have at free
// energy.
//
// 2. The correlation time. The sum over the balls of psi(v_i) is the k = 0
// part of the one-ball distribution; to leading order in 1 / N it relaxes by
// the linearised collision operator (Enskog: Boltzmann's times g), the
// product of two fluctuations being a 1 / N correction. So its
// autocorrelation is <psi exp(L t) psi> / N and its integral
// <psi (-L)^-1 psi> / N = tau_int <psi^2> / N, with, for a perturbation phi
// of Maxwell's distribution f0 (1 + phi),
//   L phi(v1) = n g s < integral over e of (w.e) theta(w.e) D phi >_{v2},
//   D phi = phi(v1') + phi(v2') - phi(v1) - phi(v2),
// w = v1 - v2, v1' = v1 - (w.e) e, v2' = v2 + (w.e) e, e over the unit
// circle (the collision rule of tests/test_enskog_transport.cpp). Swapping
// the two balls and the collision with its inverse makes it symmetric:
//   <phi (-L) chi> = (n g s / 4) < integral de (w.e) theta(w.e) D phi D chi >,
// the average over two Maxwellian balls. So L_0 and L_1 (number, energy)
// give zero, and -L is positive on the rest.
//
// The matrix elements. With V = (v1 + v2) / 2 and w = |w| (1, 0) (the pair
// is isotropic), w' = |w| (cos chi, sin chi), and the e integral becomes
// one over the scattering angle chi with the weight |w| (1/2) sin(chi / 2)
// dchi on 0 ... 2 pi (impact parameter b = s sin((pi - chi) / 2)); x1, x2 =
// V^2 / 2 + w^2 / 8 +- V.w / 2 (kT = 1), and after the collision the same
// with w'. D L_p D L_q is a polynomial in V_x, V_y, |w|, cos chi, sin chi;
// under Maxwell's distribution V and w are independent Gaussians with
// variances 1/2 and 2 a component, so <V_x^a> = (a - 1)!! / 2^(a/2),
// <|w|^m> = 2^m Gamma(m / 2 + 1) (|w|^2 / 4 is exponential), and the chi
// integral of sin(chi / 2) cos^i chi sin^j chi is rational (t = cos(chi / 2)
// turns it into a polynomial's integral over -1 ... 1). So
//   <L_p (-L) L_q> = n g s sqrt(kT) sqrt(pi) r_pq,   r_pq rational:
// r_22 = 1, r_23 = -1/4, r_33 = 27/16, r_34 = -59/128, r_44 = 2305/1024, and
// r_2q = (-1/2)_(q-2) / ((q - 2)! 2^(q-2)). We expanded the polynomials
// with a computer algebra system (SymPy) and tabulate r_pq below for p, q
// <= 10 as the rationals themselves (their denominators are powers of 2 and
// their numerators below 2^53, so each double is exact); the test checks
// them by Monte Carlo.
//
// 3. The Sonine approximation. <psi (-L)^-1 psi> = max over phi of
// 2 <psi phi> - <phi (-L) phi>; over phi in L_2 ... L_P the maximum is
// c^T M^-1 c (M_pq = r_pq, c the c_p, p = 2 ... P), a lower bound that grows
// with P to the limit. It grows slowly: |v| has a square-root cusp at v = 0,
// so c_p falls only as p^(-3/2), and the P-th step adds about c_P^2 over
// the P-th eigenvalue of -L, which grows as the collision rate at the
// speeds L_P reaches (|v| ~ sqrt(P) for hard discs): steps of about
// P^(-3.5). Measured: the local exponent of the steps climbs 2.95, 3.12,
// 3.22, 3.29, 3.33, 3.35, 3.36 from P = 4 to 10. We add the tail as the
// steps continued with the last step's local exponent beta (the sum over
// p > P of d_P (P / p)^beta): an overestimate while beta still climbs, and
// beta = 3.5 an underestimate; they bracket the limit within 0.1 %. Values
// of tau_int n g s sqrt(kT): P = 2: sqrt(pi) / 128 / (2 - 5 pi / 8) =
// 0.3793; P = 3: (35 sqrt(pi) / 3328) / (2 - 5 pi / 8) = 0.5106; 4: 0.5669;
// 5: 0.5950; 6: 0.6106; 8: 0.6260; 10: 0.6329; the limit 0.6436 (from P = 8
// 0.6439, from P = 6 0.6456; with beta = 3.5 from P = 10, 0.6429). In mean
// free times 1 / (2 sqrt(pi) n g s sqrt(kT)) the limit is 2.28: the shape of
// the speed distribution forgets itself in about two collisions per ball.
//
// 4. The time average. For a stationary series of variance sigma^2 and
// correlation rho(t), the average over W has the variance
// (sigma^2 / W^2) integral over [0, W]^2 of rho(t - t'), which tends to
// 2 tau_int sigma^2 / W for W >> tau_int. For rho = exp(-|t| / tau) the
// integral is exact: (2 tau / W)(1 - (tau / W)(1 - exp(-W / tau))) sigma^2.
// The true rho is a sum of exponentials (the eigenvalues of -L), so this
// finite-W form is a model; both agree once W >> tau_int.
//
// Against the program (not a test: 80 runs). 40 gases of 1000 discs of
// radius 1 on 118.16 x 88.62 (eta = 0.300, g = 1.772, kT = 0.517 ... 0.559,
// mean 0.542; `random 1000 SEED 1`, SEED 701 ... 740, T0 = 50): tau_int =
// 2.58 time units (mean free time 1.13). The spread over the seeds of
// mean_speed_average / sqrt(kT) at T = 1000 (W = 872): 4.91e-4 measured,
// 4.64e-4 predicted; at T = 400 (W = 272): 8.75e-4 against 8.28e-4. Both
// ratios 1.06, within the 11 % a spread of 40 seeds is known to. The
// exponential model also gives the autocorrelation of the mean speed over
// single time units that data/reports/kinetic-seeds.md measured: 0.779,
// 0.529, 0.359, 0.166 at lags 1, 2, 3, 5 (measured 0.773, 0.516, 0.345,
// 0.162), and the square root of the statistical inefficiency over W,
// 2.39 to 2.42 for W = 100 ... 1300 (measured 2.05 ... 2.52).
#include "beyond/speed_relaxation.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "beyond/hard_disc_fluid.hpp"

namespace gas {

namespace {

constexpr double not_known = std::numeric_limits<double>::quiet_NaN();
constexpr int order_count = speed_sonine_order_limit - 1;  // p = 2 ... limit

// r_pq = <L_p (-L) L_q> / (n g s sqrt(kT) sqrt(pi)) for 2 <= p <= q <= the
// limit, row by row (section 2 above): the exact rationals.
// clang-format off
constexpr std::array<double, order_count * (order_count + 1) / 2> upper_rows = {
    // p = 2, q = 2 ... 10
    1.0, -1.0 / 4, -1.0 / 32, -1.0 / 128, -5.0 / 2048, -7.0 / 8192, -21.0 / 65536,
    -33.0 / 262144, -429.0 / 8388608,
    // p = 3, q = 3 ... 10
    27.0 / 16, -59.0 / 128, -33.0 / 512, -147.0 / 8192, -203.0 / 32768, -623.0 / 262144,
    -1017.0 / 1048576, -13827.0 / 33554432,
    // p = 4, q = 4 ... 10
    2305.0 / 1024, -2635.0 / 4096, -6299.0 / 65536, -7517.0 / 262144,
    -22219.0 / 2097152, -36395.0 / 8388608, -505875.0 / 268435456,
    // p = 5, q = 5 ... 10
    44915.0 / 16384, -211155.0 / 262144, -131887.0 / 1048576, -330431.0 / 8388608,
    -513125.0 / 33554432, -7062275.0 / 1073741824,
    // p = 6, q = 6 ... 10
    13345689.0 / 4194304, -15983429.0 / 16777216, -20609463.0 / 134217728,
    -26766963.0 / 536870912, -345354655.0 / 17179869184,
    // p = 7, q = 7 ... 10
    240604539.0 / 67108864, -584256393.0 / 536870912, -385812567.0 / 2147483648,
    -4122564501.0 / 68719476736,
    // p = 8, q = 8 ... 10
    17007167097.0 / 4294967296, -20865292767.0 / 17179869184,
    -112319122575.0 / 549755813888,
    // p = 9, q = 9 ... 10
    296241032835.0 / 68719476736, -2931523875555.0 / 2199023255552,
    // p = 10, q = 10 ... 10
    326685872126185.0 / 70368744177664,
};
// clang-format on

// (-1/2)_p / p!, the coefficient of x^(1/2) on L_p over Gamma(3/2).
double half_coefficient(int p) {
  double value = 1;
  for (int k = 0; k < p; ++k) value *= (k - 0.5) / (k + 1);
  return value;
}

// Solves the symmetric positive system a y = b (n by n, row-major) by
// Cholesky's factorisation; returns y.
std::vector<double> solve_positive(std::vector<double> a, std::vector<double> b, int n) {
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k < j; ++k) a[j * n + j] -= a[j * n + k] * a[j * n + k];
    a[j * n + j] = std::sqrt(a[j * n + j]);
    for (int i = j + 1; i < n; ++i) {
      for (int k = 0; k < j; ++k) a[i * n + j] -= a[i * n + k] * a[j * n + k];
      a[i * n + j] /= a[j * n + j];
    }
  }
  for (int i = 0; i < n; ++i) {  // L z = b
    for (int k = 0; k < i; ++k) b[i] -= a[i * n + k] * b[k];
    b[i] /= a[i * n + i];
  }
  for (int i = n - 1; i >= 0; --i) {  // L^T y = z
    for (int k = i + 1; k < n; ++k) b[i] -= a[k * n + i] * b[k];
    b[i] /= a[i * n + i];
  }
  return b;
}

}  // namespace

double speed_shape_variance() {
  return 2 - 5 * std::numbers::pi / 8;
}

double speed_sonine_coefficient(int p) {
  if (p < 0) return not_known;
  return std::sqrt(std::numbers::pi / 2) * half_coefficient(p);
}

double sonine_collision_element(int p, int q) {
  if (p < 0 || q < 0 || p > speed_sonine_order_limit || q > speed_sonine_order_limit)
    return not_known;
  if (p < 2 || q < 2) return 0;
  if (p > q) std::swap(p, q);
  // Row p - 2 of the upper triangle starts after the rows above it.
  const int row = p - 2, column = q - 2;
  const int start = row * order_count - row * (row - 1) / 2;
  return std::sqrt(std::numbers::pi) * upper_rows[start + column - row];
}

double speed_relaxation_sonine(int order) {
  if (order < 2 || order > speed_sonine_order_limit) return not_known;
  const int n = order - 1;
  std::vector<double> m(n * n), c(n);
  for (int i = 0; i < n; ++i) {
    c[i] = speed_sonine_coefficient(i + 2);
    for (int j = 0; j < n; ++j) m[i * n + j] = sonine_collision_element(i + 2, j + 2);
  }
  const std::vector<double> y = solve_positive(m, c, n);
  double form = 0;  // c^T M^-1 c = <psi (-L)^-1 psi> / (kT / (n g s sqrt(kT)))
  for (int i = 0; i < n; ++i) form += c[i] * y[i];
  return form / speed_shape_variance();
}

SonineLimit speed_relaxation_limit() {
  static const SonineLimit limit = [] {
    const int last = speed_sonine_order_limit;
    const double k2 = speed_relaxation_sonine(last - 2);
    const double k1 = speed_relaxation_sonine(last - 1);
    const double k0 = speed_relaxation_sonine(last);
    const double step = k0 - k1, before = k1 - k2;
    // The local exponent of the steps, d_P ~ P^-beta.
    const double beta = std::log(before / step) / std::log(double(last) / (last - 1));
    // The sum over p > P of step (P / p)^beta, to p = 10^5 P: what it leaves
    // out is about P / (beta - 1) (10^5)^(1 - beta), below 1e-10 of the value
    // for beta > 3.
    double tail = 0;
    for (double p = last + 1; p <= 1e5 * last; ++p) tail += std::pow(last / p, beta);
    return SonineLimit{k0 + step * tail, step * tail};
  }();
  return limit;
}

MeanSpeedWander mean_speed_wander(double area_fraction, double radius, double kT,
                                  std::size_t balls, double duration) {
  MeanSpeedWander out{not_known, not_known, not_known, not_known, not_known};
  const double g = hard_disc_fluid_contact_value(area_fraction);
  if (!(area_fraction > 0) || std::isnan(g) || !(radius > 0) || !(kT > 0) || balls < 2)
    return out;
  const double pi = std::numbers::pi;
  const double density = area_fraction / (pi * radius * radius);
  const double rate = density * g * 2 * radius * std::sqrt(kT);  // n g s sqrt(kT)
  const double n = static_cast<double>(balls);
  out.instant_spread = std::sqrt(speed_shape_variance() * kT / n);
  out.collision_time = 1 / (2 * std::sqrt(pi) * rate);
  out.relaxation_time = speed_relaxation_limit().value / rate;
  if (!(duration > 0)) return out;
  const double tau = out.relaxation_time, ratio = tau / duration, y = duration / tau;
  // (2 tau / W)(1 - (tau / W)(1 - exp(-W / tau))) = (2 / y^2)(y - 1 + e^-y),
  // y = W / tau; below y = 1e-3 its series 1 - y / 3 + y^2 / 12 (the next
  // term, y^3 / 60, is below 2e-11), where the closed form cancels.
  const double factor =
      y < 1e-3 ? 1 - y / 3 + y * y / 12 : 2 / (y * y) * (y + std::expm1(-y));
  out.error = out.instant_spread * std::sqrt(factor);
  out.long_time_error = out.instant_spread * std::sqrt(2 * ratio);
  return out;
}

}  // namespace gas
