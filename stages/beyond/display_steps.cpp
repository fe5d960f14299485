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
Step take_display_step(Control& control, double time_limit, std::FILE* trace,
                       StepKeeps keeps) {
  Gas& gas = control.gas;
  Step step;
  // The step's end: T + T0, or the time limit if that comes first.
  const double now = gas.time;
  const double end = now + gas.display_step;
  const double target = end < time_limit ? end : time_limit;
  const long long before = control.wall_collisions + control.ball_collisions;

  // Collision after collision up to the end, with no picture: the clock to
  // TC, stage 5 for every collision due then, stage 4 for the next one.
  find_next_collision(control, trace);
  while (control.next.kind != CollisionKind::none && control.next.time <= target) {
    gas.time = control.next.time;
    carry_out_due_collisions(control, step, trace);
    if (!keeps.collisions) step.collisions.clear();  // no list: nobody reads it
  }

  // The picture: the centres at the end of the step (only the clock, if
  // nothing draws them).
  step.length = target - now;
  if (keeps.picture) {
    shift_time(gas, control.picture, target);
  } else {
    gas.time = target;
  }
  if (trace != nullptr) {
    fmt::print(
        trace,
        "stage 5  new coordinates: T1 = {} = {}, T = {}, {} collisions on the way\n",
        target < end ? "the time left" : "T0", step.length, gas.time,
        control.wall_collisions + control.ball_collisions - before);
  }
  return step;
}
// [/anchor: take-display-step]

Step take_step_by(PictureRule rule, Control& control, double time_limit, std::FILE* trace,
                  StepKeeps keeps) {
  return rule == PictureRule::every_collision
             ? take_step(control, time_limit, trace)
             : take_display_step(control, time_limit, trace, keeps);
}

}  // namespace gas
