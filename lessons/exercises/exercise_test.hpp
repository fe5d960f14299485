// The provided tests of the student exercises: what every test file of
// lessons/exercises/NN-name/ includes.
//
// EXERCISE_TEST("name") is doctest's TEST_CASE("name"), locked — skipped,
// with doctest::skip — until GAS_UNLOCKED reaches it (lessons/exercises/
// README.md). The tests are numbered in order: exercise 01's first, in the
// order they are written in their file, then exercise 02's, and so on.
// lessons/exercises/CMakeLists.txt compiles each test file with
// GAS_TESTS_BEFORE, the number of tests of the exercises before it, and the
// counter below numbers the file's own tests: doctest registers the tests of
// one file from top to bottom, so the counter meets them in that order.
//
// Also a small table to put balls on, and how doctest prints the stages'
// small structs in a failed check.
#pragma once

#include <doctest/doctest.h>

#include <ostream>
#include <utility>
#include <vector>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"

namespace gas::exercises {

// Whether test number `ordinal` (1 = the first test of exercise 01) is locked
// in this test program. Defined in unlock.cpp, which each test program
// compiles with its own number of unlocked tests.
bool locked(int ordinal);

// A 40 x 30 table with balls of radius 1, so that every centre stays within
// 1 <= x <= 39, 1 <= y <= 29; T = `time`, T0 = 1.
inline Gas table(std::vector<Ball> balls, double time = 0) {
  Gas gas;
  gas.radius = 1;
  gas.width = 40;
  gas.height = 30;
  gas.balls = std::move(balls);
  gas.time = time;
  gas.display_step = 1;
  return gas;
}

}  // namespace gas::exercises

namespace {
int exercise_tests_in_this_file = 0;
}  // namespace

// (In TEST_CASE, `name * decorator` is doctest's way to decorate a test.)
#define EXERCISE_TEST(name)      \
  TEST_CASE(name* doctest::skip( \
      gas::exercises::locked(GAS_TESTS_BEFORE + ++exercise_tests_in_this_file)))

// Printed in failed checks as (x, y) and [column, row].
namespace gas {
inline std::ostream& operator<<(std::ostream& out, const Point& p) {
  return out << '(' << p.x << ", " << p.y << ')';
}
inline std::ostream& operator<<(std::ostream& out, const Cell& c) {
  return out << "[column " << c.column << ", row " << c.row << ']';
}
}  // namespace gas
