// Stage 2 — input: the scene-file reader. See stage2_input.hpp for the
// contract and data/README.md for the format.
//
// In the order a scene goes through them: the file into lines (read_lines,
// a block at a time), a line into words (split_words), a word into a number
// (read_number), a keyword line into what the file said (read_line, into a
// SceneText); then the checks of the whole scene, each its own function
// (check_complete, check_sizes, check_random_line, check_count, check_times,
// check_inside_table, check_no_overlap), and the description built from it.
#include "stage2_input.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <memory>
#include <utility>
#include <vector>

namespace gas {
namespace {

// A value given on some line of the file, remembered with that line so that
// later checks can point at it.
struct Given {
  double value = 0;
  int line = 0;
};

// A 'random COUNT SEED SPEED' or 'lattice COUNT SEED SPEED' line as
// written, its numbers not checked yet.
struct RandomLine {
  double count = 0, seed = 0, speed = 0;
  int line = 0;
  const char* keyword = "random";  // or "lattice"
};

// What the file said, line by line, before any check that needs the whole
// file.
struct SceneText {
  std::string file_name;                                     // for messages
  std::optional<Given> radius, display_step, width, height;  // a, T0, A1, A2
  std::optional<Given> ball_count;                           // N
  std::optional<Given> start_time;  // T, the moment the scene starts (none: 0)
  std::vector<Ball> balls;          // the 'ball' lines: R, a ball's column a line
  std::vector<int> ball_lines;      // the line of each
  std::vector<bool> since_given;    // whether each gave SINCE (else: since = T)
  std::optional<RandomLine> random;
  int last_line = 1;  // where something missing is reported
};

// Refuses the scene: "FILE:LINE: what is wrong".
[[noreturn]] void fail(const std::string& file_name, int line, const std::string& what) {
  throw SceneError(fmt::format("{}:{}: {}", file_name, line, what));
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

// ---- Reading: a line into words, a word into a number, a line into SceneText

// The words of a line, separated by spaces and tabs.
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

// A number of the scene: the whole word and nothing else, a finite double,
// and 0 or of a size the program computes with.
// [anchor: read-number]
double read_number(std::string_view word, const std::string& file_name, int line) {
  std::string_view digits = word;
  // std::from_chars takes no '+' sign: drop one before a digit.
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-') digits.remove_prefix(1);
  double value = 0;
  const auto [end, error] =
      std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error == std::errc::result_out_of_range) {
    fail(file_name, line,
         fmt::format("'{}' is out of the range of a double", printable(word)));
  }
  if (error != std::errc() || end != digits.data() + digits.size()) {
    fail(file_name, line, fmt::format("'{}' is not a number", printable(word)));
  }
  if (!std::isfinite(value)) {
    fail(file_name, line, fmt::format("'{}' is not a finite number", printable(word)));
  }
  if (value != 0 &&
      (std::fabs(value) < smallest_magnitude || std::fabs(value) > largest_magnitude)) {
    fail(file_name, line,
         fmt::format("'{}' is outside the range of sizes this program computes with "
                     "({:g} to {:g}, or 0)",
                     printable(word), smallest_magnitude, largest_magnitude));
  }
  return value;
}
// [/anchor: read-number]

// What to add to "unknown keyword 'WORD'": the keyword meant, if the word is
// one in the wrong case, else the list of keywords.
std::string keyword_hint(std::string_view keyword) {
  auto lower = [](std::string_view word) {
    std::string out(word);
    for (char& c : out)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
  };
  std::string hint;
  for (const char* known :
       {"a", "T0", "A1", "A2", "N", "ball", "random", "lattice", "T"}) {
    if (lower(keyword) == lower(known))
      hint = fmt::format(" (names are case-sensitive: did you mean '{}'?)", known);
  }
  if (hint.empty()) hint = " (expected a, T0, A1, A2, N, ball, random or lattice)";
  return hint;
}

// A 'ball' line's numbers into `scene`: x y vx vy, and SINCE if there is a
// fifth (its line's count of numbers already checked).
void add_ball(const std::vector<double>& v, int line_number, SceneText& scene) {
  if (static_cast<double>(scene.balls.size()) >= most_balls) {
    fail(scene.file_name, line_number,
         fmt::format("ball {}: a scene holds at most {} balls", scene.balls.size() + 1,
                     most_balls));
  }
  const bool since_given = v.size() == 5;
  scene.balls.push_back(Ball{v[0], v[1], v[2], v[3], since_given ? v[4] : 0.0});
  scene.ball_lines.push_back(line_number);
  scene.since_given.push_back(since_given);
}

// One line of the file into `scene`: the comment after '#' cut, the words
// split, the keyword's numbers read and kept with their line.
void read_line(std::string_view line, int line_number, SceneText& scene) {
  if (const auto hash = line.find('#'); hash != std::string_view::npos) {
    line = line.substr(0, hash);
  }
  const std::vector<std::string_view> words = split_words(line);
  if (words.empty()) return;
  const std::string_view keyword = words[0];
  const std::size_t count = words.size() - 1;

  // The numbers after the keyword: exactly `wanted` of them.
  auto numbers = [&](std::size_t wanted, const char* meaning) {
    if (count != wanted) {
      fail(scene.file_name, line_number,
           fmt::format("'{}' takes {} number{} ({}), found {}", keyword, wanted,
                       wanted == 1 ? "" : "s", meaning, count));
    }
    std::vector<double> values;
    for (std::size_t i = 1; i < words.size(); ++i) {
      values.push_back(read_number(words[i], scene.file_name, line_number));
    }
    return values;
  };
  // A keyword that is given once, with one number.
  auto single = [&](std::optional<Given>& slot, const char* meaning) {
    const double value = numbers(1, meaning)[0];
    if (slot) {
      fail(scene.file_name, line_number,
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
  } else if (keyword == "T") {
    single(scene.start_time, "the model time the scene starts at");
  } else if (keyword == "ball") {
    // x y vx vy, or (as --dump writes) x y vx vy SINCE: the ball's column of R
    // as it was written at the moment SINCE. Without SINCE the column is the
    // centre at the scene's T, filled in once the whole file is read (checked()).
    if (count > 5) {
      fail(scene.file_name, line_number,
           fmt::format("'ball' takes 4 numbers (x y vx vy) or 5 (x y vx vy SINCE), "
                       "found {}",
                       count));
    }
    const bool since_given = count == 5;
    add_ball(numbers(since_given ? 5 : 4, "x y vx vy"), line_number, scene);
  } else if (keyword == "random" || keyword == "lattice") {
    const std::vector<double> v = numbers(3, "COUNT SEED SPEED");
    if (scene.random) {
      fail(scene.file_name, line_number,
           keyword == scene.random->keyword
               ? fmt::format("'{}' is given twice (first on line {})", keyword,
                             scene.random->line)
               : fmt::format("one 'random' or 'lattice' line only ('{}' is on line {})",
                             scene.random->keyword, scene.random->line));
    }
    scene.random = RandomLine{v[0], v[1], v[2], line_number,
                              keyword == "random" ? "random" : "lattice"};
  } else {
    const std::string unknown =
        fmt::format("unknown keyword '{}'{}", printable(keyword), keyword_hint(keyword));
    fail(scene.file_name, line_number, unknown);
  }
}

// ---- Checking the whole scene (in this order: the first problem is reported)

// Check that the scene is not empty and gives a, T0, A1 and A2.
void check_complete(const SceneText& scene) {
  const int end = scene.last_line;
  if (!scene.radius && !scene.display_step && !scene.width && !scene.height &&
      !scene.ball_count && scene.balls.empty() && !scene.random) {
    fail(scene.file_name, end,
         "the scene is empty: it needs a, T0, A1, A2 and at least one ball");
  }
  auto required = [&](const std::optional<Given>& slot, const char* keyword,
                      const char* meaning) {
    if (!slot)
      fail(scene.file_name, end, fmt::format("missing '{}' ({})", keyword, meaning));
  };
  required(scene.radius, "a", "the ball radius");
  required(scene.display_step, "T0", "the display time step");
  required(scene.width, "A1", "the table width");
  required(scene.height, "A2", "the table height");
}

// Check that a, T0, A1 and A2 are positive and that a ball has room to move.
// [anchor: check-sizes]
void check_sizes(const SceneText& scene) {
  for (const auto& [given, name] :
       {std::pair{*scene.radius, "a"}, std::pair{*scene.display_step, "T0"},
        std::pair{*scene.width, "A1"}, std::pair{*scene.height, "A2"}}) {
    if (given.value <= 0) {
      fail(scene.file_name, given.line,
           fmt::format("{} = {} must be positive", name, given.value));
    }
  }
  // On a table exactly 2a wide a ball would bounce between the two walls at
  // one instant for ever.
  const double diameter = 2 * scene.radius->value;
  for (const Given& side : {*scene.width, *scene.height}) {
    if (side.value <= diameter * (1 + contact_tolerance)) {
      fail(scene.file_name, side.line,
           fmt::format("the table ({} x {}) leaves no room to move for a ball of "
                       "diameter 2a = {}",
                       scene.width->value, scene.height->value, diameter));
    }
  }
}
// [/anchor: check-sizes]

// Check the numbers of a 'random' (or 'lattice') line: COUNT a whole number from 1 to
// most_balls, and with the 'ball' lines at most most_balls, SEED a whole number from 0 to
// 2^53 (a double holds every such number exactly), SPEED > 0 and small enough that 1.5
// SPEED is still a size the program computes with. The request, or none without the line.
std::optional<RandomBalls> check_random_line(const SceneText& scene) {
  if (!scene.random) return std::nullopt;
  const RandomLine& random = *scene.random;
  if (random.count < 1 || random.count > most_balls ||
      random.count != std::floor(random.count)) {
    fail(scene.file_name, random.line,
         fmt::format("'{}' COUNT = {} must be a whole number from 1 to {}",
                     random.keyword, random.count, most_balls));
  }
  const auto lines = static_cast<double>(scene.balls.size());
  if (lines + random.count > most_balls) {
    fail(scene.file_name, random.line,
         fmt::format("'{}' places {} balls besides {} 'ball' line{}: {} in all, more "
                     "than the {} a scene may hold",
                     random.keyword, random.count, lines, lines == 1 ? "" : "s",
                     lines + random.count, most_balls));
  }
  if (random.seed < 0 || random.seed > 0x1.0p53 ||
      random.seed != std::floor(random.seed)) {
    fail(scene.file_name, random.line,
         fmt::format("'{}' SEED = {} must be a whole number from 0 to 2^53",
                     random.keyword, random.seed));
  }
  if (random.speed <= 0 || 1.5 * random.speed > largest_magnitude) {
    fail(scene.file_name, random.line,
         fmt::format("'{}' SPEED = {} must be positive and at most {:g}", random.keyword,
                     random.speed, largest_magnitude / 1.5));
  }
  return RandomBalls{static_cast<std::size_t>(random.count),
                     static_cast<std::uint64_t>(random.seed), random.speed, random.line,
                     random.keyword == std::string_view("lattice")};
}

// Check that N, if given, is a whole number that agrees with the balls of the
// file, and that there is at least one ball.
// [anchor: check-count]
void check_count(const SceneText& scene) {
  const std::size_t lines = scene.balls.size();
  const char* plural = lines == 1 ? "" : "s";
  const double random_count = scene.random ? scene.random->count : 0;
  if (scene.ball_count) {
    const Given& n = *scene.ball_count;
    if (n.value < 0 || n.value != std::floor(n.value)) {
      fail(scene.file_name, n.line,
           fmt::format("N = {} must be a whole number of balls", n.value));
    }
    if (n.value != static_cast<double>(lines) + random_count) {
      const std::string found =
          fmt::format("N = {} but the file has {} 'ball' line{}", n.value, lines, plural);
      if (scene.random) {
        fail(scene.file_name, n.line,
             fmt::format("{} and '{}' places {}", found, scene.random->keyword,
                         random_count));
      }
      fail(scene.file_name, n.line, found);
    }
  }
  if (lines == 0 && !scene.random) {
    fail(scene.file_name, scene.last_line,
         "no 'ball' lines: a gas needs at least one ball");
  }
}
// [/anchor: check-count]

// The scene's T: its 'T' line, or 0.
double start_time(const SceneText& scene) {
  return scene.start_time ? scene.start_time->value : 0.0;
}

// Check the times of a scene that carries them (a --dump): T is not negative
// (model time starts at 0 and only goes on), no column of R was written after T, and
// T leaves the clock fine enough to follow the gas. Doubles near T lie
// T * 2^-52 apart; the quickest crossing of the room between two walls (the
// smaller of A1 - 2a and A2 - 2a, at the highest speed along an axis) must
// last at least 2^20 of those steps, or stage 4's times, added to T, would
// round back to T and time could not move on.
// [anchor: check-times]
void check_times(const SceneText& scene) {
  const double now = start_time(scene);
  if (now < 0) {
    fail(scene.file_name, scene.start_time->line,
         fmt::format("T = {} must not be negative", now));
  }
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    if (scene.since_given[i] && scene.balls[i].since > now) {
      fail(scene.file_name, scene.ball_lines[i],
           fmt::format("ball {}: its row is written at SINCE = {}, after the scene's "
                       "T = {} (a row cannot be written in the future)",
                       i + 1, scene.balls[i].since, now));
    }
  }
  double fastest = scene.random ? 1.5 * scene.random->speed : 0.0;
  for (const Ball& ball : scene.balls)
    fastest = std::max({fastest, std::fabs(ball.vx), std::fabs(ball.vy)});
  const double a = scene.radius->value;
  const double crossing =
      (std::min(scene.width->value, scene.height->value) - 2 * a) / fastest;
  if (fastest > 0 && now * 0x1.0p-32 > crossing) {
    fail(scene.file_name, scene.start_time->line,
         fmt::format("T = {} is too late for this gas: the clock could not tell apart "
                     "moments {:.3g} apart (the quickest crossing of the table); T may "
                     "be at most {:.6g}",
                     now, crossing, crossing * 0x1.0p32));
  }
}
// [/anchor: check-times]

// Where each ball's centre is at the scene's T, the moment the run starts
// from: the checks below look at these, not at the columns of R. A 'ball' line
// without SINCE gives its centre at T itself (taken as written, not
// recomputed); one with SINCE gives it at SINCE, and it has flown since.
// [anchor: centres-at-start]
std::vector<Point> centres_at_start(const SceneText& scene) {
  std::vector<Point> centres;
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    const Ball& row = scene.balls[i];
    centres.push_back(scene.since_given[i] ? centre_at(row, start_time(scene))
                                           : Point{row.x, row.y});
  }
  return centres;
}
// [/anchor: centres-at-start]

// In a message about a ball given with SINCE before T: that the centre meant
// is the one at T, not the line's x and y.
std::string when(const SceneText& scene, std::size_t i) {
  if (!scene.since_given[i] || scene.balls[i].since == start_time(scene)) return "";
  return fmt::format(" at T = {}", start_time(scene));
}

// Check that every centre at T is within its limits a <= x <= A1 - a,
// a <= y <= A2 - a (up to the contact tolerance).
// [anchor: check-inside-table]
void check_inside_table(const SceneText& scene, const std::vector<Point>& centres) {
  const double a = scene.radius->value;
  const double slack = contact_tolerance * (2 * a);
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    auto within = [&](double value, double side, char axis) {
      if (value < a - slack || value > side - a + slack) {
        fail(scene.file_name, scene.ball_lines[i],
             fmt::format("ball {}: its centre {} = {}{} is outside the table "
                         "(a <= {} <= {} - a, i.e. {} .. {})",
                         i + 1, axis, value, when(scene, i), axis,
                         axis == 'x' ? "A1" : "A2", a, side - a));
      }
    };
    within(centres[i].x, scene.width->value, 'x');
    within(centres[i].y, scene.height->value, 'y');
  }
}
// [/anchor: check-inside-table]

// Check that no two balls overlap at T: no two centres closer than 2a
// (touching is allowed, up to the contact tolerance). `search` finds the
// first pair that does (first_overlap_of_all_pairs, or a faster way).
// [anchor: check-no-overlap]
void check_no_overlap(const SceneText& scene, const std::vector<Point>& centres,
                      const OverlapSearch& search) {
  const double diameter = 2 * scene.radius->value;
  const double closest = diameter - contact_tolerance * diameter;
  if (const std::optional<Overlap> pair = search(centres, closest)) {
    const std::size_t j = pair->later, i = pair->earlier;
    const double apart =
        std::hypot(centres[j].x - centres[i].x, centres[j].y - centres[i].y);
    fail(scene.file_name, scene.ball_lines[j],
         fmt::format("ball {} overlaps ball {} (line {}): centres {:.9g} apart{}, "
                     "less than 2a = {}",
                     j + 1, i + 1, scene.ball_lines[i], apart,
                     when(scene, j).empty() ? when(scene, i) : when(scene, j), diameter));
  }
}
// [/anchor: check-no-overlap]

// The description of a scene that passes every check (its balls moved out
// of `scene`).
SceneDescription checked(SceneText&& scene, const OverlapSearch& search) {
  check_complete(scene);
  check_sizes(scene);
  std::optional<RandomBalls> random = check_random_line(scene);
  check_count(scene);
  check_times(scene);
  const std::vector<Point> centres = centres_at_start(scene);
  check_inside_table(scene, centres);
  check_no_overlap(scene, centres, search);

  SceneDescription description;
  description.file_name = scene.file_name;
  description.gas.radius = scene.radius->value;
  description.gas.width = scene.width->value;
  description.gas.height = scene.height->value;
  description.gas.display_step = scene.display_step->value;
  description.gas.time = start_time(scene);
  description.gas.balls = std::move(scene.balls);
  for (std::size_t i = 0; i < description.gas.balls.size(); ++i) {
    if (!scene.since_given[i]) description.gas.balls[i].since = description.gas.time;
  }
  description.random = random;
  return description;
}

// "FILE: larger than 256 MiB, not a scene file".
[[noreturn]] void fail_too_large(const std::string& file_name) {
  throw SceneError(fmt::format("{}: larger than {} MiB, not a scene file", file_name,
                               largest_scene_file >> 20));
}

// Line `line_number` of the file, its line end cut, into `scene`: a
// byte-order mark skipped at the very start, a CR before the line end cut
// (CRLF files), a line longer than longest_scene_line refused.
void read_file_line(std::string_view line, int line_number, SceneText& scene) {
  if (line_number == 1 && line.substr(0, 3) == "\xEF\xBB\xBF")
    line.remove_prefix(3);  // UTF-8 byte-order mark
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.size() > longest_scene_line) {
    fail(scene.file_name, line_number,
         fmt::format("the line is longer than {} characters, the most a scene's line "
                     "may have",
                     longest_scene_line));
  }
  read_line(line, line_number, scene);
}

