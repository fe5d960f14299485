// Exercise 02 — YOUR scene_text (stage 2, input: the scene file, written).
//
// The task: lessons/exercises/02-scene-text/instructions.md. The tests:
// test_scene_text.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in stages/stage2_input.cpp.
// ([[maybe_unused]] only keeps the compiler quiet while the body is a
// placeholder; delete it when you like.)
#include <fmt/format.h>

#include <string>

#include "stage2_input.hpp"

namespace gas {

std::string scene_text([[maybe_unused]] const Gas& gas) {
  // TODO: the lines T, a, T0, A1, A2 and N, then one line
  // "ball x y vx vy since" for every ball: its column of R as it is.
  return "";  // placeholder: an empty scene, which stage 2 refuses
}

}  // namespace gas
