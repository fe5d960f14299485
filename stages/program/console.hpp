// The console program `gas`: reads its command line, then runs the main loop.
//
// Not one of the article's stages: this is the glue that reads the command
// line (options.hpp), runs stage 2 on the scene, stage 3 on the terminal, and
// then stage 7's loop with stage 6 drawing every step — the program a student
// runs. The loop's keys come from key_source.hpp, its files from
// run_outputs.hpp.
// Lesson: lessons/7-model-control.md; the reference: README.md.
#pragma once

#include <string>
#include <vector>

#include "program/options.hpp"

namespace gas {

// The default scene, built into the program from data/default.scene.
extern const char* const default_scene_text;
inline constexpr const char* default_scene_name = "data/default.scene";

// Runs the program; returns its exit status (0 success, 2 bad usage or a bad
// scene, 1 anything else). Messages go to standard error.
int run_console(const std::vector<std::string>& arguments);

}  // namespace gas
