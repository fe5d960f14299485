// Exercise 01, kinetic_energy: the provided tests (suite exercise-01).
//
// Every test here fails against the untouched stub (CI checks that), passes
// against stages/stage1_data.cpp, and catches the wrong answers in wrong/
// (CI checks those too). Don't change this file to make a test pass: change
// your kinetic_energy.cpp.
//
// The first velocities are chosen exact in binary (halves, quarters,
// integers), so that the energy is exact too, whatever order the balls are
// added in: those checks ask for equality. The generated gases ask for
// 1e-14 of the value, and say why.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include "exercise_test.hpp"
#include "program/console.hpp"
#include "stage1_data.hpp"
#include "stage2_input.hpp"

namespace {

using gas::exercises::describe;
using gas::exercises::Draw;
using gas::exercises::table;

// The energy as it must be: each term exact in long double (a product of two
// doubles needs 106 bits; long double keeps 64, so each term and the sum are
// within 1e-19 of exact), rounded once to a double at the end.
double exact_energy(const gas::Gas& gas) {
  long double twice = 0;
  for (const gas::Ball& ball : gas.balls)
    twice += static_cast<long double>(ball.vx) * ball.vx +
             static_cast<long double>(ball.vy) * ball.vy;
  return static_cast<double>(twice / 2);
}

#define CHECK_ENERGY(of, wanted, relative)                                           \
  CHECK_NUMBER("kinetic_energy of " + describe(of), gas::kinetic_energy(of), wanted, \
               relative)

}  // namespace

TEST_SUITE("exercise-01") {
  TEST_CASE("exercise-01 one ball moving at (3 4) has energy 12.5") {
    INFO(
        "a ball of mass 1 moving at (vx, vy) has energy (vx^2 + vy^2) / 2 = (9 + 16) / "
        "2");
    CHECK_ENERGY(table({{10, 10, 3, 4}}), 12.5, 0);
  }

  TEST_CASE("exercise-01 the energies of all the balls add up") {
    // 0.5 + 2 + 0.25 + 0 = 2.75.
    CHECK_ENERGY(table({{5, 5, 1, 0}, {10, 5, 0, -2}, {15, 5, 0.5, 0.5}, {20, 5, 0, 0}}),
                 2.75, 0);
    INFO("no balls, no energy");
    CHECK_ENERGY(table({}), 0, 0);
  }

  TEST_CASE(
      "exercise-01 only the speeds count: not the direction or the place or the time") {
    INFO("the energy depends on vx and vy only, through their squares");
    CHECK_ENERGY(table({{10, 10, -3, -4}}), 12.5, 0);
    CHECK_ENERGY(table({{10, 10, 4, -3}}), 12.5, 0);
    // The same ball elsewhere, written at another moment, seen at another T.
    CHECK_ENERGY(table({{33, 2, 3, 4, 7.5}}, 9), 12.5, 0);
  }

  TEST_CASE("exercise-01 the default scene has energy 7.35 as lesson 1 says") {
    const gas::Gas scene = gas::build_gas(
        gas::parse_scene_description(gas::default_scene_text, "default scene"));
    // Why 1e-14: the scene's velocities are decimals (1.3, 0.7, ...), each a
    // hair off in binary (1.1e-16 of itself); squaring and adding 14 terms
    // adds a few more such roundings, so the sum is within ~3e-15 of 7.35.
    // A wrong formula (no /2, a square root, a missing ball) is off by more
    // than 0.1, a sum kept in float by about 1e-8.
    CHECK_ENERGY(scene, 7.35, 1e-14);
  }

  TEST_CASE("exercise-01 300 generated gases: any number of balls and any velocities") {
    Draw draw(101);
    for (int n = 1; n <= 300; ++n) {
      std::vector<gas::Ball> balls(static_cast<std::size_t>(draw.integer(0, 60)));
      const double scale = draw.magnitude(-3, 3);  // speeds from 0.001 to 1000
      for (gas::Ball& ball : balls) {
        ball = {draw.uniform(1, 39), draw.uniform(1, 29), scale * draw.uniform(-1, 1),
                scale * draw.uniform(-1, 1), draw.uniform(0, 50)};
      }
      const gas::Gas gas = table(balls, draw.uniform(50, 100));
      CAPTURE(n);
      // Why 1e-14: a sum of at most 60 positive terms, in any order, rounds
      // 60 times at most, each by 1.1e-16 of the sum: within 7e-15 of the
      // exact energy, which exact_energy gives to 1e-19. A sum in float is
      // off by about 1e-8, a missing or doubled ball by far more.
      if (!CHECK_ENERGY(gas, exact_energy(gas), 1e-14)) break;
    }
  }

  TEST_CASE(
      "exercise-01 the same velocities give the same energy wherever and whenever") {
    Draw draw(102);
    for (int n = 1; n <= 100; ++n) {
      std::vector<gas::Ball> balls(static_cast<std::size_t>(draw.integer(1, 20)));
      for (gas::Ball& ball : balls)
        ball = {draw.uniform(1, 39), draw.uniform(1, 29), draw.uniform(-3, 3),
                draw.uniform(-3, 3), draw.uniform(0, 5)};
      const gas::Gas here = table(balls, 5);
      for (gas::Ball& ball : balls)
        ball = {draw.uniform(1, 39), draw.uniform(1, 29), ball.vx, ball.vy,
                draw.uniform(0, 500)};
      const gas::Gas there = table(balls, draw.uniform(500, 1000));
      CAPTURE(n);
      INFO("the same velocities as " << describe(here));
      if (!CHECK_ENERGY(there, gas::kinetic_energy(here), 0)) break;
    }
  }
}
