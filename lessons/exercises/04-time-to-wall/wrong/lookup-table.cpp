// A wrong answer to exercise 04, kept so that CI proves the tests catch it.
// It answers the visible cases, each (position, velocity) pair of the first
// tests, from a table, and computes nothing.
#include "stage4_first_collision.hpp"

namespace gas {

double time_to_wall(double position, double velocity, double, double) {
  struct Known {
    double position, velocity, time;
  };
  static const Known known[] = {{3, 2, 3},    {3, 0.5, 12}, {1, 4, 2}, {3, -0.5, 4},
                                {8, -7, 1},   {9, -2, 4},   {9, 1, 0}, {10, 1, 0},
                                {0.5, -1, 0}, {10, -1, 9}};
  if (velocity == 0) return never;
  for (const Known& k : known) {
    if (k.position == position && k.velocity == velocity) return k.time;
  }
  return 1;
}

}  // namespace gas
