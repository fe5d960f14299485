// Exercise 10, press_key: the provided tests (suite exercise-10).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage7_control.cpp. Don't change this file to make a
// test pass: change your press_key.cpp.
//
// The loop's state is a Control (stage 7), set up by start_control from a
// gas of three balls at T = 2, T0 = 1. The numbers are exact in binary.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "exercise_test.hpp"
#include "stage7_control.hpp"

namespace {

using gas::Control;
using gas::KeyEffect;

Control three_balls() {
  return gas::start_control(gas::exercises::table(
      {{10, 10, 1, 0.5, 0}, {20, 15, -0.25, 1, 1.5}, {30, 5, 0, -2, 2}}, 2));
}

// KeyEffect as a number, for doctest to print: 0 none, 1 redraw, 2 end.
int effect(Control& control, char key) {
  return static_cast<int>(gas::press_key(control, key));
}
constexpr int none = static_cast<int>(KeyEffect::none);
constexpr int redraw = static_cast<int>(KeyEffect::redraw);
constexpr int end = static_cast<int>(KeyEffect::end);

}  // namespace

TEST_SUITE("exercise-10") {
  TEST_CASE("exercise-10 S stops the model and R runs it again") {
    Control control = three_balls();
    CHECK(effect(control, 'S') == none);
    CHECK(control.stopped);
    CHECK(effect(control, 'R') == none);
    CHECK_FALSE(control.stopped);
  }

  TEST_CASE("exercise-10 > doubles T0 and < halves it") {
    Control control = three_balls();
    CHECK(effect(control, '>') == none);
    CHECK(control.gas.display_step == 2);
    gas::press_key(control, '>');
    CHECK(control.gas.display_step == 4);
    gas::press_key(control, '<');
    gas::press_key(control, '<');
    gas::press_key(control, '<');
    CHECK(control.gas.display_step == 0.5);
    INFO("T0 only decides where the pictures are taken: the clock T stays where it is");
    CHECK(control.gas.time == 2);
  }

  TEST_CASE(
      "exercise-10 B reverses every velocity at the present time and changes the tone") {
    Control control = three_balls();
    control.must_find_collision = false;
    const std::vector<gas::Ball> before = control.gas.balls;
    const std::vector<gas::Point> centres = gas::centres_at(control.gas, 2);
    CHECK(effect(control, 'B') == none);
    for (std::size_t i = 0; i < before.size(); ++i) {
      CAPTURE(i + 1);  // the ball's number
      CHECK(control.gas.balls[i].vx == -before[i].vx);
      CHECK(control.gas.balls[i].vy == -before[i].vy);
    }
    INFO(
        "the balls must still be where they are now: reverse them at T "
        "(reverse_velocities)");
    const std::vector<gas::Point> after = gas::centres_at(control.gas, 2);
    for (std::size_t i = 0; i < before.size(); ++i) {
      CAPTURE(i + 1);
      CHECK(after[i].x == centres[i].x);
      CHECK(after[i].y == centres[i].y);
    }
    CHECK(control.tone == 1);
    INFO("every future collision changes: stage 4 must run again");
    CHECK(control.must_find_collision);
    gas::press_key(control, 'B');
    CHECK(control.tone == 0);
    CHECK(control.gas.balls[0].vx == before[0].vx);
  }

  TEST_CASE("exercise-10 B on a stopped model reverses it and goes on computing") {
    Control control = three_balls();
    control.stopped = true;
    const double vx = control.gas.balls[0].vx;
    CHECK(effect(control, 'B') == none);
    CHECK(control.gas.balls[0].vx == -vx);
    INFO(
        "B reverses, changes the tone and goes on computing: a stopped model runs again "
        "(our reading of the article)");
    CHECK_FALSE(control.stopped);
  }

  TEST_CASE("exercise-10 B tells the observer before it rewrites the columns of R") {
    // An observer that notes what the columns of R were when it was told.
    struct Listener final : gas::CollisionObserver {
      int told = 0;
      std::vector<gas::Ball> balls_then;  // as they were when told
      void before_rows_rewritten(const gas::Gas& gas) override {
        ++told;
        balls_then = gas.balls;
      }
    } listener;
    Control control = three_balls();
    const std::vector<gas::Ball> before = control.gas.balls;
    control.observer = &listener;
    gas::press_key(control, 'B');
    INFO("B must call control.observer->before_rows_rewritten(control.gas) once");
    CHECK(listener.told == 1);
    INFO("... and before reverse_velocities: the observer must see the old columns");
    REQUIRE(listener.balls_then.size() == before.size());
    for (std::size_t i = 0; i < before.size(); ++i) {
      CAPTURE(i + 1);
      CHECK(listener.balls_then[i].vx == before[i].vx);
      CHECK(listener.balls_then[i].since == before[i].since);
    }
    // No other key tells it anything; and with no observer B still works.
    for (const char key : std::string("SR><0.x")) gas::press_key(control, key);
    CHECK(listener.told == 1);
    control.observer = nullptr;
    gas::press_key(control, 'B');
    CHECK(control.tone == 0);
  }

  TEST_CASE("exercise-10 0 asks for a redraw and E ends") {
    Control control = three_balls();
    CHECK(effect(control, '0') == redraw);
    CHECK_FALSE(control.ended);
    CHECK(effect(control, 'E') == end);
    CHECK(control.ended);
  }

  TEST_CASE("exercise-10 keys work in lower case and other keys do nothing") {
    Control control = three_balls();
    gas::press_key(control, 's');
    CHECK(control.stopped);
    gas::press_key(control, 'r');
    CHECK_FALSE(control.stopped);
    CHECK(effect(control, 'e') == end);
    Control quiet = three_balls();
    for (const char key : {'.', 'x', ' ', '1', '\n'}) {
      CAPTURE(key);
      CHECK(effect(quiet, key) == none);
    }
    CHECK(quiet.gas.display_step == 1);
    CHECK(quiet.gas.balls[2].vy == -2);
    CHECK(quiet.tone == 0);
    CHECK_FALSE(quiet.stopped);
    CHECK_FALSE(quiet.ended);
  }

  TEST_CASE("exercise-10 T0 stays a positive finite number that still moves T") {
    Control control = three_balls();
    for (int press = 0; press < 2000; ++press) gas::press_key(control, '>');
    INFO("doubled 2000 times a double overflows to infinity: stop doubling before that");
    CHECK(std::isfinite(control.gas.display_step));
    CHECK(control.gas.display_step > 1e300);
    control.gas.display_step = 1;
    control.gas.time = 1000;
    for (int press = 0; press < 2000; ++press) gas::press_key(control, '<');
    INFO(
        "halved 2000 times T0 would reach 0, or become so small that T + T0 == T: "
        "stop halving before that");
    CHECK(control.gas.display_step > 0);
    CHECK(control.gas.time + control.gas.display_step > control.gas.time);
    CHECK(control.gas.display_step < 1e-10);
  }

  TEST_CASE("exercise-10 300 generated runs of keys against a model of the keys") {
    // A model of what the keys do, kept beside the Control: each run
    // presses 1 to 40 keys drawn from the ones that do something and some
    // that do nothing, then the state must be the model's.
    constexpr char keys[] = "SRBE0<>srbe.x 1";
    gas::exercises::Draw draw(1001);
    for (int n = 1; n <= 300; ++n) {
      Control control = three_balls();
      control.gas.display_step = draw.magnitude(-3, 3);
      control.must_find_collision = false;
      bool stopped = false, ended = false, must_find = false;
      int tone = 0;
      double step = control.gas.display_step;
      std::vector<gas::Ball> balls = control.gas.balls;
      std::string pressed;
      bool right = true;
      CAPTURE(n);
      for (int k = draw.integer(1, 40); k > 0 && right; --k) {
        const char key = keys[draw.integer(0, static_cast<int>(sizeof keys) - 2)];
        pressed += key;
        int wanted = none;
        switch (key) {
          case 'S':
          case 's':
            stopped = true;
            break;
          case 'R':
          case 'r':
            stopped = false;
            break;
          case 'B':
          case 'b': {
            gas::Gas reversed = control.gas;
            reversed.balls = balls;
            gas::reverse_velocities(reversed);
            balls = reversed.balls;
            tone = 1 - tone;
            must_find = true;
            stopped = false;  // and go on computing
            break;
          }
          case 'E':
          case 'e':
            ended = true;
            wanted = end;
            break;
          case '0':
            wanted = redraw;
            break;
          case '>':  // T0 stays finite (exercise-10 T0 stays a positive ...)
            if (std::isfinite(2 * step)) step *= 2;
            break;
          case '<':  // ... and a normal number that still moves T
            if (std::isnormal(step / 2) && 2 + step / 2 > 2) step /= 2;
            break;
          default:
            break;
        }
        const int got = effect(control, key);
        const std::string what = fmt::format("after the keys \"{}\"", pressed);
        right = CHECK_NUMBER(what + ": press_key's effect (0 none, 1 redraw, 2 end)", got,
                             wanted, 0) &&
                CHECK_NUMBER(what + ": T0", control.gas.display_step, step, 0) &&
                CHECK_NUMBER(what + ": T", control.gas.time, 2, 0) &&
                CHECK_NUMBER(what + ": stopped", control.stopped, stopped, 0) &&
                CHECK_NUMBER(what + ": ended", control.ended, ended, 0) &&
                CHECK_NUMBER(what + ": tone", control.tone, tone, 0) &&
                CHECK_NUMBER(what + ": must_find_collision", control.must_find_collision,
                             must_find, 0);
        for (std::size_t i = 0; i < balls.size() && right; ++i) {
          const gas::Ball& b = control.gas.balls[i];
          const std::string ball = fmt::format("{}: ball {} ", what, i + 1);
          right = CHECK_NUMBER(ball + "x", b.x, balls[i].x, 0) &&
                  CHECK_NUMBER(ball + "y", b.y, balls[i].y, 0) &&
                  CHECK_NUMBER(ball + "vx", b.vx, balls[i].vx, 0) &&
                  CHECK_NUMBER(ball + "vy", b.vy, balls[i].vy, 0) &&
                  CHECK_NUMBER(ball + "since", b.since, balls[i].since, 0);
        }
      }
      if (!right) break;
    }
  }
}
