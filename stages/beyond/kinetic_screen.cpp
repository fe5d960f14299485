// The statistics screen of kinetic theory. See beyond/kinetic_screen.hpp.
#include "beyond/kinetic_screen.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "beyond/hard_disc_fluid.hpp"

namespace gas {

KineticFigures kinetic_figures(const Gas& gas, const GasStatistics& statistics) {
  KineticFigures k;
  const auto n = static_cast<double>(gas.balls.size());
  k.rms_speed = gas.balls.empty() ? 0.0 : std::sqrt(2 * kinetic_energy(gas) / n);
  k.theory = kinetic_theory(gas);
  k.measured = statistics.measured(gas);
  const MeasuredFigures& m = k.measured;
  // The bulk: the reference at the interior's own density (like with like).
  const double eta = m.interior_area_fraction.value;
  k.bulk_z_theory = hard_disc_fluid_compressibility(eta);
  k.bulk_z_henderson = henderson_compressibility(eta);
  k.pair_contact_theory = hard_disc_fluid_contact_value(eta);
  k.pair_contact_theory_error =
      std::abs(hard_disc_fluid_contact_value_slope(eta)) * m.interior_area_fraction.error;
  const double interior_density = eta / (std::numbers::pi * gas.radius * gas.radius);
  k.pressure_theory = k.bulk_z_theory * interior_density * k.theory.kT;
  k.mean_free_path = m.collision_rate.value > 0
                         ? m.mean_speed.value / m.collision_rate.value
                         : not_known;
  return k;
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

}  // namespace

// [anchor: draw-histogram]
// The histogram of speeds in rows first_row ... last_row: a title, bars of
// '#' (the measured fraction of ball-time in each speed bin), a '*' on each
// column at the height of the 2D Maxwell-Boltzmann fraction for the same
// bin, and an axis of speeds.
void draw_histogram(TextScreen& screen, const KineticFigures& k, int first_row,
                    int last_row) {
  const int bar_rows = last_row - first_row - 1;  // less the title and the axis
  const int width = screen.columns - 4;           // columns 2 ... columns - 3
  const MeasuredFigures& m = k.measured;
  const auto bins = static_cast<int>(m.speed_fractions.size());
  const double kT = k.theory.kT;
  if (bar_rows < 2 || width < 4 || bins == 0 || !(kT > 0) || !(m.bin_width > 0)) return;
  // Merge neighbouring bins when there are more bins than columns; spread a
  // bin over `span` columns when there are fewer.
  const int merge = (bins + width - 1) / width;
  const int shown_bins = bins / merge;
  const int span = std::max(1, width / shown_bins);
  const double width_shown = merge * m.bin_width;
  std::vector<double> measured(static_cast<std::size_t>(shown_bins), 0.0);
  std::vector<double> expected(static_cast<std::size_t>(shown_bins), 0.0);
  for (int b = 0; b < shown_bins; ++b) {
    for (int j = 0; j < merge; ++j)
      measured[b] += m.speed_fractions[static_cast<std::size_t>(b * merge + j)];
    expected[b] = maxwell_fraction_below((b + 1) * width_shown, kT) -
                  maxwell_fraction_below(b * width_shown, kT);
  }
  // The scale: the curve's peak at 4/5 of the height, whatever the bars do.
  const double top = 1.25 * *std::max_element(expected.begin(), expected.end());
  auto height = [&](double fraction) {
    return static_cast<int>(std::lround(fraction / top * bar_rows));
  };
  write_text(screen, first_row,
             fmt::format("speeds: # measured, * 2D Maxwell-Boltzmann; {:.2g}% faster",
                         100 * m.fraction_beyond));
  const int axis = last_row;
  for (int column = 2; column < 2 + shown_bins * span; ++column) {
    const auto b = static_cast<std::size_t>((column - 2) / span);
    const int bar = height(measured[b]);
    for (int h = 1; h <= std::min(bar, bar_rows); ++h)
      screen.at({column, axis - h}) = '#';
    if (bar > bar_rows) screen.at({column, axis - bar_rows}) = '^';  // cut off
    const int curve = height(expected[b]);
    if (curve >= 1) screen.at({column, axis - std::min(curve, bar_rows)}) = '*';
    screen.at({column, axis}) = '-';
  }
  // The axis: 0, the predicted mean speed <v>, and the last speed.
  screen.at({2, axis}) = '0';
  const int mean_column =
      2 + static_cast<int>(k.theory.mean_speed / width_shown * span) - 1;
  const std::string end = fmt::format("{:.3g}", shown_bins * width_shown);
  const int end_column = 2 + shown_bins * span - static_cast<int>(end.size());
  if (mean_column + 3 < end_column) {
    for (int k = 0; k < 3; ++k) screen.at({mean_column + k, axis}) = "<v>"[k];
  }
  for (std::size_t k = 0; k < end.size(); ++k)
    screen.at({end_column + static_cast<int>(k), axis}) = end[k];
}
// [/anchor: draw-histogram]

// [anchor: draw-kinetic-figures]
void draw_kinetic_figures(TextScreen& screen, const Figures& f, const KineticFigures& k) {
  const KineticTheory& t = k.theory;
  const MeasuredFigures& m = k.measured;
  // Each measured figure beside the theory's: now, its average with its
  // error, and the prediction.
  auto row = [](const char* label, const std::string& now, const std::string& average,
                double theory, const std::string& source) {
    return fmt::format("{:<16}{:<10}{:<22}{:<11}{}", label, now, average, shown(theory),
                       source);
  };
  const std::vector<std::string> lines = {
      fmt::format("T {:.6f}  T0 {:g}  collisions {} (walls {}, balls {})", f.time,
                  f.display_step, f.wall_collisions + f.ball_collisions,
                  f.wall_collisions, f.ball_collisions),
      fmt::format("N {}  eta {:.4f}  kT {:.5g}  drift {:+.1e}  momentum ({:.2g}, {:.2g})",
                  f.balls, t.area_fraction, t.kT, f.energy_drift, f.momentum.x,
                  f.momentum.y),
      m.warming_up
          ? fmt::format("H {:.4f}  warming up: averages start after {} "
                        "collisions a ball",
                        m.h_now, warm_up_collisions_per_ball)
          : fmt::format("H {:.4f}  averages over T {:.6g} ... {:.6g} (A restarts)",
                        m.h_now, m.since, m.since + m.duration),
      fmt::format("{:<16}{:<10}{:<22}{}", "", "now", "average +- error", "theory"),
      row("mean speed", shown(f.mean_speed), shown(m.mean_speed), t.mean_speed,
          "Maxwell"),
      row("rms speed", shown(k.rms_speed), "", t.rms_speed, "(E fixed)"),
      row("pressure", "", shown(m.pressure), k.pressure_theory, "bulk, reference"),
      fmt::format("{:<26}{:<22}{}", "  Px, Py (equal)", shown(m.pressure_x),
                  shown(m.pressure_y)),
      fmt::format("{:<26}{:<22}{}", "Z box: walls, virial", shown(m.box_z_walls),
                  shown(m.box_z_virial)),
      row("Z bulk", "", shown(m.bulk_z), k.bulk_z_theory,
          fmt::format("Henderson {}", shown(k.bulk_z_henderson))),
      row("  eta inside", "", shown(m.interior_area_fraction), t.area_fraction, "N/A"),
      row("  g(2a) inside", "", shown(m.pair_contact), k.pair_contact_theory,
          "reference"),
      row("kT n at walls", "", shown(m.wall_contact_pressure),
          m.wall_middle_pressure.value, "P there"),
      row("collision rate", "", shown(m.collision_rate), t.collision_rate, "Enskog"),
      row("mean free path", "", shown(k.mean_free_path), t.mean_free_path, "Enskog"),
  };
  draw_figures(screen, lines);  // stage 6: the lines at their places
  // Below them, after a blank row, the histogram, if there is room for it.
  const int count = static_cast<int>(lines.size());
  draw_histogram(screen, k, count + 2, screen.rows - 2);
}
// [/anchor: draw-kinetic-figures]

std::string csv_header() {
  return "T,T0,wall_collisions,ball_collisions,mean_speed,energy,energy_drift,px,py,"
         "kT,mean_speed_average,mean_speed_error,mean_speed_theory,"
         "pressure,pressure_error,pressure_theory,pressure_x,pressure_x_error,"
         "pressure_y,pressure_y_error,"
         "Z,Z_error,Z_theory,Z_henderson,eta_interior,eta_interior_error,"
         "Z_box_walls,Z_box_walls_error,Z_box_virial,Z_box_virial_error,"
         "collision_rate,collision_rate_error,collision_rate_theory,"
         "mean_free_path,mean_free_path_theory,H,averages_since,"
         "g_contact,g_contact_error,g_contact_theory,g_contact_theory_error,"
         "wall_contact_pressure,wall_contact_pressure_error,"
         "wall_middle_pressure,wall_middle_pressure_error";
}

std::string csv_row(const Figures& f, const KineticFigures& k) {
  const KineticTheory& t = k.theory;
  const MeasuredFigures& m = k.measured;
  fmt::memory_buffer row;
  auto add = [&row](double x) { fmt::format_to(std::back_inserter(row), ",{:.17g}", x); };
  auto add_average = [&add](const Average& a) {
    add(a.value);
    add(a.error);
  };
  fmt::format_to(std::back_inserter(row), "{:.17g},{:.17g},{},{}", f.time, f.display_step,
                 f.wall_collisions, f.ball_collisions);
  for (const double x :
       {f.mean_speed, f.energy, f.energy_drift, f.momentum.x, f.momentum.y, t.kT})
    add(x);
  add_average(m.mean_speed);
  add(t.mean_speed);
  add_average(m.pressure);
  add(k.pressure_theory);
  add_average(m.pressure_x);
  add_average(m.pressure_y);
  add_average(m.bulk_z);
  add(k.bulk_z_theory);
  add(k.bulk_z_henderson);
  add_average(m.interior_area_fraction);
  add_average(m.box_z_walls);
  add_average(m.box_z_virial);
  add_average(m.collision_rate);
  add(t.collision_rate);
  add(k.mean_free_path);
  add(t.mean_free_path);
  add(m.h_now);
  add(m.since);
  add_average(m.pair_contact);
  add(k.pair_contact_theory);
  add(k.pair_contact_theory_error);
  add_average(m.wall_contact_pressure);
  add_average(m.wall_middle_pressure);
  return fmt::to_string(row);
}

}  // namespace gas
