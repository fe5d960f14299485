// Tests for the statistics screen's physics (stages/beyond/kinetic_theory.*,
// lessons/12-statistics-screen.md, 13-box-and-bulk.md, 14-error-bars.md): the
// gas, run by the program's own stages, against kinetic theory.
//
// - The formulas themselves: the 2D Maxwell-Boltzmann mean, Henderson's Z
//   and g(2a) through the virial theorem, Enskog's rate through the contact
//   relation; the mean speed of N balls at fixed energy against its density
//   and against points drawn on the sphere.
// - One ball: the wall push gives P (A1 - 2a)(A2 - 2a) = N kT exactly.
// - A gas started with every ball at one speed relaxes to 2D Maxwell-
//   Boltzmann: a Kolmogorov-Smirnov test on speeds sampled at well-separated
//   times, and the mean speed; the default scene's 7 balls keep the mean
//   speed of fixed energy, not Maxwell's.
// - The warm-up: L / lambda collisions of two balls a ball, kept.
// - The equation of state at area fractions 0.1, 0.3 and 0.5, in the
//   interior of a box of 1024 balls: Z against the reference at the
//   interior's density, and the interior's collision rate against Enskog's
//   there, each by its difference sample by sample; the box's Z from its
//   walls and from its collisions (the virial theorem) and the contact
//   relation; g(2a+) and the contact theorem at the walls.
// - The H-theorem and its reversal by B; the interior's time across B.
//
// Every run is seeded (the lattice start and the directions), so the checks
// give the same result every time; the tolerances are statistical, from the
// run lengths, and each comment says how. Each test takes about a second or
// less in a Release build.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "beyond/boltzmann_h.hpp"
#include "beyond/box_modes.hpp"
#include "beyond/display_steps.hpp"
#include "beyond/enskog_transport.hpp"
#include "beyond/gas_statistics.hpp"
#include "beyond/hard_disc_fluid.hpp"
#include "beyond/kinetic_theory.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/speed_relaxation.hpp"
#include "beyond/strategy.hpp"
#include "beyond/wall_push.hpp"
#include "program/console.hpp"
#include "stage7_control.hpp"

namespace {

using gas::Average;
using gas::Control;
using gas::Gas;
using gas::GasStatistics;
constexpr double pi = std::numbers::pi;

// A table `width` x `height` with no balls yet, radius 1; take_step's time
// limit decides every step.
Gas bare_table(double width, double height) {
  Gas g;
  g.radius = 1;
  g.width = width;
  g.height = height;
  g.display_step = 1e9;
  return g;
}

// side x side balls of radius 1 on a square lattice, in the middle of the
// cells of a square table sized for the area fraction `eta` (N pi / A1^2 =
// eta), every ball at speed 1 in a random direction: a start as far from
// Maxwell-Boltzmann as one likes (every speed the same).
Gas lattice_gas(int side, double eta, unsigned seed) {
  const int n = side * side;
  const double length = std::sqrt(n * pi / eta);
  Gas g = bare_table(length, length);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> angle(0, 2 * pi);
  const double cell = g.width / side;  // > 2a for eta < pi / 4
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const double a = angle(random);
      g.balls.push_back(
          {(i + 0.5) * cell, (j + 0.5) * cell, std::cos(a), std::sin(a), 0});
    }
  }
  return g;
}

// A run of stage 7 with kinetic theory's statistics on its hook, as the
// program runs it: every figure kept up to date collision by collision, from
// the moment start_statistics is called.
struct ObservedRun {
  Control control;
  std::optional<GasStatistics> statistics;
  explicit ObservedRun(Gas g) : control(gas::start_control_for(std::move(g))) {}
  ObservedRun(const ObservedRun&) = delete;
  ObservedRun& operator=(const ObservedRun&) = delete;
  GasStatistics& start_statistics(int bins, bool warm_up = true) {
    statistics.emplace(control.gas, bins, warm_up);
    control.observer = &*statistics;
    return *statistics;
  }
};

// Runs the gas to `time` with no picture on the way (the statistics need
// none: they hear of every collision through the hook).
void run_until(Control& control, double time) {
  while (control.gas.time < time) gas::take_display_step(control, time, nullptr);
}

// What one run measured, after the statistics' own warm-up, over `length`
// time units: a side x side lattice at area fraction eta.
struct Measured {
  double kT = 0;
  gas::MeasuredFigures m;
  double z_from_rate = 0, z_from_rate_error = 0;  // the contact relation
};

Measured measure_run(int side, double eta, double length, unsigned seed) {
  ObservedRun run(lattice_gas(side, eta, seed));
  Control& control = run.control;
  const GasStatistics& statistics = run.start_statistics(10);
  run_until(control, length);
  Measured r;
  r.kT = gas::kinetic_energy(control.gas) / (side * side);
  r.m = statistics.measured(control.gas);
  // Contact relation (lesson 12): Z - 1 = rate * s * sqrt(pi m / kT) / 4.
  const double factor = 2 * control.gas.radius * std::sqrt(pi / r.kT) / 4;
  r.z_from_rate = 1 + factor * r.m.collision_rate_box.value;
  r.z_from_rate_error = factor * r.m.collision_rate_box.error;
  return r;
}

// A time of the table (`time_of`: table_heat_time, say) is not known (NaN)
// for one ball of `gas`, or for its balls at rest.
void check_none_for_one_ball_or_rest(double (*time_of)(const Gas&), const Gas& gas) {
  Gas one = gas;
  one.balls.resize(1);
  CHECK(std::isnan(time_of(one)));
  Gas still = gas;
  for (gas::Ball& b : still.balls) b.vx = b.vy = 0;
  CHECK(std::isnan(time_of(still)));
}

// The Kolmogorov-Smirnov distance between the speeds and 2D Maxwell-
// Boltzmann at kT.
double ks_distance(std::vector<double> speeds, double kT) {
  std::sort(speeds.begin(), speeds.end());
  const auto n = static_cast<double>(speeds.size());
  double d = 0;
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double f = gas::maxwell_fraction_below(speeds[i], kT);
    d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
  }
  return d;
}

