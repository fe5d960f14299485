// Tests for the box's sound and heat (stages/beyond/box_modes.*;
// lessons/14-error-bars.md): the time average's factors against a direct
// integral, the sum over waves against Parseval's theorem and against one
// wave written out by hand.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "beyond/box_modes.hpp"

namespace {

constexpr double pi = std::numbers::pi;

// (2 / W^2) integral_0^W (W - t) C(t) dt by Simpson's rule on `steps`
// intervals: the definition, integrated without the closed forms.
double averaged_by_simpson(const std::function<double(double)>& correlation,
                           double duration, int steps) {
  const double h = duration / steps;
  double sum = 0;
  for (int i = 0; i <= steps; ++i) {
    const double t = i * h;
    const double weight = (i == 0 || i == steps) ? 1 : (i % 2 == 1 ? 4 : 2);
    sum += weight * (duration - t) * correlation(t);
  }
  return 2 * (sum * h / 3) / (duration * duration);
}

// A fluid with sound and heat of comparable strength (the numbers of eta =
// 0.3, kT = 1/2 in round figures; the sums do not care which).
gas::BoxHydrodynamics test_fluid() {
  gas::BoxHydrodynamics f;
  f.density = 0.1;
  f.kT = 0.5;
  f.structure_factor = 0.25;
  f.heat_capacity_ratio = 2.1;
  f.sound_speed = 2.1;
  f.thermal_diffusivity = 4.2;
  f.sound_attenuation = 3.7;
  return f;
}

}  // namespace

TEST_CASE("box modes: the time average's factors are the integral they stand for") {
  // Simpson's relative error is about (h / scale)^4 / 180, the scale the
  // shortest of tau, 1 / omega: with 400000 intervals at most (0.01)^4 / 180
  // = 6e-11 here (tau = 0.5 over W = 2000). 1e-9 holds that and the closed
  // forms' rounding (1e-12 measured), and fails for any wrong term.
  for (const double tau : {0.5, 40.0, 300.0})
    for (const double w : {1.0, 30.0, 270.0, 2000.0}) {
      const double direct =
          averaged_by_simpson([tau](double t) { return std::exp(-t / tau); }, w, 400000);
      CHECK(gas::averaged_decay(tau, w) == doctest::Approx(direct).epsilon(1e-9));
    }
  for (const double alpha : {0.01, 0.3})
    for (const double omega : {0.05, 0.2, 1.3})
      for (const double w : {5.0, 45.0, 400.0}) {
        auto ringing = [=](double t) {
          return std::cos(omega * t) * std::exp(-alpha * t);
        };
        const double direct = averaged_by_simpson(ringing, w, 400000);
        CHECK(gas::averaged_ringing(alpha, omega, w) ==
              doctest::Approx(direct).epsilon(1e-9));
      }
  // The limits: a moment keeps the whole variance (less W / (3 tau), or
  // alpha W / 3 ringing: 3e-6 here, inside 1e-5), a long run 2 tau / W and,
  // ringing, 2 alpha / ((alpha^2 + omega^2) W) (the integral of C; what the
  // closed forms add beyond it is of order tau / W = 2e-6, inside 1e-5 and
  // 1e-4).
  CHECK(gas::averaged_decay(50, 1e-4) == doctest::Approx(1).epsilon(1e-5));
  CHECK(gas::averaged_ringing(0.1, 0.5, 1e-4) == doctest::Approx(1).epsilon(1e-5));
  CHECK(gas::averaged_decay(2, 1e6) == doctest::Approx(4e-6).epsilon(1e-5));
  CHECK(gas::averaged_ringing(0.1, 0.5, 1e6) ==
        doctest::Approx(2 * 0.1 / (0.26 * 1e6)).epsilon(1e-4));
}

