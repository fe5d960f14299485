// Section 5 of the report: the program as users run it.
//
// Sections 1 to 4 time the stages inside the benchmark; this one runs
// `build/gas` itself as a child process (child_process.hpp), end to end and
// on the wall clock, on large scenes, with the commands a user types:
//
//   (a) gas SCENE --until T --mode none                nothing drawn
//   (b) gas SCENE --until T --mode stats --csv FILE    frames to a pipe
//   (c) (b) with --pictures collisions                 a picture at every
//       collision, as in the article (a shorter T: it is slow on purpose)
//
// and sets each beside the engine (engine.hpp) on the same scene file, in
// the same run: section 1's measurement, and the event loop from the scene
// file to the same T. The collisions a run did come from the last row of its
// --csv file; run (a), which writes none, does the engine's collisions to T
// (what is drawn never changes the physics), checked against run (b)'s file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "engine.hpp"

namespace gas::benchmark {

// A scene the section runs the program on.
struct ProgramScene {
  std::string name;            // as the report shows it: data/large-10000.scene
  std::filesystem::path path;  // where it is
  double until = 0;            // runs (a) and (b) go to this model time
  double until_pictured = 0;   // run (c): pictures at every collision
};

struct ProgramSettings {
  std::string program;               // the path of build/gas
  std::vector<ProgramScene> scenes;  // the first one is the targets'
  int rounds = 3;                    // timed runs of (a) and (b); the fastest kept
  double engine_budget = 1;          // processor seconds of section 1's measurement
  double time_limit = 600;           // wall seconds before a run is stopped
  std::filesystem::path scratch;     // where the runs write their CSV files
};

// The engine on a scene of the section.
struct EngineOnScene {
  std::string scene;
  std::size_t balls = 0;
  Throughput loop{};         // section 1's measurement
  double until = 0;          // the run from the scene file to this T:
  long long collisions = 0;  //   the collisions to T,
  double wall_seconds = 0;   //   its time on the wall clock,
  double cpu_seconds = 0;    //   and in processor time
  double per_second() const { return loop.per_second(); }
};

// One of the runs (a), (b), (c) of `gas` on one scene: the fastest round.
struct ProgramRun {
  std::string scene;
  std::size_t balls = 0;
  char label = 'a';     // a, b or c
  std::string command;  // as a user types it
  double until = 0;
  int rounds = 0;
  ChildRun child;             // the fastest round
  long long collisions = -1;  // -1: not known
  std::string count_note;     // how they were counted, or why not
  // Collisions per second of wall-clock time (0 if not known): the figure.
  double per_second() const { return per(child.wall_seconds); }
  // ... of its own processor time: what the figure would be on an idle machine.
  double per_processor_second() const { return per(child.cpu_seconds); }
  double per(double seconds) const {
    return collisions >= 0 && child.succeeded() && seconds > 0
               ? static_cast<double>(collisions) / seconds
               : 0;
  }
};

struct ProgramFigures {
  std::vector<EngineOnScene> engines;  // one a scene, in order
  std::vector<ProgramRun> runs;        // (a), (b), (c) a scene, in order
  // The target runs: (a) and (b) on the first scene, with the engine's figure.
  const ProgramRun* run(const std::string& scene, char label) const;
  const EngineOnScene* engine(const std::string& scene) const;
};

// Runs everything the section reports (progress on standard error).
ProgramFigures measure_program(const ProgramSettings& settings);

// The section's text, from its heading on.
std::string program_section(const ProgramSettings& settings,
                            const ProgramFigures& figures);

// The two rows of the Targets table this section judges.
std::string program_targets(const ProgramSettings& settings,
                            const ProgramFigures& figures);

// Every run and engine figure, one row each (data/reports/program.csv).
void write_program_csv(const std::filesystem::path& path, const ProgramFigures& figures);

// A scene of `count` random balls at area fraction 0.3 on a 4:3 table, in the
// style of data/large-10000.scene (for the smoke run's tiny scene).
std::string random_scene_text(std::size_t count, unsigned seed);

}  // namespace gas::benchmark
