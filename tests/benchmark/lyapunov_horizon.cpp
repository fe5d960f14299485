// The precision horizon the Lyapunov exponent predicts. See
// lyapunov_horizon.hpp.
#include "lyapunov_horizon.hpp"

#include <cmath>
#include <limits>

#include "beyond/lyapunov.hpp"
#include "beyond/lyapunov_screen.hpp"
#include "beyond/strategy.hpp"
#include "stage7_control.hpp"

namespace gas::benchmark {

ExponentFigures measure_exponent(const std::string& scene, const Gas& gas,
                                 long long samples) {
  Gas start = gas;
  start.display_step = 1e300;  // steps end on collisions: no pictures
  Control control = start_control_for(start);
  LyapunovExponent lyapunov(control.gas);
  control.observer = &lyapunov;
  LyapunovFigures f;
  while ((f = lyapunov.measured(control.gas)).samples < samples)
    take_step(control, never, nullptr);
  const PrecisionHorizons h = precision_horizons(control.gas, f);
  return {scene,
          f.exponent.value,
          f.exponent.error,
          f.per_collision_per_ball,
          f.per_collision_per_ball_error,
          f.samples,
          h.single,
          h.twice,
          h.extended};
}

namespace {

// A bare change carried along on stage 7's hook.
struct Carried final : CollisionObserver {
  TangentDynamics tangent;
  explicit Carried(const Gas& gas) : tangent(gas, 1989) {}
  void before_collision(const Gas& gas, const Collision& c) override {
    tangent.before_collision(gas, c);
  }
};

}  // namespace

Horizons horizons_along_the_run(const Gas& gas, double most_per_ball) {
  Gas start = gas;
  start.display_step = 1e300;
  Control control = start_control_for(start);
  Carried carried(control.gas);
  control.observer = &carried;
  const double distance = horizon_distance_radii * gas.radius;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int digits[3] = {std::numeric_limits<float>::digits,
                         std::numeric_limits<double>::digits,
                         std::numeric_limits<long double>::digits};
  double reached[3] = {nan, nan, nan};
  const auto n = static_cast<double>(gas.balls.size());
  double growth = 0;  // ln of the growth so far, less what scaling took out
  while (std::isnan(reached[2])) {
    take_step(control, never, nullptr);
    const double per_ball =
        static_cast<double>(control.wall_collisions + control.ball_collisions) / n;
    if (per_ball > most_per_ball) break;
    const double norm = carried.tangent.norm_at(control.gas.time);
    for (int t = 0; t < 3; ++t) {
      if (std::isnan(reached[t]) &&
          growth + std::log(norm) >= std::log(distance / coordinate_ulp(gas, digits[t])))
        reached[t] = per_ball;
    }
    if (norm > 1e100) {  // far from overflow, and no rounding of the growth
      growth += std::log(norm);
      carried.tangent.scale_at(control.gas.time, 1 / norm);
    }
  }
  return {reached[0], reached[1], reached[2]};
}

}  // namespace gas::benchmark
