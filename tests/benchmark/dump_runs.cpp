// Section 7 of the report: a --dump written and read back. See dump_runs.hpp.
#include "dump_runs.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "program_runs.hpp"
#include "report_text.hpp"
#include "stage2_input.hpp"

namespace gas::benchmark {
namespace {

namespace fs = std::filesystem;

// The balls of a scene: its 'ball' lines and its 'random' line's COUNT (the
// file read by stage 2, no ball placed).
std::size_t balls_of(const fs::path& scene) {
  const SceneDescription description = read_scene_description(scene.string());
  return description.gas.balls.size() +
         (description.random ? description.random->count : 0);
}

// The median processor time of the runs that succeeded (0 if none did).
double median_seconds(const std::vector<ChildRun>& runs) {
  std::vector<double> seconds;
  for (const ChildRun& run : runs)
    if (run.succeeded()) seconds.push_back(run.cpu_seconds);
  if (seconds.empty()) return 0;
  std::sort(seconds.begin(), seconds.end());
  const std::size_t n = seconds.size();
  return n % 2 == 1 ? seconds[n / 2] : (seconds[n / 2 - 1] + seconds[n / 2]) / 2;
}

// The largest resident memory of the runs, in kB.
long long largest_kb(const std::vector<ChildRun>& runs) {
  long long most = 0;
  for (const ChildRun& run : runs) most = std::max(most, run.max_rss_kb);
  return most;
}

std::string read_text(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

// Runs build/gas with `arguments`; its run, or the first failure kept.
ChildRun time_gas(const DumpSettings& settings, const std::vector<std::string>& arguments,
                  DumpRow& row) {
  ChildRun run = run_child(settings.program, arguments, "", settings.time_limit);
  if (!run.succeeded() && row.failure.empty()) row.failure = run.failure();
  return run;
}

// Whether the gas continued from the dump `at_until` to 2 T dumps the bytes
// of the gas run straight from `scene` to 2 T.
std::string round_trip(const DumpSettings& settings, const fs::path& scene,
                       const fs::path& at_until, DumpRow& row) {
  const std::string later = fmt::format("{:g}", 2 * settings.until);
  const fs::path straight = settings.scratch / "straight.scene";
  const fs::path continued = settings.scratch / "continued.scene";
  const ChildRun a = time_gas(
      settings,
      {scene.string(), "--until", later, "--mode", "none", "--dump", straight.string()},
      row);
  const ChildRun b = time_gas(settings,
                              {at_until.string(), "--until", later, "--mode", "none",
                               "--dump", continued.string()},
                              row);
  if (!a.succeeded() || !b.succeeded()) return "not run: " + row.failure;
  const std::string text = read_text(straight);
  const bool same = !text.empty() && text == read_text(continued);
  std::error_code ignored;
  fs::remove(straight, ignored);
  fs::remove(continued, ignored);
  return same ? "identical" : "**they differ**";
}

std::string seconds_text(double seconds) {
  if (seconds <= 0) return "—";
  return seconds >= 10 ? fmt::format("{:.1f}", seconds) : fmt::format("{:.2f}", seconds);
}

}  // namespace

double DumpRow::plain_seconds() const {
  return median_seconds(plain);
}
double DumpRow::dumping_seconds() const {
  return median_seconds(dumping);
}
double DumpRow::reading_seconds() const {
  return median_seconds(reading);
}

DumpFigures measure_dumps(const DumpSettings& settings) {
  DumpFigures figures;
  fs::create_directories(settings.scratch);
  const std::string until = fmt::format("{:g}", settings.until);
  for (const fs::path& scene : settings.scenes) {
    DumpRow row;
    row.scene = scene.string();
    row.balls = balls_of(scene);
    figures.rows.push_back(row);
  }
  for (int round = 1; round <= settings.rounds; ++round) {
    for (std::size_t k = 0; k < figures.rows.size(); ++k) {
      DumpRow& row = figures.rows[k];
      const fs::path& scene = settings.scenes[k];
      const fs::path dump = settings.scratch / fmt::format("dump-{}.scene", row.balls);
      progress("7/7 round {} of {}: {} balls", round, settings.rounds, row.balls);
      row.plain.push_back(
          time_gas(settings, {scene.string(), "--until", until, "--mode", "none"}, row));
      row.dumping.push_back(time_gas(
          settings,
          {scene.string(), "--until", until, "--mode", "none", "--dump", dump.string()},
          row));
      std::error_code error;
      row.dump_bytes = static_cast<long long>(fs::file_size(dump, error));
      if (error) row.dump_bytes = 0;
      row.reading.push_back(
          time_gas(settings, {dump.string(), "--until", until, "--mode", "none"}, row));
      if (round == settings.rounds) {
        row.round_trip = round_trip(settings, scene, dump, row);
        fs::remove(dump, error);
      }
    }
  }
  return figures;
}

std::string dump_section(const DumpSettings& settings, const DumpFigures& figures) {
  std::string text = "## 7. Checkpoints: a dump written and read back\n\n";
  text += fmt::format(
      "`build/gas` as a process, its processor time (user + system), the median of {} "
      "round{} of three runs interleaved: (p) `build/gas SCENE --until {:g} --mode "
      "none`, (w) the same with `--dump d.scene`, (r) `build/gas d.scene --until {:g} "
      "--mode none`. Writing is (w) less (p); reading is (r) whole: stage 2 reads and "
      "checks the dump (its overlaps through cells), and the run starts (stage 4's "
      "first predictions) and takes no step. Memory: the largest resident memory of "
      "(p) and of (w). Continued: the dump at T = {:g} run on to T = {:g}, against the "
      "gas run straight there, their dumps compared byte for byte.\n\n",
      settings.rounds, settings.rounds == 1 ? "" : "s", settings.until, settings.until,
      settings.until, 2 * settings.until);
  text +=
      "| N | dump | bytes a ball | write (s) | read (s) | memory (p) / (w) | "
      "continued |\n|---:|---:|---:|---:|---:|---:|---|\n";
  for (const DumpRow& row : figures.rows) {
    if (!row.failure.empty() && row.reading.empty()) {
      text += fmt::format("| {} | failed: {} | | | | | |\n", row.balls, row.failure);
      continue;
    }
    const double write = row.dumping_seconds() - row.plain_seconds();
    text += fmt::format(
        "| {} | {:.1f} MB | {:.1f} | {} | {} | {:.0f} / {:.0f} MB | {} |\n", row.balls,
        static_cast<double>(row.dump_bytes) / 1e6,
        static_cast<double>(row.dump_bytes) / static_cast<double>(row.balls),
        write > 0 ? seconds_text(write) : "< noise", seconds_text(row.reading_seconds()),
        static_cast<double>(largest_kb(row.plain)) / 1024,
        static_cast<double>(largest_kb(row.dumping)) / 1024, row.round_trip);
  }
  text +=
      "\nThe targets: a dump of 10^5 balls read in at most 1.5 s of processor time, "
      "one of 10^6 in at most 15 s; writing adds little to the run's memory.\n\n";
  return text;
}

void write_dump_csv(const fs::path& path, const DumpFigures& figures) {
  std::ofstream file(path);
  file << "balls,round,plain_seconds,dumping_seconds,reading_seconds,dump_bytes,"
          "plain_rss_kb,dumping_rss_kb,reading_rss_kb\n";
  for (const DumpRow& row : figures.rows) {
    for (std::size_t k = 0; k < row.reading.size(); ++k) {
      file << fmt::format("{},{},{:.3f},{:.3f},{:.3f},{},{},{},{}\n", row.balls, k + 1,
                          row.plain[k].cpu_seconds, row.dumping[k].cpu_seconds,
                          row.reading[k].cpu_seconds, row.dump_bytes,
                          row.plain[k].max_rss_kb, row.dumping[k].max_rss_kb,
                          row.reading[k].max_rss_kb);
    }
  }
}

std::string dump_report(bool smoke, const fs::path& out, double time_limit) {
  DumpSettings settings;
  settings.program = GAS_PROGRAM;
  settings.time_limit = time_limit;
  settings.scratch =
      fs::temp_directory_path() / fmt::format("gas-benchmark-dumps-{}", getpid());
  fs::create_directories(settings.scratch);
  if (smoke) {
    const fs::path tiny = settings.scratch / "smoke-200.scene";
    std::ofstream(tiny) << random_scene_text(200, 1989);
    settings.scenes = {tiny};
    settings.rounds = 1;
  } else {
    const fs::path data = fs::path(GAS_SOURCE_DIR) / "data";
    for (const char* n : {"1000", "10000", "100000", "1000000"})
      settings.scenes.push_back(data / fmt::format("large-{}.scene", n));
  }
  const DumpFigures figures = measure_dumps(settings);
  write_dump_csv(out / "dumps.csv", figures);
  fs::remove_all(settings.scratch);
  return dump_section(settings, figures);
}

}  // namespace gas::benchmark
