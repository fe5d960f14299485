// Stage 7 of the article, "model control": the loop of stages 4, 5 and 7,
// and the keys.
//
// - start_control sets the loop up.
// - take_step: T1 = T0 when no collision is due within the step; T1 = TC - T
//   when one is, and then T is exactly TC; collisions counted by kind; the
//   time limit respected exactly; simultaneous collisions (a ball into a
//   corner, a ball struck from both sides) all carried out in one step.
// - Every key: S, R, B, >, <, 0, E, in either case; '.' and other keys do
//   nothing; T0 stays finite and positive however often > or < is pressed.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "beyond/random_placement.hpp"
#include "stage2_input.hpp"
#include "stage7_control.hpp"
#include "support.hpp"

namespace {

using gas::CollisionKind;

// A 100 x 100 table, balls of radius 4: the centres stay in 4 <= x, y <= 96.
gas::Gas table(std::vector<gas::Ball> balls, double display_step = 1) {
  gas::Gas g;
  g.radius = 4;
  g.width = 100;
  g.height = 100;
  g.display_step = display_step;
  g.balls = std::move(balls);
  return g;
}

std::uint64_t bits(double value) {
  return std::bit_cast<std::uint64_t>(value);
}

// Everything a key could change, as text, to compare before and after.
std::string state(const gas::Control& c) {
  return fmt::format(
      "{}|T0 bits {:x}|next {} {} {} {}|find {}|tone {}|stopped {}|ended {}|{} {}",
      gas::scene_text(c.gas), bits(c.gas.display_step), c.next.time,
      static_cast<int>(c.next.kind), c.next.first, c.next.second, c.must_find_collision,
      c.tone, c.stopped, c.ended, c.wall_collisions, c.ball_collisions);
}

gas::Control default_scene() {
  return gas::start_control(
      gas::read_scene_file(gas::testing::source_path("data/default.scene")));
}

// Ball 1 meets the wall x = 4 at T1 = 0.3 or 0.7 (in binary a hair off);
// ball 2 meets the wall x = 96 at TC = 46 / 4.61 = 9.978308026030367. With
// T0 = 10 the second step is T1 = TC - T, with T < TC / 2, so T + (TC - T)
// is rounded: one ulp above TC from T = 0.2999999999999998, one or two ulps
// below TC from T = 0.7000000000000002 (both found by search). Either way
// the step must end at TC itself, with the collision carried out, or a ball
// is drawn a hair before its collision and a needless tiny step follows.
gas::Control two_step_trap(double x1) {
  gas::Control c =
      gas::start_control(table({{x1, 20, -1, 0, 0}, {50, 50, 4.61, 0, 0}}, 10));
  const gas::Step first = gas::take_step(c, gas::never, nullptr);
  REQUIRE(first.collisions.size() == 1);  // ball 1 at its wall
  return c;
}

}  // namespace

