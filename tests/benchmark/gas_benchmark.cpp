// gas-benchmark: speed against error.
//
// Measures what the stages cost and how far their answers can be trusted, and
// writes the report data/reports/speed-against-error.md with its CSV files:
//
//   1. Throughput: collisions per second against N for each way of stage 4
//      (the article's scan, the table of next events, the cell grid), the
//      crossovers, and the default scene as the program runs it.
//   2. The number type: float, double, long double against a 113-bit
//      reference (cost, energy drift, overlaps, how long each follows the
//      exact motion), beside the horizon the Lyapunov exponent predicts.
//   3. Time reversal: forward k collisions per ball, B, back as long: the
//      return error against k, for each number type, and how far back the
//      exponent predicts B to bring the gas.
//   4. What an event-driven program buys: a fixed-time-step program at
//      several steps against the stages.
//   5. The program as users run it: build/gas itself, timed as a process on
//      large scenes, beside the engine on the same gas (program_runs.hpp).
//   6. Beside the best peer: build/gas and Graphical-EDMD as processes on
//      the same gases, 10^3 to 10^5 balls, and build/gas alone at 10^6
//      (peer_runs.hpp); "not run" for the peer without --peer.
//   7. What the tuning buys: build/gas with the plain grid beside the tuned
//      one, in the rounds of section 6 (section_tuning.hpp).
//   8. Checkpoints: a --dump of 10^3 to 10^6 balls written and read back,
//      timed as processes (dump_runs.hpp).
//
// Each section is its own unit (section_throughput, section_accuracy,
// time_stepped, program_runs, peer_runs, section_tuning, dump_runs); this
// file runs them in turn and writes the report's head: the machine, and the
// targets.
//
// and two pictures beside it, drawn by gnuplot if it is installed
// (plots.hpp): collisions per second against N, and the distance from the
// 113-bit run against collisions per ball.
//
// Usage:  gas-benchmark [--smoke] [--out DIR] [--peer DIR]
//   --smoke   tiny sizes, a few seconds (the test suite runs this)
//   --out     where to write (default: data/reports of the source tree)
//   --peer    a checkout of github.com/Syrocco/Graphical-EDMD, for section 6
//             (built there with its own Makefile; the project holds none of it)
// Progress goes to standard error. Single-threaded: one core (and `gas`
// runs alone while it is timed).
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "benchmark_build_info.hpp"
#include "dump_runs.hpp"
#include "peer_runs.hpp"
#include "program_runs.hpp"
#include "report_common.hpp"
#include "report_pictures.hpp"
#include "report_text.hpp"
#include "section_accuracy.hpp"
#include "section_throughput.hpp"
#include "section_tuning.hpp"
#include "time_stepped.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using namespace gas::benchmark;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Settings {
  bool smoke = false;
  fs::path out = fs::path(GAS_SOURCE_DIR) / "data" / "reports";
  std::optional<fs::path> peer;  // a checkout of Graphical-EDMD (section 6)
};

// ------------------------------------------------------------ the machine

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(colon + 2);
    }
  }
  return "unknown (no /proc/cpuinfo)";
}

std::string memory() {
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    if (line.rfind("MemTotal:", 0) == 0) {
      std::istringstream words(line.substr(9));
      double kib = 0;
      words >> kib;
      return fmt::format("{:.1f} GiB", kib / (1024 * 1024));
    }
  }
  return "unknown";
}

// The wait for one read from memory at a random place among `bytes` bytes:
// a chase through a random cycle of cache lines (each read gives the place
// of the next, so no two waits overlap). Small sets stay in the processor's
// caches; large ones come from main memory. This is what the grid's cost
// per collision grows by at large N (section 1).
double read_wait_ns(std::size_t bytes, bool smoke) {
  struct alignas(64) Line {
    std::size_t next = 0;
  };
  const std::size_t lines = bytes / sizeof(Line);
  std::vector<std::size_t> order(lines);
  for (std::size_t i = 0; i < lines; ++i) order[i] = i;
  std::mt19937_64 random(1);
  std::shuffle(order.begin(), order.end(), random);
  std::vector<Line> memory(lines);
  for (std::size_t i = 0; i < lines; ++i) memory[order[i]].next = order[(i + 1) % lines];
  const std::size_t reads = smoke ? 100000 : 4000000;
  std::size_t at = order[0];
  const double start = cpu_seconds();
  for (std::size_t i = 0; i < reads; ++i) at = memory[at].next;
  const double seconds = cpu_since(start);
  if (at == lines) return 0;  // never: keeps the chase from being optimised away
  return 1e9 * seconds / static_cast<double>(reads);
}

