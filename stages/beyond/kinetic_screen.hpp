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

#include "beyond/kinetic_theory.hpp"
#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage6_output.hpp"

namespace gas {

// Kinetic theory's figures: what it predicts, and the time averages since the
// start to set beside it.
struct KineticFigures {
  double rms_speed = 0;                 // sqrt(2 E / N), now
  KineticTheory theory;                 // the predictions for this gas
  Average average_mean_speed;           // the mean speed, averaged over time
  Average pressure;                     // from the push on the walls
  Average compressibility;              // Z = P (A1 - 2a)(A2 - 2a) / (N kT)
  Average collision_rate;               // collisions of two balls per ball per time
  double mean_free_path = not_known;    // average mean speed / collision rate
  std::vector<double> speed_fractions;  // the histogram (GasStatistics)
  double bin_width = 0;                 // of its bins
  double fraction_beyond = 0;           // faster than its last bin
};

// The predictions for `gas` and the averages and histogram of `statistics`,
// up to the gas's time T.
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
