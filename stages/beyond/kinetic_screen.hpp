// The statistics screen of kinetic theory: each measured figure beside what
// theory predicts, and a histogram of speeds under the Maxwell-Boltzmann curve.
//
// What this file does: gathers the figures (stage 6's Figures of the gas now,
// and kinetic theory's predictions and time averages), lays them out as the
// lines of stage 6's character screen, and draws the histogram below them.
// The same figures as --csv's columns: beyond/kinetic_csv.hpp.
// Article: "Gas on the display", stage 6, the third screen ("print some
// properties of the gas, the mean speed for example"). The theory is beyond
// the article.
// Lesson: lessons/12-statistics-screen.md
//
// Assumptions: as for beyond/kinetic_theory.hpp (unit mass, k = 1).
#pragma once

#include <string>
#include <vector>

#include "beyond/gas_statistics.hpp"
#include "beyond/kinetic_theory.hpp"
#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage6_output.hpp"

namespace gas {

// Kinetic theory's figures: what it predicts, and the averages measured
// since they started to set beside it, like with like: the box's own Z from
// its walls and from its collisions; the bulk's Z, pressure, collision rate
// and mean free path, from the interior, against the reference and Enskog
// at the interior's density eta_int, each theory with the uncertainty that
// eta_int's error gives it.
struct KineticFigures {
  double rms_speed = 0;      // sqrt(2 E / N), now
  KineticTheory theory;      // the predictions for this gas, at eta = N pi a^2 / A
  MeasuredFigures measured;  // the averages, the histogram, H
  bool many_balls = false;  // N >= kinetic_theory_fewest_balls: the bulk's theory applies
  Average bulk_z_theory;    // the reference Z at eta_int, for a closed box of N balls
  double bulk_z_shift = not_known;  // its shift from the open bulk's (fixed_count_shift)
  double bulk_z_henderson = not_known;  // Henderson's at the same eta
  Average pressure_theory;  // Z_ref n kT in the strips in front of the walls' middles
  double pair_contact_theory = not_known;  // the reference g(2a) at the interior's eta
  Average collision_rate_theory;           // Enskog's at eta_int, per ball per unit time
  Average mean_free_path_theory;           // Enskog's at eta_int
  double h_noise = not_known;         // the mean H of N Maxwellian speeds in the bins
  double h_noise_spread = not_known;  // its standard deviation
  // The reference g(2a)'s uncertainty, from eta's: |dg/deta| x eta's error.
  double pair_contact_theory_error = not_known;
};
// The predictions for `gas` and what `statistics` measured, at the gas's T;
// `energy`: the gas's kinetic energy E now (kinetic_energy, or stage 6's
// figures of the same moment).
KineticFigures kinetic_figures(const Gas& gas, const GasStatistics& statistics,
                               double energy);

// The statistics screen: the figures at fixed places inside the border, and
// under them the histogram of speeds with the Maxwell-Boltzmann curve.
// `more_lines`, from other observers (the Lyapunov exponent, lesson 15),
// follow the figures. Every row says what its columns hold: a row of the
// table a measured average beside the theory of the same thing (with their
// errors, and the theory's name); a second measurement gets its own label
// within its line; a blank error says why (Average::why_no_error).
//
// A screen too short for all of it keeps the lines a student needs first —
// the gas now (N, eta, kT, the drift, the momentum, the mean and rms speed:
// stage 6's own figures), since when the averages run, the table's
// header, the mean speed, the pressure, Z, the collision rate and the mean
// free path, then the histogram (at least 4 rows of bars), then H, the
// units, g(2a), Z's difference from the reference, the interior, the
// contact theorem, the box and the Lyapunov exponent, in that order — and
// its last row names what it left out and how many rows show it all. On a
// screen with room for everything (from 30 rows of window: --rows 30) the
// histogram takes every row the figures leave.
void draw_kinetic_figures(TextScreen& screen, const Figures& figures,
                          const KineticFigures& kinetic,
                          const std::vector<std::string>& more_lines = {});

// The histogram part of it, in rows first_row ... last_row.
void draw_histogram(TextScreen& screen, const KineticFigures& kinetic, int first_row,
                    int last_row);

// The rows of the histogram's smallest drawing: a title, 4 rows of bars and
// the axis.
inline constexpr int histogram_least_rows = 6;

}  // namespace gas