TEST_SUITE("stage7") {
  TEST_CASE(
      "start_control: the gas and its limits and the picture at T and nothing found "
      "yet") {
    const gas::Gas g = table({{20, 30, 1, 2, 0}, {60, 70, -3, 0.5, 0}}, 0.25);
    const gas::Control c = gas::start_control(g);
    CHECK(gas::scene_text(c.gas) == gas::scene_text(g));
    CHECK(c.limits.x_min == 4);
    CHECK(c.limits.x_max == 96);
    CHECK(c.limits.y_min == 4);
    CHECK(c.limits.y_max == 96);
    CHECK(c.must_find_collision);
    CHECK(c.next.kind == CollisionKind::none);
    CHECK(c.wall_collisions == 0);
    CHECK(c.ball_collisions == 0);
    CHECK(c.starting_energy == gas::kinetic_energy(g));
    REQUIRE(c.picture.centres.size() == 2);
    CHECK(c.picture.centres[1].x == 60);
    CHECK(c.picture.centres[1].y == 70);
    REQUIRE(c.picture.old_centres.size() == 2);
    CHECK(c.picture.old_centres[0].x == 20);
    CHECK(c.tone == 0);
    CHECK_FALSE(c.stopped);
    CHECK_FALSE(c.ended);
  }

  TEST_CASE("take_step: T1 = T0 while no collision is due and then T1 = TC - T") {
    // One ball from x = 50 at speed 1: the wall x = 96 at TC = 46. With
    // T0 = 0.75 (exact in binary, so T = 0.75 k exactly), 61 steps reach
    // T = 45.75; the 62nd is TC - T = 0.25.
    gas::Control c = gas::start_control(table({{50, 50, 1, 0, 0}}, 0.75));
    for (int k = 1; k <= 61; ++k) {
      CAPTURE(k);
      const gas::Step step = gas::take_step(c, gas::never, nullptr);
      REQUIRE(step.length == 0.75);
      REQUIRE(step.collisions.empty());
      REQUIRE(c.gas.time == 0.75 * k);
    }
    CHECK(c.next.time == 46);
    CHECK(c.next.kind == CollisionKind::vertical_wall);
    CHECK_FALSE(c.must_find_collision);  // found once, kept while T < TC

    const gas::Step step = gas::take_step(c, gas::never, nullptr);
    CHECK(step.length == 0.25);
    CHECK(c.gas.time == 46);
    REQUIRE(step.collisions.size() == 1);
    CHECK(step.collisions[0].time == 46);
    CHECK(step.collisions[0].kind == CollisionKind::vertical_wall);
    CHECK(step.collisions[0].first == 1);
    CHECK(c.gas.balls[0].vx == -1);
    CHECK(c.gas.balls[0].x == 96);
    CHECK(c.wall_collisions == 1);
    // And the next collision is already found: the far wall, 92 later.
    CHECK(c.next.time == 46 + 92);
    CHECK(c.picture.centres[0].x == 96);
    CHECK(c.picture.old_centres[0].x == 45.75 + 50);
  }

  TEST_CASE("take_step: a step ends exactly at TC when T + (TC - T) rounds above TC") {
    gas::Control c = two_step_trap(4.3);
    const double t = c.gas.time, tc = c.next.time;
    REQUIRE(tc == 46 / 4.61);
    REQUIRE(t + (tc - t) > tc);  // the trap is really there
    const gas::Step step = gas::take_step(c, gas::never, nullptr);
    CHECK(bits(c.gas.time) == bits(tc));
    REQUIRE(step.collisions.size() == 1);
    CHECK(step.collisions[0].first == 2);
    CHECK(c.gas.balls[1].since == tc);
    CHECK(c.picture.centres[1].x == 96);
  }

  // When T + (TC - T) rounds below TC, a step that decided on the rounded
  // sum would stop an ulp short of the collision, without it, and a step of
  // ~2e-15 would follow. take_step decides by step_end's comparison and
  // ends at TC itself.
  TEST_CASE("take_step: a step ends exactly at TC when T + (TC - T) rounds below TC") {
    gas::Control c = two_step_trap(4.7);
    const double t = c.gas.time, tc = c.next.time;
    REQUIRE(tc == 46 / 4.61);
    REQUIRE(t + (tc - t) < tc);  // the trap is really there
    const gas::Step step = gas::take_step(c, gas::never, nullptr);
    CHECK(bits(c.gas.time) == bits(tc));
    REQUIRE(step.collisions.size() == 1);
    CHECK(step.collisions[0].first == 2);
  }

  TEST_CASE("take_step: the counters add up the collisions of every step by kind") {
    gas::Control c = default_scene();
    long long walls = 0, balls = 0;
    while (c.gas.time < 400) {
      const gas::Step step = gas::take_step(c, 400, nullptr);
      for (const gas::Collision& collision : step.collisions) {
        CHECK(collision.kind != CollisionKind::none);
        CHECK(collision.time == c.gas.time);  // carried out at the step's end
        (collision.kind == CollisionKind::balls ? balls : walls) += 1;
      }
    }
    CHECK(walls > 10);
    CHECK(balls > 3);
    CHECK(c.wall_collisions == walls);
    CHECK(c.ball_collisions == balls);
  }

  TEST_CASE("take_step never goes past the time limit and reaches it exactly") {
    gas::Control c = gas::start_control(table({{50, 50, 1, 0, 0}}, 0.7));
    while (c.gas.time < 5) {
      const double before = c.gas.time;
      gas::take_step(c, 5, nullptr);
      CHECK(c.gas.time > before);
      CHECK(c.gas.time <= 5);
    }
    CHECK(c.gas.time == 5);
    const gas::Step still = gas::take_step(c, 5, nullptr);  // at the limit: no further
    CHECK(still.length == 0);
    CHECK(c.gas.time == 5);

    SUBCASE("a limit just before a collision: the collision waits") {
      while (c.gas.time < 45.5) gas::take_step(c, 45.5, nullptr);
      CHECK(c.gas.time == 45.5);
      CHECK(c.wall_collisions == 0);
      CHECK(c.gas.balls[0].vx == 1);
      const gas::Step step = gas::take_step(c, 100, nullptr);
      CHECK(step.length == 0.5);
      CHECK(step.collisions.size() == 1);
    }
    SUBCASE("a limit exactly at a collision: the collision is carried out") {
      while (c.gas.time < 46) gas::take_step(c, 46, nullptr);
      CHECK(c.gas.time == 46);
      CHECK(c.wall_collisions == 1);
      CHECK(c.gas.balls[0].vx == -1);
    }
  }

  TEST_CASE(
      "take_step: a ball into a corner meets two walls at one instant in one step") {
    // From (50, 50) at (1, 1) the corner (96, 96) is reached at T = 46 in x and
    // in y at once.
    gas::Control c = gas::start_control(table({{50, 50, 1, 1, 0}}, 100));
    const gas::Step step = gas::take_step(c, gas::never, nullptr);
    CHECK(c.gas.time == 46);
    REQUIRE(step.collisions.size() == 2);
    CHECK(step.collisions[0].kind != step.collisions[1].kind);
    for (const gas::Collision& collision : step.collisions) {
      CHECK(collision.time == 46);
      CHECK(collision.first == 1);
      CHECK(collision.kind != CollisionKind::balls);
    }
    CHECK(c.gas.balls[0].vx == -1);
    CHECK(c.gas.balls[0].vy == -1);
    CHECK(c.wall_collisions == 2);
    CHECK(c.next.time == 46 + 92);  // straight back to the opposite corner
  }

  TEST_CASE("take_step: a ball at rest struck from both sides at once in one step") {
    // Balls 1 and 3 each 20 from ball 2, closing at 1: both touch it at T = 12.
    gas::Control c = gas::start_control(
        table({{30, 50, 1, 0, 0}, {50, 50, 0, 0, 0}, {70, 50, -1, 0, 0}}, 100));
    const gas::Step step = gas::take_step(c, gas::never, nullptr);
    CHECK(c.gas.time == 12);
    CHECK(step.collisions.size() >= 2);
    for (const gas::Collision& collision : step.collisions) {
      CHECK(collision.kind == CollisionKind::balls);
      CHECK(collision.time == 12);
    }
    CHECK(c.ball_collisions == static_cast<long long>(step.collisions.size()));
    CHECK(c.next.time > 12);  // nothing is left due at T = 12
    // Momentum (0) and energy (1) survive whatever the order.
    CHECK(gas::total_momentum(c.gas).x == 0);
    CHECK(gas::kinetic_energy(c.gas) == 1);
  }

  TEST_CASE("keys S and R: stop and start") {
    gas::Control c = default_scene();
    CHECK(gas::press_key(c, 'S') == gas::KeyEffect::none);
    CHECK(c.stopped);
    CHECK(gas::press_key(c, 'S') == gas::KeyEffect::none);
    CHECK(c.stopped);
    CHECK(gas::press_key(c, 'R') == gas::KeyEffect::none);
    CHECK_FALSE(c.stopped);
    gas::press_key(c, 's');
    CHECK(c.stopped);
    gas::press_key(c, 'r');
    CHECK_FALSE(c.stopped);
  }

  TEST_CASE(
      "key B: every velocity reversed with the centres kept and the tone flipped and "
      "stage 4 again") {
    // One ball from x = 50 at speed 1, reversed at T = 10 (x = 60): it now
    // reaches the wall x = 4 at T = 10 + 56 = 66, not x = 96 at T = 46.
    gas::Control c =
        gas::start_control(table({{50, 50, 1, 0.5, 0}, {20, 80, -0.25, 0, 0}}));
    for (int k = 0; k < 10; ++k) gas::take_step(c, gas::never, nullptr);
    REQUIRE(c.gas.time == 10);
    REQUIRE(c.next.time == 46);
    const std::vector<gas::Point> centres = gas::centres_at(c.gas, c.gas.time);
    const std::vector<gas::Ball> before = c.gas.balls;

    CHECK(gas::press_key(c, 'B') == gas::KeyEffect::none);
    CHECK(c.tone == 1);
    CHECK(c.must_find_collision);
    for (std::size_t i = 0; i < before.size(); ++i) {
      CAPTURE(i);
      CHECK(c.gas.balls[i].vx == -before[i].vx);
      CHECK(c.gas.balls[i].vy == -before[i].vy);
      const gas::Point now = gas::centre_at(c.gas.balls[i], c.gas.time);
      CHECK(now.x == centres[i].x);
      CHECK(now.y == centres[i].y);
    }
    CHECK(c.gas.time == 10);

    gas::take_step(c, gas::never, nullptr);
    CHECK(c.next.time == 66);
    CHECK(c.next.kind == CollisionKind::vertical_wall);
    CHECK(c.next.first == 1);

    gas::press_key(c, 'b');  // lower case too; and twice is the original tone
    CHECK(c.tone == 0);
    CHECK(c.gas.balls[0].vx == 1);
  }

  TEST_CASE("key B on a stopped model: reverse, change the tone, and go on computing") {
    // The article's B: 「すべての速度を逆にし, 基本色の色調を変えて計算過程を実行する」
    // — reverse every velocity, change the base colour's tone, and carry out
    // the computation. Our reading (lessons/README.md, glossary): pressed on
    // a stopped model it starts it, as R would; on a running one it leaves
    // it running.
    gas::Control c = default_scene();
    gas::take_step(c, gas::never, nullptr);
    const std::vector<gas::Ball> before = c.gas.balls;
    gas::press_key(c, 'S');
    REQUIRE(c.stopped);
    CHECK(gas::press_key(c, 'B') == gas::KeyEffect::none);
    CHECK_FALSE(c.stopped);
    CHECK(c.tone == 1);
    CHECK(c.gas.balls[0].vx == -before[0].vx);
    gas::press_key(c, 'b');
    CHECK_FALSE(c.stopped);
    CHECK(c.tone == 0);
  }

  TEST_CASE("keys > and <: T0 doubled and halved and nothing else changed") {
    gas::Control c = default_scene();
    gas::take_step(c, gas::never, nullptr);
    const double t0 = c.gas.display_step;
    const std::string before = state(c);
    CHECK(gas::press_key(c, '>') == gas::KeyEffect::none);
    CHECK(c.gas.display_step == 2 * t0);
    CHECK(gas::press_key(c, '<') == gas::KeyEffect::none);
    CHECK(gas::press_key(c, '<') == gas::KeyEffect::none);
    CHECK(c.gas.display_step == t0 / 2);
    gas::press_key(c, '>');
    CHECK(state(c) == before);
  }

  TEST_CASE("T0 stays finite and positive after 2000 presses of > or of <") {
    gas::Control c = default_scene();
    for (int k = 0; k < 2000; ++k) gas::press_key(c, '>');
    CHECK(std::isfinite(c.gas.display_step));
    CHECK(c.gas.display_step > 0);
    CHECK(c.gas.display_step > DBL_MAX / 2);  // as far as it could go
    gas::take_step(c, gas::never, nullptr);   // and the model still runs
    CHECK(std::isfinite(c.gas.time));

    gas::Control d = default_scene();
    for (int k = 0; k < 2000; ++k) gas::press_key(d, '<');
    CHECK(d.gas.display_step > 0);
    CHECK(std::isnormal(d.gas.display_step));
    CHECK(d.gas.display_step < 2 * DBL_MIN);  // as far as it could go
    const gas::Step step = gas::take_step(d, gas::never, nullptr);
    CHECK(step.length == d.gas.display_step);
    CHECK(d.gas.time > 0);
  }

  TEST_CASE("key 0 asks for a redraw and changes nothing and E ends") {
    gas::Control c = default_scene();
    gas::take_step(c, gas::never, nullptr);
    const std::string before = state(c);
    CHECK(gas::press_key(c, '0') == gas::KeyEffect::redraw);
    CHECK(state(c) == before);

    CHECK(gas::press_key(c, 'E') == gas::KeyEffect::end);
    CHECK(c.ended);
    gas::Control d = default_scene();
    CHECK(gas::press_key(d, 'e') == gas::KeyEffect::end);
    CHECK(d.ended);
  }

  TEST_CASE("'.' and keys that mean nothing do nothing") {
    gas::Control c = default_scene();
    for (int k = 0; k < 3; ++k) gas::take_step(c, gas::never, nullptr);
    const std::string before = state(c);
    for (const char key : std::string(".xXqQ1 ?\n\t\x7f") + '\0' + "\xff") {
      CAPTURE(static_cast<int>(key));
      CHECK(gas::press_key(c, key) == gas::KeyEffect::none);
      CHECK(state(c) == before);
    }
  }

}  // TEST_SUITE
