// Stage 2 — input: the scene-file reader. See stage2_input.hpp for the
// contract and data/README.md for the format.
#include "stage2_input.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

namespace gas {
namespace {

// A value given on some line of the file, remembered with that line so that
// later checks can point at it.
struct Given {
  double value = 0;
  int line = 0;
};

// What the file said, before any check that needs the whole file.
// A 'random COUNT SEED SPEED' line: balls the reader places itself.
struct RandomBalls {
  double count = 0, seed = 0, speed = 0;
  int line = 0;
};

struct SceneText {
  std::optional<Given> radius, display_step, width, height, ball_count;
  std::vector<Ball> balls;
  std::vector<int> ball_lines;
  std::optional<RandomBalls> random;
  int last_line = 1;
};

// A number in [0, 1) from the top 53 bits of one draw of the generator:
// exactly the same on every machine (std::uniform_real_distribution's
// output is not specified bit for bit, so two libraries may differ).
double unit_interval(std::mt19937_64& generator) {
  return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

// A token as it may be shown in a message: printable ASCII kept, other bytes
// as \xNN, long tokens cut, so that garbage in a file never garbles stderr.
std::string printable(std::string_view token) {
  constexpr std::size_t shown = 24;
  std::string out;
  for (std::size_t i = 0; i < token.size() && i < shown; ++i) {
    const auto byte = static_cast<unsigned char>(token[i]);
    if (byte >= 0x20 && byte < 0x7f) {
      out += static_cast<char>(byte);
    } else {
      out += fmt::format("\\x{:02x}", byte);
    }
  }
  if (token.size() > shown) out += "...";
  return out;
}

std::vector<std::string_view> split_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    std::size_t end = i;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t') ++end;
    if (end > i) words.push_back(line.substr(i, end - i));
    i = end;
  }
  return words;
}

class Reader {
 public:
  explicit Reader(const std::string& file_name) : file_name_(file_name) {}

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw SceneError(fmt::format("{}:{}: {}", file_name_, line, what));
  }

  // A finite double, the whole word and nothing else.
  double number(std::string_view word, int line) const {
    std::string_view digits =
        word;  // from_chars takes no '+' sign: drop one before a digit
    if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-')
      digits.remove_prefix(1);
    double value = 0;
    const auto [end, error] =
        std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (error == std::errc::result_out_of_range) {
      fail(line, fmt::format("'{}' is out of the range of a double", printable(word)));
    }
    if (error != std::errc() || end != digits.data() + digits.size()) {
      fail(line, fmt::format("'{}' is not a number", printable(word)));
    }
    if (!std::isfinite(value)) {
      fail(line, fmt::format("'{}' is not a finite number", printable(word)));
    }
    if (value != 0 &&
        (std::fabs(value) < smallest_magnitude || std::fabs(value) > largest_magnitude)) {
      fail(line,
           fmt::format("'{}' is outside the range of sizes this program computes with "
                       "({:g} to {:g}, or 0)",
                       printable(word), smallest_magnitude, largest_magnitude));
    }
    return value;
  }

