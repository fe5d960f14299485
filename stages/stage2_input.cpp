// Stage 2 — input: the scene-file reader. See stage2_input.hpp for the
// contract and data/README.md for the format.
#include "stage2_input.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
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
struct SceneText {
  std::optional<Given> radius, display_step, width, height, ball_count;
  std::vector<Ball> balls;
  std::vector<int> ball_lines;
  int last_line = 1;
};

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
    } else {
      std::string hint;
      for (const char* known : {"a", "T0", "A1", "A2", "N", "ball"}) {
        std::string lower(keyword);
        std::string lower_known(known);
        for (char& c : lower)
          c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        for (char& c : lower_known)
          c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (lower == lower_known)
          hint = fmt::format(" (names are case-sensitive: did you mean '{}'?)", known);
      }
      if (hint.empty()) hint = " (expected a, T0, A1, A2, N or ball)";
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
        !scene.ball_count && scene.balls.empty()) {
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
    for (const Given* side : {&width, &height}) {
      if (side->value < diameter) {
        fail(side->line, fmt::format("the table ({} x {}) is too small for one ball of "
                                     "diameter 2a = {}",
                                     width.value, height.value, diameter));
      }
    }

    if (scene.ball_count) {
      const Given& n = *scene.ball_count;
      if (n.value < 0 || n.value != std::floor(n.value)) {
        fail(n.line, fmt::format("N = {} must be a whole number of balls", n.value));
      }
      if (n.value != static_cast<double>(scene.balls.size())) {
        fail(n.line, fmt::format("N = {} but the file has {} 'ball' line{}", n.value,
                                 scene.balls.size(), scene.balls.size() == 1 ? "" : "s"));
      }
    }
    if (scene.balls.empty()) fail(end, "no 'ball' lines: a gas needs at least one ball");

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
    return gas;
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

}  // namespace gas
