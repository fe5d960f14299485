// The doctest runner of the exercise tests (exercise_tests and
// exercise_tests_stubs). Before any test runs it checks that the tests are
// numbered as CMake counted them, so that GAS_UNLOCKED unlocks exactly the
// first N (see exercise_test.hpp and unlock.cpp).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

namespace gas::exercises {
std::string numbering_problem();  // unlock.cpp
}

int main(int argc, char** argv) {
  if (const std::string problem = gas::exercises::numbering_problem(); !problem.empty()) {
    std::fprintf(stderr, "exercise tests: %s\n", problem.c_str());
    return 2;
  }
  doctest::Context context(argc, argv);
  return context.run();
}
