// Which exercise tests this test program runs: the first GAS_UNLOCKED_TESTS
// of them in order (-1: all); the others are skipped. Each test program
// compiles this file with its own GAS_UNLOCKED_TESTS, and with
// GAS_EXERCISE_TESTS, the number of tests CMake counted in the test files.
#include <string>
#include <vector>

namespace gas::exercises {
namespace {

// The test numbers registered so far.
struct Registrations {
  std::vector<int> times =
      std::vector<int>(GAS_EXERCISE_TESTS + 1, 0);  // times[n]: test n
  int stray = 0;  // a number outside 1 .. GAS_EXERCISE_TESTS, if one came
};

// A function's static, so that it exists before the test files' registrations
// use it, whatever order the files are initialized in.
Registrations& registrations() {
  static Registrations r;
  return r;
}

}  // namespace

// Declared in exercise_test.hpp.
bool locked(int ordinal) {
  Registrations& r = registrations();
  if (ordinal >= 1 && ordinal <= GAS_EXERCISE_TESTS) {
    ++r.times[static_cast<std::size_t>(ordinal)];
  } else {
    r.stray = ordinal;
  }
  return GAS_UNLOCKED_TESTS >= 0 && ordinal > GAS_UNLOCKED_TESTS;
}

// Used by runner.cpp: empty if the tests are numbered 1 .. GAS_EXERCISE_TESTS,
// each number once, else what is wrong.
std::string numbering_problem() {
  const Registrations& r = registrations();
  const std::string advice =
      " (lessons/exercises/CMakeLists.txt counts the lines that start with "
      "EXERCISE_TEST( in each test file)";
  if (r.stray != 0)
    return "a test numbered " + std::to_string(r.stray) + ", outside 1 to " +
           std::to_string(GAS_EXERCISE_TESTS) + advice;
  for (std::size_t n = 1; n < r.times.size(); ++n) {
    if (r.times[n] != 1)
      return "test number " + std::to_string(n) + " is registered " +
             std::to_string(r.times[n]) + " times" + advice;
  }
  return "";
}

}  // namespace gas::exercises
