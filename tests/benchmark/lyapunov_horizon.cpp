// The precision horizon the Lyapunov exponent predicts. See
// lyapunov_horizon.hpp.
#include "lyapunov_horizon.hpp"

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
  return {scene,           f.exponent.value,
          f.exponent.error, f.per_collision_per_ball,
          f.per_collision_per_ball_error, f.samples,
          h.single,        h.twice,
          h.extended};
}

}  // namespace gas::benchmark