std::string now_utc() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[64];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

// ------------------------------------------------------------ 5. the program

// The smoke run's scene for sections 5 and 6: 200 random balls, written in
// the section's scratch folder.
fs::path smoke_scene(const fs::path& scratch) {
  fs::create_directories(scratch);
  const fs::path tiny = scratch / "smoke-200.scene";
  std::ofstream(tiny) << gas::benchmark::random_scene_text(200, 1989);
  return tiny;
}

// The scenes of section 5: the targets' data/large-10000.scene and the 10^5
// one; for a smoke run, a tiny scene of its own in the scratch folder.
ProgramSettings program_settings_for(const Settings& settings, const Sizes& sizes) {
  ProgramSettings p;
  p.program = GAS_PROGRAM;
  p.rounds = sizes.program_rounds;
  p.engine_budget = sizes.seconds_per_point;
  p.time_limit = sizes.program_time_limit;
  p.scratch = fs::temp_directory_path() / fmt::format("gas-benchmark-{}", getpid());
  if (settings.smoke) {
    p.scenes.push_back({"smoke-200.scene", smoke_scene(p.scratch), 20, 2});
    return p;
  }
  const fs::path data = fs::path(GAS_SOURCE_DIR) / "data";
  p.scenes.push_back({"data/large-10000.scene", data / "large-10000.scene", 1000, 2});
  p.scenes.push_back({"data/large-100000.scene", data / "large-100000.scene", 100, 0.05});
  return p;
}

// ------------------------------------------------------------ 6. the peer

// The scenes of section 6: data/large-N.scene for N = 10^3 to 10^6, the peer
// up to 10^5; for a smoke run, a tiny scene of its own and a few collisions.
gas::benchmark::PeerSettings peer_settings_for(const Settings& settings,
                                               const Sizes& sizes) {
  gas::benchmark::PeerSettings p;
  p.program = GAS_PROGRAM;
  p.peer = settings.peer;
  p.time_limit = sizes.program_time_limit;
  p.scratch = fs::temp_directory_path() / fmt::format("gas-benchmark-peer-{}", getpid());
  if (settings.smoke) {
    p.scenes = {smoke_scene(p.scratch)};
    p.rounds = 1;
    p.collisions_per_run = 2e4;
    return p;
  }
  const fs::path data = fs::path(GAS_SOURCE_DIR) / "data";
  for (const char* n : {"1000", "10000", "100000", "1000000"})
    p.scenes.push_back(data / fmt::format("large-{}.scene", n));
  return p;
}

// The report's head: how to make it again, the machine and the build.
std::string report_head(const Settings& settings, double run_seconds,
                        const std::string& read_waits) {
  std::string text = "# Speed against error\n\n";
  text += fmt::format(
      "Written by `gas-benchmark`{} on {}. Regenerate it (from the top of the "
      "repository, minutes) with:\n\n"
      "```sh\napt-get update && apt-get install -y gnuplot-nox && cmake -S . -B build && "
      "cmake --build build -j2 --target gas gas-benchmark && "
      "build/tests/benchmark/gas-benchmark\n```\n\n"
      "(gnuplot draws the two pictures; without it the report has none.)\n\n",
      settings.smoke ? " --smoke (tiny sizes: a test of the benchmark, not a measurement)"
                     : "",
      now_utc());
  text += "| the machine and the build | |\n|---|---|\n";
  text += fmt::format("| CPU | {} ({} hardware threads; one used) |\n", cpu_model(),
                      std::thread::hardware_concurrency());
  text += fmt::format("| memory | {} |\n", memory());
  text += fmt::format("| compiler | {} (`{}`) |\n", GAS_CXX_COMPILER, __VERSION__);
  text += fmt::format("| build type | {} |\n", GAS_BUILD_TYPE);
  text += fmt::format("| flags | `{}` |\n", GAS_CXX_FLAGS);
  text += fmt::format("| run time | {:.0f} s |\n", run_seconds);
  text += fmt::format(
      "| one read from memory, at random among 1 / 4 / 16 / 64 MiB | {} |\n\n",
      read_waits);
  if (std::string(GAS_BUILD_TYPE) != "Release")
    text += "**Not a Release build: the times below do not measure the program.**\n\n";
  text +=
      "The CSV files beside this report hold every number measured; the tables below "
      "are chosen rows. How noisy the machine was shows in the last row above (other "
      "programs sharing the caches slow the reads among 4 and 16 MiB) and in the "
      "default scene's row of the targets: the same code timed twice.\n\n";
  return text;
}