TEST_CASE("box modes: a moment's average holds the interior's whole static wander") {
  // Over all waves, sum P^2 / |phi|^2 is Parseval's: the integral of the
  // interior's indicator squared, A_int, less the whole-box wave's share,
  // A_int^2 / (L1 L2). So for W -> 0 Var(N_int) = n S(0) A_int (1 - A_int /
  // (L1 L2)), whatever the heat's share; Var(X_int) the same with n kT^2.
  // The sum stops at k_max; an edge's waves fall as 1 / k^2, so the rest is
  // of order (edge length) / (pi^2 k_max): with k_max = 60 / a on this
  // table, 0.2 % of the whole (0.1 % of the error). 0.5 % of the error
  // holds that and fails for a norm or projection wrong by a factor.
  const gas::BoxHydrodynamics f = test_fluid();
  const double a = 1, width = 22, height = 17;  // L1 = 20, L2 = 15
  const gas::Region interior{6, 16, 5, 12};     // 10 x 7, off centre
  const gas::InteriorWander w =
      gas::interior_wander(f, a, width, height, interior, 1e-7, 60 / a);
  const double area = 70, box = 300;
  const double static_count = f.density * f.structure_factor * area * (1 - area / box);
  CHECK(w.area_fraction ==
        doctest::Approx(pi * a * a / area * std::sqrt(static_count)).epsilon(5e-3));
  const double static_energy = f.density * f.kT * f.kT * area * (1 - area / box);
  CHECK(w.kT ==
        doctest::Approx(std::sqrt(static_energy) / (f.density * area)).epsilon(5e-3));
}

TEST_CASE("box modes: two waves written out by hand") {
  // A long narrow table: with k_max between 2 pi / L1 and pi / L2 only the
  // waves (1, 0) and (2, 0) enter; the interior centred in x, so (1, 0)
  // gives nothing. (2, 0): P = (sin(k u1) - sin(k u0)) / k times the
  // interior's height, |phi|^2 = (L1 / 2) L2.
  const gas::BoxHydrodynamics f = test_fluid();
  const double a = 1, width = 102, height = 32;  // L1 = 100, L2 = 30
  const gas::Region interior{21, 81, 9, 24};     // u 20 ... 80, v 8 ... 23
  const double k = 2 * pi / 100, w = 270;
  const gas::InteriorWander got =
      gas::interior_wander(f, a, width, height, interior, w, 0.07);
  const double p = (std::sin(k * 80) - std::sin(k * 20)) / k * 15;
  const double weight = p * p / (50.0 * 30.0);
  const double heat = gas::averaged_decay(1 / (f.thermal_diffusivity * k * k), w);
  const double sound =
      gas::averaged_ringing(f.sound_attenuation * k * k, f.sound_speed * k, w);
  const double g = f.heat_capacity_ratio;
  const double count = weight * ((1 - 1 / g) * heat + sound / g);
  const double energy = weight * (heat / g + (1 - 1 / g) * sound);
  const double area = 60 * 15;
  // Both sides add the same few terms: agreement to rounding (1e-12).
  CHECK(got.area_fraction ==
        doctest::Approx(pi / area * std::sqrt(f.density * f.structure_factor * count))
            .epsilon(1e-12));
  CHECK(got.kT ==
        doctest::Approx(std::sqrt(f.density * f.kT * f.kT * energy) / (f.density * area))
            .epsilon(1e-12));
  // Heat and sound are weighed differently for the two figures: with no heat
  // share (gamma = 1) the count is all sound, the energy all heat.
  gas::BoxHydrodynamics plain = f;
  plain.heat_capacity_ratio = 1;
  const gas::InteriorWander only =
      gas::interior_wander(plain, a, width, height, interior, w, 0.07);
  CHECK(only.area_fraction ==
        doctest::Approx(pi / area *
                        std::sqrt(f.density * f.structure_factor * weight * sound))
            .epsilon(1e-12));
  CHECK(only.kT == doctest::Approx(std::sqrt(f.density * f.kT * f.kT * weight * heat) /
                                   (f.density * area))
                       .epsilon(1e-12));
}

