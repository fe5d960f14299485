// Stage 2 — input, the 'random COUNT SEED SPEED' line (beyond the article).
//
// What this file does: places the balls a scene's 'random' line asks for —
// COUNT balls at random places on the table, clear of the 'ball' lines' balls
// and of each other, each with a random direction and a speed between 0.5 and
// 1.5 SPEED — and gives the reader the program uses for every scene:
// parse_scene and read_scene_file, stage 2's reading and checks with the
// random balls then placed, and overlaps looked for through cells
// (beyond/overlap_cells.hpp), so that a scene of 10^6 balls reads in
// seconds.
// Article: "Gas on the display", stage 2, "input". The article types in every
// ball; a scene of thousands placed at random is beyond it (lesson 10 runs
// such gases).
// Lesson: lessons/2-input.md; the rules of the line: data/README.md.
//
// Assumptions: the same seed gives the same balls on every machine: a seeded
// std::mt19937_64 (its output is fixed by the C++ standard), our own mapping
// to [0, 1), and only +, -, *, / and sqrt (correctly rounded in IEEE
// arithmetic) after it.
#pragma once

#include <string>
#include <string_view>

#include "stage1_data.hpp"
#include "stage2_input.hpp"

namespace gas {

// How many tries each random ball gets to find a free place. Random placement
// of discs fills about 0.55 of a table at most; the tries keep a scene that
// asks for more from running for ever.
inline constexpr int most_tries_per_random_ball = 10000;
// The densest packing of equal discs covers pi / (2 sqrt 3) of the plane.
inline constexpr double densest_packing = 0.9068996821171089;

// The gas of a scene: the 'ball' lines' balls, then those of its 'random' line
// in the order placed (the 'ball' lines' gas alone if there is no such line).
// A request for more balls than can be placed is refused as
// "FILE:LINE: what is wrong" at the 'random' line.
Gas place_random_balls(const SceneDescription& scene);
// The same, the description's balls moved into the gas instead of copied.
Gas place_random_balls(SceneDescription&& scene);

// Parses scene text, a 'random' line included: stage 2's
// parse_scene_description with first_overlap_by_cells, then
// place_random_balls. `file_name` is used only in messages.
Gas parse_scene(std::string_view text, const std::string& file_name);

// Reads and parses the scene file at `path` the same way.
Gas read_scene_file(const std::string& path);

}  // namespace gas