// The equation of state of the bulk, measured in the interior of a box of
// 1024 balls, against the reference at the interior's own density; the box's
// own Z from its walls and from its collisions, which must agree; and the
// interior denser than N / A (N / A counts the strip of width a along each
// wall, where no centre goes; lesson 13). `length`: time units for about 10^6 collisions.
void check_equation_of_state(double eta, double length, unsigned seed) {
  const Measured r = measure_run(32, eta, length, seed);
  const gas::MeasuredFigures& m = r.m;
  const double eta_inside = m.interior_area_fraction.value;
  // The reference for a closed box of 1024 balls (kinetic_theory.hpp).
  const double reference = gas::fixed_count_compressibility(eta_inside, 1024);
  CAPTURE(eta);
  CAPTURE(eta_inside);
  CAPTURE(m.bulk_z.value);
  CAPTURE(m.bulk_z.error);
  CAPTURE(reference);
  CAPTURE(m.box_z_walls.value);
  CAPTURE(m.box_z_walls.error);
  CAPTURE(m.box_z_virial.value);
  CAPTURE(m.box_z_virial.error);
  // The bulk: Z - Z_ref(eta_inside) within three of its errors (below), the
  // error a real one, under 1 % (the reference's own accuracy, 0.1 %, is far
  // below it here). Z alone may have no error yet: it wanders slowly with
  // the interior's density (lesson 14).
  // The figures of the box wander with the table's heat and sound: these
  // runs are too short for their errors (rule 2 of blocking.hpp; at eta =
  // 0.1 the run just reaches it). What their batches say stands in for
  // them here: for the walls' push (sound, whose batch errors are too large
  // by up to 4 times at these lengths) a conservative figure, for the rest
  // within some tens of per cent.
  for (const gas::Average* slow : {&m.box_z_walls, &m.box_z_virial, &m.bulk_z}) {
    if (std::isnan(slow->error))
      CHECK((slow->status == gas::ErrorStatus::short_batches ||
             slow->status == gas::ErrorStatus::correlated_batches));
  }
  if (eta > 0.2) CHECK(m.bulk_z.status == gas::ErrorStatus::short_batches);
  // The box: walls and collisions give the same Z (the virial theorem for
  // the box), within three errors of their difference (the two are from one
  // run, so this is conservative).
  REQUIRE(std::isfinite(m.box_z_walls.batch_error));
  REQUIRE(std::isfinite(m.box_z_virial.batch_error));
  CHECK(std::abs(m.box_z_walls.value - m.box_z_virial.value) <=
        3 * std::hypot(m.box_z_walls.batch_error, m.box_z_virial.batch_error));
  // The contact relation holds for the box, walls and all (lesson 12).
  CHECK(std::abs(m.box_z_virial.value - r.z_from_rate) <=
        3 * std::hypot(m.box_z_virial.batch_error, r.z_from_rate_error));
  // The interior is denser than N / A (no centre enters the strip of width a
  // along each wall, lesson 13).
  CHECK(eta_inside > eta);
  // Like with like: the interior's collision rate (both balls of each
  // collision whose midpoint is inside, per ball-time inside) against
  // Enskog's at eta_inside, and Z against the reference, each within three
  // errors of the difference taken sample by sample (which carries eta's
  // error into the theory's side; lesson 14, "Errors that hold").
  CAPTURE(m.collision_rate.value);
  CAPTURE(m.collision_rate_minus_theory.value);
  CAPTURE(m.collision_rate_minus_theory.error);
  CAPTURE(m.bulk_z_minus_theory.value);
  CAPTURE(m.bulk_z_minus_theory.error);
  const double enskog = gas::enskog_collision_rate(eta_inside, 1, r.kT) *
                        gas::fixed_count_rate_factor(eta_inside, 1024);
  CHECK(m.collision_rate_minus_theory.value ==
        doctest::Approx(m.collision_rate.value - enskog).epsilon(0.01));
  REQUIRE(std::isfinite(m.collision_rate_minus_theory.error));
  CHECK(std::abs(m.collision_rate_minus_theory.value) <=
        3 * m.collision_rate_minus_theory.error);
  REQUIRE(std::isfinite(m.bulk_z_minus_theory.error));
  CHECK(m.bulk_z_minus_theory.error < 0.01 * reference);
  CHECK(m.bulk_z_minus_theory.value == doctest::Approx(m.bulk_z.value - reference));
  CHECK(std::abs(m.bulk_z_minus_theory.value) <= 3 * m.bulk_z_minus_theory.error);
  // The whole box's rate is another thing: at eta = 0.5 the walls' layers
  // lower it by about 1 %, tens of its errors.
  if (eta > 0.4) CHECK(m.collision_rate_box.value < m.collision_rate.value);
  // The structure at contact: g(2a+) among the balls of the interior against
  // the reference's (Z - 1) / (2 eta) at eta_inside, within three errors
  // (the fit at contact is biased by some 0.02 % at eta = 0.5, lesson 14).
  CAPTURE(m.pair_contact.value);
  CAPTURE(m.pair_contact.error);
  const double g_reference = gas::hard_disc_fluid_contact_value(eta_inside);
  REQUIRE(std::isfinite(m.pair_contact.error));
  CHECK(std::abs(m.pair_contact.value - g_reference) <= 3 * m.pair_contact.error);
  // The same three sample by sample (snapshot by snapshot for g): the
  // walls' middles' push against the bulk's P = Z_ref n_int kT_int, the free
  // path against Enskog's, g(2a+) against the reference at each snapshot's
  // own eta_int. Each the difference of the whole run's figures (g: to
  // within a fifth of its error, the snapshots' eta_int wandering about the
  // run's), each within three of its own error.
  CAPTURE(m.pressure_minus_theory.value);
  CAPTURE(m.pressure_minus_theory.error);
  CAPTURE(m.mean_free_path_minus_theory.value);
  CAPTURE(m.mean_free_path_minus_theory.error);
  CAPTURE(m.pair_contact_minus_theory.value);
  CAPTURE(m.pair_contact_minus_theory.error);
  // (The pressure's theory sample by sample is the reference in the strips
  // in front of the walls' middles, at their own eta and kT.)
  const double eta_beside = m.beside_walls_eta.value;
  const double pressure_beside = gas::fixed_count_compressibility(eta_beside, 1024) *
                                 eta_beside * m.beside_walls_kT.value / std::numbers::pi;
  CHECK(m.pressure_minus_theory.value ==
        doctest::Approx(m.wall_middle_pressure.value - pressure_beside));
  // Those strips are the bulk: their density is the interior's, within
  // three of the strips' own error (the strips are part of the interior,
  // whose error is some ten times smaller: the strips' alone counts). On
  // these runs 0.2, 1.6 and 0.8 errors at 0.1, 0.3 and 0.5; a strip's area
  // counted once instead of twice would be 100 % off.
  CAPTURE(eta_beside);
  CAPTURE(m.beside_walls_eta.batch_error);
  REQUIRE(std::isfinite(m.beside_walls_eta.batch_error));
  CHECK(std::abs(eta_beside - eta_inside) <= 3 * m.beside_walls_eta.batch_error);
  CHECK(m.mean_free_path_minus_theory.value ==
        doctest::Approx(m.mean_free_path.value -
                        gas::enskog_mean_free_path(eta_inside, 1) /
                            gas::fixed_count_rate_factor(eta_inside, 1024)));
  for (const gas::Average& difference :
       {m.mean_free_path_minus_theory, m.pair_contact_minus_theory}) {
    REQUIRE(std::isfinite(difference.error));
    CHECK(std::abs(difference.value) <= 3 * difference.error);
  }
  // The push on the walls' middles follows the sound across the table
  // (its samples anticorrelated over a crossing): Jonsson's test may see its
  // batches correlated (at eta = 0.5 here), and then what they say, too
  // large an error for an anticorrelated series, stands in.
  const gas::Average& pushed = m.pressure_minus_theory;
  const double pushed_error =
      std::isfinite(pushed.error) ? pushed.error : pushed.batch_error;
  CAPTURE(pushed.status);
  REQUIRE(std::isfinite(pushed_error));
  CHECK(std::abs(pushed.value) <= 3 * pushed_error);
  CHECK(
      std::abs(m.pair_contact_minus_theory.value - (m.pair_contact.value - g_reference)) <
      0.2 * m.pair_contact_minus_theory.error);
  // The contact theorem: the density of centres at a wall times kT is the
  // pressure on it (the walls' middles, away from the corners). The
  // snapshots' strips hold a few balls each, so on these runs the contact
  // density's error is 2 to 3 % and three errors resolve some 6 to 7 %: a
  // strip 15 % off fails, one 5 % off does not (data/eos-0.5.scene, four
  // times the balls and longer, resolves 2 %: lesson 13).
  CAPTURE(m.wall_contact_pressure.value);
  CAPTURE(m.wall_contact_pressure.error);
  CAPTURE(m.wall_middle_pressure.value);
  CAPTURE(m.wall_middle_pressure.batch_error);
  REQUIRE(std::isfinite(m.wall_contact_pressure.error));
  REQUIRE(std::isfinite(m.wall_middle_pressure.batch_error));
  CHECK(
      std::abs(m.wall_contact_pressure.value - m.wall_middle_pressure.value) <=
      3 * std::hypot(m.wall_contact_pressure.error, m.wall_middle_pressure.batch_error));
}

}  // namespace