// The whole lines at the start of `text` into `scene`, numbered on from
// `line_number`. What follows the last line end (a line not yet ended) is
// left; returns how many characters were read.
std::size_t read_lines(std::string_view text, int& line_number, SceneText& scene) {
  std::size_t start = 0;
  for (std::size_t end = text.find('\n'); end != std::string_view::npos;
       end = text.find('\n', start)) {
    read_file_line(text.substr(start, end - start), ++line_number, scene);
    start = end + 1;
  }
  return start;
}

}  // namespace

// [anchor: first-overlap-of-all-pairs]
std::optional<Overlap> first_overlap_of_all_pairs(const std::vector<Point>& centres,
                                                  double closest) {
  for (std::size_t j = 1; j < centres.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      const double dx = centres[j].x - centres[i].x;
      const double dy = centres[j].y - centres[i].y;
      if (dx * dx + dy * dy < closest * closest) return Overlap{j, i};
    }
  }
  return std::nullopt;
}
// [/anchor: first-overlap-of-all-pairs]

SceneDescription parse_scene_description(std::string_view text,
                                         const std::string& file_name,
                                         const OverlapSearch& search) {
  if (text.size() > largest_scene_file) fail_too_large(file_name);
  SceneText scene;
  scene.file_name = file_name;
  int line_number = 0;
  text.remove_prefix(read_lines(text, line_number, scene));
  if (!text.empty()) read_file_line(text, ++line_number, scene);  // no line end
  scene.last_line = line_number > 0 ? line_number : 1;
  return checked(std::move(scene), search);
}

