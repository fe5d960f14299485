// Pictures only at the display steps: the loop for a gas too large to be
// drawn at each of its collisions.
//
// What this file does: names the two picture rules — the article's, a
// picture at every collision and at least every T0, and the rule for large
// gases, a picture only at T, T + T0, T + 2 T0, ... — picks one for a scene
// by its number of balls, and takes a display step the second way: every
// collision in between is carried out by stages 4 and 5 with no picture, so
// that each costs the same few operations however many balls there are.
// Beyond the article: its stage 7 ends a step at every collision, where the
// picture freezes while stage 4 computes the next one. That is right for a
// handful of balls; the article itself says that with many balls drawing
// takes too long. The collisions are the same, bit for bit, under both
// rules (the physics never depends on where pictures are taken).
// Lesson: lessons/7-model-control.md ("Pictures where the scene needs them")
#pragma once

#include <cstddef>
#include <cstdio>
#include <optional>
#include <string_view>

#include "stage7_control.hpp"

namespace gas {

// Where the program takes its pictures.
enum class PictureRule {
  every_collision,  // the article's: a step ends at T + T0 or at the first collision
  display_steps,    // only at T + T0: the collisions between are not drawn
};

// The rule for a scene of `ball_count` balls: the article's up to a hundred
// balls (the default scene and the other small scenes of data/, up to the
// crowd's 48), display steps beyond, where a picture costs far more than a
// collision and collisions come many to a display step.
// [anchor: picture-rule-for]
inline constexpr std::size_t most_balls_for_every_collision = 100;
inline PictureRule picture_rule_for(std::size_t ball_count) {
  return ball_count <= most_balls_for_every_collision ? PictureRule::every_collision
                                                      : PictureRule::display_steps;
}
// [/anchor: picture-rule-for]

// "collisions", "steps"; and back (nothing for any other name).
const char* picture_rule_name(PictureRule rule);
std::optional<PictureRule> picture_rule_named(std::string_view name);

// What a display step keeps for its caller besides the model: the picture's
// centres (for a table drawn: 16 bytes a ball, twice, with the old ones) and
// the list of its collisions (for --events and the bell: 24 bytes a
// collision, some 10 a ball in a step). A run that reads neither keeps
// neither: at N = 10^6 they were a quarter of the program's memory.
struct StepKeeps {
  bool picture = true;     // control.picture brought to the step's end
  bool collisions = true;  // Step::collisions filled
};

// One display step with no picture at the collisions inside it: from T to
// T + T0 (never past `time_limit`), carrying out every collision due on the
// way, including those at the step's end, as take_step does. The picture's
// centres are computed once, at the end, if `keeps` asks for them (else only
// the clock moves there), and the collisions listed if it asks for them.
// With `trace`, stage 5 says how many collisions the step carried out.
Step take_display_step(Control& control, double time_limit, std::FILE* trace,
                       StepKeeps keeps = {});

// One step by the rule: take_step (which always keeps both) or
// take_display_step.
Step take_step_by(PictureRule rule, Control& control, double time_limit, std::FILE* trace,
                  StepKeeps keeps = {});

}  // namespace gas
