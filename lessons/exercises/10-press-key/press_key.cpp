// Exercise 10 — YOUR press_key (stage 7, model control: the keys).
//
// The task: lessons/exercises/10-press-key/instructions.md. The tests:
// test_press_key.cpp beside this file. Once you have edited it,
// this definition stands in for the reference one in stages/stage7_control.cpp.
// ([[maybe_unused]] only keeps the compiler quiet while the body is a
// placeholder; delete it when you like.)
#include <cctype>
#include <cmath>

#include "stage7_control.hpp"

namespace gas {

KeyEffect press_key([[maybe_unused]] Control& control, [[maybe_unused]] char key) {
  // TODO: S stop, R run, B reverse every velocity and change the tone,
  // > double T0, < halve T0, 0 ask for a redraw, E end; other keys nothing.
  return KeyEffect::none;  // placeholder: no key does anything (Ctrl-C still ends)
}

}  // namespace gas