SceneDescription read_scene_description(const std::string& path,
                                        const OverlapSearch& search) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) {
    throw SceneError(fmt::format("{}: no such scene file", path));
  }
  if (std::filesystem::is_directory(path, error)) {
    throw SceneError(fmt::format("{}: is a directory, not a scene file", path));
  }
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(
      std::fopen(path.c_str(), "rb"), std::fclose);
  if (!file) throw SceneError(fmt::format("{}: cannot open the scene file", path));

  // A block at a time: its whole lines read, the start of a line not yet
  // ended kept for the next block. Only that start and the scene read so far
  // are in memory, never the file.
  SceneText scene;
  scene.file_name = path;
  int line_number = 0;
  std::size_t total = 0;
  constexpr std::size_t block = std::size_t{1} << 20;
  std::string pending;  // the lines not read yet: a line's start, then a block
  while (true) {
    const std::size_t kept = pending.size();
    pending.resize(kept + block);
    const std::size_t got = std::fread(pending.data() + kept, 1, block, file.get());
    pending.resize(kept + got);
    total += got;
    if (total > largest_scene_file) fail_too_large(path);
    if (got == 0) break;
    pending.erase(0, read_lines(pending, line_number, scene));
    // A line not ended within the longest line (its CR and the mark aside)
    // is refused now, before more of it is read.
    if (pending.size() > longest_scene_line + 4)
      read_file_line(pending, ++line_number, scene);
  }
  if (std::ferror(file.get()) != 0)
    throw SceneError(fmt::format("{}: cannot read the scene file", path));
  if (!pending.empty()) read_file_line(pending, ++line_number, scene);  // no line end
  scene.last_line = line_number > 0 ? line_number : 1;
  return checked(std::move(scene), search);
}

