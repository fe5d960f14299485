// The command line of `gas`: what each option means and how it is read.
//
// Not one of the article's stages: the article's stage 2 sets the initial
// centres and velocities, and T0 (「過程の“刻み” T_0 も与えられる」), and
// does not say how; ours reads them from a scene file. These options choose the
// scene, how long to run, which keys to press and which files to write, so
// that a run can be repeated exactly.
// Lesson: lessons/7-model-control.md; the reference: README.md ("The program").
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "beyond/display_steps.hpp"
#include "beyond/strategy.hpp"
#include "stage6_output.hpp"

namespace gas {

// A command line that cannot be obeyed; what() says why.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the command line asks for; an option not given keeps its default here.
struct Options {
  std::optional<std::string> scene_path;   // a file or a scene's name; none: the default
  std::optional<long long> frames;         // --frames N: N display steps, then exit
  std::optional<double> until;             // --until T: stop at model time T
  std::optional<std::string> keys;         // --keys: one key per display step
  ScreenMode mode = ScreenMode::balls;     // --mode
  bool drawn = true;                       // false for --mode none: nothing drawn
  std::optional<std::string> events_path;  // --events FILE
  std::optional<std::string> dump_path;    // --dump FILE
  std::optional<std::string> csv_path;     // --csv FILE
  std::optional<int> columns;              // --cols
  std::optional<int> rows;                 // --rows
  bool step = false;                       // --step
  bool trace = false;                      // --trace
  bool bell = false;                       // --bell
  bool help = false;                       // --help
  bool version = false;                    // --version
  std::optional<Strategy> strategy;        // --strategy; none: chosen by N
  std::optional<PictureRule> pictures;     // --pictures; none: chosen by N
  // --structure FILE
  std::optional<std::string> structure_path;
  // --vacf FILE
  std::optional<std::string> vacf_path;
};

// Reads the arguments after the program's name. Throws UsageError.
Options parse_options(const std::vector<std::string>& arguments);

// The text of --help.
std::string help_text();

}  // namespace gas
