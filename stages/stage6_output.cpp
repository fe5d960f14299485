// Stage 6 — output to the screen. See stage6_output.hpp.
#include "stage6_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace gas {

const char* mode_name(ScreenMode mode) {
  switch (mode) {
    case ScreenMode::balls:
      return "balls";
    case ScreenMode::trails:
      return "trails";
    case ScreenMode::stats:
      return "stats";
  }
  return "?";
}

#ifndef GAS_STUDENT_BALL_IMAGE  // see lessons/exercises/09-ball-image
// [anchor: ball-image]
std::vector<Cell> ball_image(const TextScreen& screen, Point centre, double radius) {
  const Cell middle = screen.cell_of(centre);
  std::vector<Cell> cells{middle};
  // Only cells within the ball's bounding box can hold a cell middle within a.
  const Cell top_left = screen.cell_of({centre.x - radius, centre.y + radius});
  const Cell bottom_right = screen.cell_of({centre.x + radius, centre.y - radius});
  for (int row = top_left.row; row <= bottom_right.row; ++row) {
    for (int column = top_left.column; column <= bottom_right.column; ++column) {
      const Cell cell{column, row};
      const Point m = screen.middle_of(cell);
      const double dx = m.x - centre.x, dy = m.y - centre.y;
      if (!(cell == middle) && dx * dx + dy * dy <= radius * radius)
        cells.push_back(cell);
    }
  }
  return cells;
}
// [/anchor: ball-image]
#endif

// [anchor: draw-balls]
void draw_balls(TextScreen& screen, const Picture& picture, double radius,
                const Tone& tone) {
  // Erase the old images: paint them in the background colour.
  for (const Point& old_centre : picture.old_centres) {
    for (const Cell& cell : ball_image(screen, old_centre, radius)) screen.at(cell) = ' ';
  }
  // Draw the balls at their new positions in the base colour.
  for (const Point& centre : picture.centres) {
    for (const Cell& cell : ball_image(screen, centre, radius))
      screen.at(cell) = tone.ball_glyph;
  }
}
// [/anchor: draw-balls]

// [anchor: draw-trails]
void draw_trails(TextScreen& screen, const Picture& picture, const Tone& tone) {
  for (std::size_t i = 0; i < picture.centres.size(); ++i) {
    // The segment from the old centre to the new one, one cell per step along
    // its longer direction.
    const Cell from = screen.cell_of(picture.old_centres[i]);
    const Cell to = screen.cell_of(picture.centres[i]);
    const int steps =
        std::max(std::abs(to.column - from.column), std::abs(to.row - from.row));
    for (int k = 0; k <= steps; ++k) {
      const double f = steps == 0 ? 0.0 : static_cast<double>(k) / steps;
      const Cell cell{
          static_cast<int>(std::lround(from.column + f * (to.column - from.column))),
          static_cast<int>(std::lround(from.row + f * (to.row - from.row)))};
      screen.at(cell) = tone.trail_glyph;
    }
  }
}
// [/anchor: draw-trails]

Figures measure(const Gas& gas, double starting_energy, long long wall_collisions,
                long long ball_collisions) {
  Figures figures;
  figures.time = gas.time;
  figures.display_step = gas.display_step;
  figures.wall_collisions = wall_collisions;
  figures.ball_collisions = ball_collisions;
  figures.balls = gas.balls.size();
  figures.mean_speed = mean_speed(gas);
  figures.energy = kinetic_energy(gas);
  figures.energy_drift =
      starting_energy > 0 ? (figures.energy - starting_energy) / starting_energy : 0.0;
  figures.momentum = total_momentum(gas);
  return figures;
}

void write_text(TextScreen& screen, int row, const std::string& text) {
  for (std::size_t k = 0; k < text.size() && static_cast<int>(k) + 3 < screen.columns - 1;
       ++k) {
    screen.at({2 + static_cast<int>(k), row}) = text[k];
  }
}

