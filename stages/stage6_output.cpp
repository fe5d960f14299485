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
  figures.mean_speed = mean_speed(gas);
  figures.energy = kinetic_energy(gas);
  figures.energy_drift =
      starting_energy > 0 ? (figures.energy - starting_energy) / starting_energy : 0.0;
  figures.momentum = total_momentum(gas);
  figures.balls = gas.balls.size();
  figures.rms_speed = gas.balls.empty() ? 0.0
                                        : std::sqrt(2 * figures.energy /
                                                    static_cast<double>(gas.balls.size()));
  figures.theory = kinetic_theory(gas);
  return figures;
}

void add_statistics(Figures& figures, const GasStatistics& statistics) {
  figures.average_mean_speed = statistics.mean_speed();
  figures.pressure = statistics.pressure();
  figures.compressibility = statistics.compressibility();
  figures.collision_rate = statistics.collision_rate();
  figures.mean_free_path = figures.collision_rate.value > 0
                               ? figures.average_mean_speed.value / figures.collision_rate.value
                               : not_known;
  figures.speed_fractions = statistics.speed_fractions();
  figures.bin_width = statistics.bin_width();
  figures.fraction_beyond = statistics.fraction_beyond();
}

namespace {

// A figure for the screen: 5 significant digits, "-" when not known.
std::string shown(double value) {
  return std::isnan(value) ? std::string("-") : fmt::format("{:.5g}", value);
}

// An average and its error: "1.2345 +- 0.0012", or without the error while
// it is not known.
std::string shown(const Average& average) {
  if (std::isnan(average.value)) return "-";
  if (std::isnan(average.error)) return shown(average.value);
  return fmt::format("{:.5g} +- {:.2g}", average.value, average.error).substr(0, 21);
}

// Writes `text` from column 2 of `row`, cut at the border.
void write_line(TextScreen& screen, int row, const std::string& text) {
  for (std::size_t k = 0;
       k < text.size() && static_cast<int>(k) + 3 < screen.columns - 1; ++k) {
    screen.at({2 + static_cast<int>(k), row}) = text[k];
  }
}

}  // namespace

// [anchor: draw-histogram]
// The histogram of speeds in rows first_row ... last_row: a title, bars of
// '#' (the measured fraction of ball-time in each speed bin), a '*' on each
// column at the height of the 2D Maxwell-Boltzmann fraction for the same
// bin, and an axis of speeds.
void draw_histogram(TextScreen& screen, const Figures& f, int first_row, int last_row) {
  const int bar_rows = last_row - first_row - 1;  // less the title and the axis
  const int width = screen.columns - 4;           // columns 2 ... columns - 3
  const auto bins = static_cast<int>(f.speed_fractions.size());
  const double kT = f.theory.kT;
  if (bar_rows < 2 || width < 4 || bins == 0 || !(kT > 0) || !(f.bin_width > 0)) return;
  // Merge neighbouring bins when there are more bins than columns.
  // Merge neighbouring bins when there are more bins than columns; spread a
  // bin over `span` columns when there are fewer.
  const int merge = (bins + width - 1) / width;
  const int shown_bins = bins / merge;
  const int span = std::max(1, width / shown_bins);
  const double width_shown = merge * f.bin_width;
  std::vector<double> measured(static_cast<std::size_t>(shown_bins), 0.0);
  std::vector<double> expected(static_cast<std::size_t>(shown_bins), 0.0);
  for (int b = 0; b < shown_bins; ++b) {
    for (int k = 0; k < merge; ++k)
      measured[b] += f.speed_fractions[static_cast<std::size_t>(b * merge + k)];
    expected[b] = maxwell_fraction_below((b + 1) * width_shown, kT) -
                  maxwell_fraction_below(b * width_shown, kT);
  }
  // The scale: the curve's peak at 4/5 of the height, whatever the bars do.
  const double top = 1.25 * *std::max_element(expected.begin(), expected.end());
  auto height = [&](double fraction) {
    return static_cast<int>(std::lround(fraction / top * bar_rows));
  };
  write_line(screen, first_row,
             fmt::format("speeds: # measured, * 2D Maxwell-Boltzmann; {:.2g}% faster",
                         100 * f.fraction_beyond));
  const int axis = last_row;
  for (int column = 2; column < 2 + shown_bins * span; ++column) {
    const auto b = static_cast<std::size_t>((column - 2) / span);
    const int bar = height(measured[b]);
    for (int h = 1; h <= std::min(bar, bar_rows); ++h) screen.at({column, axis - h}) = '#';
    if (bar > bar_rows) screen.at({column, axis - bar_rows}) = '^';  // cut off
    const int curve = height(expected[b]);
    if (curve >= 1) screen.at({column, axis - std::min(curve, bar_rows)}) = '*';
    screen.at({column, axis}) = '-';
  }
  // The axis: 0, the predicted mean speed <v>, and the last speed.
  screen.at({2, axis}) = '0';
  const int mean_column =
      2 + static_cast<int>(f.theory.mean_speed / width_shown * span) - 1;
  const std::string end = fmt::format("{:.3g}", shown_bins * width_shown);
  const int end_column = 2 + shown_bins * span - static_cast<int>(end.size());
  if (mean_column + 3 < end_column) {
    for (int k = 0; k < 3; ++k) screen.at({mean_column + k, axis}) = "<v>"[k];
  }
  for (std::size_t k = 0; k < end.size(); ++k)
    screen.at({end_column + static_cast<int>(k), axis}) = end[k];
}
// [/anchor: draw-histogram]

