// Section 6 of the report: build/gas beside the best peer. See peer_runs.hpp.
#include "peer_runs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "engine.hpp"
#include "report_text.hpp"

namespace gas::benchmark {
namespace {

namespace fs = std::filesystem;

// The peer's gas is hotter than the scenes' (its start: kT = 1, a mean
// square speed of 2 against the scenes' 1.08), so it collides about 1.36
// times as often in a unit of model time: its runs are that much shorter,
// for about as many collisions.
constexpr double peer_time_scale = 1 / 1.36;

std::string read_text(const fs::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string first_line(const std::string& text) {
  return text.substr(0, text.find('\n'));
}

// The commit a checkout is at: .git/HEAD, and the branch it names.
std::string commit_of(const fs::path& checkout) {
  const fs::path git = checkout / ".git";
  const std::string head = first_line(read_text(git / "HEAD"));
  if (head.rfind("ref: ", 0) != 0) return head.empty() ? "unknown" : head;
  const std::string ref = head.substr(5);
  const std::string loose = first_line(read_text(git / ref));
  if (!loose.empty()) return loose;
  std::istringstream packed(read_text(git / "packed-refs"));
  for (std::string line; std::getline(packed, line);) {
    if (line.size() > 41 && line.substr(41) == ref) return line.substr(0, 40);
  }
  return "unknown";
}

// Ball-ball collisions of the engine from the scene's start to model time
// `end` (what build/gas does on the scene, drawn or not).
long long ball_collisions_to(const Gas& start, double end) {
  EventLoop loop(start, strategy_for(start.balls.size()));
  long long balls = 0;
  for (Collision c = loop.finder->first(loop.gas);
       c.kind != CollisionKind::none && c.time <= end; c = loop.finder->first(loop.gas)) {
    loop.gas.time = c.time;
    apply_collision(loop.gas, loop.limits, c);
    loop.finder->update(loop.gas, c);
    balls += c.kind == CollisionKind::balls;
  }
  return balls;
}

// The scene's gas as the peer's --load reads it: "N Lx Ly", then a line
// "type x y radius mass" a ball (type 1, the large discs; radius a, mass 1).
void write_peer_start(const Gas& gas, const fs::path& path) {
  std::ofstream file(path);
  file << fmt::format("{} {} {}\n", gas.balls.size(), gas.width, gas.height);
  for (const Ball& ball : gas.balls) {
    const Point centre = centre_at(ball, gas.time);
    file << fmt::format("1 {} {} {} 1\n", centre.x, centre.y, gas.radius);
  }
}

// The peer's count of collisions: the last "n° coll = 1.23e+06" it printed
// (three digits: the count is known to 0.5 %).
long long peer_collisions(const std::string& output) {
  const std::string mark = "coll = ";
  const std::size_t at = output.rfind(mark);
  if (at == std::string::npos) return -1;
  std::size_t start = at + mark.size();
  if (start < output.size() && output[start] == '\033')
    start = output.find('m', start) + 1;
  try {
    return static_cast<long long>(std::stod(output.substr(start, 16)));
  } catch (const std::exception&) {
    return -1;
  }
}

double rate(long long long_count, long long short_count, const ChildRun& long_run,
            const ChildRun& short_run) {
  const double seconds = long_run.cpu_seconds - short_run.cpu_seconds;
  return seconds > 0 ? static_cast<double>(long_count - short_count) / seconds : 0;
}

// One round of build/gas with `extra` arguments on a scene: long and short.
void time_gas(const PeerSettings& settings, const PeerRow& row,
              const std::vector<std::string>& extra, RatePairs& pairs) {
  ChildRun runs[2];
  const double untils[2] = {row.until, row.until / 10};
  for (int i = 0; i < 2; ++i) {
    std::vector<std::string> arguments = {row.scene, "--until",
                                          fmt::format("{}", untils[i])};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    runs[i] = run_child(settings.program, arguments, "", settings.time_limit);
    if (!runs[i].succeeded()) {
      pairs.failure = runs[i].failure();
      return;
    }
  }
  pairs.max_rss_kb = std::max(pairs.max_rss_kb, runs[0].max_rss_kb);
  pairs.rates.push_back(rate(row.collisions, row.short_collisions, runs[0], runs[1]));
}

// One round of the peer on a scene: long and short, from its start file.
void time_peer(const PeerSettings& settings, const PeerRow& row, RatePairs& pairs) {
  ChildRun runs[2];
  long long counts[2] = {0, 0};
  const double untils[2] = {row.peer_until, row.peer_until / 10};
  for (int i = 0; i < 2; ++i) {
    // In the scratch folder: it writes its files under dump/ where it runs.
    const std::string command = fmt::format(
        "cd '{}' && exec '{}' --load peer-{}.txt -t {} -D {} -o {} > peer.out",
        settings.scratch.string(), (*settings.peer / "a.out").string(), row.balls,
        untils[i], untils[i], untils[i]);
    runs[i] = run_child("/bin/sh", {"-c", command}, "", settings.time_limit);
    counts[i] = peer_collisions(read_text(settings.scratch / "peer.out"));
    // (Its main returns 1 at a normal end.)
    if (!runs[i].started || runs[i].timed_out || runs[i].signal != 0 || counts[i] < 0) {
      pairs.failure =
          runs[i].started ? "no collision count in its output" : runs[i].error;
      return;
    }
  }
  pairs.max_rss_kb = std::max(pairs.max_rss_kb, runs[0].max_rss_kb);
  pairs.rates.push_back(rate(counts[0], counts[1], runs[0], runs[1]));
}

std::string rate_text(const RatePairs& pairs) {
  if (!pairs.failure.empty() && pairs.rates.empty()) return "failed";
  return pairs.rates.empty() ? "not run" : count_text(pairs.median());
}

const PeerRow* row_with(const PeerFigures& figures, std::size_t balls) {
  for (const PeerRow& row : figures.rows)
    if (row.balls == balls) return &row;
  return nullptr;
}

// The section's table: a row for each N.
std::string peer_table(const PeerSettings& settings, const PeerFigures& figures) {
  std::string text;
  text +=
      "| N | `--mode none` | `--events` | its cost | peer | ratio | largest memory | "
      "bytes a ball | cost a collision against 10^3 |\n"
      "|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  const double first_rate = figures.rows.front().plain.median();
  for (const PeerRow& row : figures.rows) {
    const double plain = row.plain.median(), events = row.events.median(),
                 peer = row.peer.median();
    const double bytes = bytes_per_ball(figures, row);
    text += fmt::format(
        "| {} | {} | {} | {} | {} | {} | {:.1f} MB | {} | {} |\n", row.balls,
        rate_text(row.plain), rate_text(row.events),
        plain > 0 && events > 0 ? fmt::format("{:+.0f} %", 100 * (plain / events - 1))
                                : "—",
        figures.peer_run && row.balls <= settings.peer_most_balls ? rate_text(row.peer)
                                                                  : "not run",
        plain > 0 && peer > 0 ? fmt::format("{:.2f}x", plain / peer) : "—",
        static_cast<double>(row.plain.max_rss_kb) / 1024.0,
        bytes > 0 ? fmt::format("{:.0f}", bytes) : "—",
        plain > 0 && first_rate > 0 ? fmt::format("{:.2f}x", first_rate / plain) : "—");
  }
  return text;
}

}  // namespace

double bytes_per_ball(const PeerFigures& figures, const PeerRow& row,
                      RatePairs PeerRow::*way) {
  const PeerRow& first = figures.rows.front();
  const long long first_kb = (first.*way).max_rss_kb, kb = (row.*way).max_rss_kb;
  if (&row == &first || kb == 0 || first_kb == 0) return 0;
  return 1024.0 * static_cast<double>(kb - first_kb) /
         static_cast<double>(row.balls - first.balls);
}

double RatePairs::median() const {
  if (rates.empty()) return 0;
  std::vector<double> sorted = rates;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
}

PeerFigures measure_peer(const PeerSettings& settings) {
  PeerFigures figures;
  fs::create_directories(settings.scratch);
  if (!settings.peer) {
    figures.peer_build = "no checkout given (gas-benchmark --peer DIR)";
  } else {
    figures.peer_commit = commit_of(*settings.peer);
    progress("6/6 the peer: make -C {}", settings.peer->string());
    const ChildRun make =
        run_child("make", {"-C", settings.peer->string()}, "", settings.time_limit);
    figures.peer_run = make.succeeded() && fs::exists(*settings.peer / "a.out");
    figures.peer_build = figures.peer_run ? "`make` (its Makefile's target EDMD)"
                                          : "its `make` failed: " + make.failure();
  }
  for (const fs::path& scene : settings.scenes) {
    const Gas gas = read_scene_file(scene.string());
    PeerRow row;
    row.scene = scene.string();
    row.balls = gas.balls.size();
    // Ball collisions per unit of model time: about 0.44 a ball (area
    // fraction 0.3, the scenes' speeds).
    row.until = settings.collisions_per_run / (0.44 * static_cast<double>(row.balls));
    row.peer_until = row.until * peer_time_scale;
    row.collisions = ball_collisions_to(gas, row.until);
    row.short_collisions = ball_collisions_to(gas, row.until / 10);
    progress("6/6 {}: {} ball collisions to T = {}", row.scene, row.collisions,
             row.until);
    row.plain.command = fmt::format("build/gas {} --until {} --mode none",
                                    scene.filename().string(), row.until);
    row.events.command = row.plain.command + " --events FILE";
    row.plain_grid.command = row.plain.command + " --strategy plain-grid";
    row.stats.command = fmt::format("build/gas {} --until {} --mode stats --csv FILE",
                                    scene.filename().string(), row.until);
    row.peer.command =
        fmt::format("a.out --load START -t {0} -D {0} -o {0}", row.peer_until);
    if (figures.peer_run && row.balls <= settings.peer_most_balls)
      write_peer_start(gas, settings.scratch / fmt::format("peer-{}.txt", row.balls));
    figures.rows.push_back(row);
  }
  const std::string events = (settings.scratch / "events.csv").string();
  const std::string csv = (settings.scratch / "stats.csv").string();
  for (int round = 1; round <= settings.rounds; ++round) {
    for (PeerRow& row : figures.rows) {
      progress("6/6 round {} of {}: {} balls", round, settings.rounds, row.balls);
      time_gas(settings, row, {"--mode", "none"}, row.plain);
      time_gas(settings, row, {"--mode", "none", "--strategy", "plain-grid"},
               row.plain_grid);
      time_gas(settings, row, {"--mode", "none", "--events", events}, row.events);
      if (row.balls >= settings.stats_least_balls)
        time_gas(settings, row, {"--mode", "stats", "--csv", csv}, row.stats);
      if (figures.peer_run && row.balls <= settings.peer_most_balls)
        time_peer(settings, row, row.peer);
    }
  }
  std::error_code ignored;
  fs::remove(events, ignored);
  fs::remove(csv, ignored);
  return figures;
}

std::string peer_section(const PeerSettings& settings, const PeerFigures& figures) {
  std::string text =
      "## 6. Beside the best peer, and a million balls\n\n"
      "`build/gas` as a process beside **Graphical-EDMD** "
      "(github.com/Syrocco/Graphical-EDMD, a C program of the same kind: 2D hard "
      "discs, event-driven, cell lists, a tree and a buffer of events), ";
  if (figures.peer_run) {
    text += fmt::format(
        "at commit `{}`, built with its own Makefile ({}: `gcc -O3 -ffast-math`), "
        "run from the very centres of each scene (`--load`, a file written from the "
        "scene's gas) as `{}` (START the centres; -D and -o put its one "
        "picture and one row of figures at the end).\n\n",
        figures.peer_commit, figures.peer_build, figures.rows.front().peer.command);
  } else {
    text += fmt::format("**not run**: {}.\n\n", figures.peer_build);
  }
  text +=
      "(To run it: `git clone https://github.com/Syrocco/Graphical-EDMD /tmp/peer`, "
      "then `build/tests/benchmark/gas-benchmark --peer /tmp/peer`; it needs `make` "
      "and `gcc`.)\n\n";
  text += fmt::format(
      "Ball-ball collisions per second of each process's own processor time (user + "
      "system, by wait4), the fixed costs (reading, placing, the first predictions, "
      "the peer's files) removed by a run a tenth as long; the median of {} rounds, "
      "the runs of both programs interleaved in each round so that a load on the "
      "machine falls on both. Each long run does about {} ball collisions.\n\n",
      settings.rounds, count_text(settings.collisions_per_run));
  text += peer_table(settings, figures);
  for (const PeerRow& row : figures.rows) {
    if (row.stats.rates.empty() && row.stats.failure.empty()) continue;
    text += fmt::format(
        "\nAt N = {}, `{}`: {} ball collisions per processor second, {} of the plain "
        "run's.\n",
        row.balls, row.stats.command, rate_text(row.stats),
        row.plain.median() > 0 && row.stats.median() > 0
            ? fmt::format("{:.2f}x", row.stats.median() / row.plain.median())
            : "—");
  }
  text +=
      "\nThe memory is the process's largest resident set (VmHWM, read every 20 ms while "
      "it runs); bytes a "
      "ball is its growth from the smallest scene, per ball added (the rows of R, the "
      "picture's centres, stage 4's books, and what the reading and placing of the "
      "scene held at once).\n\n"
      "What is not like for like: the peer's box is periodic (no walls: every event "
      "is a collision or a cell crossing; `build/gas` has walls, about 1 event in 20 "
      "at N = 10^3, fewer beyond); its start gives each disc a Maxwellian velocity at "
      "kT = 1 (a gas 1.36x faster than the scenes' speeds of 0.5 to 1.5: its runs are "
      "that much shorter in model time, for as many collisions); it is compiled with "
      "-ffast-math (the compiler may reorder sums: `build/gas` may not, it promises "
      "the article's scan bit for bit); its collision count is the three digits it "
      "prints (0.5 %). Both run on one core.\n\n"
      "The ratios at 10^4 and 10^5 depend on the machine's caches and memory as much "
      "as on the two programs: the peer waits for memory more than `build/gas` does. "
      "On a quiet machine whose reads among 4 MiB took 16 ns they were 1.18x, 1.40x "
      "and 2.50x at 10^3, 10^4 and 10^5; in the report of 2026-12-02, whose reads "
      "among 4 MiB took 182 ns, 1.22x, 2.67x and 3.73x (this report's reads: its "
      "machine table).\n\n";
  for (const PeerRow& row : figures.rows) {
    for (const RatePairs* pairs :
         {&row.plain, &row.events, &row.stats, &row.peer, &row.plain_grid})
      if (!pairs->failure.empty())
        text += fmt::format("A run failed at N = {} (`{}`): {}\n\n", row.balls,
                            pairs->command, pairs->failure);
  }
  return text;
}

std::string peer_targets(const PeerFigures& figures) {
  std::string text;
  std::string ratios;
  bool ahead = figures.peer_run;
  for (const PeerRow& row : figures.rows) {
    if (row.peer.rates.empty()) continue;
    const double ratio = row.plain.median() / row.peer.median();
    ratios +=
        fmt::format("{}{:.2f}x at {}", ratios.empty() ? "" : ", ", ratio, row.balls);
    ahead = ahead && ratio > 1;
  }
  // (How far ahead depends on the machine's memory as much as on the
  // programs: section 6 says so, with the ratios of other machines.)
  text += fmt::format(
      "| `build/gas --mode none` ahead of Graphical-EDMD at N = 10^3, 10^4, 10^5, same "
      "run (section 6) | {} | {} |\n",
      ratios.empty() ? "not run" : ratios, ratios.empty() ? "—" : yes_no(ahead));
  double worst = 0;
  for (const PeerRow& row : figures.rows)
    if (row.plain.median() > 0 && row.events.median() > 0)
      worst = std::max(worst, row.plain.median() / row.events.median() - 1);
  text += fmt::format(
      "| `--events` costs at most 15 % over the run without it (section 6) | at most "
      "{:+.0f} % | {} |\n",
      100 * worst,
      worst <= 0.15 ? yes_no(true)
                    : std::string("**open**: a line costs some 470 instructions and its "
                                  "share of the writing, about a sixth of a collision at "
                                  "10^3 (callgrind); what is left beyond 15 % is not "
                                  "found yet"));
  const PeerRow* million = row_with(figures, 1000000);
  if (million != nullptr && million->plain.median() > 0) {
    const double bytes = bytes_per_ball(figures, *million);
    text += fmt::format(
        "| N = 10^6: at most 100 bytes a ball (section 6) | {:.0f} bytes | {} |\n", bytes,
        yes_no(bytes <= 100));
    if (million->stats.median() > 0) {
      const double kept_stats = million->stats.median() / million->plain.median();
      text += fmt::format(
          "| N = 10^6: `--mode stats --csv` at least 0.5x the plain run (section 6) | "
          "{:.2f}x | {} |\n",
          kept_stats, yes_no(kept_stats >= 0.5));
    }
  }
  return text;
}

void write_peer_csv(const fs::path& path, const PeerFigures& figures) {
  std::ofstream file(path);
  file << "balls,run,round,ball_collisions_per_cpu_second,max_rss_kb\n";
  for (const PeerRow& row : figures.rows) {
    const std::pair<const char*, const RatePairs*> runs[] = {
        {"none", &row.plain},
        {"events", &row.events},
        {"stats", &row.stats},
        {"peer", &row.peer},
        {"plain-grid", &row.plain_grid}};
    for (const auto& [name, pairs] : runs)
      for (std::size_t i = 0; i < pairs->rates.size(); ++i)
        file << fmt::format("{},{},{},{:.0f},{}\n", row.balls, name, i + 1,
                            pairs->rates[i], pairs->max_rss_kb);
  }
}

}  // namespace gas::benchmark
