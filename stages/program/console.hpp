// The console program `gas`: its command line and its main loop.
//
// Not one of the article's stages: this is the glue that reads the command
// line, runs stage 2 on the scene, stage 3 on the terminal, and then stage 7's
// loop with stage 6 drawing every step — the program a student runs.
// Lesson: lessons/7-model-control.md; the reference: README.md.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "beyond/strategy.hpp"
#include "stage6_output.hpp"

namespace gas {

// A command line that cannot be obeyed; what() says why.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Options {
  std::optional<std::string> scene_path;   // none: the built-in default scene
  std::optional<long long> frames;         // --frames N: N display steps, then exit
  std::optional<double> until;             // --until T: stop at model time T
  std::optional<std::string> keys;         // --keys: one key per display step
  ScreenMode mode = ScreenMode::balls;     // --mode
  std::optional<std::string> events_path;  // --events FILE
  std::optional<std::string> dump_path;    // --dump FILE
  std::optional<std::string> csv_path;     // --csv FILE
  std::optional<int> columns;              // --cols
  std::optional<int> rows;                 // --rows
  bool step = false;                       // --step
  bool trace = false;                      // --trace
  bool bell = false;                       // --bell
  bool help = false;                       // --help
  std::optional<Strategy> strategy;        // --strategy; none: chosen by N
};

// Reads the arguments after the program's name. Throws UsageError.
Options parse_options(const std::vector<std::string>& arguments);

// The text of --help.
std::string help_text();

// The default scene, built into the program from data/default.scene.
extern const char* const default_scene_text;
inline constexpr const char* default_scene_name = "data/default.scene";

// Runs the program; returns its exit status (0 success, 2 bad usage or a bad
// scene, 1 anything else). Messages go to standard error.
int run_console(const std::vector<std::string>& arguments);

}  // namespace gas