// [anchor: draw-figures]
void draw_figures(TextScreen& screen, const std::vector<std::string>& lines) {
  clear_inside(screen);
  const int count = static_cast<int>(lines.size());
  for (int i = 0; i < count && 1 + i < screen.rows - 1; ++i)
    write_text(screen, 1 + i, lines[static_cast<std::size_t>(i)]);
}
// [/anchor: draw-figures]

std::string status_line(const Figures& f, ScreenMode mode, bool stopped) {
  return fmt::format("T={:.6f} T0={:g} collisions={} (walls {}, balls {}) screen={}{}",
                     f.time, f.display_step, f.wall_collisions + f.ball_collisions,
                     f.wall_collisions, f.ball_collisions, mode_name(mode),
                     stopped ? " [stopped]" : "");
}

std::vector<std::string> fit_words(const std::vector<std::string>& words, int columns,
                                   int rows) {
  const auto width = static_cast<std::size_t>(columns > 0 ? columns : 0);
  auto wrapped = [&](std::size_t first) {
    std::vector<std::string> lines;
    for (std::size_t k = first; k < words.size(); ++k) {
      if (!lines.empty() &&
          (width == 0 || lines.back().size() + 1 + words[k].size() <= width)) {
        lines.back() += ' ' + words[k];
      } else {
        lines.push_back(width == 0 ? words[k] : words[k].substr(0, width));
      }
    }
    return lines;
  };
  // Leave out words from the front until the lines fit the rows.
  for (std::size_t first = 0; first < words.size(); ++first) {
    std::vector<std::string> lines = wrapped(first);
    if (rows <= 0 || lines.size() <= static_cast<std::size_t>(rows)) return lines;
  }
  return {};
}

void Display::keys_below(std::vector<std::string> forms) {
  keys_ = std::move(forms);
  invalidate();
}

std::string Display::key_line() const {
  if (keys_.empty()) return {};
  for (const std::string& form : keys_) {
    if (window_columns_ == 0 || form.size() <= static_cast<std::size_t>(window_columns_))
      return form;
  }
  std::string line = keys_.back();
  cut_to_window(line);
  return line;
}

void Display::fit_window(int columns, int rows) {
  window_columns_ = std::max(columns, 0);
  window_rows_ = std::max(rows, 0);
  invalidate();
}

void Display::show(const TextScreen& screen, const std::string& status,
                   const Tone* tone) {
  std::vector<std::string> frame;
  frame.reserve(screen.lines.size() + 1);
  frame.push_back(status);
  frame.insert(frame.end(), screen.lines.begin(), screen.lines.end());

  if (!in_place_) {
    for (const std::string& line : frame) fmt::print(out_, "{}\n", line);
    if (!keys_.empty()) fmt::print(out_, "{}\n", key_line());
    std::fflush(out_);
    return;
  }

  // Nothing outside the window: lines cut at its right edge, and none below
  // its last row but one (the key line's, or the cursor's).
  if (window_rows_ > 0 && frame.size() + 1 > static_cast<std::size_t>(window_rows_))
    frame.resize(static_cast<std::size_t>(std::max(window_rows_ - 1, 1)));
  for (std::string& line : frame) cut_to_window(line);
  // The key line on the row under the frame, where the window has it.
  if (!keys_.empty() &&
      (window_rows_ == 0 || frame.size() < static_cast<std::size_t>(window_rows_))) {
    frame.push_back(key_line());
    keys_shown_ = true;
  } else {
    keys_shown_ = false;
  }

  std::string out;
  if (shown_.size() != frame.size()) {
    out += "\x1b[?25l\x1b[H\x1b[2J";  // hide the cursor, clear the screen
    shown_.assign(frame.size(), std::string());
  }
  notice_.clear();
  // The table's inside: frame rows 2 ... screen.rows - 1, columns 1 ... screen.columns
  // - 2.
  out += changes(frame, tone, {screen.columns - 1, screen.rows});
  // The cursor parks under the frame (on the key line, if it is there).
  out += fmt::format("\x1b[{};1H", frame.size() + (keys_shown_ ? 0 : 1));
  std::fwrite(out.data(), 1, out.size(), out_);
  std::fflush(out_);
}