// The wait for one read at random among 1, 4, 16 and 64 MiB, in words.
std::string read_waits(bool smoke) {
  std::string text;
  for (const std::size_t mebibytes : {1, 4, 16, 64}) {
    const double wait = read_wait_ns(mebibytes << 20, smoke);
    text += fmt::format("{}{:.0f} ns", text.empty() ? "" : " / ", wait);
  }
  progress("memory: one read at random among 1 / 4 / 16 / 64 MiB: {}", text);
  return text;
}

int run(const Settings& settings) {
  const Sizes sizes = sizes_for(settings.smoke);
  fs::create_directories(settings.out);
  const auto began = Clock::now();
  // The memory first, while nothing else of ours is in the caches.
  const std::string waits = read_waits(settings.smoke);
  const ThroughputFigures throughput = measure_throughputs(sizes, settings.out);
  const NumberTypeFigures types = measure_number_types(sizes, settings.out);
  const std::vector<ReversalRow> reversal = measure_time_reversal(sizes, settings.out);
  const TimeStepFigures steps = measure_time_steps(sizes, settings.out);
  const ProgramSettings program_settings = program_settings_for(settings, sizes);
  const ProgramFigures program_runs = measure_program(program_settings);
  write_program_csv(settings.out / "program.csv", program_runs);
  fs::remove_all(program_settings.scratch);
  const PeerSettings peer_settings = peer_settings_for(settings, sizes);
  const PeerFigures peer_runs = measure_peer(peer_settings);
  write_peer_csv(settings.out / "peer.csv", peer_runs);
  fs::remove_all(peer_settings.scratch);
  const std::string dumps =
      dump_report(settings.smoke, settings.out, sizes.program_time_limit);

  progress("pictures: gnuplot");
  const std::string throughput_picture = picture_markdown(
      throughput_figure(settings.out, throughput.all, {dense, sparse}, program_runs),
      "Collisions per second against N, log-log: each way of stage 4 at area fraction "
      "0.3 and 0.05, and the program");
  const std::string distance_picture =
      picture_markdown(distance_figure(settings.out, types.distances),
                       "The distance from the 113-bit run against collisions per ball, "
                       "for each number type");

  progress("writing {}", (settings.out / "speed-against-error.md").string());
  std::string report = report_head(settings, seconds_since(began), waits);
  report += "## Targets\n\n| target | measured | |\n|---|---|---|\n" +
            throughput_targets(throughput, waits) +
            program_targets(program_settings, program_runs) + peer_targets(peer_runs) +
            "\n(\"No slower\" allows 3 %: the default scene's row times the same code "
            "twice, and reads within that of 1.)\n\n";
  report += throughput_section(sizes, throughput, throughput_picture);
  report += number_types_section(sizes, types, distance_picture);
  report += time_reversal_section(sizes, reversal, types);
  report += time_steps_section(sizes, steps);
  report += program_section(program_settings, program_runs);
  report += peer_section(peer_settings, peer_runs);
  report += tuning_section(peer_settings, peer_runs);
  report += dumps;
  std::ofstream file(settings.out / "speed-against-error.md");
  if (!file)
    throw std::runtime_error(fmt::format("{}: cannot write", settings.out.string()));
  file << report;
  progress("done in {:.0f} s", seconds_since(began));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Settings settings;
  for (int i = 1; i < argc; ++i) {
    const std::string argument = argv[i];
    if (argument == "--smoke") {
      settings.smoke = true;
    } else if (argument == "--out" && i + 1 < argc) {
      settings.out = argv[++i];
    } else if (argument == "--peer" && i + 1 < argc) {
      settings.peer = fs::absolute(argv[++i]);
    } else {
      fmt::print(stderr, "usage: gas-benchmark [--smoke] [--out DIR] [--peer DIR]\n");
      return 2;
    }
  }
  try {
    return run(settings);
  } catch (const std::exception& error) {
    fmt::print(stderr, "gas-benchmark: {}\n", error.what());
    return 1;
  }
}
