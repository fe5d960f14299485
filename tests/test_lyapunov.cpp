// Tests for the tangent dynamics and the Lyapunov exponent
// (stages/beyond/tangent_dynamics.*, lyapunov.*, lyapunov_screen.*;
// lessons/15-chaos.md).
//
// Two independent checks of the linearised collision map, both through the
// project's own stages 4 and 5, never through a second copy of the formulas:
// - finite differences at single collisions (a wall, a pair, a grazing
//   pair): the derivative of "run the stages to a moment after the
//   collision" by central differences, column by column, against the map;
// - twin runs, as Benettin did: a second gas a tiny distance away, run by
//   stage 7's loop. Over a few collisions a ball the twins' difference is the
//   tangent vector itself; over a long run, renormalised, their exponent is
//   the tangent-space exponent within its error (the default scene, the
//   crowd, and a dense gas).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "beyond/blocking.hpp"
#include "beyond/kinetic_screen.hpp"
#include "beyond/lyapunov.hpp"
#include "beyond/lyapunov_screen.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "beyond/tangent_dynamics.hpp"
#include "stage2_input.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"
#include "stage5_new_coordinates.hpp"
#include "stage7_control.hpp"
#include "support.hpp"

namespace {

using gas::Ball;
using gas::Collision;
using gas::CollisionKind;
using gas::Gas;

// The state of a gas at `time` as 4N numbers: x, y, vx, vy of each ball.
std::vector<double> state_at(const Gas& gas, double time) {
  std::vector<double> s;
  for (const Ball& b : gas.balls) {
    const gas::Point p = gas::centre_at(b, time);
    s.insert(s.end(), {p.x, p.y, b.vx, b.vy});
  }
  return s;
}

// A gas at rest in time: every row written at its T, from a 4N state.
Gas with_state(Gas gas, const std::vector<double>& s) {
  for (std::size_t i = 0; i < gas.balls.size(); ++i)
    gas.balls[i] = {s[4 * i], s[4 * i + 1], s[4 * i + 2], s[4 * i + 3], gas.time};
  return gas;
}

// Stage 4 (the article's scan) and stage 5, collision after collision, up to
// `end`; each collision told to `observer` first, if any. Returns the
// collisions carried out.
std::vector<Collision> run_stages(Gas& gas, double end,
                                  gas::TangentDynamics* tangent = nullptr) {
  const gas::CentreLimits limits = gas::centre_limits(gas);
  std::vector<Collision> done;
  while (true) {
    const Collision c = gas::find_first_collision(gas, limits);
    if (c.kind == CollisionKind::none || c.time > end) break;
    if (tangent) tangent->before_collision(gas, c);
    gas::apply_collision(gas, limits, c);
    done.push_back(c);
  }
  gas.time = end;
  return done;
}

// The worst difference, |finite difference - map| / (1 + |map|), over every
// column of the derivative of "the stages from T = 0 to `end`", for the
// single collision the run holds (checked: the same collision, K, N1, N2, in
// every perturbed run).
double finite_difference_mismatch(const Gas& start, double end, double h,
                                  CollisionKind kind) {
  Gas exact = start;
  const std::vector<Collision> collisions = run_stages(exact, end);
  REQUIRE(collisions.size() == 1);
  CHECK(collisions[0].kind == kind);
  const std::vector<double> x = state_at(start, 0);
  double worst = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    // The map applied to the k-th unit vector.
    Gas g = start;
    gas::TangentDynamics tangent(g, 1);
    for (gas::BallTangent& t : tangent.balls()) t = {};
    gas::BallTangent& unit = tangent.balls()[k / 4];
    (k % 4 == 0 ? unit.qx : k % 4 == 1 ? unit.qy : k % 4 == 2 ? unit.px : unit.py) = 1;
    run_stages(g, end, &tangent);
    // The stages themselves, a step h either side.
    std::vector<double> up = x, down = x;
    up[k] += h;
    down[k] -= h;
    Gas g_up = with_state(start, up), g_down = with_state(start, down);
    const auto c_up = run_stages(g_up, end), c_down = run_stages(g_down, end);
    REQUIRE(c_up.size() == 1);
    REQUIRE(c_down.size() == 1);
    CHECK(c_up[0].kind == kind);
    CHECK(c_down[0].kind == kind);
    const std::vector<double> s_up = state_at(g_up, end), s_down = state_at(g_down, end);
    for (std::size_t i = 0; i < g.balls.size(); ++i) {
      const gas::BallTangent& t = tangent.balls()[i];
      const gas::Point dq = gas::tangent_dq_at(t, end);
      const double mapped[4] = {dq.x, dq.y, t.px, t.py};
      for (std::size_t c = 0; c < 4; ++c) {
        const double difference = (s_up[4 * i + c] - s_down[4 * i + c]) / (2 * h);
        worst = std::max(worst,
                         std::fabs(difference - mapped[c]) / (1 + std::fabs(mapped[c])));
      }
    }
  }
  return worst;
}

