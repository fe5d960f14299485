// Stage 7 — model control. See stage7_control.hpp.
#include "stage7_control.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace gas {

Control start_control(Gas gas, std::unique_ptr<FirstCollisionFinder> finder) {
  Control control;
  control.finder = finder ? std::move(finder) : std::make_unique<ArticleScan>();
  control.gas = std::move(gas);
  control.limits = centre_limits(control.gas);
  control.starting_energy = kinetic_energy(control.gas);
  control.picture.centres = centres_at(control.gas, control.gas.time);
  control.picture.old_centres = control.picture.centres;
  return control;
}

long long most_collisions_at_one_instant(std::size_t ball_count) {
  const auto n = static_cast<long long>(ball_count);
  return 1000 + 100 * n * n;
}

namespace {

const char* kind_name(CollisionKind kind) {
  switch (kind) {
    case CollisionKind::none:
      return "none";
    case CollisionKind::horizontal_wall:
      return "horizontal wall";
    case CollisionKind::vertical_wall:
      return "vertical wall";
    case CollisionKind::balls:
      return "two balls";
  }
  return "?";
}

void trace_first_collision(std::FILE* trace, const Collision& c) {
  if (trace == nullptr) return;
  fmt::print(trace, "stage 4  first collision: TC={} K={} ({}) N1={} N2={}\n", c.time,
             static_cast<int>(c.kind), kind_name(c.kind), c.first, c.second);
}

// Stage 4, as the loop calls it. At the start, and after a key changed the
// velocities, every prediction is made afresh; otherwise the finder goes on
// from the collisions it was told of (for the article's scan: the same thing).
void find_next(Control& control, std::FILE* trace) {
  if (control.must_find_collision) control.finder->rebuild(control.gas, control.limits);
  control.next = control.finder->first(control.gas);
  control.must_find_collision = false;
  trace_first_collision(trace, control.next);
}

// Stage 5's velocity part, as the loop calls it.
void carry_out(Control& control, Step& step, std::FILE* trace) {
  const Collision& c = control.next;
  if (control.observer != nullptr) control.observer->before_collision(control.gas, c);
  apply_collision(control.gas, control.limits, c);
  if (control.observer != nullptr) control.observer->after_collision(control.gas, c);
  control.finder->update(control.gas, c);
  if (c.kind == CollisionKind::balls) {
    ++control.ball_collisions;
  } else {
    ++control.wall_collisions;
  }
  step.collisions.push_back(c);
  if (trace != nullptr) {
    fmt::print(trace, "stage 5  new velocities: K={} N1={} N2={}\n",
               static_cast<int>(c.kind), c.first, c.second);
  }
}

}  // namespace

// [anchor: take-step]
Step take_step(Control& control, double time_limit, std::FILE* trace) {
  Gas& gas = control.gas;
  Step step;

  // Stage 4, if the last step ended on a collision (or a key changed the
  // velocities).
  find_next_collision(control, trace);

  // Stage 5: T1 = T0 if no collision is due within the step, else TC - T;
  // never past the time limit.
  const double now = gas.time;
  StepEnd end = step_end(now, gas.display_step, control.next.time);
  const bool limited = end.time > time_limit;
  if (limited) end = {time_limit, control.next.time <= time_limit};
  step.length = end.time - now;
  shift_time(gas, control.picture, end.time);
  if (trace != nullptr) {
    fmt::print(trace, "stage 5  new coordinates: T1 = {} = {}, T = {}\n",
               end.on_collision ? "TC - T"
               : limited        ? "the time left"
                                : "T0",
               step.length, gas.time);
  }

  // Stage 5 for the collision, then stage 7: while TC <= T, back to stage 4.
  if (end.on_collision) carry_out_due_collisions(control, step, trace);
  return step;
}
// [/anchor: take-step]

void find_next_collision(Control& control, std::FILE* trace) {
  if (control.must_find_collision) find_next(control, trace);
}

// [anchor: due-collisions]
void carry_out_due_collisions(Control& control, Step& step, std::FILE* trace) {
  const Gas& gas = control.gas;
  const long long most = most_collisions_at_one_instant(gas.balls.size());
  long long at_this_instant = 0;
  while (control.next.kind != CollisionKind::none && control.next.time <= gas.time) {
    if (++at_this_instant > most) {
      throw std::runtime_error(
          fmt::format("at T = {:.17g} more than {} collisions happened at one instant; "
                      "round-off has "
                      "trapped the balls and time cannot move on",
                      gas.time, most));
    }
    carry_out(control, step, trace);
    if (trace != nullptr)
      fmt::print(trace, "stage 7  model control: TC <= T, back to stage 4\n");
    find_next(control, trace);
  }
}
// [/anchor: due-collisions]

void trace_decision(const Control& control, std::FILE* trace) {
  fmt::print(trace, "stage 7  model control: TC = {} > T = {}, back to stage 5\n",
             control.next.time, control.gas.time);
}

#ifndef GAS_STUDENT_PRESS_KEY  // see lessons/exercises/10-press-key
// [anchor: press-key]
KeyEffect press_key(Control& control, char key) {
  switch (std::toupper(static_cast<unsigned char>(key))) {
    case 'S':
      control.stopped = true;
      break;
    case 'R':
      control.stopped = false;
      break;
    case 'B':  // reverse all velocities, change the tone, go on computing
      if (control.observer != nullptr)
        control.observer->before_rows_rewritten(control.gas);
      reverse_velocities(control.gas);
      control.tone = 1 - control.tone;
      control.must_find_collision = true;
      // A stopped model runs again: our reading of 「計算過程を実行する」
      // (lessons/README.md, glossary).
      control.stopped = false;
      break;
    // The article, after "<": if such an operation changes TC, the next
    // command goes to stage 4. Here T0 only decides where pictures are taken
    // and TC never depends on it, so > and < never need stage 4.
    // (T0 stays a positive, finite number that moves T, however often a key
    // is pressed.)
    case '>':
      if (std::isfinite(2 * control.gas.display_step)) control.gas.display_step *= 2;
      break;
    case '<':  // (and T + T0 must still move past T)
      if (std::isnormal(control.gas.display_step / 2) &&
          control.gas.time + control.gas.display_step / 2 > control.gas.time) {
        control.gas.display_step /= 2;
      }
      break;
    case '0':
      return KeyEffect::redraw;
    case 'E':
      control.ended = true;
      return KeyEffect::end;
    default:
      break;
  }
  return KeyEffect::none;
}
// [/anchor: press-key]
#endif

}  // namespace gas