TEST_SUITE("kinetic-theory") {
  TEST_CASE("the closed box's shift of Z: Lebowitz and Percus, worked out again") {
    // kinetic_theory.hpp: dZ = -Var(N) (dn/dN)^2 w''(n) / (2 n kT), w = P - n kT,
    // Var(N) = N kT dn/dP of the open box, dn/dN = n / N. Here each piece
    // from the reference's Z alone, by central differences in the density n
    // (discs of radius 1, kT = 1): w(n) = n (Z(pi n) - 1), P(n) = n Z(pi n).
    // (Step 1e-5 of n: the differences' own errors, h^2 w'''' / 12 and
    // rounding 1e-16 / h^2 of w, are some 1e-7 of the shift.)
    auto w = [](double n) {
      return n * (gas::hard_disc_fluid_compressibility(pi * n) - 1);
    };
    auto p = [](double n) { return n * gas::hard_disc_fluid_compressibility(pi * n); };
    for (const double eta : {0.05, 0.1, 0.3, 0.45, 0.6}) {
      for (const std::size_t balls : {256, 1024}) {
        const double n = eta / pi, h = 1e-5 * n;
        const double w2 = (w(n + h) - 2 * w(n) + w(n - h)) / (h * h);
        const double dp_dn = (p(n + h) - p(n - h)) / (2 * h);
        const double count = static_cast<double>(balls);
        const double variance = count / dp_dn;  // N kT dn/dP
        const double dn_dN = n / count;
        const double expected = -variance * dn_dN * dn_dN * w2 / (2 * n);
        CAPTURE(eta);
        CAPTURE(balls);
        CHECK(gas::fixed_count_shift(eta, balls) ==
              doctest::Approx(expected).epsilon(1e-5));
        CHECK(gas::fixed_count_compressibility(eta, balls) ==
              gas::hard_disc_fluid_compressibility(eta) +
                  gas::fixed_count_shift(eta, balls));
        // The rate's factor is the shift on Z - 1 (w = kT n (Z - 1)).
        CHECK(gas::fixed_count_rate_factor(eta, balls) ==
              doctest::Approx(1 +
                              expected / (gas::hard_disc_fluid_compressibility(eta) - 1))
                  .epsilon(1e-5));
      }
    }
    // At low density, N - 1 partners instead of N: dZ = -2 eta / N (to
    // order eta^2: 1e-4 of it at eta = 1e-4), the rate's factor 1 - 1 / N.
    CHECK(gas::fixed_count_shift(1e-4, 256) ==
          doctest::Approx(-2e-4 / 256).epsilon(1e-3));
    CHECK(gas::fixed_count_rate_factor(0, 256) == 1 - 1.0 / 256);
    CHECK(gas::fixed_count_rate_factor(1e-6, 256) ==
          doctest::Approx(1 - 1.0 / 256).epsilon(1e-6));
    // Its size where the seeds check it (data/reports/kinetic-seeds.md):
    // -0.0030 at eta = 0.3 and N = 256, a quarter of that at 1024.
    CHECK(gas::fixed_count_shift(0.3, 256) == doctest::Approx(-0.00302).epsilon(0.01));
    CHECK(gas::fixed_count_shift(0.3, 1024) ==
          doctest::Approx(gas::fixed_count_shift(0.3, 256) / 4));
    CHECK(gas::fixed_count_shift(0.3, 0) == 0);
    CHECK(std::isnan(gas::fixed_count_shift(0.8, 256)));
    // Near the fluid's end no shift: the open bulk's theory (at 0.69 the
    // formula would give +0.08 for N = 256, the wrong sign, from a
    // reference whose curvature has turned).
    CHECK(gas::fixed_count_shift(0.6, 256) < 0);
    CHECK(gas::fixed_count_shift(0.65, 256) == 0);
    CHECK(gas::fixed_count_rate_factor(0.69, 256) == 1);
  }

  TEST_CASE("the table's heat time: a wavelength of the longer side over lambda <v>") {
    // data/large-1000.scene: 1000 balls of radius 1 on 118.16 x 88.62.
    // Worked out by hand from its parts: eta = 1000 pi / (118.16 x 88.62),
    // lambda = 1 / (2 sqrt 2 (2a) n g(2a)), <v> = sqrt(pi kT / 2).
    const Gas gas = gas::read_scene_file(GAS_SOURCE_DIR "/data/large-1000.scene");
    const double kT = gas::kinetic_energy(gas) / 1000;
    const double eta = 1000 * pi / (118.16 * 88.62);
    const double n = eta / pi;
    const double path =
        1 / (2 * std::sqrt(2.0) * 2 * n * gas::hard_disc_fluid_contact_value(eta));
    const double wave = 118.16 / (2 * pi);
    const double expected = wave * wave / (path * std::sqrt(pi * kT / 2));
    CHECK(gas::table_heat_time(gas) == doctest::Approx(expected).epsilon(1e-12));
    // Some 370 time units (kT about 0.54 here).
    CHECK(gas::table_heat_time(gas) > 300);
    CHECK(gas::table_heat_time(gas) < 450);
    check_none_for_one_ball_or_rest(gas::table_heat_time, gas);
  }

  TEST_CASE("a table too narrow for an interior: its figures are not known") {
    // 22 x 60, radius 1: the interior would run from x = 12 to x = 10, so it
    // is empty, and every figure of it is NaN (not 1 for Z, not infinite for
    // eta: a flight's time in an empty region is 0, and no time inside, no
    // figure). The box's own figures are there.
    Gas g = bare_table(22, 60);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 8; ++j)
        g.balls.push_back(
            {5.0 + 6 * i, 5.0 + 7 * j, std::cos(i + 3.0 * j), std::sin(i + 3.0 * j), 0});
    ObservedRun run(g);
    const GasStatistics& statistics = run.start_statistics(10);
    run_until(run.control, 600);
    const gas::MeasuredFigures m = statistics.measured(run.control.gas);
    REQUIRE_FALSE(m.warming_up);
    CHECK(std::isnan(m.interior_area_fraction.value));
    CHECK(std::isnan(m.interior_kT.value));
    CHECK(std::isnan(m.bulk_z.value));
    CHECK(std::isnan(m.collision_rate.value));
    CHECK(std::isnan(m.mean_free_path.value));
    CHECK(std::isfinite(m.box_z_virial.value));
    CHECK(std::isfinite(m.mean_speed.value));
  }

  TEST_CASE(
      "the mean speed's shortest batch: 25 pair collisions per ball at Enskog's rate") {
    // data/large-1000.scene, by hand: rate = 2 (2a) n g(2a) sqrt(pi kT).
    const Gas gas = gas::read_scene_file(GAS_SOURCE_DIR "/data/large-1000.scene");
    const double kT = gas::kinetic_energy(gas) / 1000;
    const double eta = 1000 * pi / (118.16 * 88.62);
    const double rate =
        2 * 2 * (eta / pi) * gas::hard_disc_fluid_contact_value(eta) * std::sqrt(pi * kT);
    CHECK(gas::speeds_batch_time(gas) == doctest::Approx(25 / rate).epsilon(1e-12));
    CHECK(gas::speeds_batch_time(gas) > 20);  // some 28 time units
    CHECK(gas::speeds_batch_time(gas) < 40);
    check_none_for_one_ball_or_rest(gas::speeds_batch_time, gas);
  }

  TEST_CASE(
      "the mean speed's error waits for its own batches, not for the table's heat") {
    // data/large-1000.scene: the averages start after the warm-up (some 110
    // time units). Sixteen batches of speeds_batch_time (some 28) need some
    // 450 time units of averages, twice that at most (the batches are
    // powers of two samples long); sixteen of the heat time (some 370),
    // about 6000. At 250 time units of averages the mean speed's batches are
    // too short, and its error is kinetic theory's; at 1200 the batches' own,
    // while eta_int's still waits for the heat. (Without the batches' floor
    // theirs would show at 250; with the heat's, not at 1200.)
    ObservedRun run(gas::read_scene_file(GAS_SOURCE_DIR "/data/large-1000.scene"));
    Control& control = run.control;
    const GasStatistics& statistics = run.start_statistics(10);
    run_until(control, 150);
    const gas::MeasuredFigures at_start = statistics.measured(control.gas);
    REQUIRE_FALSE(at_start.warming_up);
    const double since = at_start.since;
    const double batch = gas::speeds_batch_time(control.gas);
    REQUIRE(16 * batch > 250);
    REQUIRE(2 * 16 * batch < 1200);
    run_until(control, since + 250);
    const gas::MeasuredFigures early = statistics.measured(control.gas);
    CAPTURE(early.mean_speed.batch_error);
    CHECK(early.mean_speed.from_theory);
    CHECK(early.mean_speed.status == gas::ErrorStatus::short_batches);
    run_until(control, since + 1200);
    const gas::MeasuredFigures later = statistics.measured(control.gas);
    CAPTURE(later.mean_speed.status);
    CHECK(std::isfinite(later.mean_speed.error));
    CHECK_FALSE(later.mean_speed.from_theory);
    CHECK(later.interior_area_fraction.status == gas::ErrorStatus::short_batches);
  }

  TEST_CASE(
      "the interior's slow figures: errors from the box's heat and sound, then from "
      "the batches") {
    // data/large-1000.scene after 263 time units of averages: the batches are
    // far shorter than the table's heat time, so eta_int, kT_int, Z, the
    // collision rate and the free path take their errors from the box's
    // waves (beyond/box_modes.hpp) over the time averaged, at the interior's
    // measured eta and the gas's kT, and Z's adds dZ/deta times eta_int's to
    // its difference from the reference's own; the short part of each is
    // what the run's batches say
    // (corrected_by_batches). Computed again here from those inputs, the
    // same sums give the same numbers to rounding (1e-12).
    ObservedRun run(gas::read_scene_file(GAS_SOURCE_DIR "/data/large-1000.scene"));
    Control& control = run.control;
    const GasStatistics& statistics = run.start_statistics(10);
    run_until(control, 150);
    const double since = statistics.measured(control.gas).since;
    run_until(control, since + 263);
    const gas::MeasuredFigures m = statistics.measured(control.gas);
    const Gas& g = control.gas;
    REQUIRE(m.interior_area_fraction.status == gas::ErrorStatus::short_batches);
    CHECK(m.interior_area_fraction.from_theory);
    CHECK(m.interior_kT.from_theory);
    CHECK(m.bulk_z.from_theory);
    const double eta = m.interior_area_fraction.value;
    const double kT = gas::kinetic_energy(g) / static_cast<double>(g.balls.size());
    const gas::EnskogTransport e = gas::enskog_transport(eta, g.radius, kT);
    gas::BoxHydrodynamics fluid;
    fluid.density = eta / (std::numbers::pi * g.radius * g.radius);
    fluid.kT = kT;
    const double slope = gas::hard_disc_fluid_compressibility_slope(eta);
    fluid.structure_factor =
        1 / (gas::hard_disc_fluid_compressibility(eta) + eta * slope);
    fluid.heat_capacity_ratio = e.heat_capacity_ratio;
    fluid.sound_speed = e.sound_speed;
    fluid.thermal_diffusivity = e.thermal_diffusivity;
    fluid.sound_attenuation = e.sound_attenuation;
    const double margin = gas::interior_margin_radii * g.radius;
    const gas::Region interior{margin, g.width - margin, margin, g.height - margin};
    auto wander = [&](double duration) {
      return gas::interior_wander(fluid, g.radius, g.width, g.height, interior, duration);
    };
    const gas::Average& eta_int = m.interior_area_fraction;
    REQUIRE(eta_int.batches >= 16);
    const gas::InteriorWander whole = wander(m.duration),
                              one = wander(eta_int.batch_time),
                              all = wander(eta_int.batches * eta_int.batch_time);
    const double eta_error = gas::corrected_by_batches(
        whole.area_fraction, one.area_fraction, all.area_fraction, eta_int.batches,
        eta_int.batch_error);
    CHECK(eta_int.error == doctest::Approx(eta_error).epsilon(1e-12));
    CHECK(m.interior_kT.error ==
          doctest::Approx(gas::corrected_by_batches(whole.kT, one.kT, all.kT,
                                                    eta_int.batches,
                                                    m.interior_kT.batch_error))
              .epsilon(1e-12));
    REQUIRE(std::isfinite(m.bulk_z_minus_theory.error));
    CHECK(m.bulk_z.error ==
          doctest::Approx(std::hypot(slope * eta_error, m.bulk_z_minus_theory.error))
              .epsilon(1e-12));
    // The collision rate and the free path follow eta_int and kT_int:
    // d ln rate = (1 + eta g'/g) d ln eta_int + d ln kT_int / 2, the free
    // path -(1 + eta g'/g) d ln eta_int; each over its own batches.
    const double eta_power = 1 + eta * gas::hard_disc_fluid_contact_value_slope(eta) /
                                     gas::hard_disc_fluid_contact_value(eta);
    auto following = [&](const gas::Average& figure, double of_eta, double of_kT) {
      auto relative = [&](double duration) {
        return figure.value *
               gas::following_wander(wander(duration), eta, kT, of_eta, of_kT);
      };
      return gas::corrected_by_batches(relative(m.duration), relative(figure.batch_time),
                                       relative(figure.batches * figure.batch_time),
                                       figure.batches, figure.batch_error);
    };
    REQUIRE(m.collision_rate.status == gas::ErrorStatus::short_batches);
    CHECK(m.collision_rate.from_theory);
    CHECK(m.collision_rate.error ==
          doctest::Approx(following(m.collision_rate, eta_power, 0.5)).epsilon(1e-12));
    CHECK(m.mean_free_path.from_theory);
    CHECK(m.mean_free_path.error ==
          doctest::Approx(following(m.mean_free_path, -eta_power, 0)).epsilon(1e-12));
    // The mean speed's batches (25 pair collisions per ball) do not fit
    // yet either: its error is kinetic theory's at the table's eta.
    REQUIRE(m.mean_speed.status == gas::ErrorStatus::short_batches);
    CHECK(m.mean_speed.from_theory);
    const double table_eta =
        1000 * std::numbers::pi * g.radius * g.radius / (g.width * g.height);
    CHECK(m.mean_speed.error ==
          doctest::Approx(
              gas::mean_speed_wander(table_eta, g.radius, kT, 1000, m.duration).error)
              .epsilon(1e-12));
    // The push on the walls' middles: the fluid's friction on them and the
    // box's sound (beyond/wall_push.hpp) at the interior's eta.
    REQUIRE(m.wall_middle_pressure.status == gas::ErrorStatus::short_batches);
    CHECK(m.wall_middle_pressure.from_theory);
    CHECK(m.wall_middle_pressure.error ==
          doctest::Approx(
              gas::middles_push_wander(fluid, {e.shear_viscosity, e.bulk_viscosity},
                                       g.radius, g.width, g.height,
                                       {interior.y_min, interior.y_max}, m.duration))
              .epsilon(1e-12));
    // The batches behind batch_error: 16 to 31 of them, filling the time
    // averaged but for less than one batch.
    CHECK(eta_int.batches <= 31);
    CHECK(eta_int.batches * eta_int.batch_time <= m.duration * (1 + 1e-12));
    CHECK((eta_int.batches + 1) * eta_int.batch_time > m.duration);
    // A table of 256 balls, whose heat time is short: once 16 batches that
    // long fit, the batches' own error stands and the theory steps back.
    ObservedRun small(lattice_gas(16, 0.3, 5));
    const GasStatistics& small_statistics = small.start_statistics(10);
    const double heat = gas::table_heat_time(small.control.gas);
    run_until(small.control, 150);
    const double small_since = small_statistics.measured(small.control.gas).since;
    run_until(small.control, small_since + 2 * 16 * heat);
    const gas::MeasuredFigures late = small_statistics.measured(small.control.gas);
    CAPTURE(late.interior_area_fraction.status);
    CHECK(late.interior_area_fraction.status != gas::ErrorStatus::short_batches);
    CHECK_FALSE(late.interior_area_fraction.from_theory);
    CHECK_FALSE(late.bulk_z.from_theory);
    CHECK_FALSE(late.mean_speed.from_theory);
    CHECK_FALSE(late.wall_middle_pressure.from_theory);
    CHECK_FALSE(late.collision_rate.from_theory);
    CHECK_FALSE(late.mean_free_path.from_theory);
  }

  TEST_CASE(
      "the formulas: 2D Maxwell-Boltzmann and Henderson and Enskog agree with each "
      "other") {
    // The mean of the Rayleigh density by the midpoint rule (steps of 1e-4
    // up to 12 sqrt(kT): truncation and step errors below 1e-8).
    for (const double kT : {0.5, 1.0, 3.0}) {
      double mean = 0, total = 0, square = 0;
      const double h = 1e-4 * std::sqrt(kT);
      for (double v = h / 2; v < 12 * std::sqrt(kT); v += h) {
        total += gas::maxwell_density(v, kT) * h;
        mean += v * gas::maxwell_density(v, kT) * h;
        square += v * v * gas::maxwell_density(v, kT) * h;
      }
      CHECK(total == doctest::Approx(1).epsilon(1e-8));
      CHECK(mean == doctest::Approx(std::sqrt(pi * kT / 2)).epsilon(1e-8));
      CHECK(square == doctest::Approx(2 * kT).epsilon(1e-8));
      CHECK(gas::maxwell_fraction_below(std::sqrt(2 * kT), kT) ==
            doctest::Approx(1 - std::exp(-1.0)));
    }
    // The virial theorem in 2D: Z = 1 + 2 eta g(2a).
    for (const double eta : {0.05, 0.3, 0.6}) {
      CHECK(gas::henderson_compressibility(eta) ==
            doctest::Approx(1 + 2 * eta * gas::henderson_contact_value(eta)));
    }
    CHECK(gas::henderson_compressibility(0.5) == 4.125);
    // A hand-made gas: Enskog's rate through the contact relation gives the
    // reference Z again, and the mean free path is 1 / (2 sqrt 2 s n g).
    Gas g;
    g.radius = 2;
    g.width = 100;
    g.height = 60;
    g.balls = {{10, 10, 3, 4, 0}, {50, 30, -1, 0, 0}, {80, 50, 0, 2, 0}};
    const gas::KineticTheory t = gas::kinetic_theory(g);
    CHECK(t.kT == doctest::Approx((25.0 + 1 + 4) / 2 / 3));
    CHECK(t.area_fraction == doctest::Approx(3 * pi * 4 / 6000));
    const double s = 4, n = 3.0 / 6000;
    const double rate = gas::enskog_collision_rate(t.area_fraction, g.radius, t.kT);
    CHECK(1 + rate * s * std::sqrt(pi / t.kT) / 4 == doctest::Approx(t.compressibility));
    CHECK(gas::enskog_mean_free_path(t.area_fraction, g.radius) ==
          doctest::Approx(1 / (2 * std::sqrt(2.0) * s * n * t.contact_value)));
    CHECK(gas::enskog_mean_free_path(t.area_fraction, g.radius) ==
          doctest::Approx(t.maxwell_mean_speed / rate));
    // The bulk's Z at the gas's eta: the reference, with Henderson's beside it.
    CHECK(t.compressibility == gas::hard_disc_fluid_compressibility(t.area_fraction));
    CHECK(t.henderson == gas::henderson_compressibility(t.area_fraction));
  }

  TEST_CASE("one ball: the push on the walls gives P times the centres' area = N kT") {
    // A ball with velocity (3, 4) on a 40 x 30 table, radius 1: its centre
    // crosses 38 in x and 28 in y. Over a whole number of both periods
    // (2 * 38 / 3 and 2 * 28 / 4 = 14; 532 is 21 of the first and 38 of the
    // second) each wall is hit as often as the others of its pair, and
    // Z = 1 to round-off.
    Gas g = bare_table(40, 30);
    g.balls = {{10, 10, 3, 4, 0}};
    ObservedRun run(g);
    Control& control = run.control;
    const GasStatistics& statistics = run.start_statistics(10, false);
    run_until(control, 532);
    const gas::MeasuredFigures m = statistics.measured(control.gas);
    CHECK(m.box_z_walls.value == doctest::Approx(1).epsilon(1e-12));
    CHECK(m.box_z_virial.value == 1);  // no collision of two balls
    CHECK(m.pressure_box.value == doctest::Approx(12.5 / (38.0 * 28.0)).epsilon(1e-12));
    // Each direction alone: 2 |v| per bounce, one bounce every 2 L / |v|.
    CHECK(m.pressure_box_x.value == doctest::Approx(9.0 / 38 / 28).epsilon(1e-12));
    CHECK(m.pressure_box_y.value == doctest::Approx(16.0 / 38 / 28).epsilon(1e-12));
    CHECK(m.collision_rate_box.value == 0);
    CHECK(m.mean_speed.value == doctest::Approx(5));
  }

  TEST_CASE("a gas started at one speed relaxes to the 2D Maxwell-Boltzmann speeds") {
    // 100 balls at area fraction 0.3, all at speed 1. Kinetic theory gives
    // a ball 0.85 collisions per unit time here, so after 30 time units each
    // has collided ~25 times. Then 60 snapshots of the 100 speeds, 6 time
    // units (~5 collisions of each ball) apart: a ball's speed after five
    // collisions has forgotten the one before, so the 6000 speeds are close
    // to independent draws. (Within one snapshot the speeds are tied by the
    // fixed energy; that makes their distribution slightly closer to the
    // curve, never farther, and the exact distribution for a finite N
    // differs from Maxwell-Boltzmann by about 0.2 / N = 0.002 in F, far below
    // what this test can see.)
    Control control = gas::start_control_for(lattice_gas(10, 0.3, 3));
    const double kT = gas::kinetic_energy(control.gas) / 100;
    // At the start the speeds are nowhere near: all of them at one speed.
    std::vector<double> speeds;
    for (const gas::Ball& b : control.gas.balls) speeds.push_back(std::hypot(b.vx, b.vy));
    CHECK(ks_distance(speeds, kT) > 0.3);
    speeds.clear();
    run_until(control, 30);
    for (int k = 1; k <= 60; ++k) {
      run_until(control, 30 + 6 * k);
      for (const gas::Ball& b : control.gas.balls)
        speeds.push_back(std::hypot(b.vx, b.vy));
    }
    // Kolmogorov-Smirnov at the 0.1 % level: D * sqrt(n) < 1.949.
    const double n = static_cast<double>(speeds.size());
    const double critical = 1.949 / std::sqrt(n);
    const double d = ks_distance(speeds, kT);
    CAPTURE(d);
    CAPTURE(critical);
    CHECK(d < critical);
    // The test has the power to see a wrong temperature: 10 % off is rejected.
    CHECK(ks_distance(speeds, 1.1 * kT) > critical);
    // The mean speed: the standard deviation of a Maxwell-Boltzmann speed is
    // sqrt((2 - pi / 2) kT), so the mean of n independent speeds is within
    // 3 sqrt((2 - pi / 2) kT / n) (three standard errors) of sqrt(pi kT / 2).
    double mean = 0;
    for (const double v : speeds) mean += v / n;
    CAPTURE(mean);
    CHECK(std::abs(mean - std::sqrt(pi * kT / 2)) <=
          3 * std::sqrt((2 - pi / 2) * kT / n));
  }

  TEST_CASE(
      "the time-averaged mean speed of GasStatistics converges to sqrt(pi kT / 2)") {
    // The screen's own average over 1500 time units after 30 to relax; its
    // block error (at least 16 batches, each of speeds_batch_collisions = 25
    // or more pair collisions per ball, ten times the mean speed's correlation
    // time: lesson 14) gives the tolerance, three errors.
    ObservedRun run(lattice_gas(10, 0.3, 5));
    Control& control = run.control;
    run_until(control, 30);
    const GasStatistics& statistics = run.start_statistics(10);
    run_until(control, 1530);
    const gas::MeasuredFigures m = statistics.measured(control.gas);
    const Average mean = m.mean_speed;
    const gas::KineticTheory theory = gas::kinetic_theory(control.gas);
    CAPTURE(mean.value);
    CAPTURE(mean.error);
    REQUIRE(std::isfinite(mean.error));
    CHECK(std::abs(mean.value - theory.maxwell_mean_speed) <= 3 * mean.error);
    // The histogram's fractions and the fraction beyond make the whole.
    double sum = m.fraction_beyond;
    for (const double f : m.speed_fractions) sum += f;
    CHECK(sum == doctest::Approx(1));
  }

  // Run lengths: about 10^6 collisions each (some 2000 collisions a ball).
  TEST_CASE("the mean speed of N balls at fixed energy, and its limit, Maxwell's") {
    // The formula against the density it comes from, (N - 1) (1 - s)^(N - 2)
    // in s = v^2 / R^2, integrated by the midpoint rule in u = sqrt(s)
    // (R u (N - 1) (1 - u^2)^(N - 2) 2u du, smooth: 10^5 steps leave an error
    // below 1e-9 for these N), and against N points drawn uniformly on the
    // sphere of radius R in 2N dimensions (normal coordinates, scaled): the
    // mean of one ball's speed over 20000 draws, within three of its
    // standard errors.
    const double kT = 1.05;
    for (const std::size_t n : {2, 3, 7, 50}) {
      const double nn = static_cast<double>(n), R = std::sqrt(2 * nn * kT);
      double mean = 0;
      const int steps = 100000;
      for (int i = 0; i < steps; ++i) {
        const double u = (i + 0.5) / steps;
        mean += R * u * (nn - 1) * std::pow(1 - u * u, nn - 2) * 2 * u / steps;
      }
      CAPTURE(n);
      CHECK(gas::fixed_energy_mean_speed(n, kT) == doctest::Approx(mean).epsilon(1e-8));
      std::mt19937_64 random(n);
      std::normal_distribution<double> normal;
      double sum = 0, squares = 0;
      const int draws = 20000;
      std::vector<double> x(2 * n);
      for (int d = 0; d < draws; ++d) {
        double norm = 0;
        for (double& c : x) {
          c = normal(random);
          norm += c * c;
        }
        const double v = R * std::hypot(x[0], x[1]) / std::sqrt(norm);
        sum += v;
        squares += v * v;
      }
      const double sample = sum / draws;
      const double error = std::sqrt((squares / draws - sample * sample) / draws);
      CHECK(std::abs(sample - gas::fixed_energy_mean_speed(n, kT)) <= 3 * error);
    }
    // One ball keeps its speed; many tend to Maxwell's sqrt(pi kT / 2), with
    // the relative correction -1 / (8 N) of Gamma's expansion.
    CHECK(gas::fixed_energy_mean_speed(1, kT) == doctest::Approx(std::sqrt(2 * kT)));
    const double maxwell = std::sqrt(pi * kT / 2);
    CHECK(gas::fixed_energy_mean_speed(100000, kT) / maxwell - 1 ==
          doctest::Approx(-1.0 / 800000).epsilon(1e-3));
    // The default scene's 7 balls (kT = 1.05): 1.8 % above Maxwell.
    CHECK(gas::fixed_energy_mean_speed(7, kT) == doctest::Approx(1.307384).epsilon(1e-6));
  }

  TEST_CASE(
      "the default scene's 7 balls: the mean speed of fixed energy, not Maxwell's") {
    // A long run of the built-in scene (6 10^5 time units, about 8000
    // collisions of two balls; the blocking finds the mean speed's error,
    // 0.0024, from about there on), its averages after the warm-up: the
    // time-averaged mean speed within three of its errors of the fixed-energy
    // mean, and more than three from Maxwell's, 1.8 % lower (the test can
    // tell the two apart).
    const Gas g = gas::parse_scene(gas::default_scene_text, gas::default_scene_name);
    ObservedRun run(g);
    const GasStatistics& statistics = run.start_statistics(36);
    run_until(run.control, 600000);
    const gas::MeasuredFigures m = statistics.measured(run.control.gas);
    const gas::KineticTheory t = gas::kinetic_theory(run.control.gas);
    CAPTURE(m.mean_speed.value);
    CAPTURE(m.mean_speed.error);
    REQUIRE(std::isfinite(m.mean_speed.error));
    CHECK(std::abs(m.mean_speed.value - t.mean_speed) <= 3 * m.mean_speed.error);
    CHECK(std::abs(m.mean_speed.value - t.maxwell_mean_speed) > 3 * m.mean_speed.error);
  }

  TEST_CASE("the warm-up: a ball's crossings of the table in mean free paths") {
    // 1024 balls on a lattice at eta = 0.5 on a square table of side
    // sqrt(1024 pi / 0.5) = 80.2: lambda = 1 / (2 sqrt 2 (2a) n g(2a)) with the
    // reference's g(2a) at 0.5, 3.1064, and n = 0.5 / pi: lambda = 0.35756,
    // and L / lambda = 224.3, so 225 collisions a ball (the regeneration
    // script of lesson 14 checks across seeds that the averages after it
    // carry no bias). A dilute gas, one mean free path wider than the table,
    // keeps the fewest, 10; one ball none.
    const Gas dense = lattice_gas(32, 0.5, 1);
    const double n = 0.5 / pi;
    const double path =
        1 / (2 * std::sqrt(2.0) * 2 * n * gas::hard_disc_fluid_contact_value(0.5));
    CHECK(gas::hard_disc_fluid_contact_value(0.5) ==
          doctest::Approx(3.1064).epsilon(1e-4));
    CHECK(path == doctest::Approx(0.35756).epsilon(1e-4));
    CHECK(gas::warm_up_collisions_a_ball(dense) ==
          static_cast<long long>(std::ceil(dense.width / path)));
    CHECK(gas::warm_up_collisions_a_ball(dense) == 225);
    const Gas g = gas::parse_scene(gas::default_scene_text, gas::default_scene_name);
    CHECK(gas::warm_up_collisions_a_ball(g) == gas::fewest_warm_up_collisions);
    Gas one = g;
    one.balls.resize(1);
    CHECK(gas::warm_up_collisions_a_ball(one) == 0);
    // And the statistics keep it: no averages before 225 * 1024 / 2
    // collisions of two balls, averages right after.
    ObservedRun run(dense);
    const GasStatistics& statistics = run.start_statistics(36);
    long long pairs = 0;
    auto collide_until = [&](long long count) {
      while (pairs < count) {
        const gas::Step step = gas::take_step(run.control, 1e9, nullptr);
        for (const gas::Collision& c : step.collisions)
          if (c.kind == gas::CollisionKind::balls) ++pairs;
      }
    };
    collide_until(225 * 512 - 1);
    CHECK(statistics.measured(run.control.gas).warming_up);
    collide_until(225 * 512);
    CHECK_FALSE(statistics.measured(run.control.gas).warming_up);
  }

  TEST_CASE("the equation of state of the bulk at area fraction 0.1") {
    check_equation_of_state(0.1, 6000, 7);
  }
  TEST_CASE("the equation of state of the bulk at area fraction 0.3") {
    check_equation_of_state(0.3, 2400, 8);
  }
  TEST_CASE("the equation of state of the bulk at area fraction 0.5") {
    // Seed 10: with the warm-up of issue 21 and the fixed-moment snapshots
    // together, seed 9's window put the contact theorem 3.4 errors off. Over
    // six other seeds of the same state (build/gas, lattice 1024, T = 800)
    // (kT n - P) / error read -1.2, 1.05, -0.15, 0.14, 0.92, 1.5: spread 1,
    // so seed 9 was the one-in-a-thousand draw, not a bias.
    check_equation_of_state(0.5, 800, 10);
  }

  TEST_CASE(
      "the H-theorem: H falls and after B it climbs back until the precision "
      "horizon") {
    // data/h-theorem.scene: 1024 balls on a lattice at area fraction 0.3,
    // every speed 1. H of the speeds now (38 bins, as on an 80-column
    // screen; bins chosen so that speed 1 is not on a bin's edge) measured at
    // T = 1, 2, 4, 8: it falls to the noise of 1024 speeds in 38 bins
    // (bins / 2N = 0.019, boltzmann_h_noise_floor) within about 6 collisions
    // a ball (T = 8).
    const gas::Gas start = gas::read_scene_file(GAS_SOURCE_DIR "/data/h-theorem.scene");
    auto h_after = [&](double forward, double back, double* retrace_error) {
      ObservedRun run(start);
      const GasStatistics& statistics = run.start_statistics(38, false);
      run_until(run.control, forward);
      gas::press_key(run.control, 'B');
      run_until(run.control, forward + back);
      // How far the balls are from their start, in radii (when back = forward).
      *retrace_error = 0;
      for (std::size_t i = 0; i < start.balls.size(); ++i) {
        const gas::Point p = gas::centre_at(run.control.gas.balls[i], forward + back);
        *retrace_error = std::max(
            *retrace_error, std::hypot(p.x - start.balls[i].x, p.y - start.balls[i].y));
      }
      return statistics.measured(run.control.gas).h_now;
    };
    ObservedRun run(start);
    const GasStatistics& statistics = run.start_statistics(38, false);
    const double h0 = statistics.measured(run.control.gas).h_now;
    CAPTURE(h0);
    CHECK(h0 > 3);                  // every ball in one bin: H = -ln q of that bin, 3.05
    std::vector<double> forward_h;  // at T = 1, 2, 4, 8
    double last = h0;
    for (const double t : {1.0, 2.0, 4.0, 8.0}) {
      run_until(run.control, t);
      forward_h.push_back(statistics.measured(run.control.gas).h_now);
      CAPTURE(t);
      CAPTURE(forward_h.back());
      CHECK(forward_h.back() < last);  // falls
      last = forward_h.back();
    }
    CHECK(last < 2 * gas::boltzmann_h_noise_floor(38, 1024));

    // B at T = 10 (8 collisions a ball): the gas retraces its path, and H
    // with it: at T = 10 + s it is H(10 - s), for s = 2, 6, 8, 9, so it
    // climbs, and at T = 20 the gas is back at its start with H(0).
    double error = 0;
    const std::vector<double> back_h = {h_after(10, 2, &error), h_after(10, 6, &error),
                                        h_after(10, 8, &error), h_after(10, 9, &error)};
    for (std::size_t i = 0; i < back_h.size(); ++i) {
      CAPTURE(i);
      // The speeds at 10 + s and 10 - s differ by round-off (some 1e-12 by
      // T = 20, below) and each bin's share is a count: H is the same
      // unless a speed sits within 1e-12 of a bin's edge, which none does.
      CHECK(std::abs(back_h[i] - forward_h[3 - i]) < 1e-9);
      if (i > 0) CHECK(back_h[i] > back_h[i - 1]);  // climbs
    }
    CHECK(std::abs(h_after(10, 10, &error) - h0) < 1e-9);  // every speed 1 again
    CHECK(error < 1e-6);
    // In double the retrace holds to about 20 collisions a ball (B at T = 24:
    // back within 0.01 radii), and not after 25 (B at T = 30: the round-off
    // of 2^-53, multiplied by some 3.5 at each collision of a ball, has grown
    // to the size of a ball, and H climbs only half way).
    const double h_24 = h_after(24, 24, &error);
    CAPTURE(error);
    CHECK(error < 0.01);
    CHECK(std::abs(h_24 - h0) < 1e-3);
    const double h_30 = h_after(30, 30, &error);
    CAPTURE(h_30);
    CHECK(error > 1);
    CHECK(h_30 < 0.6 * h0);
  }

  TEST_CASE(
      "the interior's time survives B: a ball that retraces its path spends as "
      "long inside") {
    // data/one-ball.scene's ball, averages from T = 0: over [0, 300] and, B
    // pressed at 300, over [0, 600] it spends the same share of its time in
    // the interior (the second half retraces the first). B rewrites the
    // ball's row at T, so stage 7 tells the statistics first, and they end
    // its flight there; the shares agree to round-off.
    const gas::Gas start = gas::read_scene_file(GAS_SOURCE_DIR "/data/one-ball.scene");
    ObservedRun run(start);
    const GasStatistics& statistics = run.start_statistics(10, false);
    run_until(run.control, 300);
    const double before =
        statistics.measured(run.control.gas).interior_area_fraction.value;
    gas::press_key(run.control, 'B');
    run_until(run.control, 600);
    const double after =
        statistics.measured(run.control.gas).interior_area_fraction.value;
    CAPTURE(before);
    CAPTURE(after);
    CHECK(before > 0);
    CHECK(after == doctest::Approx(before).epsilon(1e-12));
  }
}