TEST_CASE(
    "box modes: heat pulls the interior's density and warmth apart, sound together") {
  // The table of the test above, one wave (2, 0): its heat part moves the
  // count and the energy exactly opposite ways, its sound part the same way,
  // so Corr = sqrt(gamma - 1) (sound - heat) / sqrt(((gamma - 1) heat +
  // sound) (heat + (gamma - 1) sound)), written out here (agreement to
  // rounding, 1e-12).
  const gas::BoxHydrodynamics f = test_fluid();
  const double a = 1, width = 102, height = 32;
  const gas::Region interior{21, 81, 9, 24};
  const double k = 2 * pi / 100, g = f.heat_capacity_ratio;
  for (const double w : {3.0, 30.0, 270.0}) {
    const double heat = gas::averaged_decay(1 / (f.thermal_diffusivity * k * k), w);
    const double sound =
        gas::averaged_ringing(f.sound_attenuation * k * k, f.sound_speed * k, w);
    const double expected =
        std::sqrt(g - 1) * (sound - heat) /
        std::sqrt(((g - 1) * heat + sound) * (heat + (g - 1) * sound));
    CHECK(gas::interior_wander(f, a, width, height, interior, w, 0.07).correlation ==
          doctest::Approx(expected).epsilon(1e-12));
  }
  // Many waves. A moment holds both parts whole: no correlation (each
  // ball's energy is its own, whatever the count; left over O(W k^2 D_T),
  // 1e-6 here). A long run keeps mostly the heat, which forgets slowest:
  // nearly -1 (the sound's share of a wave's integral is of order D_T Gamma
  // k^2 / c^2, at most 0.2 up to k = 0.07 / a here, less for the long waves
  // that carry the sum; -0.9 holds with room and fails for a wrong sign).
  const gas::Region middle{6, 16, 5, 12};
  CHECK(std::abs(gas::interior_wander(f, 1, 22, 17, middle, 1e-7, 60).correlation) <
        1e-4);
  const gas::InteriorWander long_run =
      gas::interior_wander(f, a, width, height, interior, 1e6, 0.07);
  CHECK(long_run.correlation < -0.9);
  CHECK(long_run.correlation >= -1);
}

TEST_CASE("box modes: a figure that follows the interior's density and warmth") {
  // d ln f = p d ln eta_int + q d ln kT_int: the relative errors add with
  // their correlation, (p e_eta / eta)^2 + (q e_kT / kT)^2 + 2 rho p q
  // (e_eta / eta)(e_kT / kT). Plain arithmetic on both sides: 1e-12.
  gas::InteriorWander w;
  w.area_fraction = 0.003;  // of eta = 0.3: 1 %
  w.kT = 0.01;              // of kT = 0.5: 2 %
  w.correlation = -0.6;
  CHECK(gas::following_wander(w, 0.3, 0.5, 1.7, 0) ==
        doctest::Approx(0.017).epsilon(1e-12));
  CHECK(gas::following_wander(w, 0.3, 0.5, 0, 0.5) ==
        doctest::Approx(0.01).epsilon(1e-12));
  const double both = std::sqrt(0.017 * 0.017 + 0.01 * 0.01 - 2 * 0.6 * 0.017 * 0.01);
  CHECK(gas::following_wander(w, 0.3, 0.5, 1.7, 0.5) ==
        doctest::Approx(both).epsilon(1e-12));
  // Perfectly anticorrelated and equal shares cancel (to rounding, never
  // below zero).
  w.correlation = -1;
  CHECK(gas::following_wander(w, 0.3, 0.5, 1, 0.5) < 1e-9);
}

TEST_CASE(
    "box modes: nothing to say without an interior, a duration, or sound and heat") {
  const gas::BoxHydrodynamics f = test_fluid();
  CHECK(std::isnan(gas::interior_wander(f, 1, 22, 17, gas::Region{}, 100).area_fraction));
  CHECK(std::isnan(gas::interior_wander(f, 1, 22, 17, {6, 16, 5, 12}, 0).kT));
  gas::BoxHydrodynamics still = f;
  still.thermal_diffusivity = 0;
  CHECK(std::isnan(gas::interior_wander(still, 1, 22, 17, {6, 16, 5, 12}, 100).kT));
}

TEST_CASE("box modes: the run's batches take the place of the theory's short part") {
  // Batches that say what the theory expects of them leave the theory's
  // error as it is; batches that see more add the difference to its square.
  const double whole = 0.02, one = 0.09, all = 0.021, n = 20;
  const double expected = std::sqrt((one * one - all * all) / (n - 1));
  CHECK(gas::corrected_by_batches(whole, one, all, n, expected) ==
        doctest::Approx(whole).epsilon(1e-14));
  const double more = 1.5 * expected;
  CHECK(gas::corrected_by_batches(whole, one, all, n, more) ==
        doctest::Approx(std::sqrt(whole * whole + more * more - expected * expected))
            .epsilon(1e-14));
  CHECK(std::isnan(gas::corrected_by_batches(whole, one, all, 1, expected)));
}