// A tiny observer that carries a bare tangent vector along (no
// renormalisation), for the twins' short check.
struct TangentObserver final : gas::CollisionObserver {
  gas::TangentDynamics tangent;
  explicit TangentObserver(const Gas& gas) : tangent(gas, 7) {}
  void before_collision(const Gas& gas, const Collision& c) override {
    tangent.before_collision(gas, c);
  }
};

// Stage 7's loop to `end` (steps end only on collisions or at `end`).
void run_to(gas::Control& control, double end) {
  while (control.gas.time < end) gas::take_step(control, end, nullptr);
}

// The gas `control` runs, moved by `epsilon` times the change `direction`
// holds at its T (positions and velocities), every row written at T.
Gas displaced(const gas::Control& control, const std::vector<double>& direction,
              double epsilon) {
  std::vector<double> s = state_at(control.gas, control.gas.time);
  for (std::size_t k = 0; k < s.size(); ++k) s[k] += epsilon * direction[k];
  return with_state(control.gas, s);
}

// The 4N components of a tangent vector at `time`.
std::vector<double> tangent_at(const gas::TangentDynamics& tangent, double time) {
  std::vector<double> v;
  for (const gas::BallTangent& t : tangent.balls()) {
    const gas::Point dq = gas::tangent_dq_at(t, time);
    v.insert(v.end(), {dq.x, dq.y, t.px, t.py});
  }
  return v;
}

double norm(const std::vector<double>& v) {
  double sum = 0;
  for (const double x : v) sum += x * x;
  return std::sqrt(sum);
}

// The twins over `per_ball` collisions a ball from the gas at hand (after a
// warm-up of the same length): the largest |twin difference / epsilon -
// tangent| / |tangent| at the end.
double twin_mismatch(const Gas& start, double per_ball, double epsilon) {
  gas::Control a = gas::start_control_for(start);
  a.gas.display_step = 1e300;
  // Warm up: the gas a few collisions a ball from its start.
  const auto n = static_cast<long long>(start.balls.size());
  auto collisions = [](const gas::Control& c) {
    return c.wall_collisions + c.ball_collisions;
  };
  while (collisions(a) < static_cast<long long>(per_ball * static_cast<double>(n)))
    gas::take_step(a, gas::never, nullptr);
  TangentObserver observer(a.gas);
  a.observer = &observer;
  const std::vector<double> u = tangent_at(observer.tangent, a.gas.time);
  gas::Control b = gas::start_control_for(displaced(a, u, epsilon));
  b.gas.display_step = 1e300;
  const long long until = collisions(a) + static_cast<long long>(per_ball * n);
  while (collisions(a) < until) gas::take_step(a, gas::never, nullptr);
  // Compared halfway to the next collision: at a collision itself one twin
  // may have had it and the other not yet.
  const double end = (a.gas.time + a.finder->first(a.gas).time) / 2;
  run_to(a, end);
  run_to(b, end);
  const std::vector<double> sa = state_at(a.gas, end), sb = state_at(b.gas, end);
  const std::vector<double> t = tangent_at(observer.tangent, end);
  std::vector<double> miss(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) miss[k] = (sb[k] - sa[k]) / epsilon - t[k];
  return norm(miss) / norm(t);
}

