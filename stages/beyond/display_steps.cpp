// Pictures only at the display steps. See beyond/display_steps.hpp.
#include "beyond/display_steps.hpp"

#include <fmt/format.h>

namespace gas {

const char* picture_rule_name(PictureRule rule) {
  return rule == PictureRule::every_collision ? "collisions" : "steps";
}

std::optional<PictureRule> picture_rule_named(std::string_view name) {
  for (const PictureRule rule :
       {PictureRule::every_collision, PictureRule::display_steps})
    if (name == picture_rule_name(rule)) return rule;
  return std::nullopt;
}

// [anchor: take-display-step]
Step take_display_step(Control& control, double time_limit, std::FILE* trace) {
  Gas& gas = control.gas;
  Step step;
  // The step's end: T + T0, or the time limit if that comes first.
  const double now = gas.time;
  const double end = now + gas.display_step;
  const double target = end < time_limit ? end : time_limit;

  // Collision after collision up to the end, with no picture: the clock to
  // TC, stage 5 for every collision due then, stage 4 for the next one.
  find_next_collision(control, trace);
  while (control.next.kind != CollisionKind::none && control.next.time <= target) {
    gas.time = control.next.time;
    carry_out_due_collisions(control, step, trace);
  }

  // The picture: the centres at the end of the step.
  step.length = target - now;
  shift_time(gas, control.picture, target);
  if (trace != nullptr) {
    fmt::print(
        trace,
        "stage 5  new coordinates: T1 = {} = {}, T = {}, {} collisions on the way\n",
        target < end ? "the time left" : "T0", step.length, gas.time,
        step.collisions.size());
  }
  return step;
}
// [/anchor: take-display-step]

Step take_step_by(PictureRule rule, Control& control, double time_limit,
                  std::FILE* trace) {
  return rule == PictureRule::every_collision
             ? take_step(control, time_limit, trace)
             : take_display_step(control, time_limit, trace);
}

}  // namespace gas
