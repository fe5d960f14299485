// The statistics screen of kinetic theory. See beyond/kinetic_screen.hpp.
#include "beyond/kinetic_screen.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "beyond/boltzmann_h.hpp"
#include "beyond/hard_disc_fluid.hpp"

namespace gas {

// [anchor: kinetic-figures]
KineticFigures kinetic_figures(const Gas& gas, const GasStatistics& statistics,
                               double energy) {
  KineticFigures k;
  const auto n = static_cast<double>(gas.balls.size());
  k.rms_speed = gas.balls.empty() ? 0.0 : std::sqrt(2 * energy / n);
  k.theory = kinetic_theory(gas, energy);
  k.measured = statistics.measured(gas);
  const MeasuredFigures& m = k.measured;
  // H's noise: 2 N H of N Maxwellian speeds in B bins and one beyond is
  // chi-squared with B - 1 degrees of freedom (B + 1 categories, less one
  // for their sum N and one for the energy, fixed): mean (B - 1) / 2N.
  k.h_noise = boltzmann_h_noise_floor(static_cast<std::size_t>(statistics.bins()),
                                      gas.balls.size());
  k.h_noise_spread = boltzmann_h_noise_spread(static_cast<std::size_t>(statistics.bins()),
                                              gas.balls.size());
  // The bulk: the reference at the interior's own density (like with like),
  // for many balls only; each theory's error is its slope in eta times
  // eta_int's error.
  k.many_balls = gas.balls.size() >= kinetic_theory_fewest_balls;
  if (!k.many_balls) return k;
  const double eta = m.interior_area_fraction.value;
  const double eta_error = m.interior_area_fraction.error;
  // kT: the interior's own (the box's on average; lesson 13).
  const double kT = m.interior_kT.value, a = gas.radius, pi = std::numbers::pi;
  // The reference for a closed box of N balls (kinetic_theory.hpp): the
  // open bulk's Z shifted by fixed_count_shift, Enskog's rate by its factor.
  const std::size_t balls = gas.balls.size();
  k.bulk_z_shift = fixed_count_shift(eta, balls);
  const double z = fixed_count_compressibility(eta, balls);
  const double slope = hard_disc_fluid_compressibility_slope(eta);  // dZ / d eta
  k.bulk_z_theory = {z, std::abs(slope) * eta_error};
  k.bulk_z_henderson = henderson_compressibility(eta);
  k.pair_contact_theory = hard_disc_fluid_contact_value(eta);
  // P = Z n kT, n = eta / (pi a^2): dP / d eta = (Z + eta Z') kT / (pi a^2);
  // for the push on the walls' middles, of the gas in front of them: the
  // strips of the interior beside those middles, at their own eta and kT
  // (their slow sound waves push on the middles too; lesson 14).
  const double eta_beside = m.beside_walls_eta.value, kT_beside = m.beside_walls_kT.value;
  const double z_beside = fixed_count_compressibility(eta_beside, balls);
  k.pressure_theory = {
      z_beside * eta_beside * kT_beside / (pi * a * a),
      std::abs(z_beside +
               eta_beside * hard_disc_fluid_compressibility_slope(eta_beside)) *
          kT_beside / (pi * a * a) * m.beside_walls_eta.error};
  // Enskog: rate = 2 (2a) n g sqrt(pi kT) with n g = (Z - 1) / (2 eta) n
  // = (Z - 1) / (2 pi a^2), so d rate / d eta = Z' 2 sqrt(pi kT) / (pi a);
  // the free path lambda = sqrt(pi kT / 2) / rate moves the other way.
  const double factor = fixed_count_rate_factor(eta, balls);
  const double rate = enskog_collision_rate(eta, a, kT) * factor;
  const double rate_error =
      std::abs(slope) * 2 * std::sqrt(pi * kT) / (pi * a) * eta_error;
  k.collision_rate_theory = {rate, rate_error};
  const double path = enskog_mean_free_path(eta, a) / factor;
  k.mean_free_path_theory = {path, path * rate_error / rate};
  // The reference g(2a)'s uncertainty, from eta's: |dg/deta| x eta's error.
  k.pair_contact_theory_error =
      std::abs(hard_disc_fluid_contact_value_slope(eta)) * eta_error;
  return k;
}
// [/anchor: kinetic-figures]

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

// Where the theory of the bulk does not apply to so few balls.
constexpr const char* few_balls = "needs many balls";

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
void draw_kinetic_figures(TextScreen& screen, const Figures& f, const KineticFigures& k,
                          const std::vector<std::string>& more_lines) {
  const KineticTheory& t = k.theory;
  const MeasuredFigures& m = k.measured;
  // Each measured figure, its average since the averages started with its
  // error, beside the theory of the same thing with the theory's error, and
  // which theory. The bulk's theories only for many balls.
  auto row = [](const char* label, const Average& average, const std::string& theory,
                const std::string& source) {
    return fmt::format("{:<18}{:<22}{:<21}{}", label, shown(average), theory, source);
  };
  auto bulk = [&](const char* label, const Average& average, const Average& theory,
                  const std::string& source) {
    return k.many_balls ? row(label, average, shown(theory), source)
                        : row(label, average, few_balls, "");
  };
  // Z - Z_theory with its error, combined sample by sample (gas_statistics).
  const std::string z_difference =
      k.many_balls ? fmt::format("Z - reference {}", shown(m.bulk_z_minus_theory)) : "";
  std::vector<std::string> lines = {
      fmt::format("T {:.6f}  T0 {:g}  collisions {} (walls {}, balls {})", f.time,
                  f.display_step, f.wall_collisions + f.ball_collisions,
                  f.wall_collisions, f.ball_collisions),
      fmt::format("N {}  eta {:.4f}  kT {:.5g}  drift {:+.1e}  momentum ({:.2g}, {:.2g})",
                  f.balls, t.area_fraction, t.kT, f.energy_drift, f.momentum.x,
                  f.momentum.y),
      "units: a, mass 1, kT = E/N; P per unit length, rates per unit time",
      fmt::format("speeds now: mean {}, rms {} (fixed by E)", shown(f.mean_speed),
                  shown(k.rms_speed)),
      k.many_balls
          ? fmt::format("H {:.4f}  its noise for {} balls in {} bins: {:.2g} +- {:.2g}",
                        m.h_now, f.balls, m.speed_fractions.size(), k.h_noise,
                        k.h_noise_spread)
          : fmt::format("H {:.4f}  (of {} speeds in {} bins: mostly noise)", m.h_now,
                        f.balls, m.speed_fractions.size()),
      m.warming_up
          ? fmt::format(
                "warming up: averages start after {} collisions of two balls a ball",
                m.warm_up_collisions)
          : fmt::format("averages over T {:.6g} ... {:.6g} (A restarts)", m.since,
                        m.since + m.duration),
      fmt::format("{:<18}{:<22}{:<21}{}", "", "average +- error", "theory +- error",
                  "(theory)"),
      row("mean speed", m.mean_speed, shown(t.mean_speed), "E fixed"),
      bulk("P walls' middles", m.wall_middle_pressure, k.pressure_theory,
           "bulk, reference"),
      fmt::format("{:<18}{:<22}{:<21}{}", "P whole walls", shown(m.pressure_box),
                  "(box, corners too)", ""),
      fmt::format("{:<18}{:<22}{}", "  Px, Py (box)", shown(m.pressure_box_x),
                  shown(m.pressure_box_y)),
      fmt::format("{:<18}{:<22}{}", "Z box: walls, vir", shown(m.box_z_walls),
                  shown(m.box_z_virial)),
      bulk("Z bulk", m.bulk_z, k.bulk_z_theory,
           std::isnan(k.bulk_z_shift) ? std::string("N fixed -")
                                      : fmt::format("N fixed {:+.2g}", k.bulk_z_shift)),
      fmt::format("{:<18}{:<22}{}", "  eta inside", shown(m.interior_area_fraction),
                  z_difference),
      row("  g(2a) inside", m.pair_contact,
          k.many_balls ? shown(k.pair_contact_theory) : few_balls, "reference"),
      row("kT n at walls", m.wall_contact_pressure, shown(m.wall_middle_pressure.value),
          "P there"),
      bulk("collisions/ball", m.collision_rate, k.collision_rate_theory,
           "Enskog (inside)"),
      fmt::format("{:<18}{:<22}{}", "  whole box", shown(m.collision_rate_box),
                  "(box: walls too)"),
      bulk("mean free path", m.mean_free_path, k.mean_free_path_theory,
           "Enskog (inside)"),
  };
  // Other observers' lines after them, as many as leave the histogram its
  // room: a blank row, a title, two rows of bars, the axis, and the border.
  const auto room = static_cast<std::size_t>(
      std::max(0, screen.rows - 7 - static_cast<int>(lines.size())));
  lines.insert(lines.end(), more_lines.begin(),
               more_lines.begin() +
                   static_cast<std::ptrdiff_t>(std::min(room, more_lines.size())));
  draw_figures(screen, lines);  // stage 6: the lines at their places
  // Below them, after a blank row, the histogram, if there is room for it.
  const int count = static_cast<int>(lines.size());
  draw_histogram(screen, k, count + 2, screen.rows - 2);
}
// [/anchor: draw-kinetic-figures]

// [anchor: csv-columns]
namespace {

// One column of --csv: its name and how its value is read from the figures.
struct Column {
  const char* name;
  double (*value)(const Figures& f, const KineticFigures& k);
};

// Readers for the columns: an average measured (its value or its error), a
// theory with its error, a plain figure of kinetic theory.
template <Average MeasuredFigures::*average>
double measured_value(const Figures&, const KineticFigures& k) {
  return (k.measured.*average).value;
}
template <Average MeasuredFigures::*average>
double measured_error(const Figures&, const KineticFigures& k) {
  return (k.measured.*average).error;
}
template <Average KineticFigures::*theory>
double theory_value(const Figures&, const KineticFigures& k) {
  return (k.*theory).value;
}
template <Average KineticFigures::*theory>
double theory_error(const Figures&, const KineticFigures& k) {
  return (k.*theory).error;
}
// A difference from the theory: only where the theory applies (many balls).
template <Average MeasuredFigures::*average>
double deviation_value(const Figures&, const KineticFigures& k) {
  return k.many_balls ? (k.measured.*average).value : not_known;
}
template <Average MeasuredFigures::*average>
double deviation_error(const Figures&, const KineticFigures& k) {
  return k.many_balls ? (k.measured.*average).error : not_known;
}
template <double KineticFigures::*figure>
double kinetic_value(const Figures&, const KineticFigures& k) {
  return k.*figure;
}

using M = MeasuredFigures;
using K = KineticFigures;

// The columns in order: the article's figures, then kinetic theory's (the
// naming convention in data/README.md). A block of columns is appended at
// the end.
constexpr Column columns[] = {
    {"T", [](const Figures& f, const KineticFigures&) { return f.time; }},
    {"T0", [](const Figures& f, const KineticFigures&) { return f.display_step; }},
    {"wall_collisions",
     [](const Figures& f, const KineticFigures&) {
       return static_cast<double>(f.wall_collisions);
     }},
    {"ball_collisions",
     [](const Figures& f, const KineticFigures&) {
       return static_cast<double>(f.ball_collisions);
     }},
    {"mean_speed", [](const Figures& f, const KineticFigures&) { return f.mean_speed; }},
    {"energy", [](const Figures& f, const KineticFigures&) { return f.energy; }},
    {"energy_drift",
     [](const Figures& f, const KineticFigures&) { return f.energy_drift; }},
    {"px", [](const Figures& f, const KineticFigures&) { return f.momentum.x; }},
    {"py", [](const Figures& f, const KineticFigures&) { return f.momentum.y; }},
    {"kT", [](const Figures&, const KineticFigures& k) { return k.theory.kT; }},
    {"averages_since",
     [](const Figures&, const KineticFigures& k) { return k.measured.since; }},
    {"H", [](const Figures&, const KineticFigures& k) { return k.measured.h_now; }},
    {"H_noise", kinetic_value<&K::h_noise>},
    {"H_noise_spread", kinetic_value<&K::h_noise_spread>},
    {"mean_speed_average", measured_value<&M::mean_speed>},
    {"mean_speed_average_error", measured_error<&M::mean_speed>},
    {"mean_speed_average_theory",
     [](const Figures&, const KineticFigures& k) { return k.theory.mean_speed; }},
    {"pressure", measured_value<&M::wall_middle_pressure>},
    {"pressure_error", measured_error<&M::wall_middle_pressure>},
    {"pressure_theory", theory_value<&K::pressure_theory>},
    {"pressure_theory_error", theory_error<&K::pressure_theory>},
    {"pressure_box", measured_value<&M::pressure_box>},
    {"pressure_box_error", measured_error<&M::pressure_box>},
    {"pressure_box_x", measured_value<&M::pressure_box_x>},
    {"pressure_box_x_error", measured_error<&M::pressure_box_x>},
    {"pressure_box_y", measured_value<&M::pressure_box_y>},
    {"pressure_box_y_error", measured_error<&M::pressure_box_y>},
    {"Z", measured_value<&M::bulk_z>},
    {"Z_error", measured_error<&M::bulk_z>},
    {"Z_theory", theory_value<&K::bulk_z_theory>},
    {"Z_theory_error", theory_error<&K::bulk_z_theory>},
    {"Z_deviation", deviation_value<&M::bulk_z_minus_theory>},
    {"Z_deviation_error", deviation_error<&M::bulk_z_minus_theory>},
    {"Z_henderson", kinetic_value<&K::bulk_z_henderson>},
    {"eta_interior", measured_value<&M::interior_area_fraction>},
    {"eta_interior_error", measured_error<&M::interior_area_fraction>},
    {"kT_interior", measured_value<&M::interior_kT>},
    {"kT_interior_error", measured_error<&M::interior_kT>},
    {"Z_box_walls", measured_value<&M::box_z_walls>},
    {"Z_box_walls_error", measured_error<&M::box_z_walls>},
    {"Z_box_virial", measured_value<&M::box_z_virial>},
    {"Z_box_virial_error", measured_error<&M::box_z_virial>},
    {"collision_rate", measured_value<&M::collision_rate>},
    {"collision_rate_error", measured_error<&M::collision_rate>},
    {"collision_rate_theory", theory_value<&K::collision_rate_theory>},
    {"collision_rate_theory_error", theory_error<&K::collision_rate_theory>},
    {"collision_rate_deviation", deviation_value<&M::collision_rate_minus_theory>},
    {"collision_rate_deviation_error", deviation_error<&M::collision_rate_minus_theory>},
    {"collision_rate_box", measured_value<&M::collision_rate_box>},
    {"collision_rate_box_error", measured_error<&M::collision_rate_box>},
    {"mean_free_path", measured_value<&M::mean_free_path>},
    {"mean_free_path_error", measured_error<&M::mean_free_path>},
    {"mean_free_path_theory", theory_value<&K::mean_free_path_theory>},
    {"mean_free_path_theory_error", theory_error<&K::mean_free_path_theory>},
    {"g_contact", measured_value<&M::pair_contact>},
    {"g_contact_error", measured_error<&M::pair_contact>},
    {"g_contact_theory", kinetic_value<&K::pair_contact_theory>},
    {"g_contact_theory_error", kinetic_value<&K::pair_contact_theory_error>},
    {"wall_contact_pressure", measured_value<&M::wall_contact_pressure>},
    {"wall_contact_pressure_error", measured_error<&M::wall_contact_pressure>},
    {"pressure_deviation", deviation_value<&M::pressure_minus_theory>},
    {"pressure_deviation_error", deviation_error<&M::pressure_minus_theory>},
    {"mean_free_path_deviation", deviation_value<&M::mean_free_path_minus_theory>},
    {"mean_free_path_deviation_error", deviation_error<&M::mean_free_path_minus_theory>},
    {"g_contact_deviation", deviation_value<&M::pair_contact_minus_theory>},
    {"g_contact_deviation_error", deviation_error<&M::pair_contact_minus_theory>},
    {"Z_fixed_N_shift", kinetic_value<&K::bulk_z_shift>},
};

}  // namespace

std::string csv_header() {
  std::string header;
  for (const Column& column : columns) {
    if (!header.empty()) header += ',';
    header += column.name;
  }
  return header;
}

std::string csv_row(const Figures& f, const KineticFigures& k) {
  fmt::memory_buffer row;
  for (const Column& column : columns) {
    if (row.size() > 0) row.push_back(',');
    fmt::format_to(std::back_inserter(row), "{:.17g}", column.value(f, k));
  }
  return fmt::to_string(row);
}
// [/anchor: csv-columns]

}  // namespace gas
