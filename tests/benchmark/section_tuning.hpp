// Section 7 of the report: what the tuning buys. The plain grid
// (stages/beyond/plain_grid.*, `--strategy plain-grid`) beside the tuned one
// that the program runs (stages/beyond/cell_grid.*, `grid`), both as
// `build/gas` processes, timed in the rounds of section 6 (peer_runs.hpp):
// interleaved, on their processor time, the fixed costs removed by a run a
// tenth as long. And the tuned grid's steps, each with what it bought when it
// was added (the history is lessons/11-memory.md's; the figures here are the
// commits' own).
#pragma once

#include <string>

#include "peer_runs.hpp"

namespace gas::benchmark {

// The section's text, from its heading on.
std::string tuning_section(const PeerSettings& settings, const PeerFigures& figures);

}  // namespace gas::benchmark
