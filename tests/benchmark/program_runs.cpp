// The program as users run it: section 5 of the report. See program_runs.hpp.
#include "program_runs.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <tuple>

#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "report_text.hpp"
#include "time_stepped.hpp"  // cpu_seconds

namespace gas::benchmark {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// What the last row of a --csv file says: the model time and the collisions
// so far (wall_collisions + ball_collisions, found by the header's names).
struct LastRow {
  bool read = false;
  double time = 0;
  long long collisions = 0;
  std::string problem;  // why it could not be read
};

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream words(line);
  for (std::string field; std::getline(words, field, ',');) fields.push_back(field);
  return fields;
}

LastRow last_row(const fs::path& path) {
  LastRow row;
  std::ifstream file(path);
  std::string header, line, last;
  if (!file || !std::getline(file, header)) {
    row.problem = fmt::format("no CSV file {}", path.filename().string());
    return row;
  }
  while (std::getline(file, line))
    if (!line.empty()) last = line;
  if (last.empty()) {
    row.problem = "its CSV file has no rows";
    return row;
  }
  const std::vector<std::string> names = fields_of(header), values = fields_of(last);
  auto column = [&](const std::string& name) -> const std::string* {
    for (std::size_t i = 0; i < names.size() && i < values.size(); ++i)
      if (names[i] == name) return &values[i];
    return nullptr;
  };
  const std::string *time = column("T"), *walls = column("wall_collisions"),
                    *balls = column("ball_collisions");
  if (!time || !walls || !balls) {
    row.problem = "its CSV file has no columns T, wall_collisions, ball_collisions";
    return row;
  }
  try {
    row.time = std::stod(*time);
    row.collisions = std::stoll(*walls) + std::stoll(*balls);
    row.read = true;
  } catch (const std::exception&) {
    row.problem = fmt::format("its CSV file's last row is not numbers: {}", last);
  }
  return row;
}

// The text of a child's failure, fit for a cell of a markdown table.
std::string cell_text(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c == '\n' ? ' ' : c;
  }
  return out;
}

// One run of gas: the command of run (a), (b) or (c) on the scene, timed.
ProgramRun run_gas(const ProgramSettings& settings, const ProgramScene& scene,
                   std::size_t balls, char label) {
  ProgramRun run;
  run.scene = scene.name;
  run.balls = balls;
  run.label = label;
  run.until = label == 'c' ? scene.until_pictured : scene.until;
  const std::string until = fmt::format("{:g}", run.until);
  const fs::path csv = settings.scratch / fmt::format("{}.csv", label);
  std::vector<std::string> arguments = {scene.path.string(), "--until", until, "--mode"};
  switch (label) {
    case 'a':
      arguments.push_back("none");
      run.command = fmt::format("build/gas {} --until {} --mode none", scene.name, until);
      break;
    case 'b':
      arguments.insert(arguments.end(), {"stats", "--csv", csv.string()});
      run.command = fmt::format("build/gas {} --until {} --mode stats --csv out.csv",
                                scene.name, until);
      break;
    default:
      arguments.insert(arguments.end(),
                       {"stats", "--csv", csv.string(), "--pictures", "collisions"});
      run.command = fmt::format(
          "build/gas {} --until {} --mode stats --csv out.csv --pictures collisions",
          scene.name, until);
      break;
  }
  std::error_code ignored;
  fs::remove(csv, ignored);
  run.child = run_child(settings.program, arguments, "", settings.time_limit);
  run.rounds = 1;
  progress("  ({}) {}: {}", label, run.command,
           run.child.succeeded() ? fmt::format("{:.2f} s", run.child.wall_seconds)
                                 : run.child.failure());
  if (label != 'a' && run.child.succeeded()) {
    const LastRow row = last_row(csv);
    if (!row.read) {
      run.count_note = row.problem;
    } else if (std::fabs(row.time - run.until) > 1e-9 * std::max(1.0, run.until)) {
      run.count_note =
          fmt::format("its CSV file ends at T = {:g}, not {:g}", row.time, run.until);
    } else {
      run.collisions = row.collisions;
      run.count_note = "the last row of its CSV file";
    }
  }
  return run;
}

