// Section 7 of the report: checkpoints, a --dump written and read back, at
// 10^3 to 10^6 balls.
//
// `build/gas` is timed as a process on its processor time (user + system,
// from wait4), three runs a round on data/large-N.scene, interleaved round
// after round so that a load on the machine falls on all three, each figure
// the median of the rounds:
//
//   (p) gas SCENE --until 1 --mode none                    the plain run
//   (w) gas SCENE --until 1 --mode none --dump d.scene     the same, dumping
//   (r) gas d.scene --until 1 --mode none                  reading the dump
//
// Writing costs (w) less (p); reading is (r) whole: stage 2 reading and
// checking the dump, and the run's start (stage 4's first predictions); it
// takes no step, the dump being at T = 1 already. Beside them: the dump's
// bytes a ball, the largest resident memory of (p) and (w) (what writing
// adds), and once a size, whether the gas continued from the dump to T = 2
// dumps the very bytes of the gas run straight to T = 2.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "child_process.hpp"

namespace gas::benchmark {

struct DumpSettings {
  std::string program;                        // the path of build/gas
  std::vector<std::filesystem::path> scenes;  // data/large-N.scene, N ascending
  int rounds = 3;                             // of which the median is kept
  double until = 1;                           // the dump's model time T
  double time_limit = 600;                    // wall seconds before a run is stopped
  std::filesystem::path scratch;              // the dumps
};

// One scene: its runs, a round each.
struct DumpRow {
  std::string scene;  // data/large-1000.scene
  std::size_t balls = 0;
  std::vector<ChildRun> plain, dumping, reading;  // (p), (w), (r), a round each
  long long dump_bytes = 0;                       // the dump's size
  std::string round_trip;                         // "identical", or what went wrong
  std::string failure;                            // why it could not be timed, if so

  // Medians over the rounds, in processor seconds (0 if none ran).
  double plain_seconds() const;
  double dumping_seconds() const;
  double reading_seconds() const;
};

struct DumpFigures {
  std::vector<DumpRow> rows;  // a scene each
};

DumpFigures measure_dumps(const DumpSettings& settings);

// The section's text, from its heading on.
std::string dump_section(const DumpSettings& settings, const DumpFigures& figures);

// Every run, one row a round (data/reports/dumps.csv).
void write_dump_csv(const std::filesystem::path& path, const DumpFigures& figures);

// The section of a run of gas-benchmark, the one call the report makes:
// data/large-N.scene for N = 10^3 to 10^6 (for a smoke run, one tiny scene
// of its own and one round), measured, dumps.csv written into `out`, and the
// text returned.
std::string dump_report(bool smoke, const std::filesystem::path& out, double time_limit);

}  // namespace gas::benchmark