namespace {

// The bin of the statistics screen's histogram a speed belongs in, worked
// out here from its definition (lesson 12): `bins` equal bins from 0 to
// 2.5 v_rms, v_rms = sqrt(2 kT) of the gas at the start (its energy does not
// change); `bins` itself for a speed beyond the last bin.
std::size_t histogram_bin(double speed, double kT, int bins) {
  const double width = 2.5 * std::sqrt(2 * kT) / bins;
  return static_cast<std::size_t>(std::min(std::floor(speed / width), double(bins)));
}

}  // namespace

TEST_SUITE("kinetic-theory") {
  TEST_CASE(
      "the speed histogram: a ball faster than 2.5 v_rms is counted beyond the last "
      "bin") {
    // Ten balls far apart on a large table (no collision before T = 2): one
    // at speed 3, which is beyond 2.5 v_rms (v_rms^2 = (9 + 9 x 0.25) / 10,
    // 2.5 v_rms = 2.65), and nine at 0.5 in various directions. Over [0, 2]
    // the histogram's fractions of ball-time are those of the balls: 9/10 in
    // the bin of speed 0.5 (the second of ten bins 0.265 wide), 1/10 beyond,
    // none in the last bin.
    Gas g;
    g.radius = 1;
    g.width = g.height = 400;
    g.display_step = 1e9;
    g.balls.push_back({200, 200, 3, 0, 0});
    for (int i = 0; i < 9; ++i) {
      const double angle = 0.7 * i;
      g.balls.push_back(
          {40.0 + 40 * i, 100, 0.5 * std::cos(angle), 0.5 * std::sin(angle), 0});
    }
    const double kT = gas::kinetic_energy(g) / 10;
    constexpr int bins = 10;
    ObservedRun run(g);
    const GasStatistics& statistics = run.start_statistics(bins, false);
    run_until(run.control, 2);
    REQUIRE(run.control.wall_collisions + run.control.ball_collisions == 0);
    const gas::MeasuredFigures m = statistics.measured(run.control.gas);
    REQUIRE(m.speed_fractions.size() == bins);
    // The width 2.5 v_rms / bins, to a rounding or two (kT the same sum).
    CHECK(m.bin_width == doctest::Approx(2.5 * std::sqrt(2 * kT) / bins).epsilon(1e-15));
    const std::size_t slow = histogram_bin(0.5, kT, bins);
    REQUIRE(slow == 1);
    REQUIRE(histogram_bin(3, kT, bins) == bins);
    // Why 1e-12: each fraction is a ball-time (a count times 2) over 20.
    CHECK(m.fraction_beyond == doctest::Approx(0.1).epsilon(1e-12));
    for (std::size_t b = 0; b < bins; ++b) {
      CAPTURE(b);
      CHECK(m.speed_fractions[b] ==
            doctest::Approx(b == slow ? 0.9 : 0.0).epsilon(1e-12));
    }
  }

  TEST_CASE(
      "the speed histogram: each bin holds the ball-time its speeds spent there, to "
      "round-off") {
    // 36 balls, started at speed 1 and colliding (area fraction 0.3), from
    // T = 0 to 40 (about 35 collisions a ball): the speeds spread out and
    // some pass 2.5 v_rms. The reference: step by step (take_step stops at
    // every collision, and speeds change only there), each ball's step
    // length added to the bin of its speed in this test's own reckoning.
    constexpr int bins = 12;
    ObservedRun run(lattice_gas(6, 0.3, 21));
    Control& control = run.control;
    const double kT = gas::kinetic_energy(control.gas) / 36;
    const GasStatistics& statistics = run.start_statistics(bins, false);
    std::vector<double> ball_time(bins + 1, 0.0);
    while (control.gas.time < 40) {
      std::vector<std::size_t> bin_of_ball;
      for (const gas::Ball& b : control.gas.balls)
        bin_of_ball.push_back(
            histogram_bin(std::sqrt(b.vx * b.vx + b.vy * b.vy), kT, bins));
      const gas::Step step = gas::take_step(control, 40, nullptr);
      for (const std::size_t bin : bin_of_ball) ball_time[bin] += step.length;
    }
    const gas::MeasuredFigures m = statistics.measured(control.gas);
    REQUIRE(m.speed_fractions.size() == bins);
    const double total = 36 * 40.0;
    // Why 1e-12: both sides add the same step lengths (some 2500 of them,
    // each exact to an ulp of T = 40) in a different order.
    for (std::size_t b = 0; b < bins; ++b) {
      CAPTURE(b);
      CHECK(m.speed_fractions[b] == doctest::Approx(ball_time[b] / total).epsilon(1e-12));
    }
    CAPTURE(ball_time[bins] / total);
    CHECK(ball_time[bins] > 0);  // the case this test is for: balls beyond the last bin
    CHECK(m.fraction_beyond == doctest::Approx(ball_time[bins] / total).epsilon(1e-12));
  }
}
