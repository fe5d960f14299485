// The statistics screen of kinetic theory. See beyond/kinetic_screen.hpp.
#include "beyond/kinetic_screen.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

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
  // (A theory's error is eta's carried over: blank while eta's is, for its reason.)
  const char* const why = m.interior_area_fraction.why_no_error;
  k.bulk_z_theory = {z, std::abs(slope) * eta_error, why};
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
          kT_beside / (pi * a * a) * m.beside_walls_eta.error,
      m.beside_walls_eta.why_no_error};
  // Enskog: rate = 2 (2a) n g sqrt(pi kT) with n g = (Z - 1) / (2 eta) n
  // = (Z - 1) / (2 pi a^2), so d rate / d eta = Z' 2 sqrt(pi kT) / (pi a);
  // the free path lambda = sqrt(pi kT / 2) / rate moves the other way.
  const double factor = fixed_count_rate_factor(eta, balls);
  const double rate = enskog_collision_rate(eta, a, kT) * factor;
  const double rate_error =
      std::abs(slope) * 2 * std::sqrt(pi * kT) / (pi * a) * eta_error;
  k.collision_rate_theory = {rate, rate_error, why};
  const double path = enskog_mean_free_path(eta, a) / factor;
  k.mean_free_path_theory = {path, path * rate_error / rate, why};
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

// A small shift with its sign, 2 significant digits, "-" when not known.
std::string signed_shown(double value) {
  return std::isnan(value) ? std::string("-") : fmt::format("{:+.2g}", value);
}

// An average and its error: "1.2345 +- 0.0012"; while the error is not
// known, the reason in its place ("1.2345 +- not yet"), or the value alone
// if none is given.
std::string shown(const Average& average) {
  if (std::isnan(average.value)) return "-";
  if (!std::isnan(average.error))
    return fmt::format("{:.5g} +- {:.2g}", average.value, average.error);
  if (average.why_no_error != nullptr)
    return fmt::format("{:.5g} +- {}", average.value, average.why_no_error);
  return shown(average.value);
}

// Where the theory of the bulk does not apply to so few balls.
constexpr const char* few_balls = "needs many balls";

}  // namespace

// [anchor: draw-histogram]
// The histogram of speeds in rows first_row ... last_row: a title, bars of
// '#' (the measured fraction of ball-time in each speed bin; '^' tops a bar
// too tall for the rows), a '*' on each column at the height of the 2D
// Maxwell-Boltzmann fraction for the same bin, and an axis of speeds.
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
  // The title says what the marks are, and how much of the ball-time went
  // faster than the axis reaches (no bar of its own).
  const std::string end = fmt::format("{:.3g}", shown_bins * width_shown);
  write_text(screen, first_row,
             fmt::format("speeds: # measured  * Maxwell-Boltzmann  ^ off scale  {:.2g}% "
                         "faster than {}",
                         100 * m.fraction_beyond, end));
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
  const int end_column = 2 + shown_bins * span - static_cast<int>(end.size());
  if (mean_column + 3 < end_column) {
    for (int k = 0; k < 3; ++k) screen.at({mean_column + k, axis}) = "<v>"[k];
  }
  for (std::size_t k = 0; k < end.size(); ++k)
    screen.at({end_column + static_cast<int>(k), axis}) = end[k];
}
// [/anchor: draw-histogram]

