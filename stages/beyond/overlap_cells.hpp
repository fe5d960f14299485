// Stage 2 — input, the check that no two balls overlap, for a large scene
// (beyond the article).
//
// What this file does: finds the first overlapping pair of a scene's balls
// the way stage 2's first_overlap_of_all_pairs does — the same pair, by the
// same comparison — but compares each ball only with the balls before it in
// the 3 x 3 cells around its own, cells a little wider than the least
// distance allowed. Before the first overlap no two balls met so far overlap,
// so a cell holds a few of them: the search takes some ten comparisons a
// ball, where the plain one takes N / 2 (at 10^5 balls, some 5 * 10^9 in all,
// seconds; at 10^6, minutes).
// Article: "Gas on the display", stage 2, "input" (the article sets the
// initial centres; that no two overlap is our check). A teaching scene's few
// balls need no cells; a scene of 10^6 balls, a --dump of the program's
// largest gas, does.
// Lesson: lessons/2-input.md (the check of overlaps); the cells:
// beyond/cell_layout.hpp, lessons/10-scaling.md.
//
// Assumptions: the centres are finite (stage 2 has checked that each lies on
// the table). A few balls far from a dense cluster make the cells large (at
// most about 2N of them cover the box around every centre): the search then
// slows towards the plain one, but its answer is the same.
#pragma once

#include <optional>
#include <vector>

#include "stage1_data.hpp"
#include "stage2_input.hpp"

namespace gas {

// The first pair of `centres` closer than `closest`, as stage 2's
// OverlapSearch promises (first_overlap_of_all_pairs' answer), through cells.
std::optional<Overlap> first_overlap_by_cells(const std::vector<Point>& centres,
                                              double closest);

}  // namespace gas
