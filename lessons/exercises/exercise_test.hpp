// The provided tests of the student exercises: what every test file of
// lessons/exercises/NN-name/ includes.
//
// - A small table to put balls on (`table`).
// - Generated cases: `Draw`, numbers drawn from a fixed seed, the same on
//   every machine and every run, so that a test can try hundreds of inputs
//   that an answer cannot be shaped to.
// - Failure messages that say everything: CHECK_NUMBER says the inputs, the
//   value wanted and the value your code gave, each to 17 significant digits
//   (enough to tell any two doubles apart), and how far apart they are; and
//   when your code gave NaN (the untouched stub's placeholder), what to
//   write instead, read from the stub's TODO.
#pragma once

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"

namespace gas::exercises {

// A 40 x 30 table with balls of radius 1, so that every centre stays within
// 1 <= x <= 39, 1 <= y <= 29; T = `time`, T0 = 1.
inline Gas table(std::vector<Ball> balls, double time = 0) {
  Gas gas;
  gas.radius = 1;
  gas.width = 40;
  gas.height = 30;
  gas.balls = std::move(balls);
  gas.time = time;
  gas.display_step = 1;
  return gas;
}

// Numbers drawn from a fixed seed. std::mt19937_64's sequence is fixed by the
// C++ standard; the <random> distributions are not, so the draws are written
// out here and give the same numbers with every compiler.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [low, high), every one of a double's 53 bits drawn.
  double uniform(double low, double high) {
    const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    return low + (high - low) * unit;
  }
  // Uniform among the whole numbers low .. high.
  int integer(int low, int high) {
    const auto span = static_cast<std::uint64_t>(high - low) + 1;
    return low + static_cast<int>(engine_() % span);
  }
  bool coin() { return (engine_() >> 63) != 0; }
  // A size spread over many orders of magnitude: from 10^low to 10^high.
  double magnitude(double low, double high) { return std::pow(10.0, uniform(low, high)); }

 private:
  std::mt19937_64 engine_;
};

// A double to 17 significant digits: read back, it is the same double.
inline std::string digits(double value) {
  return fmt::format("{:.17g}", value);
}

// A ball as its column of R: {x, y, vx, vy, since}, to 17 digits.
inline std::string column_of_r(const Ball& ball) {
  return fmt::format("{{{}, {}, {}, {}, {}}}", digits(ball.x), digits(ball.y),
                     digits(ball.vx), digits(ball.vy), digits(ball.since));
}

// The balls a failed check lists, at most: enough to see a case by, and a
// failure of 60 balls still reads on a screen.
inline constexpr std::size_t balls_listed = 12;

// The balls of a gas, one per line (the first balls_listed), after T and
// the table.
inline std::string describe(const Gas& gas) {
  std::string text =
      fmt::format("a gas of {} ball{} at T = {} (a = {}, A1 = {}, A2 = {})",
                  gas.balls.size(), gas.balls.size() == 1 ? "" : "s", digits(gas.time),
                  digits(gas.radius), digits(gas.width), digits(gas.height));
  for (std::size_t i = 0; i < gas.balls.size() && i < balls_listed; ++i)
    text += fmt::format("\n    ball {}: {}", i + 1, column_of_r(gas.balls[i]));
  if (gas.balls.size() > balls_listed)
    text += fmt::format("\n    ... and {} balls more", gas.balls.size() - balls_listed);
  return text;
}

// Whether `got` is `wanted`: the same number (+0 and -0 alike; infinity
// only infinity; NaN nothing), or within `relative` times |wanted| of it, or
// within `absolute` of it.
inline bool agrees(double got, double wanted, double relative, double absolute = 0) {
  if (got == wanted) return true;
  return std::isfinite(wanted) &&
         std::fabs(got - wanted) <= std::max(relative * std::fabs(wanted), absolute);
}

