// Helpers shared by the tests: files of the source tree, running the `gas`
// program, and golden files (expected outputs kept in data/).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "stage1_data.hpp"
#include "stage6_output.hpp"

namespace gas::testing {

// A hand-made gas for the stage tests: a 40 x 30 table with balls of
// radius 1, so that centres stay in [1, 39] x [1, 29].
gas::Gas table_with(std::vector<gas::Ball> balls, double time = 0);

// A fresh folder for the files one test makes, removed with this object.
struct Scratch {
  std::filesystem::path path;  // the folder
  Scratch();
  ~Scratch();
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  std::string file(const std::string& name) const { return (path / name).string(); }
};

// Figures of stage 6 with a value in every field, numbers that need many
// digits among them (T = 12.5, T0 = 0.5, 4 wall and 3 ball collisions, ...).
gas::Figures some_figures();

// A mean over independent batch values (Monte Carlo batches, say) and its
// standard error.
struct Estimate {
  double value = 0;
  double error = 0;
};
Estimate over_batches(const std::vector<double>& values);

// A path inside the source tree, e.g. source_path("data/default.scene").
std::string source_path(const std::string& relative);

// The whole content of a file; fails the test if it cannot be read.
std::string read_file(const std::string& path);

// The lines of a text, without their ends; and the comma-separated fields of
// one line (of a --csv or --events file).
std::vector<std::string> lines_of(const std::string& text);
std::vector<std::string> fields_of(const std::string& line);

// The result of running the `gas` program.
struct ProgramRun {
  int status = -1;  // exit status
  std::string out;  // standard output
  std::string err;  // standard error
};

// Runs build/gas with these arguments (each one passed as it is), with
// standard input from /dev/null (or `input`), from the source directory.
ProgramRun run_program(const std::vector<std::string>& arguments,
                       const std::string& input = "");

// The same, run from the folder `folder`: a scene named that is no file
// there is looked for by name (stages/program/scene_lookup.hpp).
ProgramRun run_program_in(const std::string& folder,
                          const std::vector<std::string>& arguments,
                          const std::string& input = "");

// Compares `actual` with the golden file data/<relative>. With the
// environment variable GAS_UPDATE_GOLDEN=1 the golden file is rewritten
// instead (then read the diff before committing it).
void check_golden(const std::string& relative, const std::string& actual);

}  // namespace gas::testing