void Display::status_only(const std::string& status) {
  if (in_place_) return;
  fmt::print(out_, "{}\n", status);
  std::fflush(out_);
}

// Send only what changed: for each line, each run of characters that differs
// from what the terminal already shows, after moving the cursor there.
std::string Display::changes(const std::vector<std::string>& frame, const Tone* tone,
                             Cell table_end) {
  std::string out;
  // Colour for the table's glyphs only: never the status line, the border,
  // the key line or a screen of figures.
  auto coloured = [&](std::size_t row, std::size_t column, char c) {
    const bool in_table = row >= 2 && row < static_cast<std::size_t>(table_end.row) &&
                          column >= 1 &&
                          column < static_cast<std::size_t>(table_end.column);
    if (colour_ && tone != nullptr && in_table &&
        (c == tone->ball_glyph || c == tone->trail_glyph)) {
      return fmt::format("\x1b[1;{}m{}\x1b[0m", tone->ansi_colour, c);
    }
    return std::string(1, c);
  };
  for (std::size_t row = 0; row < frame.size(); ++row) {
    const std::string& want = frame[row];
    std::string& have = shown_[row];
    auto differs = [&](std::size_t k) {
      const char w = k < want.size() ? want[k] : ' ';
      const char h = k < have.size() ? have[k] : '\0';
      return w != h;
    };
    const std::size_t width = std::max(want.size(), have.size());
    for (std::size_t column = 0; column < width;) {
      if (!differs(column)) {
        ++column;
        continue;
      }
      out += fmt::format("\x1b[{};{}H", row + 1, column + 1);
      for (; column < width && differs(column); ++column)
        out += coloured(row, column, column < want.size() ? want[column] : ' ');
    }
    have = want;
  }
  return out;
}

void Display::cut_to_window(std::string& line) const {
  if (window_columns_ > 0 && line.size() > static_cast<std::size_t>(window_columns_))
    line.resize(static_cast<std::size_t>(window_columns_));
}

void Display::notice(const std::vector<std::string>& words) {
  if (!in_place_) {
    fmt::print(out_, "{}\n", fit_words(words, 0, 1).front());
    std::fflush(out_);
    return;
  }
  // The window's rows but the cursor's.
  const std::vector<std::string> lines =
      fit_words(words, window_columns_, window_rows_ > 1 ? window_rows_ - 1 : 1);
  std::string text;
  for (std::size_t k = 0; k < lines.size(); ++k)
    text += fmt::format("\x1b[{};1H{}", k + 1, lines[k]);
  if (!notice_.empty() && notice_ == text) return;  // already on the terminal
  // Hide the cursor, clear the screen, the lines at the top; the next frame
  // is drawn whole.
  fmt::print(out_, "\x1b[?25l\x1b[H\x1b[2J{}", text);
  std::fflush(out_);
  shown_.clear();
  notice_ = text;
  notice_rows_ = lines.size();
  keys_shown_ = false;
}

void Display::bell() {
  std::fputc('\a', out_);
  std::fflush(out_);
}

void Display::finish() {
  if (!in_place_) return;
  if (keys_shown_) {
    // The key line wiped, and the cursor left on it for the shell's prompt.
    fmt::print(out_, "\x1b[{};1H\x1b[2K\x1b[?25h", shown_.size());
  } else {
    // Below the frame (or the notice), but not below the window.
    std::size_t row = std::max(shown_.size(), notice_.empty() ? 0 : notice_rows_) + 1;
    if (window_rows_ > 0) row = std::min(row, static_cast<std::size_t>(window_rows_));
    fmt::print(out_, "\x1b[{};1H\x1b[?25h\n", row);
  }
  std::fflush(out_);
}

}  // namespace gas
