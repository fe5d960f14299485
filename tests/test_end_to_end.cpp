// End to end: the whole loop of stages 4, 5 and 7 over many steps.
//
// - The display step T0 never changes the physics: the same scene with
//   T0 = 1 and T0 = 0.37 gives bit for bit the same collisions and the same
//   state at the same model time; and so does the picture rule (a picture
//   at every collision, or only at the display steps).
// - Time reversal (the B key): forward, B, as long again, B returns a short
//   run to its start.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "beyond/display_steps.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "program/console.hpp"
#include "stage7_control.hpp"

namespace {

// A gas of `count` balls of radius 4 at random, non-overlapping places on the
// default scene's 256 x 192 table, with random velocities (seeded: the same
// gas every time).
gas::Gas random_gas(int count, std::uint64_t seed) {
  gas::Gas g;
  g.radius = 4;
  g.width = 256;
  g.height = 192;
  g.display_step = 1;
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> across(4, 252), down(4, 188), speed(-2, 2);
  while (static_cast<int>(g.balls.size()) < count) {
    const gas::Ball candidate{across(random), down(random), speed(random), speed(random),
                              0};
    bool free = true;
    for (const gas::Ball& b : g.balls) {
      free = free && std::hypot(b.x - candidate.x, b.y - candidate.y) >= 8;
    }
    if (free) g.balls.push_back(candidate);
  }
  return g;
}

struct Run {
  std::vector<gas::Collision> collisions;
  gas::Control control;
};

// Runs the gas to model time `end` with display step `display_step`,
// pictures taken by `rule`.
Run run_until(gas::Gas g, double display_step, double end, gas::PictureRule rule) {
  g.display_step = display_step;
  Run run{{}, gas::start_control_for(g)};
  while (run.control.gas.time < end) {
    const gas::Step step = gas::take_step_by(rule, run.control, end, nullptr);
    run.collisions.insert(run.collisions.end(), step.collisions.begin(),
                          step.collisions.end());
  }
  return run;
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// The same collisions, bit for bit, and the same gas at `end`.
void check_same_run(const gas::Gas& g, const Run& first, const Run& other, double end) {
  REQUIRE(first.collisions.size() > 10);  // the comparison means something
  REQUIRE(first.collisions.size() == other.collisions.size());
  for (std::size_t i = 0; i < first.collisions.size(); ++i) {
    const gas::Collision& a = first.collisions[i];
    const gas::Collision& b = other.collisions[i];
    INFO("collision " << i + 1);
    CHECK(bits(a.time) == bits(b.time));
    CHECK(a.kind == b.kind);
    CHECK(a.first == b.first);
    CHECK(a.second == b.second);
  }
  CHECK(bits(first.control.gas.time) == bits(other.control.gas.time));
  for (std::size_t i = 0; i < g.balls.size(); ++i) {
    const gas::Ball& a = first.control.gas.balls[i];
    const gas::Ball& b = other.control.gas.balls[i];
    const gas::Point pa = gas::centre_at(a, end), pb = gas::centre_at(b, end);
    INFO("ball " << i + 1);
    CHECK(bits(pa.x) == bits(pb.x));
    CHECK(bits(pa.y) == bits(pb.y));
    CHECK(bits(a.vx) == bits(b.vx));
    CHECK(bits(a.vy) == bits(b.vy));
  }
}

// T0 = 1 and T0 = 0.37, under both picture rules: four runs, one physics.
void check_same_physics(const gas::Gas& g, double end) {
  using gas::PictureRule;
  const Run coarse = run_until(g, 1.0, end, PictureRule::every_collision);
  for (const PictureRule rule :
       {PictureRule::every_collision, PictureRule::display_steps}) {
    for (const double display_step : {1.0, 0.37}) {
      INFO("T0 = " << display_step << ", pictures " << gas::picture_rule_name(rule));
      check_same_run(g, coarse, run_until(g, display_step, end, rule), end);
    }
  }
}

}  // namespace

TEST_SUITE("end-to-end") {
  TEST_CASE(
      "T0 never changes the physics: the default scene with T0 = 1 and T0 = 0.37 "
      "under either picture rule") {
    check_same_physics(gas::parse_scene(gas::default_scene_text, gas::default_scene_name),
                       300);
  }

  TEST_CASE(
      "T0 never changes the physics: 40 random balls with T0 = 1 and T0 = 0.37 under "
      "either picture rule") {
    check_same_physics(random_gas(40, 1989), 100);
  }

  TEST_CASE("B then as long again then B: a short run returns to its start") {
    const gas::Gas start =
        gas::parse_scene(gas::default_scene_text, gas::default_scene_name);
    gas::Control control = gas::start_control_for(start);
    long long collisions = 0;
    auto run_to = [&](double end) {
      while (control.gas.time < end)
        collisions += static_cast<long long>(
            gas::take_step(control, end, nullptr).collisions.size());
    };
    run_to(150);
    gas::press_key(control, 'B');
    run_to(300);
    gas::press_key(control, 'B');
    REQUIRE(collisions > 10);  // the run went through collisions both ways
    CHECK(control.tone == 0);  // B twice: the tone is back too

    // How far the gas is from where it started. Measured: 1.7e-13 after
    // 8 collisions each way. Each collision can amplify an error (see
    // test_high_precision.cpp: about a factor of two every three
    // collisions), so rounding errors of 1e-14 on these coordinates (~100 *
    // 2^-53) grow by a few hundred over this run; 1e-9 is far above that yet
    // far below anything visible, and a reversal that missed a collision or
    // got one wrong would be off by whole units.
    double worst = 0;
    for (std::size_t i = 0; i < start.balls.size(); ++i) {
      const gas::Point now = gas::centre_at(control.gas.balls[i], control.gas.time);
      const gas::Ball& was = start.balls[i];
      worst = std::max({worst, std::fabs(now.x - was.x), std::fabs(now.y - was.y),
                        std::fabs(control.gas.balls[i].vx - was.vx),
                        std::fabs(control.gas.balls[i].vy - was.vy)});
    }
    MESSAGE(fmt::format("{} collisions; largest difference from the start {:.3g}",
                        collisions, worst));
    CHECK(worst < 1e-9);
  }
}