namespace {

// One line of the statistics screen: its text, its rank (the lower, the
// sooner a student needs it: a short screen keeps the lowest ranks), and
// the name the line of what is left out gives it.
struct FigureLine {
  std::string text;
  int rank;
  const char* name;
};

// The histogram's rank among the lines' (after the mean free path's).
constexpr int histogram_rank = 9;

// A row of the table: a label, the measured average with its error, the
// theory of the same thing with its error, and the theory's name. The
// columns start at fixed places (17, 42 and 61 characters in), each cut to
// leave a blank before the next.
constexpr std::size_t measured_width = 24, theory_width = 18;  // characters
std::string table_row(const char* label, const std::string& measured,
                      const std::string& theory, const std::string& source) {
  return fmt::format("{:<17}{:<25}{:<19}{}", label, measured.substr(0, measured_width),
                     theory.substr(0, theory_width), source);
}

// A theory in its column: its error waits for the same samples as the
// measured figure beside it, so where the reason would be cut short the
// value stands alone (the measured column says why).
std::string theory_shown(const Average& theory) {
  const std::string full = shown(theory);
  return full.size() <= theory_width ? full : shown(theory.value);
}

// The gas now (stage 6's figures), the units, H, and since when the
// averages run; then the table's header.
std::vector<FigureLine> heading_lines(const Figures& f, const KineticFigures& k) {
  const KineticTheory& t = k.theory;
  const MeasuredFigures& m = k.measured;
  return {
      {fmt::format(
           "N {}  eta {:.4f}  kT {:.5g}  drift {:+.1e}  momentum ({:.2g}, {:.2g})",
           f.balls, t.area_fraction, t.kT, f.energy_drift, f.momentum.x, f.momentum.y),
       0, "N"},
      {fmt::format("speeds now: mean {}, rms {} (fixed by E)", shown(f.mean_speed),
                   shown(k.rms_speed)),
       1, "speeds now"},
      {"units: a, mass 1, kT = E/N; P per unit length, rates per unit time", 11, "units"},
      {k.many_balls
           ? fmt::format("H {:.4f}  its noise for {} balls in {} bins: {:.2g} +- {:.2g}",
                         m.h_now, f.balls, m.speed_fractions.size(), k.h_noise,
                         k.h_noise_spread)
           : fmt::format("H {:.4f}  (of {} speeds in {} bins: mostly noise)", m.h_now,
                         f.balls, m.speed_fractions.size()),
       10, "H"},
      {m.warming_up
           ? fmt::format("warming up: averages start after {} pair collisions per ball",
                         m.warm_up_collisions)
           : fmt::format("averages over T {:.6g} ... {:.6g} (A restarts them)", m.since,
                         m.since + m.duration),
       2, "averages"},
      {table_row("", "measured +- error", "theory +- error", "which theory"), 3,
       "header"},
  };
}

// The table: each measured average beside the theory of the same thing.
// The bulk's theories only for many balls.
std::vector<FigureLine> table_lines(const KineticFigures& k) {
  const KineticTheory& t = k.theory;
  const MeasuredFigures& m = k.measured;
  auto bulk = [&](const Average& theory) {
    return k.many_balls ? theory_shown(theory) : std::string(few_balls);
  };
  const Average contact_theory{k.pair_contact_theory, k.pair_contact_theory_error,
                               m.interior_area_fraction.why_no_error};
  return {
      {table_row("mean speed", shown(m.mean_speed), shown(t.mean_speed), "E fixed"), 4,
       "mean speed"},
      {table_row("P walls' middles", shown(m.wall_middle_pressure),
                 bulk(k.pressure_theory), k.many_balls ? "bulk, reference" : ""),
       5, "P"},
      {table_row("Z bulk", shown(m.bulk_z), bulk(k.bulk_z_theory),
                 k.many_balls ? "Henderson " + shown(k.bulk_z_henderson) : ""),
       6, "Z"},
      // Z - Z_ref, sample by sample (its error is the smaller): 0 if the
      // reference holds. The reference is for N balls in a closed box: the
      // open bulk's shifted by fixed_count_shift, shown beside it.
      {table_row("  Z - reference", k.many_balls ? shown(m.bulk_z_minus_theory) : "-",
                 k.many_balls ? "0" : few_balls,
                 k.many_balls ? "N fixed " + signed_shown(k.bulk_z_shift) : ""),
       13, "Z - ref"},
      {table_row("g(2a) inside", shown(m.pair_contact), bulk(contact_theory),
                 k.many_balls ? "reference" : ""),
       12, "g(2a)"},
      {table_row("collision rate", shown(m.collision_rate), bulk(k.collision_rate_theory),
                 k.many_balls ? "Enskog (inside)" : ""),
       7, "rate"},
      {table_row("mean free path", shown(m.mean_free_path), bulk(k.mean_free_path_theory),
                 k.many_balls ? "Enskog (inside)" : ""),
       8, "free path"},
  };
}

// Figures measured with no theory beside them, each labelled in its line:
// the interior the bulk's theories are taken at, the contact theorem at the
// walls (two measurements that must agree), and the whole box.
std::vector<FigureLine> measured_lines(const KineticFigures& k) {
  const MeasuredFigures& m = k.measured;
  return {
      {fmt::format("inside: eta {}  kT {}", shown(m.interior_area_fraction),
                   shown(m.interior_kT)),
       14, "inside"},
      {fmt::format("contact theorem at walls: kT n {} = P {}",
                   shown(m.wall_contact_pressure), shown(m.wall_middle_pressure)),
       15, "contact"},
      {fmt::format("box: P {}  Px {}  Py {}", shown(m.pressure_box),
                   shown(m.pressure_box_x), shown(m.pressure_box_y)),
       16, "box"},
      {fmt::format("box: Z from walls {}  from collisions {}", shown(m.box_z_walls),
                   shown(m.box_z_virial)),
       17, "box"},
      {fmt::format("box: collision rate {} (walls' layers too)",
                   shown(m.collision_rate_box)),
       18, "box"},
  };
}

// Which lines a screen of `rows` rows inside the border shows, and how
// many rows the histogram gets (0: none).
struct Layout {
  std::vector<bool> kept;
  int histogram_rows = 0;
  bool gap = false;      // a blank row between the lines and the histogram
  std::string left_out;  // the last row's text, when something is left out
};

// Everything when it fits (the histogram in all the rows left); else, in
// the order of rank, each line and the histogram that still fits, a row kept
// for the line that names what is left out.
Layout lay_out(const std::vector<FigureLine>& lines, int rows) {
  const int count = static_cast<int>(lines.size());
  Layout layout;
  if (count + histogram_least_rows <= rows) {
    layout.kept.assign(lines.size(), true);
    layout.gap = count + histogram_least_rows < rows;
    layout.histogram_rows = rows - count - (layout.gap ? 1 : 0);
    return layout;
  }
  layout.kept.assign(lines.size(), false);
  int room = rows - 1;
  bool histogram = false;
  std::vector<std::size_t> order(lines.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
    return lines[p].rank < lines[q].rank;
  });
  for (const std::size_t i : order) {
    if (!histogram && lines[i].rank > histogram_rank && room >= histogram_least_rows) {
      histogram = true;
      room -= histogram_least_rows;
    }
    if (room >= 1) {
      layout.kept[i] = true;
      --room;
    }
  }
  if (histogram) layout.histogram_rows = histogram_least_rows + room;
  // The names of what is left out, each once, in the order of rank (a
  // narrow screen cuts the least needed).
  std::vector<std::string> names;
  bool histogram_named = histogram;  // (shown: not named)
  for (const std::size_t i : order) {
    if (!histogram_named && lines[i].rank > histogram_rank) {
      names.emplace_back("histogram");
      histogram_named = true;
    }
    if (!layout.kept[i] &&
        std::find(names.begin(), names.end(), lines[i].name) == names.end())
      names.emplace_back(lines[i].name);
  }
  // The window all of it needs: the figures, the histogram, the border,
  // the status line and the row under the frame.
  layout.left_out = fmt::format("more with {} rows: {}", count + histogram_least_rows + 4,
                                fmt::join(names, ", "));
  return layout;
}

}  // namespace