std::string seconds_text(double seconds) {
  return seconds >= 10 ? fmt::format("{:.1f} s", seconds)
                       : fmt::format("{:.2f} s", seconds);
}

std::string bytes_text(long long bytes) {
  if (bytes >= 1'000'000)
    return fmt::format("{:.1f} MB", static_cast<double>(bytes) / 1e6);
  if (bytes >= 1000) return fmt::format("{:.1f} kB", static_cast<double>(bytes) / 1e3);
  return fmt::format("{} B", bytes);
}

std::string ratio_text(double program, double engine) {
  return program > 0 && engine > 0 ? fmt::format("{:.2f}x", program / engine) : "—";
}

// The engine's event loop from the scene file to its T, reading the scene
// and placing its balls included: what run (a) does, inside this process.
struct EngineToT {
  long long collisions = 0;
  double wall_seconds = 0, cpu_seconds = 0;
};

EngineToT engine_to_t(const ProgramScene& scene) {
  const auto began = Clock::now();
  const double began_cpu = cpu_seconds();
  const Gas gas = read_scene_file(scene.path.string());
  EventLoop loop(gas, strategy_for(gas.balls.size()));
  EngineToT run;
  run.collisions = loop.run_to(scene.until);
  run.wall_seconds = std::chrono::duration<double>(Clock::now() - began).count();
  run.cpu_seconds = cpu_seconds() - began_cpu;
  progress("  the engine from the scene file to T = {:g}: {} collisions in {:.2f} s",
           scene.until, run.collisions, run.wall_seconds);
  return run;
}

}  // namespace

const ProgramRun* ProgramFigures::run(const std::string& scene, char label) const {
  for (const ProgramRun& r : runs)
    if (r.scene == scene && r.label == label) return &r;
  return nullptr;
}

const EngineOnScene* ProgramFigures::engine(const std::string& scene) const {
  for (const EngineOnScene& e : engines)
    if (e.scene == scene) return &e;
  return nullptr;
}

ProgramFigures measure_program(const ProgramSettings& settings) {
  ProgramFigures figures;
  fs::create_directories(settings.scratch);
  for (const ProgramScene& scene : settings.scenes) {
    // The scene, read once for section 1's measurement of the engine.
    const Gas gas = read_scene_file(scene.path.string());
    const Strategy strategy = strategy_for(gas.balls.size());
    progress("5/5 the program as users run it: {} ({} balls, stage 4 by the {})",
             scene.name, gas.balls.size(), strategy_name(strategy));
    EngineOnScene engine;
    engine.scene = scene.name;
    engine.balls = gas.balls.size();
    engine.until = scene.until;

    // Then in turn, each round: section 1's measurement of the engine, the
    // engine from the scene file to T, (a) and (b); the fastest round of each
    // kept (the machine's noise only ever slows a run down). A failure is
    // kept and not tried again. Then (c) once.
    ProgramRun none, stats;
    for (int round = 0; round < settings.rounds; ++round) {
      const Throughput loop = measure_throughput(gas, strategy, settings.engine_budget);
      progress("  the engine as section 1 measures it: {} collisions/s",
               count_text(loop.per_second()));
      if (round == 0 || loop.per_second() > engine.loop.per_second()) engine.loop = loop;
      const EngineToT to_t = engine_to_t(scene);
      if (round == 0 || to_t.wall_seconds < engine.wall_seconds) {
        engine.collisions = to_t.collisions;
        engine.wall_seconds = to_t.wall_seconds;
        engine.cpu_seconds = to_t.cpu_seconds;
      }
      for (auto [kept, label] : {std::pair{&none, 'a'}, std::pair{&stats, 'b'}}) {
        if (kept->rounds > 0 && !kept->child.succeeded()) continue;
        ProgramRun fresh = run_gas(settings, scene, engine.balls, label);
        fresh.rounds = kept->rounds + 1;
        if (kept->rounds == 0 || !fresh.child.succeeded() ||
            fresh.child.wall_seconds < kept->child.wall_seconds) {
          *kept = fresh;
        } else {
          kept->rounds = fresh.rounds;
        }
      }
    }
    figures.engines.push_back(engine);
    // Run (a) writes no CSV file: it does the engine's collisions to T.
    if (none.child.succeeded()) {
      none.collisions = engine.collisions;
      none.count_note = "the engine's run to the same T";
      if (stats.collisions >= 0 && stats.collisions != engine.collisions)
        none.count_note += fmt::format(
            " (but run (b)'s CSV file counts {}: the program's physics is not the "
            "engine's)",
            stats.collisions);
    }
    figures.runs.push_back(none);
    figures.runs.push_back(stats);
    figures.runs.push_back(run_gas(settings, scene, engine.balls, 'c'));
  }
  return figures;
}