  void read_line(std::string_view line, int line_number, SceneText& scene) const {
    if (const auto hash = line.find('#'); hash != std::string_view::npos) {
      line = line.substr(0, hash);
    }
    const std::vector<std::string_view> words = split_words(line);
    if (words.empty()) return;
    const std::string_view keyword = words[0];
    const std::size_t count = words.size() - 1;

    auto numbers = [&](std::size_t wanted, const char* meaning) {
      if (count != wanted) {
        fail(line_number, fmt::format("'{}' takes {} number{} ({}), found {}", keyword,
                                      wanted, wanted == 1 ? "" : "s", meaning, count));
      }
      std::vector<double> values;
      for (std::size_t i = 1; i < words.size(); ++i) {
        values.push_back(number(words[i], line_number));
      }
      return values;
    };
    auto single = [&](std::optional<Given>& slot, const char* meaning) {
      const double value = numbers(1, meaning)[0];
      if (slot) {
        fail(line_number,
             fmt::format("'{}' is given twice (first on line {})", keyword, slot->line));
      }
      slot = Given{value, line_number};
    };

    if (keyword == "a") {
      single(scene.radius, "the ball radius");
    } else if (keyword == "T0") {
      single(scene.display_step, "the display time step");
    } else if (keyword == "A1") {
      single(scene.width, "the table width");
    } else if (keyword == "A2") {
      single(scene.height, "the table height");
    } else if (keyword == "N") {
      single(scene.ball_count, "the number of balls");
    } else if (keyword == "ball") {
      const std::vector<double> v = numbers(4, "x y vx vy");
      scene.balls.push_back(Ball{v[0], v[1], v[2], v[3], 0.0});
      scene.ball_lines.push_back(line_number);
    } else if (keyword == "random") {
      const std::vector<double> v = numbers(3, "COUNT SEED SPEED");
      if (scene.random) {
        fail(line_number, fmt::format("'random' is given twice (first on line {})",
                                      scene.random->line));
      }
      scene.random = RandomBalls{v[0], v[1], v[2], line_number};
    } else {
      std::string hint;
      for (const char* known : {"a", "T0", "A1", "A2", "N", "ball", "random"}) {
        std::string lower(keyword);
        std::string lower_known(known);
        for (char& c : lower)
          c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        for (char& c : lower_known)
          c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower == lower_known)
          hint = fmt::format(" (names are case-sensitive: did you mean '{}'?)", known);
      }
      if (hint.empty()) hint = " (expected a, T0, A1, A2, N, ball or random)";
      fail(line_number, fmt::format("unknown keyword '{}'{}", printable(keyword), hint));
    }
  }

  const Given& required(const std::optional<Given>& slot, const char* keyword,
                        const char* meaning, int last_line) const {
    if (!slot) fail(last_line, fmt::format("missing '{}' ({})", keyword, meaning));
    return *slot;
  }

  Gas check(const SceneText& scene) const {
    const int end = scene.last_line;
    if (!scene.radius && !scene.display_step && !scene.width && !scene.height &&
        !scene.ball_count && scene.balls.empty() && !scene.random) {
      fail(end, "the scene is empty: it needs a, T0, A1, A2 and at least one ball");
    }
    const Given& radius = required(scene.radius, "a", "the ball radius", end);
    const Given& step = required(scene.display_step, "T0", "the display time step", end);
    const Given& width = required(scene.width, "A1", "the table width", end);
    const Given& height = required(scene.height, "A2", "the table height", end);

    if (radius.value <= 0)
      fail(radius.line, fmt::format("a = {} must be positive", radius.value));
    if (step.value <= 0)
      fail(step.line, fmt::format("T0 = {} must be positive", step.value));
    if (width.value <= 0)
      fail(width.line, fmt::format("A1 = {} must be positive", width.value));
    if (height.value <= 0)
      fail(height.line, fmt::format("A2 = {} must be positive", height.value));
    const double diameter = 2 * radius.value;
    // A ball must have room to move: on a table exactly 2a wide it would
    // bounce between the two walls at one instant for ever.
    for (const Given* side : {&width, &height}) {
      if (side->value <= diameter * (1 + contact_tolerance)) {
        fail(side->line, fmt::format("the table ({} x {}) leaves no room to move for a ball "
                                     "of diameter 2a = {}",
                                     width.value, height.value, diameter));
      }
    }

    if (scene.random) check_random(*scene.random);
    const double random_count = scene.random ? scene.random->count : 0;
    if (scene.ball_count) {
      const Given& n = *scene.ball_count;
      if (n.value < 0 || n.value != std::floor(n.value)) {
        fail(n.line, fmt::format("N = {} must be a whole number of balls", n.value));
      }
      if (n.value != static_cast<double>(scene.balls.size()) + random_count) {
        if (scene.random) {
          fail(n.line,
               fmt::format("N = {} but the file has {} 'ball' line{} and 'random' "
                           "places {}",
                           n.value, scene.balls.size(),
                           scene.balls.size() == 1 ? "" : "s", random_count));
        }
        fail(n.line, fmt::format("N = {} but the file has {} 'ball' line{}", n.value,
                                 scene.balls.size(), scene.balls.size() == 1 ? "" : "s"));
      }
    }
    if (scene.balls.empty() && !scene.random)
      fail(end, "no 'ball' lines: a gas needs at least one ball");

    // Every centre within its limits a <= x <= A1 - a, a <= y <= A2 - a.
    const double slack = contact_tolerance * diameter;
    for (std::size_t i = 0; i < scene.balls.size(); ++i) {
      const Ball& ball = scene.balls[i];
      auto within = [&](double value, double high, char axis) {
        if (value < radius.value - slack || value > high - radius.value + slack) {
          fail(scene.ball_lines[i],
               fmt::format("ball {}: its centre {} = {} is outside the table "
                           "(a <= {} <= {} - a, i.e. {} .. {})",
                           i + 1, axis, value, axis, axis == 'x' ? "A1" : "A2",
                           radius.value, high - radius.value));
        }
      };
      within(ball.x, width.value, 'x');
      within(ball.y, height.value, 'y');
    }

    // No two balls closer than 2a (touching is allowed, within the slack).
    const double closest = diameter - slack;
    for (std::size_t j = 1; j < scene.balls.size(); ++j) {
      for (std::size_t i = 0; i < j; ++i) {
        const double dx = scene.balls[j].x - scene.balls[i].x;
        const double dy = scene.balls[j].y - scene.balls[i].y;
        if (dx * dx + dy * dy < closest * closest) {
          fail(scene.ball_lines[j],
               fmt::format("ball {} overlaps ball {} (line {}): centres {:.9g} apart, "
                           "less than 2a = {}",
                           j + 1, i + 1, scene.ball_lines[i], std::hypot(dx, dy),
                           diameter));
        }
      }
    }

    Gas gas;
    gas.radius = radius.value;
    gas.width = width.value;
    gas.height = height.value;
    gas.display_step = step.value;
    gas.balls = scene.balls;
    if (scene.random) place_random(*scene.random, gas);
    return gas;
  }

  // COUNT a whole number from 1 to most_random_balls, SEED a whole number
  // from 0 to 2^53 (a double holds every such number exactly), SPEED > 0
  // and small enough that 1.5 SPEED is still a size the program computes with.
  void check_random(const RandomBalls& random) const {
    if (random.count < 1 || random.count > most_random_balls ||
        random.count != std::floor(random.count)) {
      fail(random.line,
           fmt::format("'random' COUNT = {} must be a whole number from 1 to {}",
                       random.count, most_random_balls));
    }
    if (random.seed < 0 || random.seed > 0x1.0p53 ||
        random.seed != std::floor(random.seed)) {
      fail(random.line,
           fmt::format("'random' SEED = {} must be a whole number from 0 to 2^53",
                       random.seed));
    }
    if (random.speed <= 0 || 1.5 * random.speed > largest_magnitude) {
      fail(random.line,
           fmt::format("'random' SPEED = {} must be positive and at most {:g}",
                       random.speed, largest_magnitude / 1.5));
    }
  }

  // The 'random' line: COUNT balls at random places, clear of the balls
  // already there and of each other, each with a random direction and a
  // speed between 0.5 and 1.5 SPEED. The same scene on every machine: a
  // seeded std::mt19937_64 (its output is fixed by the C++ standard), our
  // own mapping to [0, 1), and only +, -, *, / and sqrt (correctly rounded
  // in IEEE arithmetic) after it.
  void place_random(const RandomBalls& random, Gas& gas) const {
    const auto count = static_cast<std::size_t>(random.count);
    const double diameter = 2 * gas.radius;
    const double total = static_cast<double>(gas.balls.size() + count);
    const double covered =
        total * std::numbers::pi * gas.radius * gas.radius / (gas.width * gas.height);
    if (covered > densest_packing) {
      fail(random.line,
           fmt::format("'random' cannot place {} balls of radius {} on a {} x {} table: "
                       "they would cover {:.3g} of it, more than any packing of discs "
                       "({:.4f})",
                       count, gas.radius, gas.width, gas.height, covered,
                       densest_packing));
    }

    // Where each ball is: cells at least 2a wide, so that a place is checked
    // only against the balls in the 3 x 3 cells around it; not many more
    // cells than balls.
    const double most_cells = 2 * total + 16;
    double columns =
        std::min(std::max(1.0, std::floor(gas.width / diameter)), most_cells);
    double rows = std::min(std::max(1.0, std::floor(gas.height / diameter)), most_cells);
    if (columns * rows > most_cells) {
      const double shrink = std::sqrt(most_cells / (columns * rows));
      columns = std::max(1.0, std::floor(columns * shrink));
      rows = std::max(1.0, std::floor(rows * shrink));
    }
    const auto across = static_cast<std::size_t>(columns),
               down = static_cast<std::size_t>(rows);
    const double cell_width = gas.width / columns, cell_height = gas.height / rows;
    auto cell = [](double coordinate, double width, std::size_t cells) {
      return static_cast<std::size_t>(std::clamp(std::floor(coordinate / width), 0.0,
                                                 static_cast<double>(cells - 1)));
    };
    std::vector<std::size_t> head(across * down, 0);  // ball number + 1, 0: empty
    std::vector<std::size_t> next(gas.balls.size() + count, 0);
    auto file = [&](std::size_t index) {
      const Ball& ball = gas.balls[index];
      const std::size_t c =
          cell(ball.y, cell_height, down) * across + cell(ball.x, cell_width, across);
      next[index] = head[c];
      head[c] = index + 1;
    };
    auto free = [&](double x, double y) {
      const std::size_t column = cell(x, cell_width, across),
                        row = cell(y, cell_height, down);
      for (std::size_t r = row == 0 ? 0 : row - 1; r <= std::min(down - 1, row + 1);
           ++r) {
        for (std::size_t c = column == 0 ? 0 : column - 1;
             c <= std::min(across - 1, column + 1); ++c) {
          for (std::size_t k = head[r * across + c]; k != 0; k = next[k - 1]) {
            const double dx = gas.balls[k - 1].x - x, dy = gas.balls[k - 1].y - y;
            if (dx * dx + dy * dy < diameter * diameter) return false;
          }
        }
      }
      return true;
    };
    for (std::size_t i = 0; i < gas.balls.size(); ++i) file(i);

    std::mt19937_64 generator(static_cast<std::uint64_t>(random.seed));
    const std::size_t first = gas.balls.size();
    for (std::size_t k = 0; k < count; ++k) {
      bool placed = false;
      for (int tries = 0; tries < most_tries_per_random_ball && !placed; ++tries) {
        const double x = gas.radius + (gas.width - diameter) * unit_interval(generator);
        const double y = gas.radius + (gas.height - diameter) * unit_interval(generator);
        if (free(x, y)) {
          gas.balls.push_back(Ball{x, y, 0, 0, 0});
          file(gas.balls.size() - 1);
          placed = true;
        }
      }
      if (!placed) {
        fail(random.line,
             fmt::format("'random' found no free place for ball {} in {} tries ({} "
                         "balls would cover {:.3g} of the table; random placement rarely "
                         "gets past 0.5)",
                         first + k + 1, most_tries_per_random_ball, total, covered));
      }
    }
    // The velocities: a direction uniform on the circle (a point drawn in the
    // square [-1, 1)^2 until it falls inside the unit disc), a speed uniform in
    // [0.5, 1.5) SPEED. A component too small to compute with is 0.
    for (std::size_t k = first; k < gas.balls.size(); ++k) {
      double u = 0, v = 0, square = 0;
      do {
        u = 2 * unit_interval(generator) - 1;
        v = 2 * unit_interval(generator) - 1;
        square = u * u + v * v;
      } while (square == 0 || square > 1);
      const double speed = random.speed * (0.5 + unit_interval(generator));
      const double length = std::sqrt(square);
      Ball& ball = gas.balls[k];
      ball.vx = speed * (u / length);
      ball.vy = speed * (v / length);
      if (std::fabs(ball.vx) < smallest_magnitude) ball.vx = 0;
      if (std::fabs(ball.vy) < smallest_magnitude) ball.vy = 0;
    }
  }

 private:
  std::string file_name_;
};

}  // namespace

