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

void Display::fit_window(int columns, int rows) {
  window_columns_ = std::max(columns, 0);
  window_rows_ = std::max(rows, 0);
  invalidate();
}

// Send only what changed: for each line, each run of characters that differs
// from what the terminal already shows, after moving the cursor there.
void Display::show(const TextScreen& screen, const std::string& status,
                   const Tone& tone) {
  std::vector<std::string> frame;
  frame.reserve(screen.lines.size() + 1);
  frame.push_back(status);
  frame.insert(frame.end(), screen.lines.begin(), screen.lines.end());

  if (!terminal_) {
    for (const std::string& line : frame) fmt::print(out_, "{}\n", line);
    std::fflush(out_);
    return;
  }

  // Nothing outside the window: lines cut at its right edge, and none below
  // its last row but one (the cursor's).
  if (window_rows_ > 0 && frame.size() + 1 > static_cast<std::size_t>(window_rows_))
    frame.resize(static_cast<std::size_t>(std::max(window_rows_ - 1, 1)));
  for (std::string& line : frame) cut_to_window(line);

  std::string out;
  if (shown_.size() != frame.size()) {
    out += "\x1b[?25l\x1b[H\x1b[2J";  // hide the cursor, clear the screen
    shown_.assign(frame.size(), std::string());
  }
  notice_.clear();
  auto coloured = [&](char c) {
    if (colour_ && (c == tone.ball_glyph || c == tone.trail_glyph)) {
      return fmt::format("\x1b[1;{}m{}\x1b[0m", tone.ansi_colour, c);
    }
    return std::string(1, c);
  };
  for (std::size_t row = 0; row < frame.size(); ++row) {
    const std::string& want = frame[row];
    std::string& have = shown_[row];
    std::size_t column = 0;
    const std::size_t width = std::max(want.size(), have.size());
    while (column < width) {
      auto differs = [&](std::size_t k) {
        const char w = k < want.size() ? want[k] : ' ';
        const char h = k < have.size() ? have[k] : '\0';
        return w != h;
      };
      if (!differs(column)) {
        ++column;
        continue;
      }
      out += fmt::format("\x1b[{};{}H", row + 1, column + 1);
      while (column < width && differs(column)) {
        out += coloured(column < want.size() ? want[column] : ' ');
        ++column;
      }
    }
    have = want;
  }
  out += fmt::format("\x1b[{};1H", frame.size() + 1);
  std::fwrite(out.data(), 1, out.size(), out_);
  std::fflush(out_);
}

void Display::cut_to_window(std::string& line) const {
  if (window_columns_ > 0 && line.size() > static_cast<std::size_t>(window_columns_))
    line.resize(static_cast<std::size_t>(window_columns_));
}

void Display::notice(const std::string& line) {
  if (!terminal_) {
    fmt::print(out_, "{}\n", line);
    std::fflush(out_);
    return;
  }
  std::string text = line;
  cut_to_window(text);
  if (!notice_.empty() && notice_ == text) return;  // already on the terminal
  // Hide the cursor, clear the screen, the line at the top; the next frame is
  // drawn whole.
  fmt::print(out_, "\x1b[?25l\x1b[H\x1b[2J{}", text);
  std::fflush(out_);
  shown_.clear();
  notice_ = text;
}

void Display::bell() {
  std::fputc('\a', out_);
  std::fflush(out_);
}

void Display::finish() {
  if (terminal_) {
    // Below the frame (or the notice), but not below the window.
    std::size_t row = std::max<std::size_t>(shown_.size(), notice_.empty() ? 0 : 1) + 1;
    if (window_rows_ > 0) row = std::min(row, static_cast<std::size_t>(window_rows_));
    fmt::print(out_, "\x1b[{};1H\x1b[?25h\n", row);
    std::fflush(out_);
  }
}

}  // namespace gas