// [anchor: draw-figures]
void draw_figures(TextScreen& screen, const Figures& f) {
  clear_inside(screen);
  const KineticTheory& t = f.theory;
  // Each measured figure beside the theory's: now, its average since the
  // start with its error, and the prediction.
  auto row = [](const char* label, const std::string& now, const std::string& average,
                double theory, const char* source) {
    return fmt::format("{:<16}{:<10}{:<22}{:<11}{}", label, now, average, shown(theory),
                       source);
  };
  const std::string lines[] = {
      fmt::format("T {:.6f}  T0 {:g}  collisions {} (walls {}, balls {})", f.time,
                  f.display_step, f.wall_collisions + f.ball_collisions,
                  f.wall_collisions, f.ball_collisions),
      fmt::format("N {}  eta {:.4f}  kT {:.5g}  drift {:+.1e}  momentum ({:.2g}, {:.2g})",
                  f.balls, t.area_fraction, t.kT, f.energy_drift, f.momentum.x,
                  f.momentum.y),
      fmt::format("{:<16}{:<10}{:<22}{}", "", "now", "average +- error", "theory"),
      row("mean speed", shown(f.mean_speed), shown(f.average_mean_speed), t.mean_speed,
          "Maxwell"),
      row("rms speed", shown(f.rms_speed), "", t.rms_speed, "(E fixed)"),
      row("pressure", "", shown(f.pressure), t.pressure, "Henderson"),
      row("Z = P Ac/(N kT)", "", shown(f.compressibility), t.compressibility,
          "Henderson"),
      row("collision rate", "", shown(f.collision_rate), t.collision_rate, "Enskog"),
      row("mean free path", "", shown(f.mean_free_path), t.mean_free_path, "Enskog"),
  };
  const int count = static_cast<int>(std::size(lines));
  for (int i = 0; i < count && 1 + i < screen.rows - 1; ++i) write_line(screen, 1 + i, lines[i]);
  // Below them, after a blank row, the histogram, if there is room for it.
  draw_histogram(screen, f, count + 2, screen.rows - 2);
}
// [/anchor: draw-figures]

std::string status_line(const Figures& f, ScreenMode mode, bool stopped) {
  return fmt::format("T={:.6f} T0={:g} collisions={} (walls {}, balls {}) screen={}{}",
                     f.time, f.display_step, f.wall_collisions + f.ball_collisions,
                     f.wall_collisions, f.ball_collisions, mode_name(mode),
                     stopped ? " [stopped]" : "");
}

std::string csv_header() {
  return "T,T0,wall_collisions,ball_collisions,mean_speed,energy,energy_drift,px,py,"
         "kT,mean_speed_average,mean_speed_error,mean_speed_theory,"
         "pressure,pressure_error,pressure_theory,Z,Z_error,Z_theory,"
         "collision_rate,collision_rate_error,collision_rate_theory,"
         "mean_free_path,mean_free_path_theory";
}

std::string csv_row(const Figures& f) {
  const KineticTheory& t = f.theory;
  return fmt::format(
      "{:.17g},{:.17g},{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},"
      "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},"
      "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}",
      f.time, f.display_step, f.wall_collisions, f.ball_collisions, f.mean_speed,
      f.energy, f.energy_drift, f.momentum.x, f.momentum.y, t.kT,
      f.average_mean_speed.value, f.average_mean_speed.error, t.mean_speed,
      f.pressure.value, f.pressure.error, t.pressure, f.compressibility.value,
      f.compressibility.error, t.compressibility, f.collision_rate.value,
      f.collision_rate.error, t.collision_rate, f.mean_free_path, t.mean_free_path);
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

  std::string out;
  if (shown_.size() != frame.size()) {
    out += "\x1b[?25l\x1b[H\x1b[2J";  // hide the cursor, clear the screen
    shown_.assign(frame.size(), std::string());
  }
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

void Display::bell() {
  std::fputc('\a', out_);
  std::fflush(out_);
}

void Display::finish() {
  if (terminal_) {
    fmt::print(out_, "\x1b[{};1H\x1b[?25h\n", shown_.size() + 1);
    std::fflush(out_);
  }
}

}  // namespace gas