// Benettin's exponent from twins: every `interval`, the twins' distance d
// (Euclidean, all 4N components) gives a sample ln(d / epsilon) / interval,
// and the second twin is put back at epsilon from the first along the same
// line. The tangent-space exponent is measured along the first twin's path.
struct TwinExponents {
  gas::Average twins;
  gas::Average tangent;
};

TwinExponents twin_exponents(const Gas& start, long long samples) {
  gas::Control a = gas::start_control_for(start);
  a.gas.display_step = 1e300;
  gas::LyapunovExponent lyapunov(a.gas);
  a.observer = &lyapunov;
  // The warm-up of the exponent's own (it sets dT).
  while (lyapunov.interval() == 0) gas::take_step(a, gas::never, nullptr);
  const double interval = lyapunov.interval();
  const double epsilon = 1e-9 * start.radius;
  std::mt19937_64 random(3);
  std::normal_distribution<double> normal;
  std::vector<double> u(4 * start.balls.size());
  for (double& x : u) x = normal(random);
  const double u_norm = norm(u);
  for (double& x : u) x /= u_norm;
  gas::Control b = gas::start_control_for(displaced(a, u, epsilon));
  b.gas.display_step = 1e300;
  gas::BlockingAnalysis blocking;
  // A few samples first, for the twins to turn to the fastest direction.
  const long long turning = 20;
  for (long long k = 0; k < samples + turning; ++k) {
    const double next = a.gas.time + interval;
    run_to(a, next);
    run_to(b, next);
    const std::vector<double> sa = state_at(a.gas, next), sb = state_at(b.gas, next);
    std::vector<double> d(sa.size());
    for (std::size_t i = 0; i < d.size(); ++i) d[i] = sb[i] - sa[i];
    const double distance = norm(d);
    if (k >= turning) blocking.add(std::log(distance / epsilon) / interval);
    for (double& x : d) x /= distance;
    b = gas::start_control_for(displaced(a, d, epsilon));
    b.gas.display_step = 1e300;
  }
  const gas::LyapunovFigures f = lyapunov.measured(a.gas);
  return {{blocking.mean(), blocking.error()}, f.exponent};
}

// A dense gas: 256 balls of radius 1 on a lattice at area fraction 0.5.
Gas dense_gas() {
  const double side = std::sqrt(256 * std::acos(-1.0) / 0.5);
  return gas::parse_scene("a 1\nT0 1\nA1 " + std::to_string(side) + "\nA2 " +
                              std::to_string(side) + "\nlattice 256 1989 1\n",
                          "dense");
}

}  // namespace

