// Stage 2 — input.
//
// What this stage does: reads a scene file — the radius, the table, the
// display step and the initial centre and velocity of every ball — checks
// that it describes a gas the later stages can run, and builds the Gas.
// Article: "Gas on the display", stage 2, "input" (initial coordinates and
// velocities of the centres, and the step T0).
// Lesson: lessons/2-input.md; the file format: data/README.md.
//
// Assumptions: a scene is small enough to read into memory. Every problem is
// reported as "FILE:LINE: what is wrong"; the reader never guesses.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "stage1_data.hpp"

namespace gas {

// A scene file that does not describe a runnable gas. what() is the whole
// message, "FILE:LINE: what is wrong".
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How far one ball may reach into another (or a centre beyond its limit)
// before the scene is rejected, as a fraction of the diameter 2a.
//
// Why 1e-9: a scene that means two balls just touching, written in decimal
// (by hand, or by --dump with 17 digits), puts them 2a apart only up to the
// rounding of its coordinates, about 1e-16 of the coordinates themselves;
// on a table up to 10^6 diameters wide that is at most ~1e-10 of a diameter.
// 1e-9 accepts every such scene with a margin, while any overlap a person
// could mean or see (a millionth of a diameter, say) is still refused.
inline constexpr double contact_tolerance = 1e-9;

// The sizes a scene's numbers may have, besides 0. The stages multiply up to
// four lengths or speeds together (the discriminant holds (d.w)^2 and
// (w.w)(d.d)); with every factor between 1e-75 and 1e75, every such product
// lies between 1e-300 and 1e300, inside the normal doubles (about 2.2e-308 to
// 1.8e308), so none overflows to infinity or sinks into the less precise
// subnormal numbers.
inline constexpr double smallest_magnitude = 1e-75;
inline constexpr double largest_magnitude = 1e75;

// The 'random COUNT SEED SPEED' line (data/README.md): at most this many
// balls, placed at random, each given at most this many tries to find a free
// place (random placement of discs fills about 0.55 of a table at most; the
// tries keep a scene that asks for more from running for ever).
inline constexpr double most_random_balls = 1e5;
inline constexpr int most_tries_per_random_ball = 10000;
// The densest packing of equal discs covers pi / (2 sqrt 3) of the plane.
inline constexpr double densest_packing = 0.9068996821171089;

// Parses scene text; `file_name` is used only in messages.
Gas parse_scene(std::string_view text, const std::string& file_name);

// Reads and parses the scene file at `path`.
Gas read_scene_file(const std::string& path);

// The gas as a scene file that parse_scene reads back: the centres at the
// present time T, every number with 17 significant digits (enough to give
// back the same double).
std::string scene_text(const Gas& gas);

}  // namespace gas