// [anchor: draw-kinetic-figures]
void draw_kinetic_figures(TextScreen& screen, const Figures& f, const KineticFigures& k,
                          const std::vector<std::string>& more_lines) {
  // Every line in the screen's order, each with its rank.
  std::vector<FigureLine> lines = heading_lines(f, k);
  std::vector<FigureLine> table = table_lines(k), measured = measured_lines(k);
  lines.insert(lines.end(), table.begin(), table.end());
  lines.insert(lines.end(), measured.begin(), measured.end());
  for (std::size_t i = 0; i < more_lines.size(); ++i)
    lines.push_back({more_lines[i], 19 + static_cast<int>(i), "Lyapunov"});
  // As many as the screen has room for, the histogram below them.
  const Layout layout = lay_out(lines, screen.rows - 2);
  std::vector<std::string> shown_lines;
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (layout.kept[i]) shown_lines.push_back(lines[i].text);
  draw_figures(screen, shown_lines);  // stage 6: the lines at their places
  int row = 1 + static_cast<int>(shown_lines.size()) + (layout.gap ? 1 : 0);
  if (layout.histogram_rows > 0) {
    draw_histogram(screen, k, row, row + layout.histogram_rows - 1);
  }
  if (!layout.left_out.empty()) write_text(screen, screen.rows - 2, layout.left_out);
}
// [/anchor: draw-kinetic-figures]

}  // namespace gas
