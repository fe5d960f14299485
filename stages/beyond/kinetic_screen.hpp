// The statistics screen of kinetic theory: each measured figure beside what
// theory predicts, and a histogram of speeds under the Maxwell-Boltzmann curve.
//
// What this file does: gathers the figures (stage 6's Figures of the gas now,
// and kinetic theory's predictions and time averages), lays them out as the
// lines of stage 6's character screen, draws the histogram below them, and
// writes the same figures as a CSV row (--csv).
// Article: "Gas on the display", stage 6, the third screen ("print some
// properties of the gas, the mean speed for example"). The theory is beyond
// the article.
// Lesson: lessons/11-kinetic-theory.md
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
// its walls and from its collisions, and the bulk's Z, from the interior,
// against the reference at the interior's density.
struct KineticFigures {
  double rms_speed = 0;      // sqrt(2 E / N), now
  KineticTheory theory;      // the predictions for this gas, at eta = N pi a^2 / A
  MeasuredFigures measured;  // the averages, the histogram, H
  double bulk_z_theory = not_known;     // the reference Z at the interior's eta
  double bulk_z_henderson = not_known;  // Henderson's at the same eta
  double pressure_theory = not_known;   // the reference Z n_int kT: the bulk's pressure
  double pair_contact_theory = not_known;  // the reference g(2a) at the interior's eta
  double mean_free_path = not_known;       // average mean speed / collision rate
  // The reference g(2a)'s uncertainty, from eta's: |dg/deta| x eta's error.
  double pair_contact_theory_error = not_known;
};

// The predictions for `gas` and what `statistics` measured, at the gas's T.
KineticFigures kinetic_figures(const Gas& gas, const GasStatistics& statistics);

// The statistics screen: the figures at fixed places inside the border, each
// beside its prediction, and under them the histogram of speeds with the
// Maxwell-Boltzmann curve, as far as the screen has room.
void draw_kinetic_figures(TextScreen& screen, const Figures& figures,
                          const KineticFigures& kinetic);

// The histogram part of it, in rows first_row ... last_row.
void draw_histogram(TextScreen& screen, const KineticFigures& kinetic, int first_row,
                    int last_row);

// The CSV header and one row of figures (--csv): the article's nine columns,
// then kinetic theory's.
std::string csv_header();
std::string csv_row(const Figures& figures, const KineticFigures& kinetic);

}  // namespace gas