namespace {

// The section's opening: what is run, and how it is timed.
std::string program_intro(const ProgramSettings& settings) {
  return fmt::format(
      "Sections 1 to 4 time the stages inside this benchmark. Here the benchmark runs "
      "`build/gas` itself, the program users type, as a child process (`posix_spawn`, "
      "`tests/benchmark/child_process.cpp`): end to end — starting, reading the scene "
      "and placing its balls, the run, writing its files, exiting — on the wall clock, "
      "its standard output going to a pipe that the benchmark reads and throws away. "
      "Three commands on each scene: (a) nothing drawn; (b) the statistics screen and "
      "a CSV file, the frames going to the pipe (a large scene's pictures are taken "
      "at the display steps only); (c) for reference, (b) with a picture at every "
      "collision as the article's loop takes them, over a shorter time (each picture "
      "walks all N balls). Beside them, the engine on the same scene file in the "
      "same run: section 1's measurement (the best of three rounds of about {:g} s of "
      "processor time, after a warm-up), and the same event loop from the scene file "
      "to the same T, reading the scene and placing its balls included, in this "
      "process, on the wall clock. {}. A run's collisions are read from "
      "the last row of its `--csv` file (wall_collisions + ball_collisions); run (a) "
      "writes none and does the engine's collisions to T (what is drawn never changes "
      "the physics; run (b)'s file checks it). *× engine*: the run's collisions per "
      "second (of the wall clock) over section 1's figure for the same gas; *in "
      "processor time*: the same with the run's own processor time, what the wall "
      "clock would say if no other program shared the machine.\n\n",
      settings.engine_budget,
      settings.rounds > 1
          ? fmt::format("The engine's two measurements, (a) and (b) run {} times in "
                        "turn, the fastest of each kept (the machine's noise only ever "
                        "slows a run down); (c) once",
                        settings.rounds)
          : std::string("Each runs once"));
}

// The table: the engine, then each run, on each scene; and notes on how a
// run's collisions were counted.
std::string program_table(const ProgramFigures& figures) {
  std::string text =
      "| scene | N | run | T | collisions | wall time | its processor time | output | "
      "collisions/s | × engine | in processor time "
      "|\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  std::vector<std::string> notes;
  for (const EngineOnScene& engine : figures.engines) {
    const double reference = engine.per_second();
    text += fmt::format(
        "| `{}` | {} | the engine: section 1's event loop | — | {} | — | {} | — | {} | "
        "1 | 1 |\n",
        engine.scene, engine.balls,
        count_text(static_cast<double>(engine.loop.collisions)),
        seconds_text(engine.loop.seconds), count_text(reference));
    const double to_t = static_cast<double>(engine.collisions) / engine.wall_seconds;
    text += fmt::format(
        "| | | the engine from the scene file to T | {:g} | {} | {} | {} | — | {} | {} | "
        "{} |\n",
        engine.until, engine.collisions, seconds_text(engine.wall_seconds),
        seconds_text(engine.cpu_seconds), count_text(to_t), ratio_text(to_t, reference),
        ratio_text(static_cast<double>(engine.collisions) / engine.cpu_seconds,
                   reference));
    for (const ProgramRun& run : figures.runs) {
      if (run.scene != engine.scene) continue;
      const std::string what = fmt::format("({}) `{}`{}", run.label, run.command,
                                           run.label == 'a' ? "" : ", frames to a pipe");
      if (!run.child.succeeded()) {
        text += fmt::format("| | | {} | {:g} | failed: {} | — | — | — | — | — | — |\n",
                            what, run.until, cell_text(run.child.failure()));
        continue;
      }
      text += fmt::format(
          "| | | {} | {:g} | {} | {} | {} | {} | {} | {} | {} |\n", what, run.until,
          run.collisions >= 0 ? fmt::format("{}", run.collisions) : "not known",
          seconds_text(run.child.wall_seconds), seconds_text(run.child.cpu_seconds),
          bytes_text(run.child.output_bytes),
          run.per_second() > 0 ? count_text(run.per_second()) : "—",
          ratio_text(run.per_second(), reference),
          ratio_text(run.per_processor_second(), reference));
      if (run.collisions < 0 || run.count_note.find("but") != std::string::npos)
        notes.push_back(fmt::format("{} on `{}`: collisions counted from {}.", run.label,
                                    run.scene, run.count_note));
    }
  }
  text += "\n";
  for (const std::string& note : notes) text += fmt::format("- Run {}\n", note);
  if (!notes.empty()) text += "\n";
  return text;
}

// What the program adds to the engine, for each scene where (a) ran.
std::string program_costs(const ProgramFigures& figures) {
  std::string text;
  for (const EngineOnScene& engine : figures.engines) {
    const ProgramRun* none = figures.run(engine.scene, 'a');
    const ProgramRun* stats = figures.run(engine.scene, 'b');
    if (!none || !none->child.succeeded()) continue;
    // In processor time: the wall clock of a shared machine also counts the
    // other programs' turns.
    text += fmt::format(
        "`{}`: run (a) uses {:.2f} s of processor time against the engine's {:.2f} s "
        "for the same collisions from the same file ({:+.0f} %): what the program does "
        "beyond the event loop, starting included.",
        engine.scene, none->child.cpu_seconds, engine.cpu_seconds,
        100 * (none->child.cpu_seconds / engine.cpu_seconds - 1));
    if (stats && stats->child.succeeded())
      text += fmt::format(
          " Run (b), with the statistics, their CSV file and {} of frames, uses {:.2f} "
          "s ({:+.0f} % on run (a)).",
          bytes_text(stats->child.output_bytes), stats->child.cpu_seconds,
          100 * (stats->child.cpu_seconds / none->child.cpu_seconds - 1));
    text += "\n\n";
  }
  return text;
}

}  // namespace

