// --csv's columns: the figures of the statistics screen, one row a picture
// (beyond the article).
//
// What this file does: names every column of --csv once, in a table of
// columns, and writes the header and a row from the figures of one moment:
// the nine figures of stage 6's character screen (stage 6's Figures; the
// article names one such figure, as an example: 「例えば平均速度」), then kinetic
// theory's (KineticFigures). The naming convention is data/README.md's: a bulk figure
// plain, the whole box's `_box`, `_error` its error, `_theory` the theory of
// the same thing, `_theory_error` the theory's own. A new block of columns is
// a new stretch of rows at the table's end. The Lyapunov exponent's block
// follows them (beyond/lyapunov_screen.hpp). Numbers are written with 17
// significant digits, so that they read back bit for bit; `nan` while not
// known.
// Article: "Gas on the display", stage 6, the third screen ("print some
// properties of the gas"); kinetic theory is beyond the article.
// Lesson: lessons/12-statistics-screen.md; the columns: data/README.md.
#pragma once

#include <string>

#include "beyond/kinetic_screen.hpp"
#include "stage6_output.hpp"

namespace gas {

// The CSV header and one row of figures (--csv), without a line end.
std::string csv_header();
std::string csv_row(const Figures& figures, const KineticFigures& kinetic);

}  // namespace gas
