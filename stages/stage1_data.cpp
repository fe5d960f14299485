// Stage 1 — variables and data: the few sums over the balls that every later
// stage and the statistics screen share. See stage1_data.hpp.
#include "stage1_data.hpp"

#include <cmath>

namespace gas {

// [anchor: centres-at]
std::vector<Point> centres_at(const Gas& gas, double time) {
  std::vector<Point> centres;
  centres.reserve(gas.balls.size());
  for (const Ball& ball : gas.balls) centres.push_back(centre_at(ball, time));
  return centres;
}
// [/anchor: centres-at]

#ifndef GAS_STUDENT_KINETIC_ENERGY  // see lessons/exercises/01-kinetic-energy
double kinetic_energy(const Gas& gas) {
  double twice_energy = 0;
  for (const Ball& ball : gas.balls)
    twice_energy += ball.vx * ball.vx + ball.vy * ball.vy;
  return twice_energy / 2;
}
#endif

Point total_momentum(const Gas& gas) {
  Point momentum;
  for (const Ball& ball : gas.balls) {
    momentum.x += ball.vx;
    momentum.y += ball.vy;
  }
  return momentum;
}

#ifndef GAS_STUDENT_MEAN_SPEED  // see lessons/exercises/11-mean-speed
double mean_speed(const Gas& gas) {
  if (gas.balls.empty()) return 0;
  double sum = 0;
  for (const Ball& ball : gas.balls) sum += std::hypot(ball.vx, ball.vy);
  return sum / static_cast<double>(gas.balls.size());
}
#endif

}  // namespace gas