std::string program_section(const ProgramSettings& settings,
                            const ProgramFigures& figures) {
  return "## 5. The program as users run it\n\n" + program_intro(settings) +
         program_table(figures) + program_costs(figures) +
         "The picture of section 1 sets these runs beside each way of stage 4.\n\n";
}

std::string program_targets(const ProgramSettings& settings,
                            const ProgramFigures& figures) {
  std::string rows;
  const ProgramScene& scene = settings.scenes.front();
  const EngineOnScene* engine = figures.engine(scene.name);
  for (const auto& [label, least, what] :
       {std::tuple{
            'a', 0.8,
            fmt::format("`build/gas {} --until {:g} --mode none`: at least 0.8x "
                        "the engine's collisions per processor second measured in the "
                        "same run",
                        scene.name, scene.until)},
        std::tuple{
            'b', 0.5,
            std::string("the same with `--mode stats --csv out.csv` and the frames "
                        "going to a pipe: at least 0.5x the engine")}}) {
    const ProgramRun* run = figures.run(scene.name, label);
    std::string measured;
    bool met = false;
    if (!run || !engine) {
      measured = "not measured";
    } else if (!run->child.succeeded()) {
      measured = fmt::format("not measured: the program failed ({})",
                             cell_text(run->child.failure()));
    } else if (run->per_second() <= 0) {
      measured = fmt::format("not measured: collisions not known ({})", run->count_note);
    } else {
      // Judged on the run's processor time, as the engine's figure is: the
      // wall clock of a shared machine also counts the other programs' turns.
      const double ratio = run->per_processor_second() / engine->per_second();
      const double to_t = static_cast<double>(engine->collisions) / engine->cpu_seconds;
      measured = fmt::format(
          "{:.2f}x the engine's {} collisions/s in processor time ({:.2f}x on the wall "
          "clock; {:.2f}x the engine's own run from the scene file to T; section 5)",
          ratio, count_text(engine->per_second()),
          run->per_second() / engine->per_second(), run->per_processor_second() / to_t);
      met = ratio >= least;
    }
    rows += fmt::format("| {} | {} | {} |\n", what, measured, yes_no(met));
  }
  return rows;
}

