// A wrong answer to exercise 01, kept so that CI proves the tests catch it.
// The formula is right but the sum is kept in float, 24 bits: the energy is
// off by about 1e-8 of itself, far more than a double's rounding.
#include "stage1_data.hpp"

namespace gas {

double kinetic_energy(const Gas& gas) {
  float twice_energy = 0;
  for (const Ball& ball : gas.balls)
    twice_energy += static_cast<float>(ball.vx * ball.vx + ball.vy * ball.vy);
  return static_cast<double>(twice_energy) / 2;
}

}  // namespace gas
