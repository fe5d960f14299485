// Section 6 of the report: `build/gas` beside the best peer, and a million
// balls.
//
// The peer is Graphical-EDMD (github.com/Syrocco/Graphical-EDMD), a C
// program of the same kind: two-dimensional hard discs, event-driven, cell
// lists and a queue of events. The project never holds its code: given the
// path of a checkout (gas-benchmark --peer DIR), the section builds it with
// its own Makefile (`make -C DIR`: -O3 -ffast-math) and runs it from the very
// centres of the scene the program runs; without one, it says "not run".
//
// Both are timed as processes, on their processor time (user + system, from
// wait4): ball-ball collisions per processor second, with the fixed costs
// (reading, placing, the first predictions, the peer's files) removed by a
// run a tenth as long: (collisions of the long run - of the short) / (its
// time - the short's). The runs of the two programs are interleaved, round
// after round, so that a load on the machine falls on both; each figure is
// the median of the rounds. Beside them: `build/gas` with --events (what
// writing every collision costs), with --mode stats --csv at 10^6 (what the
// statistics cost there), and the memory per ball (the largest resident
// memory, VmHWM, against N). And in the same rounds, for section 7, build/gas
// with the plain grid (--strategy plain-grid) beside the tuned one.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "child_process.hpp"

namespace gas::benchmark {

struct PeerSettings {
  std::string program;                        // the path of build/gas
  std::optional<std::filesystem::path> peer;  // a checkout of Graphical-EDMD
  std::vector<std::filesystem::path> scenes;  // data/large-N.scene, N ascending
  std::size_t peer_most_balls = 100000;       // the peer is run up to this N
  std::size_t stats_least_balls = 1000000;    // --mode stats --csv from this N on
  double collisions_per_run = 2e6;            // about, in a long run
  // Rounds, of which the median is kept: 5, as with 3 two reports of the
  // same code on a shared machine read --events' cost at 10^3 as +1 % and
  // +17 %.
  int rounds = 5;
  double time_limit = 600;        // wall seconds before a run is stopped
  std::filesystem::path scratch;  // the runs' files
};

// One way of running, on one scene: the long and the short run of each round.
struct RatePairs {
  std::string command;        // the long run's, as a user types it
  std::vector<double> rates;  // ball collisions per processor second, a round each
  long long max_rss_kb = 0;   // the long runs' largest resident memory
  std::string failure;        // why it could not be timed, if so
  double median() const;      // 0 if no round was timed
};

struct PeerRow {
  std::string scene;  // data/large-1000.scene
  std::size_t balls = 0;
  double until = 0, peer_until = 0;      // the long runs' model times (short: a tenth)
  long long collisions = 0;              // ball collisions of build/gas's long run,
  long long short_collisions = 0;        //   and of its short run (by the engine)
  RatePairs plain, events, stats, peer;  // --mode none; + --events; stats + --csv; peer
  RatePairs plain_grid;                  // --mode none --strategy plain-grid (section 7)
};

struct PeerFigures {
  std::string peer_commit;    // the checkout's commit ("" if not run)
  std::string peer_build;     // how it was built, or why it could not be
  bool peer_run = false;      // was it built and run?
  std::vector<PeerRow> rows;  // a scene each
};

PeerFigures measure_peer(const PeerSettings& settings);

// The section's text, from its heading on; and its rows of the Targets table.
std::string peer_section(const PeerSettings& settings, const PeerFigures& figures);
std::string peer_targets(const PeerFigures& figures);

// Bytes per ball of a way of running: the growth of the largest resident
// memory from the smallest scene to `row`, per ball added (0 for the first).
double bytes_per_ball(const PeerFigures& figures, const PeerRow& row,
                      RatePairs PeerRow::*way = &PeerRow::plain);

// Every rate measured, one row a round (data/reports/peer.csv).
void write_peer_csv(const std::filesystem::path& path, const PeerFigures& figures);

}  // namespace gas::benchmark
