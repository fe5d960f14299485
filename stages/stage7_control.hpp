// Stage 7 — model control.
//
// What this stage does: runs the loop of the article — stage 4 when a new
// first collision is needed, stage 5 to shift time by T1, and back — counts
// the collisions, and carries out the keys S R B > < 0 E.
// Article: "Gas on the display", stage 7, "model control" (T = T + T1; if
// TC > T go to stage 5, if TC <= T go to stage 4; keys S, R, B, >, <, 0, E).
// Lesson: lessons/7-model-control.md
//
// Assumptions: drawing (stage 6) and the terminal are the caller's; this
// stage only decides what happens to the model, so that tests can drive it.
#pragma once

#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage4_first_collision.hpp"
#include "stage5_new_coordinates.hpp"

namespace gas {

// Beyond the article, one narrow hook: an observer is told of each collision
// just before stage 5 carries it out, with the gas as it was, and just after,
// with the new velocities; and, before the key B writes every ball's column of
// R afresh at T, of that too. Kinetic theory keeps its running sums this way
// (stages/beyond/, lesson 13); the stages themselves need none.
class CollisionObserver {
 public:
  virtual ~CollisionObserver() = default;
  virtual void before_collision(const Gas& /*gas*/, const Collision& /*collision*/) {}
  virtual void after_collision(const Gas& /*gas*/, const Collision& /*collision*/) {}
  virtual void before_rows_rewritten(const Gas& /*gas*/) {}
};

// Everything the control loop keeps between two steps.
// [anchor: control]
struct Control {
  // The model and stage 4.
  Gas gas;                          // the model: R, a, A1, A2, T, T0
  CentreLimits limits;              // from stage 3
  Collision next;                   // TC, K, N1, N2 of stage 4
  bool must_find_collision = true;  // stage 4 from scratch before the next step
  std::unique_ptr<FirstCollisionFinder> finder;  // how stage 4 finds them

  // What the picture and the figures need.
  Picture picture;                        // RS and the centres at T
  long long wall_collisions = 0;          // K = 1 or 2, so far
  long long ball_collisions = 0;          // K = 3, so far
  double starting_energy = 0;             // kinetic energy at T = 0, for the drift
  CollisionObserver* observer = nullptr;  // told of each collision, if any

  // The keys.
  int tone = 0;          // the base colour's tone; B changes it
  bool stopped = false;  // S stops, R starts again
  bool ended = false;    // E
};
// [/anchor: control]

// Sets the loop up for a gas read by stage 2, with stage 4 done by `finder`
// (none: the article's scan; the faster ways are in stages/beyond/, lesson 10).
Control start_control(Gas gas, std::unique_ptr<FirstCollisionFinder> finder = nullptr);

// The most collisions allowed at one instant of model time. Real cascades at
// one instant (a row of touching balls struck at one end) take about N
// collisions; far more means that round-off has trapped balls in a loop that
// would never let time move on, and the run is stopped with an error rather
// than left hanging.
long long most_collisions_at_one_instant(std::size_t ball_count);

// One display step: the collisions it carried out, in order, and its T1.
struct Step {
  double length = 0;                  // T1
  std::vector<Collision> collisions;  // the collisions at the step's end (often none)
};

// Takes one step of the article's loop: finds the first collision if needed
// (stage 4), shifts time by T1 (stage 5), and, if the step ends on a
// collision, carries it out together with every other collision due at the
// same instant (stage 7 going back to stage 4 while TC <= T). The step never
// goes past `time_limit`. With `trace`, each stage says what it did.
// Throws std::runtime_error if collisions at one instant never stop.
Step take_step(Control& control, double time_limit, std::FILE* trace);

// The two halves of take_step's loop, for a loop that takes its pictures
// elsewhere (stages/beyond/display_steps.hpp):
// stage 4, if the last step ended on a collision or a key changed the
// velocities (otherwise the next collision is known already);
void find_next_collision(Control& control, std::FILE* trace);
// stage 5 for every collision due at T (TC <= T), stage 7 going back to
// stage 4 after each. Adds them to `step`. Throws std::runtime_error if
// collisions at one instant never stop.
void carry_out_due_collisions(Control& control, Step& step, std::FILE* trace);

// For --trace: stage 7's decision after a step, "TC > T, back to stage 5".
void trace_decision(const Control& control, std::FILE* trace);

// What a key asks of the caller, beyond what it did to the model.
enum class KeyEffect { none, redraw, end };

// Carries out a key (case does not matter): S stop, R start, B reverse every
// velocity and change the tone, > double T0, < halve T0, 0 redraw, E end.
// Other keys, and '.', do nothing.
// [anchor: press-key-declaration]
KeyEffect press_key(Control& control, char key);
// [/anchor: press-key-declaration]

}  // namespace gas