void write_program_csv(const fs::path& path, const ProgramFigures& figures) {
  std::ofstream file(path);
  if (!file) throw std::runtime_error(fmt::format("{}: cannot write", path.string()));
  file << "scene,balls,run,command,model_time,collisions,wall_seconds,cpu_seconds,"
          "output_bytes,collisions_per_second,engine_collisions_per_second,"
          "ratio_to_engine,status\n";
  for (const EngineOnScene& e : figures.engines) {
    const double reference = e.per_second();
    file << fmt::format(
        "{},{},engine,section 1's event loop,,{},,{:.6f},,{:.6g},{:.6g},1,ok\n", e.scene,
        e.balls, e.loop.collisions, e.loop.seconds, reference, reference);
    const double to_t = static_cast<double>(e.collisions) / e.wall_seconds;
    file << fmt::format(
        "{},{},engine to T,the event loop from the scene file,{:g},{},{:.6f},{:.6f},,"
        "{:.6g},{:.6g},{:.4g},ok\n",
        e.scene, e.balls, e.until, e.collisions, e.wall_seconds, e.cpu_seconds, to_t,
        reference, to_t / reference);
    for (const ProgramRun& r : figures.runs) {
      if (r.scene != e.scene) continue;
      const bool ok = r.child.succeeded();
      file << fmt::format(
          "{},{},{},{},{:g},{},{},{},{},{},{:.6g},{},{}\n", r.scene, r.balls, r.label,
          r.command, r.until, r.collisions >= 0 ? fmt::format("{}", r.collisions) : "",
          ok ? fmt::format("{:.6f}", r.child.wall_seconds) : "",
          ok ? fmt::format("{:.6f}", r.child.cpu_seconds) : "",
          ok ? fmt::format("{}", r.child.output_bytes) : "",
          r.per_second() > 0 ? fmt::format("{:.6g}", r.per_second()) : "", reference,
          r.per_second() > 0 ? fmt::format("{:.4g}", r.per_second() / reference) : "",
          ok                  ? "ok"
          : r.child.timed_out ? "stopped"
                              : "failed");
    }
  }
}

std::string random_scene_text(std::size_t count, unsigned seed) {
  const double area = static_cast<double>(count) * std::numbers::pi / 0.3;
  const double height = std::sqrt(area * 3 / 4), width = area / height;
  return fmt::format(
      "# A gas of {0} balls of radius 1 at random places on a 4:3 table, area\n"
      "# fraction 0.3 (written by gas-benchmark, in the style of "
      "data/large-10000.scene).\n"
      "a  1\nT0 1\nA1 {1:.2f}\nA2 {2:.2f}\nN  {0}\nrandom {0} {3} 1\n",
      count, width, height, seed);
}

}  // namespace gas::benchmark
