// Helpers shared by the tests. See support.hpp.
#include "support.hpp"

#include <doctest/doctest.h>
#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace gas::testing {

gas::Gas table_with(std::vector<gas::Ball> balls, double time) {
  gas::Gas gas;
  gas.radius = 1;
  gas.width = 40;
  gas.height = 30;
  gas.balls = std::move(balls);
  gas.time = time;
  return gas;
}

gas::Figures some_figures() {
  gas::Figures f;
  f.time = 12.5;
  f.display_step = 0.5;
  f.wall_collisions = 4;
  f.ball_collisions = 3;
  f.mean_speed = 1.0 / 3;
  f.energy = 2.0 / 7;
  f.energy_drift = -1.25e-16;
  f.momentum = {0.1, -2.0 / 3};
  return f;
}

Estimate over_batches(const std::vector<double>& values) {
  double sum = 0, square = 0;
  for (const double x : values) sum += x;
  const auto n = static_cast<double>(values.size());
  const double mean = sum / n;
  for (const double x : values) square += (x - mean) * (x - mean);
  return {mean, std::sqrt(square / (n - 1) / n)};
}

std::string source_path(const std::string& relative) {
  return std::string(GAS_SOURCE_DIR) + "/" + relative;
}

std::string read_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  REQUIRE_MESSAGE(file.good(), "cannot read " << path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  return fields;
}

Scratch::Scratch()
    : path(std::filesystem::temp_directory_path() /
           fmt::format("gas-test-{}-{}", getpid(), std::rand())) {
  std::filesystem::create_directories(path);
}

Scratch::~Scratch() {
  std::error_code ignored;  // a destructor must not throw
  std::filesystem::remove_all(path, ignored);
}

namespace {

// A single-quoted shell word.
std::string quoted(const std::string& word) {
  std::string out(1, '\'');
  for (const char c : word) {
    if (c == '\'') {
      out.append("'\\''");
    } else {
      out.push_back(c);
    }
  }
  out.push_back('\'');
  return out;
}

}  // namespace

ProgramRun run_program(const std::vector<std::string>& arguments,
                       const std::string& input) {
  return run_program_in(GAS_SOURCE_DIR, arguments, input);
}

ProgramRun run_program_in(const std::string& folder,
                          const std::vector<std::string>& arguments,
                          const std::string& input) {
  const Scratch scratch;
  const std::string in = scratch.file("in");
  const std::string out = scratch.file("out");
  const std::string err = scratch.file("err");
  std::ofstream(in, std::ios::binary) << input;
  std::string command = fmt::format("cd {} && {}", quoted(folder), quoted(GAS_PROGRAM));
  for (const std::string& argument : arguments)
    command += fmt::format(" {}", quoted(argument));
  command += fmt::format(" <{} >{} 2>{}", quoted(in), quoted(out), quoted(err));
  const int raw = std::system(command.c_str());
  ProgramRun run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = read_file(out);
  run.err = read_file(err);
  return run;
}

void check_golden(const std::string& relative, const std::string& actual) {
  const std::string path = source_path("data/" + relative);
  const char* update = std::getenv("GAS_UPDATE_GOLDEN");
  if (update != nullptr && std::string(update) == "1") {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    std::ofstream(path, std::ios::binary) << actual;
    MESSAGE("rewrote " << path);
    return;
  }
  REQUIRE_MESSAGE(
      std::filesystem::exists(path),
      "no golden file " << path << " (run with GAS_UPDATE_GOLDEN=1 to write it)");
  const std::string expected = read_file(path);
  CHECK_MESSAGE(actual == expected,
                "output differs from "
                    << path << " (GAS_UPDATE_GOLDEN=1 rewrites it)\n--- actual ---\n"
                    << actual);
}

}  // namespace gas::testing