TEST_SUITE("lyapunov") {
  // The tolerance of the finite differences: central differences with
  // h = 1e-6 err by about h^2 times the third derivative (the map's entries
  // are at most ~10 here, its curvature like them: ~1e-11) and by the
  // rounding of states of size ~40 (ulp 7e-15) over 2h: ~1e-8. 1e-6 is far
  // above both and far below what a wrong term gives (order 1: the breaks
  // tried in lesson 15 missed by 0.1 to 10).
  constexpr double fd_tolerance = 1e-6;
  constexpr double fd_step = 1e-6;

  TEST_CASE("the map at a wall: finite differences of stage 5's bounce") {
    // One ball bouncing off the wall x = 40 (its centre at x = 39) at T = 2,
    // the other flying free; run to T = 5.
    const Gas gas =
        gas::testing::table_with({{35, 12, 2, 0.7, 0}, {10, 10, -0.3, 0.4, 0}});
    CHECK(finite_difference_mismatch(gas, 5, fd_step, CollisionKind::vertical_wall) <
          fd_tolerance);
    // And off y = 30 (centre at 29).
    const Gas up = gas::testing::table_with({{20, 25, 0.3, 1.5, 0}});
    CHECK(finite_difference_mismatch(up, 4, fd_step, CollisionKind::horizontal_wall) <
          fd_tolerance);
  }

  TEST_CASE("the map of two balls: finite differences of stage 5's collision") {
    // Head on at an angle: the line of centres 30 degrees off the velocities.
    const Gas gas =
        gas::testing::table_with({{10, 15, 1.2, 0.1, 0}, {20, 16, -0.8, -0.2, 0}});
    CHECK(finite_difference_mismatch(gas, 7, fd_step, CollisionKind::balls) <
          fd_tolerance);
  }

  TEST_CASE(
      "the map of a grazing pair: finite differences where the map's entries are large") {
    // The centres' lines 1.98 apart (2a = 2): the balls barely touch, and a
    // change of their offset moves the collision a long way.
    const Gas gas = gas::testing::table_with({{10, 15, 1, 0, 0}, {20, 16.98, -1, 0, 0}});
    CHECK(finite_difference_mismatch(gas, 8, 1e-7, CollisionKind::balls) < fd_tolerance);
  }

  TEST_CASE("twins a tiny distance apart differ by the tangent vector (stage 7's loop)") {
    // Two collisions a ball, from a moment two collisions a ball after the
    // start, compared halfway to the next collision. The change grows by
    // e^(2 lambda) (lambda: 2.5 e-folds a collision a ball in the default
    // scene, 5 in the crowd): from epsilon = 1e-9 radii to at most ~1e-5
    // radii, where the twins' difference still is the tangent vector up to a
    // quadratic term of that order (seen: 3e-7 default, 8e-4 crowd, 4e-5
    // dense), and far above the rounding of the coordinates (1e-16 relative,
    // grown alike: 1e-12 of a radius). A wrong term of the map misses by
    // order 1: 1e-2 tells the two apart.
    const Gas seven = gas::parse_scene(
        gas::testing::read_file(gas::testing::source_path("data/default.scene")),
        "default");
    const Gas crowd = gas::read_scene_file(gas::testing::source_path("data/crowd.scene"));
    for (const auto& scene : {std::pair{std::string("default"), seven},
                              std::pair{std::string("crowd"), crowd},
                              std::pair{std::string("dense"), dense_gas()}}) {
      const std::string& name = scene.first;
      const Gas& gas = scene.second;
      CAPTURE(name);
      CHECK(twin_mismatch(gas, 2, 1e-9 * gas.radius) < 1e-2);
    }
  }

  TEST_CASE("Benettin's twins give the tangent-space exponent within its error") {
    const Gas seven = gas::parse_scene(
        gas::testing::read_file(gas::testing::source_path("data/default.scene")),
        "default");
    const Gas crowd = gas::read_scene_file(gas::testing::source_path("data/crowd.scene"));
    struct Scene {
      std::string name;
      Gas gas;
      long long samples;  // renormalisations
    };
    for (const Scene& scene : {Scene{"default", seven, 2000}, Scene{"crowd", crowd, 1000},
                               Scene{"dense", dense_gas(), 400}}) {
      const std::string& name = scene.name;
      const Gas& gas = scene.gas;
      const long long samples = scene.samples;
      CAPTURE(name);
      const TwinExponents e = twin_exponents(gas, samples);
      CAPTURE(e.twins.value);
      CAPTURE(e.twins.error);
      CAPTURE(e.tangent.value);
      CAPTURE(e.tangent.error);
      REQUIRE(!std::isnan(e.tangent.error));
      REQUIRE(!std::isnan(e.twins.error));
      // Both along the same path, so their difference is far smaller than
      // either's statistical error (seen: 0.2 and 0.2 of it in the default
      // scene and the crowd); their windows differ (the twins start 20
      // samples later, from their own random direction), so agreement
      // within one error of the tangent value is the fair demand. Both turn
      // terms with the wrong sign (lesson 15) moved it by 2.0 of its errors
      // in the default scene (few collisions of two balls), 23 in the crowd
      // and 49 in the dense gas.
      CHECK(std::fabs(e.twins.value - e.tangent.value) < e.tangent.error);
    }
  }

  TEST_CASE(
      "the precision horizon: ln(d / eps) / lambda with eps one ulp of the table's "
      "size") {
    Gas gas = gas::testing::table_with({});
    gas.width = 256;  // ulp of numbers in [256, 512): 2^(8 - 52) in double
    gas.height = 192;
    CHECK(gas::coordinate_ulp(gas, 53) == std::ldexp(1.0, -44));
    CHECK(gas::coordinate_ulp(gas, 24) == std::ldexp(1.0, -15));
    // e^10 = d / eps: ten e-folds, at 2 a collision a ball, take 5.
    CHECK(gas::precision_horizon(2, std::exp(10.0), 1) ==
          doctest::Approx(5).epsilon(1e-12));
    gas::LyapunovFigures f;
    f.warming_up = false;
    f.exponent = {0.025, 0.001};
    f.per_collision_per_ball = 2.5;
    const gas::PrecisionHorizons h = gas::precision_horizons(gas, f);
    // a = 1: d = 0.01, so double's horizon is ln(0.01 / 2^-44) / 2.5.
    CHECK(h.twice == doctest::Approx(std::log(0.01 / std::ldexp(1.0, -44)) / 2.5));
    CHECK(h.single < h.twice);
    CHECK(h.twice < h.extended);
  }

  TEST_CASE("the screen's lines and the --csv block") {
    const Gas gas = gas::testing::table_with({{10, 10, 1, 0, 0}});
    gas::LyapunovFigures f;  // warming up
    const auto warming = gas::lyapunov_lines(gas, f);
    REQUIRE(warming.size() == 1);
    CHECK(warming[0].find("warming up") != std::string::npos);
    CHECK(gas::lyapunov_csv_row(f) == ",nan,nan");
    f.warming_up = false;
    f.exponent = {0.125, 0.0625};
    f.per_collision_per_ball = 2.5;
    f.per_collision_per_ball_error = 0.25;
    const auto lines = gas::lyapunov_lines(gas, f);
    REQUIRE(lines.size() == 2);
    CHECK(lines[0] ==
          "Lyapunov: 0.125 +- 0.062 per unit time, 2.5 +- 0.25 per collision per ball");
    // An error not known yet says why, for both.
    f.exponent = {0.125, gas::not_known, "not yet"};
    f.per_collision_per_ball_error = gas::not_known;
    CHECK(gas::lyapunov_lines(gas, f)[0] ==
          "Lyapunov: 0.125 +- not yet per unit time, 2.5 +- not yet per collision per "
          "ball");
    f.exponent = {0.125, 0.0625};
    f.per_collision_per_ball_error = 0.25;
    CHECK(lines[1].find("double") != std::string::npos);
    for (const std::string& line : lines)
      CHECK(line.size() <= 76);  // an 80-column screen
    CHECK(gas::lyapunov_csv_header() == ",lyapunov,lyapunov_error");
    CHECK(gas::lyapunov_csv_row(f) == ",0.125,0.0625");
  }

  TEST_CASE("B starts the exponent afresh and A restarts its averages at the next T_k") {
    const Gas crowd = gas::read_scene_file(gas::testing::source_path("data/crowd.scene"));
    gas::Control control = gas::start_control_for(crowd);
    gas::LyapunovExponent lyapunov(control.gas);
    control.observer = &lyapunov;
    while (lyapunov.measured(control.gas).samples < 50)
      gas::take_step(control, 1e9, nullptr);
    CHECK(!lyapunov.measured(control.gas).warming_up);
    lyapunov.restart();  // A
    const long long before = lyapunov.measured(control.gas).samples;
    while (lyapunov.measured(control.gas).samples == before)
      gas::take_step(control, 1e9, nullptr);
    CHECK(lyapunov.measured(control.gas).samples == 1);
    gas::press_key(control, 'B');  // tells the observer before the rows are rewritten
    CHECK(lyapunov.measured(control.gas).warming_up);
    CHECK(lyapunov.measured(control.gas).samples == 0);
    while (lyapunov.measured(control.gas).samples < 50)
      gas::take_step(control, 1e9, nullptr);
    // The reversed gas's exponent is the gas's own (the crowd's: 0.13 a unit time).
    CHECK(lyapunov.measured(control.gas).exponent.value > 0.05);
  }

  TEST_CASE(
      "the exponent's error waits for 6 overlapping batches of 16 renormalisations") {
    // Its samples are anticorrelated over some 20 renormalisations, and
    // shorter batches make the error too large (lyapunov.hpp): batches a
    // sixth of the run, never shorter than 16, so none before 6 x 16 = 96
    // samples; at 96 it is known.
    const Gas crowd = gas::read_scene_file(gas::testing::source_path("data/crowd.scene"));
    gas::Control control = gas::start_control_for(crowd);
    gas::LyapunovExponent lyapunov(control.gas);
    control.observer = &lyapunov;
    while (lyapunov.measured(control.gas).samples < 95)
      gas::take_step(control, 1e9, nullptr);
    const gas::LyapunovFigures early = lyapunov.measured(control.gas);
    CHECK(early.samples == 95);
    CHECK(std::isnan(early.exponent.error));
    CHECK(early.exponent.status == gas::ErrorStatus::short_batches);
    CHECK(std::string(early.exponent.why_no_error) == "not yet");
    while (lyapunov.measured(control.gas).samples < 96)
      gas::take_step(control, 1e9, nullptr);
    const gas::LyapunovFigures known = lyapunov.measured(control.gas);
    CHECK(known.exponent.status == gas::ErrorStatus::known);
    CHECK(std::isfinite(known.exponent.error));
    CHECK(known.exponent.why_no_error == nullptr);
  }

  TEST_CASE("the program: --csv ends with lyapunov and lyapunov_error known at the end") {
    const gas::testing::Scratch scratch;
    const std::string csv = scratch.file("crowd.csv");
    const auto run = gas::testing::run_program(
        {"data/crowd.scene", "--until", "8000", "--mode", "none", "--csv", csv});
    REQUIRE(run.status == 0);
    const std::vector<std::string> lines =
        gas::testing::lines_of(gas::testing::read_file(csv));
    REQUIRE(lines.size() > 2);
    const std::vector<std::string> names = gas::testing::fields_of(lines.front());
    const std::vector<std::string> last = gas::testing::fields_of(lines.back());
    REQUIRE(names.size() == last.size());
    CHECK(names[names.size() - 2] == "lyapunov");
    CHECK(names.back() == "lyapunov_error");
    const double lambda = std::stod(last[last.size() - 2]);
    const double error = std::stod(last.back());
    // The crowd's exponent, 0.134 +- 0.001 over T = 50000 (lesson 15): at
    // T = 8000 within a few of its own errors of that, and known to 5 %.
    // (A renormalisation every 40 time units or so: 8 batches of 16, the
    // fewest the error waits for, take until T = 5100.)
    CHECK(std::fabs(lambda - 0.134) < 5 * error + 0.002);
    CHECK(error > 0);
    CHECK(error < 0.05 * lambda);
  }

  TEST_CASE(
      "the statistics screen: the exponent's lines last and named when there is no "
      "room") {
    const gas::Figures f = gas::testing::some_figures();
    gas::KineticFigures k;
    k.theory.kT = 1;
    k.theory.mean_speed = 1.25;
    k.measured.speed_fractions.assign(20, 0.05);
    k.measured.bin_width = 0.125;
    const std::vector<std::string> more = {"Lyapunov one", "  Lyapunov two"};
    auto shows = [](const gas::TextScreen& screen, const std::string& text) {
      for (const std::string& line : screen.lines)
        if (line.find(text) != std::string::npos) return true;
      return false;
    };
    auto screen_of = [&](int rows) {
      gas::TextScreen screen = gas::prepare_character_screen(80, rows);
      gas::draw_kinetic_figures(screen, f, k, more);
      return screen;
    };
    // The exponent's lines rank last: the shortest screen that leaves nothing
    // out shows both, with the histogram; one row less, the second is named
    // in the line of what is left out, with the rows that show it all.
    int rows = 10;
    while (rows < 60 && shows(screen_of(rows), "more with")) ++rows;
    const gas::TextScreen tall = screen_of(rows);
    CHECK(shows(tall, "Lyapunov one"));
    CHECK(shows(tall, "Lyapunov two"));
    CHECK(shows(tall, "speeds:"));
    const gas::TextScreen shorter = screen_of(rows - 1);
    CHECK(shows(shorter, "speeds:"));
    CHECK(!shows(shorter, "Lyapunov two"));
    CHECK(shows(shorter, fmt::format("more with {} rows: Lyapunov", rows + 2)));
  }
}
