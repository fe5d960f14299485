// Stage 2 — input.
//
// What this stage does: reads a scene file — the radius, the table, the
// display step and the initial centre and velocity of every ball (or, in a
// checkpoint written by --dump, the start time T and every ball's column of R
// with the moment it was written) — checks
// that it describes a gas the later stages can run, and builds the Gas.
// The reading is split by job: a line into words, a word into a number, a
// keyword line into what the file said; then the checks of the whole scene,
// one function each (the sizes, the count N, every centre inside the table,
// no two balls overlapping).
// Article: "Gas on the display", stage 2, "input" (initial coordinates and
// velocities of the centres, and the step T0).
// Lesson: lessons/2-input.md; the file format: data/README.md.
//
// Beyond the article, a scene may ask for balls at random places with a line
// 'random COUNT SEED SPEED'. Stage 2 reads and checks that line and keeps it
// as a request (SceneDescription::random); placing the balls is the job of
// beyond/random_placement.*, whose parse_scene and read_scene_file give the
// whole gas of any scene. The program reads its scenes through those.
//
// Beyond the article too, the search for overlapping balls is the caller's
// to choose (OverlapSearch): stage 2 compares every pair, as a reader of a
// handful of balls may; the program passes beyond/overlap_cells.*, which
// compares each ball only with its neighbours.
//
// Assumptions: a file is read line by line, and only what it describes is
// kept (some 60 bytes a ball), so a scene's size is bounded by the balls it
// may hold, and a garbage file by the bounds below. Every problem is reported
// as "FILE:LINE: what is wrong"; the reader never guesses.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

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

// The most balls a scene may hold: its 'ball' lines and the COUNT of its
// 'random' line together (data/README.md). 10^6: research runs of hard discs
// go that far, and the program runs such a gas in some 100 bytes a ball
// (lesson 10). A --dump of any gas the program runs holds at most as many
// 'ball' lines, so it always reads back.
inline constexpr double most_balls = 1e6;

// The longest line a scene file may have, in characters (its line end not
// counted). A 'ball' line as --dump writes it takes some 100; the bound
// leaves room for any comment, and refuses a file with no line ends (a disk
// image, /dev/zero) once that much is read.
inline constexpr std::size_t longest_scene_line = std::size_t{1} << 16;

// The largest scene file, in bytes: 256 MiB, some 2.8 times a --dump of
// most_balls balls (96 bytes a ball). The reader keeps the balls, never the
// text, so this bounds only the time a garbage file takes to read (a file of
// nothing but line ends: some seconds) and the count of its lines.
inline constexpr std::size_t largest_scene_file = std::size_t{1} << 28;

// What a 'random COUNT SEED SPEED' line asks for, its numbers checked: COUNT
// balls at random places, from the generator seeded with SEED, with speeds
// around SPEED. Beyond the article; beyond/random_placement.* carries it out.
// A 'lattice COUNT SEED SPEED' line asks for the same, but on a lattice,
// every ball at speed SPEED exactly (a start far from equilibrium).
struct RandomBalls {
  std::size_t count = 0;   // COUNT, 1 to most_balls less the 'ball' lines
  std::uint64_t seed = 0;  // SEED, 0 to 2^53
  double speed = 0;        // SPEED > 0
  int line = 0;            // the line of the file it is on, for messages
  bool lattice = false;    // 'lattice': on a lattice, every speed SPEED
};

// A scene as its file describes it, every check passed: the gas of its
// 'ball' lines, and the request of its 'random' line if it has one (those
// balls are not placed yet).
struct SceneDescription {
  std::string file_name;              // for messages about the scene
  Gas gas;                            // N, a, T0, A1, A2 and R of the 'ball' lines
  std::optional<RandomBalls> random;  // the 'random' line, if any
};

// Two balls of a scene whose centres at its T are too close, by their
// numbers (0 for the first 'ball' line): `later` comes after `earlier`.
struct Overlap {
  std::size_t later = 0;
  std::size_t earlier = 0;
};

// How the reader looks for overlapping balls: given the centres at T in the
// order of the file and the least distance `closest` allowed between two, the
// first pair closer than that — the first ball closer to some ball before it,
// and the first such ball before it — or none. "Closer" means, for centres p
// (later) and q (earlier), with dx = p.x - q.x and dy = p.y - q.y in doubles:
// dx * dx + dy * dy < closest * closest. Every search gives the same answer.
using OverlapSearch =
    std::function<std::optional<Overlap>(const std::vector<Point>&, double closest)>;

// The plain search: every pair, N (N - 1) / 2 of them; the reader's own.
std::optional<Overlap> first_overlap_of_all_pairs(const std::vector<Point>& centres,
                                                  double closest);

// Parses scene text; `file_name` is used only in messages. Overlaps are
// looked for with `search`.
SceneDescription parse_scene_description(
    std::string_view text, const std::string& file_name,
    const OverlapSearch& search = first_overlap_of_all_pairs);

// Reads and parses the scene file at `path` the same way, a line at a time.
SceneDescription read_scene_description(
    const std::string& path, const OverlapSearch& search = first_overlap_of_all_pairs);

// The gas of a scene that lists all its balls. A scene with a 'random' line
// is refused (at that line): its gas comes from place_random_balls,
// parse_scene or read_scene_file (beyond/random_placement.hpp).
Gas build_gas(const SceneDescription& scene);

// The gas as a scene file that stage 2 reads back as the very same Gas, every
// double to the bit: a checkpoint for --dump. It writes the present time T
// (a line 'T') and each ball's column of R as it is, 'ball x y vx vy SINCE' (the
// centre at the moment `since`, not recomputed at T, which would round),
// every number with 17 significant digits (enough to give back the same
// double).
// [anchor: scene-text-declaration]
std::string scene_text(const Gas& gas);
// [/anchor: scene-text-declaration]

// The same text handed to `write` a piece at a time (the heading, then the
// 'ball' lines some 64 kB at a time), so that a --dump of a large gas never
// holds its whole text (96 bytes a ball: 96 MB for 10^6 balls).
void write_scene_text(const Gas& gas,
                      const std::function<void(std::string_view piece)>& write);

}  // namespace gas