Gas build_gas(const SceneDescription& scene) {
  if (scene.random) {
    fail(scene.file_name, scene.random->line,
         fmt::format("'{}' asks for balls that stage 2 does not place: read the scene "
                     "with parse_scene or read_scene_file (beyond/random_placement.hpp)",
                     scene.random->lattice ? "lattice" : "random"));
  }
  return scene.gas;
}

#ifndef GAS_STUDENT_SCENE_TEXT  // see lessons/exercises/02-scene-text
// [anchor: scene-text]
std::string scene_text(const Gas& gas) {
  // The lines themselves are write_scene_text's, below: here its pieces are
  // joined into one text.
  std::string text;
  write_scene_text(gas, [&text](std::string_view piece) { text += piece; });
  return text;
}
// [/anchor: scene-text]
#endif

void write_scene_text(const Gas& gas,
                      const std::function<void(std::string_view piece)>& write) {
  // Write the heading: a comment, T, a, T0, A1, A2 and N.
  std::string text = fmt::format(
      "# A checkpoint written by gas (--dump) at model time T = {:.17g}.\n"
      "# Each ball line is the ball's row as the run keeps it: its centre x y\n"
      "# at the moment SINCE it last collided, its velocity vx vy, and SINCE;\n"
      "# every number to 17 digits. Read back, the run goes on from T exactly.\n"
      "T  {:.17g}\na  {:.17g}\nT0 {:.17g}\nA1 {:.17g}\nA2 {:.17g}\nN  {}\n"
      "#    x y vx vy SINCE\n",
      gas.time, gas.time, gas.radius, gas.display_step, gas.width, gas.height,
      gas.balls.size());
  // Write each ball's row as it is, 'ball x y vx vy SINCE', handing the text
  // on whenever some 64 kB have gathered.
  constexpr std::size_t piece = std::size_t{1} << 16;
  for (const Ball& ball : gas.balls) {
    fmt::format_to(std::back_inserter(text),
                   "ball {:.17g} {:.17g} {:.17g} {:.17g} {:.17g}\n", ball.x, ball.y,
                   ball.vx, ball.vy, ball.since);
    if (text.size() >= piece) {
      write(text);
      text.clear();
    }
  }
  write(text);
}

}  // namespace gas