Gas parse_scene(std::string_view text, const std::string& file_name) {
  const Reader reader(file_name);
  if (text.substr(0, 3) == "\xEF\xBB\xBF")
    text.remove_prefix(3);  // UTF-8 byte-order mark
  SceneText scene;
  int line_number = 0;
  while (!text.empty()) {
    ++line_number;
    const std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    text =
        newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CRLF files
    reader.read_line(line, line_number, scene);
  }
  scene.last_line = line_number > 0 ? line_number : 1;
  return reader.check(scene);
}

Gas read_scene_file(const std::string& path) {
  // The largest scene file we read: far above any scene (10^5 balls take
  // ~5 MB), small enough that a wrong file (a disk image, /dev/zero) is
  // refused quickly instead of filling the memory.
  constexpr std::size_t largest = 64u << 20;
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw SceneError(fmt::format("{}: no such scene file", path));
  }
  if (std::filesystem::is_directory(path, error)) {
    throw SceneError(fmt::format("{}: is a directory, not a scene file", path));
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) throw SceneError(fmt::format("{}: cannot open the scene file", path));
  std::string text;
  char chunk[1 << 16];
  while (file.read(chunk, sizeof chunk) || file.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(file.gcount()));
    if (text.size() > largest) {
      throw SceneError(
          fmt::format("{}: larger than {} MiB, not a scene file", path, largest >> 20));
    }
  }
  if (file.bad()) throw SceneError(fmt::format("{}: cannot read the scene file", path));
  return parse_scene(text, path);
}

#ifndef GAS_STUDENT_SCENE_TEXT  // see lessons/exercises/02-scene-text
std::string scene_text(const Gas& gas) {
  std::string text = fmt::format(
      "# written by gas at T = {:.17g}\n"
      "a  {:.17g}\nT0 {:.17g}\nA1 {:.17g}\nA2 {:.17g}\nN  {}\n",
      gas.time, gas.radius, gas.display_step, gas.width, gas.height, gas.balls.size());
  for (const Ball& ball : gas.balls) {
    const Point centre = centre_at(ball, gas.time);
    text += fmt::format("ball {:.17g} {:.17g} {:.17g} {:.17g}\n", centre.x, centre.y,
                        ball.vx, ball.vy);
  }
  return text;
}
#endif

}  // namespace gas