// What the stub beside the test file `test_file` (NN-name/test_name.cpp:
// NN-name/name.cpp) asks for: its "// TODO:" comment, on one line; empty if
// it has none (the student's own code, say).
inline std::string task_of_stub(const std::string& test_file) {
  const std::filesystem::path test(test_file);
  std::string stem = test.stem().string();
  stem.erase(0, stem.find('_') + 1);  // test_name -> name
  std::ifstream stub(test.parent_path() / (stem + ".cpp"));
  std::string line, task;
  bool inside = false;
  // The TODO's lines: comments alone on their lines, from "// TODO:" on.
  while (std::getline(stub, line)) {
    const std::size_t start = line.find_first_not_of(' ');
    if (start == std::string::npos || line.compare(start, 2, "//") != 0) {
      if (inside) break;
      continue;
    }
    std::string words = line.substr(start + 2);
    words.erase(0, words.find_first_not_of(' '));
    if (words.rfind("TODO:", 0) == 0) {
      inside = true;
      words.erase(0, 5);
      words.erase(0, words.find_first_not_of(' '));
    } else if (!inside) {
      continue;
    }
    task += (task.empty() ? "" : " ") + words;
  }
  return task;
}

// What a result of NaN ("not a number") says: most likely the untouched
// stub's placeholder, and then what to write instead.
inline std::string about_nan(const std::string& test_file) {
  const std::string task = task_of_stub(test_file);
  const std::string stub =
      std::filesystem::path(test_file).parent_path().filename().string();
  return fmt::format(
      "\n  NaN is \"not a number\": the stub's placeholder, while the function is "
      "not written yet.{}\n  (Written already? Then look for 0 / 0, inf - inf or the "
      "square root of a negative number.)",
      task.empty() ? fmt::format(" What to write: {}/instructions.md.", stub)
                   : fmt::format("\n  What to write: {}", task));
}

// What a failed check says: the inputs, the value wanted, the value got,
// and how far apart they are; for a NaN, what it means (`test_file`: the
// test's own file, __FILE__, whose stub says what to write).
inline std::string compared(const std::string& inputs, double wanted, double got,
                            const std::string& test_file = {}) {
  // No check wants NaN: a wanted NaN came from your own code, on other input.
  std::string text =
      fmt::format("{}\n  wanted {}{}\n  got    {}", inputs, digits(wanted),
                  std::isnan(wanted) ? " (your function's own answer)" : "", digits(got));
  if (std::isnan(got) && !test_file.empty()) text += about_nan(test_file);
  if (std::isfinite(wanted) && std::isfinite(got) && wanted != 0) {
    const double off = std::fabs(got - wanted) / std::fabs(wanted);
    text += fmt::format("  (off by {:.2g} of the value wanted)", off);
    // float keeps 24 bits, about 6e-8 of a number; double 53, about 1e-16.
    if (off > 1e-9 && off < 1e-5)
      text += "\n  that is about float's precision: is a sum or a value kept in float?";
  }
  return text;
}

}  // namespace gas::exercises

// CHECK_NUMBER(inputs, got, wanted, relative): checks that the double `got`
// agrees with `wanted` (exactly if `relative` is 0, see agrees), and if not
// says `inputs` (a string: the call and its arguments), wanted and got. It
// is true when they agree, so that a loop over generated cases can stop at
// the first that fails: `if (!CHECK_NUMBER(...)) break;`.
#define CHECK_NUMBER(inputs, got, wanted, relative) \
  CHECK_CLOSE(inputs, got, wanted, relative, 0)

// CHECK_CLOSE(inputs, got, wanted, relative, absolute): the same, and `got`
// may also be within `absolute` of `wanted` (for values near 0, where a
// relative tolerance asks too much).
#define CHECK_CLOSE(inputs, got, wanted, relative, absolute)                            \
  [&] {                                                                                 \
    const double got_value = (got), wanted_value = (wanted);                            \
    const bool agrees =                                                                 \
        gas::exercises::agrees(got_value, wanted_value, (relative), (absolute));        \
    CHECK_MESSAGE(                                                                      \
        agrees, gas::exercises::compared((inputs), wanted_value, got_value, __FILE__)); \
    return agrees;                                                                      \
  }()

// Printed in failed checks as (x, y) and [column, row].
namespace gas {
inline std::ostream& operator<<(std::ostream& out, const Point& p) {
  return out << '(' << gas::exercises::digits(p.x) << ", " << gas::exercises::digits(p.y)
             << ')';
}
inline std::ostream& operator<<(std::ostream& out, const Cell& c) {
  return out << "[column " << c.column << ", row " << c.row << ']';
}
}  // namespace gas
