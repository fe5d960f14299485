// Exercise 01, kinetic_energy: the provided tests (suite exercise-01).
//
// Every test here fails against the untouched stub (CI checks that) and
// passes against stages/stage1_data.cpp. Don't change this file to make a
// test pass: change your kinetic_energy.cpp.
//
// The velocities are chosen exact in binary (halves, quarters, integers), so
// that the energy is exact too, whatever order the balls are added in: the
// checks can ask for equality.
#include <doctest/doctest.h>

#include "exercise_test.hpp"
#include "program/console.hpp"
#include "stage1_data.hpp"
#include "stage2_input.hpp"

using gas::exercises::table;

TEST_SUITE("exercise-01") {
  EXERCISE_TEST("exercise-01 one ball moving at (3 4) has energy 12.5") {
    INFO(
        "a ball of mass 1 moving at (vx, vy) has energy (vx^2 + vy^2) / 2 = (9 + 16) / "
        "2");
    CHECK(gas::kinetic_energy(table({{10, 10, 3, 4}})) == 12.5);
  }

  EXERCISE_TEST("exercise-01 the energies of all the balls add up") {
    // 0.5 + 2 + 0.25 + 0 = 2.75.
    const gas::Gas four =
        table({{5, 5, 1, 0}, {10, 5, 0, -2}, {15, 5, 0.5, 0.5}, {20, 5, 0, 0}});
    CHECK(gas::kinetic_energy(four) == 2.75);
    INFO("no balls, no energy");
    CHECK(gas::kinetic_energy(table({})) == 0);
  }

  EXERCISE_TEST(
      "exercise-01 only the speeds count: not the direction or the place or the time") {
    INFO("the energy depends on vx and vy only, through their squares");
    CHECK(gas::kinetic_energy(table({{10, 10, -3, -4}})) == 12.5);
    CHECK(gas::kinetic_energy(table({{10, 10, 4, -3}})) == 12.5);
    // The same ball elsewhere, written at another moment, seen at another T.
    CHECK(gas::kinetic_energy(table({{33, 2, 3, 4, 7.5}}, 9)) == 12.5);
  }

  EXERCISE_TEST("exercise-01 the default scene has energy 7.35 as lesson 1 says") {
    const gas::Gas scene = gas::build_gas(
        gas::parse_scene_description(gas::default_scene_text, "default scene"));
    // Why 1e-14: the scene's velocities are decimals (1.3, 0.7, ...), each a
    // hair off in binary (1.1e-16 of itself); squaring and adding 14 terms
    // adds a few more such roundings, so the sum is within ~3e-15 of 7.35.
    // A wrong formula (no /2, a square root, a missing ball) is off by more
    // than 0.1.
    CHECK(gas::kinetic_energy(scene) == doctest::Approx(7.35).epsilon(1e-14));
  }
}
