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
//   7. Checkpoints: a --dump of 10^3 to 10^6 balls written and read back,
//      timed as processes (dump_runs.hpp).
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
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <type_traits>
#include <vector>

#include "benchmark_build_info.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "dump_runs.hpp"
#include "engine.hpp"
#include "lyapunov_horizon.hpp"
#include "peer_runs.hpp"
#include "program/console.hpp"
#include "program_runs.hpp"
#include "reference_gas.hpp"
#include "report_pictures.hpp"
#include "report_text.hpp"
#include "stage2_input.hpp"
#include "stage5_new_coordinates.hpp"
#include "stage7_control.hpp"
#include "time_stepped.hpp"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using gas::Collision;
using gas::CollisionKind;
using gas::Gas;
using gas::Strategy;
using gas::benchmark::EventLoop;
using gas::benchmark::measure_throughput;
using gas::benchmark::ProgramFigures;
using gas::benchmark::ProgramScene;
using gas::benchmark::ProgramSettings;
using gas::benchmark::Throughput;
using gas::reference::ReferenceGas;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Processor time of this thread since `start` (a cpu_seconds() reading): all
// the measurements use it, so that other programs on the machine, taking
// turns on its cores, are not counted against ours.
using gas::benchmark::cpu_seconds;
double cpu_since(double start) {
  return cpu_seconds() - start;
}

using gas::benchmark::count_text;
using gas::benchmark::DistanceRow;
using gas::benchmark::progress;
using gas::benchmark::yes_no;

// ------------------------------------------------------------ settings

struct Settings {
  bool smoke = false;
  fs::path out = fs::path(GAS_SOURCE_DIR) / "data" / "reports";
  std::optional<fs::path> peer;  // a checkout of Graphical-EDMD (section 6)
};

// The sizes of each section: the full report, or a smoke run of seconds.
struct Sizes {
  std::vector<std::size_t> ball_counts;
  double seconds_per_point = 0;       // processor time of one throughput measurement
  std::size_t most_balls_scan = 0;    // the scan only up to here (it takes too long)
  std::size_t most_balls_table = 0;   // the table only up to here (its rebuild is N^2)
  std::size_t most_balls_sparse = 0;  // the sparse gases only up to here
  double seconds_default_scene = 0;   // per way, the default scene in take_step
  long long drift_collisions = 0;     // section 2: the energy-drift run
  int horizon_events = 0;             // section 2: events compared with the reference
  int distance_samples = 0;           // section 2: moments the distance is measured at
  std::vector<int> reversal_k;        // section 3: collisions per ball forward
  std::vector<int> h_theorem_k;       // section 3: the same for the H-theorem scene
  long long lyapunov_samples = 0;     // sections 2, 3: renormalisations of the exponent
  int lyapunov_seeds = 0;             // section 2: independent gases for its error bar
  std::size_t stepped_balls = 0;      // section 4
  double stepped_end = 0;             // section 4: model time of each run
  std::vector<double> stepped_dt;     // section 4: steps, in diameters per mean speed
  int program_rounds = 0;             // section 5: timed runs of each command
  double program_time_limit = 0;      // section 5: wall seconds before a run is stopped
};

Sizes sizes_for(bool smoke) {
  if (smoke) {
    return {.ball_counts = {7, 16, 64, 200},
            .seconds_per_point = 0.02,
            .most_balls_scan = 64,
            .most_balls_table = 200,
            .most_balls_sparse = 64,
            .seconds_default_scene = 0.05,
            .drift_collisions = 3000,
            .horizon_events = 300,
            .distance_samples = 10,
            .reversal_k = {1, 2},
            .h_theorem_k = {5},
            .lyapunov_samples = 100,
            .lyapunov_seeds = 3,
            .stepped_balls = 100,
            .stepped_end = 5,
            .stepped_dt = {0.5, 0.1},
            .program_rounds = 1,
            .program_time_limit = 60};
  }
  return {.ball_counts = {2,    3,    4,    5,     7,     10,    12,    16,  24,
                          32,   48,   64,   96,    128,   192,   256,   384, 512,
                          1000, 2000, 5000, 10000, 20000, 50000, 100000},
          .seconds_per_point = 1.0,
          .most_balls_scan = 2000,
          .most_balls_table = 20000,
          .most_balls_sparse = 2000,
          .seconds_default_scene = 2.0,
          .drift_collisions = 1'000'000,
          .horizon_events = 6000,
          .distance_samples = 200,
          .reversal_k = {1, 2, 3, 5, 8, 12, 20, 30, 50},
          .h_theorem_k = {5, 8, 10, 12, 15, 20},
          .lyapunov_samples = 2000,
          .lyapunov_seeds = 20,
          .stepped_balls = 2000,
          .stepped_end = 100,
          .stepped_dt = {0.5, 0.25, 0.1, 0.05, 0.02, 0.01},
          .program_rounds = 3,
          .program_time_limit = 600};
}

// ------------------------------------------------------------ scenes

// The two densities of section 1: the benchmark's gas, and a sparse one like
// the teaching scenes (the crowd covers 0.049 of its table).
constexpr double dense = 0.3, sparse = 0.05;

// N balls of radius 1 at random places (the scene keyword 'random') on a
// 4:3 table whose area makes the given area fraction; speeds 0.5 to 1.5.
Gas random_gas(std::size_t count, double fraction, std::uint64_t seed) {
  const double area = static_cast<double>(count) * std::numbers::pi / fraction;
  const double height = std::sqrt(area * 3 / 4), width = area / height;
  return gas::parse_scene(
      fmt::format("a 1\nT0 1\nA1 {:.17g}\nA2 {:.17g}\nrandom {} {} 1\n", width, height,
                  count, seed),
      fmt::format("random-{}", count));
}

Gas default_gas() {
  return gas::parse_scene(gas::default_scene_text, gas::default_scene_name);
}

Gas crowd_gas() {
  return gas::read_scene_file(std::string(GAS_SOURCE_DIR) + "/data/crowd.scene");
}

Gas h_theorem_gas() {
  return gas::read_scene_file(std::string(GAS_SOURCE_DIR) + "/data/h-theorem.scene");
}

// ------------------------------------------------------------ 1. throughput

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

// The default scene as the program runs it: take_step with its own T0 = 1,
// every display step a picture computed (shift_time), for `budget` seconds.
struct ProgramSpeed {
  std::string how;
  long long steps = 0, collisions = 0;
  double seconds = 0;
};

ProgramSpeed run_program_loop(const Gas& gas, std::optional<Strategy> strategy,
                              double budget) {
  gas::Control control = gas::start_control_for(gas, strategy);
  ProgramSpeed speed{strategy ? gas::strategy_name(*strategy) : "chosen by N"};
  const double start = cpu_seconds();
  while (true) {
    for (int i = 0; i < 1000; ++i) {
      speed.collisions += static_cast<long long>(
          gas::take_step(control, gas::never, nullptr).collisions.size());
    }
    speed.steps += 1000;
    speed.seconds = cpu_since(start);
    if (speed.seconds >= budget) break;
  }
  return speed;
}

// ------------------------------------------------------------ 2. number types

const char* type_name(int bits) {
  switch (bits) {
    case 24:
      return "float";
    case 53:
      return "double";
    case 64:
      return "long double";
    case 113:
      return "__float128";
  }
  return "?";
}

template <class Real>
constexpr int mantissa_bits() {
  if constexpr (std::is_same_v<Real, __float128>) {
    return 113;
  } else {
    return std::numeric_limits<Real>::digits;
  }
}

struct TypeFigures {
  std::string scene;
  std::string type;
  int bits = 0;
  double nanoseconds = 0;  // per collision, in the reference kernel
  long long drift_collisions = 0;
  double energy_drift = 0;     // |E - E0| / E0 after drift_collisions
  double largest_overlap = 0;  // deepest overlap seen (sampled), / 2a
  int horizon_events = -1;     // collisions in agreement with the 113-bit run
  double horizon_per_ball = -1;
  double trusted_per_ball = -1;  // collisions per ball until an error of a / 100
};

// The reference kernel's cost per collision in Real, and its energy drift
// and worst overlap over `count` collisions.
template <class Real>
void drift_and_cost(const Gas& gas, long long count, TypeFigures& figures) {
  ReferenceGas<Real> run(gas);
  const Real start_energy = run.energy();
  double overlap = 0;
  const double start = cpu_seconds();
  const long long sample = std::max<long long>(1, count / 1000);
  for (long long i = 1; i <= count; ++i) {
    run.step();
    if (i % sample == 0)
      overlap = std::max(overlap, static_cast<double>(run.largest_overlap()));
  }
  figures.nanoseconds = 1e9 * cpu_since(start) / static_cast<double>(count);
  figures.drift_collisions = count;
  figures.energy_drift =
      std::fabs(static_cast<double>((run.energy() - start_energy) / start_energy));
  figures.largest_overlap = overlap;
}

// How many leading collisions two runs share (K, N1, N2), where two
// collisions of different balls a hair apart in time (less than 1e-9 of T)
// may come in either order: which of two independent, all but simultaneous
// events is computed first says nothing about how well a run follows the
// motion. (The default scene has such a pair at T = 40: ball 5 at a wall and
// balls 3 and 4 meeting 3.6e-14 later.)
int agreement_up_to_ties(const std::vector<gas::reference::Event>& a,
                         const std::vector<gas::reference::Event>& b) {
  std::size_t i = 0;
  const std::size_t n = std::min(a.size(), b.size());
  while (i < n) {
    if (a[i] == b[i]) {
      ++i;
    } else if (i + 1 < n && a[i] == b[i + 1] && a[i + 1] == b[i] &&
               std::fabs(a[i + 1].time - a[i].time) <=
                   1e-9L * std::max(1.0L, std::fabs(a[i].time))) {
      i += 2;
    } else {
      break;
    }
  }
  return static_cast<int>(i);
}

// The stages' own collisions (double), as a list of reference events.
std::vector<gas::reference::Event> stage_events(const Gas& gas, int count) {
  EventLoop loop(gas, gas::strategy_for(gas.balls.size()));
  std::vector<gas::reference::Event> events;
  while (static_cast<int>(events.size()) < count) {
    const Collision c = loop.step();
    events.push_back({c.time, static_cast<int>(c.kind), c.first, c.second});
  }
  return events;
}

// The largest distance between the balls of two runs at the same moment, in
// radii.
// (The differences are taken in __float128, so that nothing of the
// smaller one is lost.)
template <class A>
double distance(const ReferenceGas<A>& a, const ReferenceGas<__float128>& b) {
  __float128 worst = 0;
  for (std::size_t i = 0; i < a.balls().size(); ++i) {
    const __float128 dx = static_cast<__float128>(a.balls()[i].x) - b.balls()[i].x;
    const __float128 dy = static_cast<__float128>(a.balls()[i].y) - b.balls()[i].y;
    worst = std::max(worst, gas::reference::root(dx * dx + dy * dy));
  }
  return static_cast<double>(worst / b.radius());
}

double distance_of_stages(const Gas& stages, const ReferenceGas<__float128>& exact) {
  __float128 worst = 0;
  for (std::size_t i = 0; i < stages.balls.size(); ++i) {
    const gas::Point p = gas::centre_at(stages.balls[i], stages.time);
    const __float128 dx = static_cast<__float128>(p.x) - exact.balls()[i].x;
    const __float128 dy = static_cast<__float128>(p.y) - exact.balls()[i].y;
    worst = std::max(worst, gas::reference::root(dx * dx + dy * dy));
  }
  return static_cast<double>(worst) / stages.radius;
}

// The distance of each type's run (and the stages') from the 113-bit run,
// sampled at `samples` moments up to the time of `events` reference
// collisions.
void distances(const std::string& name, const Gas& gas, int events, int samples,
               std::vector<DistanceRow>& rows, std::vector<TypeFigures>& figures) {
  // The time span: that of `events` collisions of the 113-bit run.
  ReferenceGas<__float128> probe(gas);
  for (int i = 0; i < events; ++i) probe.step();
  const double end = static_cast<double>(probe.time());
  const auto n = static_cast<double>(gas.balls.size());

  ReferenceGas<__float128> exact(gas);
  ReferenceGas<float> single(gas);
  ReferenceGas<double> twice(gas);
  ReferenceGas<long double> extended(gas);
  EventLoop stages(gas, gas::strategy_for(gas.balls.size()));
  long long exact_collisions = 0;
  std::map<std::string, double> trusted;
  for (int s = 1; s <= samples; ++s) {
    const double time = end * s / samples;
    // The 113-bit run, counting its collisions on the way.
    for (auto e = exact.next(); e.kind != 0 && exact.time() + e.dt <= time;
         e = exact.next()) {
      exact.advance(e.dt);
      exact.collide(e);
      ++exact_collisions;
    }
    exact.advance(time - exact.time());
    single.advance_to(time);
    twice.advance_to(time);
    extended.advance_to(time);
    stages.run_to(time);
    const double per_ball = static_cast<double>(exact_collisions) / n;
    const std::pair<const char*, double> errors[] = {
        {"float", distance(single, exact)},
        {"double", distance(twice, exact)},
        {"long double", distance(extended, exact)},
        {"stages (double)", distance_of_stages(stages.gas, exact)}};
    for (const auto& [type, error] : errors) {
      rows.push_back({name, type, per_ball, time, error});
      // Trusted while every ball is within a hundredth of a radius of where
      // the 113-bit run has it.
      if (error > 0.01 && !trusted.count(type)) trusted[type] = per_ball;
    }
  }
  for (TypeFigures& f : figures) {
    if (f.scene != name) continue;
    f.trusted_per_ball = trusted.count(f.type) ? trusted[f.type] : -1;
  }
}

template <class Real>
TypeFigures number_type(const std::string& name, const Gas& gas, long long drift_count,
                        const std::vector<gas::reference::Event>& exact, int events) {
  TypeFigures f{name, type_name(mantissa_bits<Real>()), mantissa_bits<Real>()};
  drift_and_cost<Real>(gas, drift_count, f);
  if constexpr (!std::is_same_v<Real, __float128>) {
    f.horizon_events =
        agreement_up_to_ties(gas::reference::reference_events<Real>(gas, events), exact);
    f.horizon_per_ball = f.horizon_events / static_cast<double>(gas.balls.size());
  }
  return f;
}

// ------------------------------------------------------------ 3. time reversal

struct ReversalRow {
  std::string scene, type;
  int per_ball;
  double time;   // T at which B is pressed
  double error;  // largest distance from the start after 2T, in radii
};

// Forward k collisions per ball (B halfway to the next collision, so that no
// pair is in contact), back as long; the largest distance of a ball from
// where it started.
template <class Real>
ReversalRow reverse_reference(const std::string& name, const Gas& gas, int k) {
  ReferenceGas<Real> run(gas);
  const auto count = static_cast<long long>(k) * static_cast<long long>(gas.balls.size());
  for (long long i = 0; i < count; ++i) run.step();
  run.advance(run.next().dt / 2);
  const Real turn = run.time();
  run.reverse();
  run.advance_to(2 * turn);
  // In Real itself, from the start as Real holds it (the run began from
  // those very numbers): the difference is the run's own error.
  Real worst = 0;
  for (std::size_t i = 0; i < gas.balls.size(); ++i) {
    const Real dx = run.balls()[i].x - Real(gas.balls[i].x);
    const Real dy = run.balls()[i].y - Real(gas.balls[i].y);
    worst = std::max(worst, gas::reference::root(dx * dx + dy * dy));
  }
  return {name, type_name(mantissa_bits<Real>()), k, static_cast<double>(turn),
          static_cast<double>(worst / Real(gas.radius))};
}

// The same with the stages and the B key (stage 7's press_key).
ReversalRow reverse_stages(const std::string& name, const Gas& gas, int k) {
  EventLoop probe(gas, gas::strategy_for(gas.balls.size()));
  const auto count = static_cast<long long>(k) * static_cast<long long>(gas.balls.size());
  double last = 0;
  for (long long i = 0; i < count; ++i) last = probe.step().time;
  const double turn = (last + probe.finder->first(probe.gas).time) / 2;
  Gas start = gas;
  start.display_step = 1e300;
  gas::Control control = gas::start_control_for(start);
  while (control.gas.time < turn) gas::take_step(control, turn, nullptr);
  gas::press_key(control, 'B');
  while (control.gas.time < 2 * turn) gas::take_step(control, 2 * turn, nullptr);
  double worst = 0;
  for (std::size_t i = 0; i < gas.balls.size(); ++i) {
    const gas::Point p = gas::centre_at(control.gas.balls[i], control.gas.time);
    worst = std::max(worst, std::hypot(p.x - gas.balls[i].x, p.y - gas.balls[i].y));
  }
  return {name, "stages (double)", k, turn, worst / gas.radius};
}

// ------------------------------------------------------------ 4. time steps

// The event-driven run of section 4, with the same figures as the
// time-stepped one, and the spread of its figures between ten equal stretches
// of time (how much a run this long is worth statistically).
struct EventDriven {
  gas::benchmark::GasRecord record;
  double collision_spread = 0;  // relative standard error of the collision count
  double impulse_spread = 0;    // ... of the wall impulse
};

EventDriven run_event_driven(const Gas& start, double end) {
  EventDriven result;
  gas::benchmark::GasRecord& r = result.record;
  const double began = cpu_seconds();
  EventLoop loop(start, gas::strategy_for(start.balls.size()));
  const double starting_energy = gas::kinetic_energy(start);
  constexpr int stretches = 10;
  double collisions[stretches] = {}, impulse[stretches] = {};
  for (Collision c = loop.finder->first(loop.gas);
       c.kind != CollisionKind::none && c.time <= end; c = loop.finder->first(loop.gas)) {
    const int stretch =
        std::min(stretches - 1, static_cast<int>(c.time / end * stretches));
    const gas::Ball& ball = loop.gas.balls[static_cast<std::size_t>(c.first - 1)];
    if (c.kind == CollisionKind::balls) {
      ++r.ball_collisions;
      ++collisions[stretch];
    } else {
      const double across = c.kind == CollisionKind::horizontal_wall ? ball.vy : ball.vx;
      r.wall_impulse += 2 * std::fabs(across);
      impulse[stretch] += 2 * std::fabs(across);
      ++r.wall_collisions;
    }
    loop.gas.time = c.time;
    gas::apply_collision(loop.gas, loop.limits, c);
    loop.finder->update(loop.gas, c);
  }
  r.seconds = cpu_since(began);
  r.energy_error =
      std::fabs(gas::kinetic_energy(loop.gas) - starting_energy) / starting_energy;
  // The standard error of a sum of `stretches` parts: sqrt(stretches) times
  // their standard deviation.
  auto spread = [&](const double* parts, double total) {
    double mean = total / stretches, square = 0;
    for (int i = 0; i < stretches; ++i) square += (parts[i] - mean) * (parts[i] - mean);
    return std::sqrt(square / (stretches - 1)) * std::sqrt(double{stretches}) / total;
  };
  result.collision_spread = spread(collisions, static_cast<double>(r.ball_collisions));
  result.impulse_spread = spread(impulse, r.wall_impulse);
  return result;
}

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

// ------------------------------------------------------------ writing

class Csv {
 public:
  Csv(const fs::path& path, const std::string& header) : file_(path) {
    if (!file_) throw std::runtime_error(fmt::format("{}: cannot write", path.string()));
    file_ << header << '\n';
  }
  template <class... Args>
  void row(fmt::format_string<Args...> format, Args&&... args) {
    file_ << fmt::format(format, std::forward<Args>(args)...) << '\n';
  }

 private:
  std::ofstream file_;
};

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

int run(const Settings& settings) {
  const Sizes sizes = sizes_for(settings.smoke);
  fs::create_directories(settings.out);
  const auto began = Clock::now();
  // The memory first, while nothing else of ours is in the caches.
  std::string read_waits_text;
  for (const std::size_t mebibytes : {1, 4, 16, 64}) {
    const double wait = read_wait_ns(mebibytes << 20, settings.smoke);
    read_waits_text +=
        fmt::format("{}{:.0f} ns", read_waits_text.empty() ? "" : " / ", wait);
  }
  progress("memory: one read at random among 1 / 4 / 16 / 64 MiB: {}", read_waits_text);
  std::string report;
  auto add = [&](const std::string& text) { report += text; };

  // ---- 1. throughput
  progress("1/5 throughput: {} sizes of random gas at area fraction 0.3",
           sizes.ball_counts.size());
  std::vector<Throughput> throughput;
  {
    Csv csv(settings.out / "throughput.csv",
            "area_fraction,strategy,balls,collisions,cpu_seconds,collisions_per_second,"
            "ns_per_collision,setup_seconds");
    for (const double fraction : {dense, sparse}) {
      for (const std::size_t n : sizes.ball_counts) {
        if (fraction == sparse && n > sizes.most_balls_sparse) continue;
        const Gas gas = random_gas(n, fraction, 1989 + n);
        for (const Strategy strategy :
             {Strategy::scan, Strategy::table, Strategy::grid}) {
          if (strategy == Strategy::scan && n > sizes.most_balls_scan) continue;
          if (strategy == Strategy::table && n > sizes.most_balls_table) continue;
          Throughput t = measure_throughput(gas, strategy, sizes.seconds_per_point);
          t.fraction = fraction;
          throughput.push_back(t);
          csv.row("{},{},{},{},{:.6f},{:.6g},{:.6g},{:.6f}", fraction,
                  gas::strategy_name(strategy), n, t.collisions, t.seconds,
                  t.per_second(), t.nanoseconds(), t.setup_seconds);
          progress(
              "  {:>5} N = {:>6} (area fraction {}): {:>10} collisions/s, {:.0f} ns each",
              gas::strategy_name(strategy), n, fraction, count_text(t.per_second()),
              t.nanoseconds());
        }
      }
    }
  }
  auto cost = [&](Strategy s, std::size_t n, double fraction) -> double {
    for (const Throughput& t : throughput)
      if (t.strategy == s && t.balls == n && t.fraction == fraction)
        return t.nanoseconds();
    return 0;
  };
  struct Crossovers {
    double scan_to_table, scan_to_grid, table_to_grid;
  };
  auto crossovers = [&](double fraction) {
    return Crossovers{crossover(throughput, fraction, Strategy::scan, Strategy::table),
                      crossover(throughput, fraction, Strategy::scan, Strategy::grid),
                      crossover(throughput, fraction, Strategy::table, Strategy::grid)};
  };
  const Crossovers at_dense = crossovers(dense), at_sparse = crossovers(sparse);

  progress("  the default scene as the program runs it (take_step, T0 = 1)");
  std::vector<ProgramSpeed> program;
  {
    const Gas seven = default_gas();
    // Ten rounds, the ways in turn, and each way's best round kept: the
    // machine's noise (other programs' use of the caches, frequency changes)
    // only ever slows a run down.
    std::map<std::string, ProgramSpeed> best;
    const std::vector<std::optional<Strategy>> ways = {std::nullopt, Strategy::scan,
                                                       Strategy::table, Strategy::grid};
    constexpr int rounds = 10;
    for (int round = 0; round < rounds; ++round) {
      for (const auto& way : ways) {
        const ProgramSpeed s =
            run_program_loop(seven, way, sizes.seconds_default_scene / rounds);
        auto& kept = best[s.how];
        if (kept.steps == 0 || s.steps / s.seconds > kept.steps / kept.seconds) kept = s;
      }
    }
    Csv csv(settings.out / "default-scene.csv",
            "strategy,steps,collisions,seconds,steps_per_second,collisions_per_second");
    for (const auto& way : ways) {
      const ProgramSpeed& s = best[way ? gas::strategy_name(*way) : "chosen by N"];
      program.push_back(s);
      csv.row("{},{},{},{:.6f},{:.6g},{:.6g}", s.how, s.steps, s.collisions, s.seconds,
              s.steps / s.seconds, s.collisions / s.seconds);
    }
  }

  // ---- 2. number types
  progress("2/5 number types: float, double, long double against __float128");
  std::vector<TypeFigures> types;
  std::vector<DistanceRow> distance_rows;
  // The Lyapunov exponent of each scene, and the horizons it predicts.
  std::vector<gas::benchmark::ExponentFigures> exponents;
  std::vector<gas::benchmark::Horizons> along;  // the same, along the run from T = 0
  for (const auto& [name, gas] : {std::pair{std::string("default"), default_gas()},
                                  std::pair{std::string("crowd"), crowd_gas()},
                                  std::pair{std::string("h-theorem"), h_theorem_gas()}}) {
    progress("  {}: the Lyapunov exponent, {} renormalisations", name,
             sizes.lyapunov_samples);
    exponents.push_back(
        gas::benchmark::measure_exponent(name, gas, sizes.lyapunov_samples));
    along.push_back(gas::benchmark::horizons_along_the_run(gas, 60));
  }
  // The exponent's error bar against independent gases: crowds of 48 random
  // balls (the crowd's table, radius and speeds), one seed each; the spread
  // of (lambda_s - their mean) / error_s should be about 1. Each seed has its
  // own energy, and lambda scales with the speeds (the same paths, run c
  // times as fast, have c times the exponent): lambda / v_rms is compared.
  std::vector<gas::benchmark::ExponentFigures> seeds;
  for (int seed = 1; seed <= sizes.lyapunov_seeds; ++seed) {
    const Gas crowd_like = gas::parse_scene(
        fmt::format("a 4\nT0 1\nA1 256\nA2 192\nrandom 48 {} 1.5\n", seed), "crowd-like");
    seeds.push_back(gas::benchmark::measure_exponent(fmt::format("seed {}", seed),
                                                     crowd_like, sizes.lyapunov_samples));
    const double rms_speed = std::sqrt(2 * gas::kinetic_energy(crowd_like) /
                                       static_cast<double>(crowd_like.balls.size()));
    seeds.back().per_time /= rms_speed;
    seeds.back().per_time_error /= rms_speed;
  }
  double seeds_mean = 0, seeds_spread = 0;
  {
    int known = 0;
    for (const auto& e : seeds)
      seeds_mean += e.per_time / static_cast<double>(seeds.size());
    for (const auto& e : seeds) {
      if (std::isnan(e.per_time_error)) continue;
      const double z = (e.per_time - seeds_mean) / e.per_time_error;
      seeds_spread += z * z;
      ++known;
    }
    // The mean of the seeds is one of the terms: (n - 1) / n of the variance.
    seeds_spread =
        known > 1 ? std::sqrt(seeds_spread / known * static_cast<double>(seeds.size()) /
                              static_cast<double>(seeds.size() - 1))
                  : std::numeric_limits<double>::quiet_NaN();
    progress("  the exponent's error bar over {} seeds: spread {:.2f}", seeds.size(),
             seeds_spread);
  }
  {
    Csv csv(settings.out / "lyapunov.csv",
            "scene,lyapunov,lyapunov_error,per_collision_per_ball,"
            "per_collision_per_ball_error,samples,predicted_float,predicted_double,"
            "predicted_long_double,along_run_float,along_run_double,"
            "along_run_long_double");
    for (std::size_t i = 0; i < exponents.size(); ++i) {
      const auto& e = exponents[i];
      csv.row(
          "{},{:.6g},{:.3g},{:.6g},{:.3g},{},{:.4g},{:.4g},{:.4g},{:.4g},{:.4g},{:.4g}",
          e.scene, e.per_time, e.per_time_error, e.per_ball, e.per_ball_error, e.samples,
          e.single, e.twice, e.extended, along[i].single, along[i].twice,
          along[i].extended);
    }
  }
  {
    const Gas seven = default_gas(), crowd = crowd_gas();
    for (const auto& [name, gas, drift] :
         {std::tuple{std::string("default"), seven, sizes.drift_collisions},
          std::tuple{std::string("crowd"), crowd, sizes.drift_collisions / 20}}) {
      const int events =
          name == "default" ? sizes.horizon_events : sizes.horizon_events / 2;
      progress("  {}: the 113-bit run, {} collisions", name, events);
      const auto exact = gas::reference::reference_events<__float128>(gas, events);
      progress("  {}: float", name);
      types.push_back(number_type<float>(name, gas, drift, exact, events));
      progress("  {}: double", name);
      types.push_back(number_type<double>(name, gas, drift, exact, events));
      progress("  {}: long double", name);
      types.push_back(number_type<long double>(name, gas, drift, exact, events));
      progress("  {}: __float128 (cost only)", name);
      types.push_back(number_type<__float128>(
          name, gas, std::max<long long>(drift / 500, 200), exact, events));
      // The stages themselves, in double.
      TypeFigures stages{name, "stages (double)", 53};
      {
        EventLoop loop(gas, gas::strategy_for(gas.balls.size()));
        const double start_energy = gas::kinetic_energy(gas);
        const double start = cpu_seconds();
        for (long long i = 0; i < drift; ++i) loop.step();
        stages.nanoseconds = 1e9 * cpu_since(start) / static_cast<double>(drift);
        stages.drift_collisions = drift;
        stages.energy_drift =
            std::fabs(gas::kinetic_energy(loop.gas) - start_energy) / start_energy;
        double overlap = 0;
        for (std::size_t i = 0; i < gas.balls.size(); ++i) {
          for (std::size_t j = i + 1; j < gas.balls.size(); ++j) {
            const gas::Point p = gas::centre_at(loop.gas.balls[i], loop.gas.time);
            const gas::Point q = gas::centre_at(loop.gas.balls[j], loop.gas.time);
            overlap = std::max(overlap,
                               1 - std::hypot(p.x - q.x, p.y - q.y) / (2 * gas.radius));
          }
        }
        stages.largest_overlap = overlap;
        stages.horizon_events = agreement_up_to_ties(stage_events(gas, events), exact);
        stages.horizon_per_ball =
            stages.horizon_events / static_cast<double>(gas.balls.size());
      }
      types.push_back(stages);
      progress("  {}: distances from the 113-bit run", name);
      distances(name, gas, events, sizes.distance_samples, distance_rows, types);
    }
    Csv csv(settings.out / "number-types.csv",
            "scene,type,mantissa_bits,ns_per_collision,drift_collisions,energy_drift,"
            "largest_overlap,horizon_collisions,horizon_collisions_per_ball,"
            "trusted_collisions_per_ball");
    for (const TypeFigures& f : types) {
      csv.row("{},{},{},{:.6g},{},{:.3g},{:.3g},{},{:.4g},{:.4g}", f.scene, f.type,
              f.bits, f.nanoseconds, f.drift_collisions, f.energy_drift,
              f.largest_overlap, f.horizon_events, f.horizon_per_ball,
              f.trusted_per_ball);
    }
    Csv distance_csv(settings.out / "number-types-distance.csv",
                     "scene,type,collisions_per_ball,time,largest_error_in_radii");
    for (const DistanceRow& r : distance_rows)
      distance_csv.row("{},{},{:.4g},{:.6g},{:.4g}", r.scene, r.type,
                       r.collisions_per_ball, r.time, r.error);
  }

  // ---- 3. time reversal
  progress("3/5 time reversal: forward k collisions per ball, B, back as long");
  std::vector<ReversalRow> reversal;
  {
    Csv csv(settings.out / "time-reversal.csv",
            "scene,type,collisions_per_ball,turn_time,return_error_in_radii");
    for (const auto& [name, gas] : {std::pair{std::string("default"), default_gas()},
                                    std::pair{std::string("crowd"), crowd_gas()}}) {
      for (const int k : sizes.reversal_k) {
        progress("  {}: k = {}", name, k);
        reversal.push_back(reverse_reference<float>(name, gas, k));
        reversal.push_back(reverse_reference<double>(name, gas, k));
        reversal.push_back(reverse_reference<long double>(name, gas, k));
        if (name == "default" || k <= 20)
          reversal.push_back(reverse_reference<__float128>(name, gas, k));
        reversal.push_back(reverse_stages(name, gas, k));
      }
    }
    // The H-theorem scene: 1024 balls, the stages only (the reference kernel
    // is O(N^2) a collision).
    for (const int k : sizes.h_theorem_k) {
      progress("  h-theorem: k = {}", k);
      reversal.push_back(reverse_stages("h-theorem", h_theorem_gas(), k));
    }
    for (const ReversalRow& r : reversal)
      csv.row("{},{},{},{:.6g},{:.4g}", r.scene, r.type, r.per_ball, r.time, r.error);
  }

  // ---- 4. time steps
  progress("4/5 a fixed time step against the events: {} balls to T = {}",
           sizes.stepped_balls, sizes.stepped_end);
  const Gas stepped_gas = random_gas(sizes.stepped_balls, 0.2, 7);
  const EventDriven events = run_event_driven(stepped_gas, sizes.stepped_end);
  std::vector<std::pair<double, gas::benchmark::GasRecord>> stepped;
  {
    const double mean_speed = gas::mean_speed(stepped_gas);
    for (const double per_diameter : sizes.stepped_dt) {
      const double dt = per_diameter * 2 * stepped_gas.radius / mean_speed;
      progress("  dt = {:.3g} ({} of a diameter at the mean speed)", dt, per_diameter);
      stepped.push_back({per_diameter, gas::benchmark::run_time_stepped(
                                           stepped_gas, dt, sizes.stepped_end)});
    }
    Csv csv(settings.out / "time-stepping.csv",
            "method,dt_in_diameters,steps,seconds,ball_collisions,wall_collisions,"
            "wall_impulse,energy_error,largest_overlap");
    auto row = [&](const std::string& method, double per,
                   const gas::benchmark::GasRecord& r) {
      csv.row("{},{},{},{:.6f},{},{},{:.9g},{:.3g},{:.4g}", method, per, r.steps,
              r.seconds, r.ball_collisions, r.wall_collisions, r.wall_impulse,
              r.energy_error, r.largest_overlap);
    };
    row("event-driven", 0, events.record);
    for (const auto& [per, r] : stepped) row("time-stepped", per, r);
  }

  // ---- 5. the program as users run it, beside the engine
  const ProgramSettings program_settings = program_settings_for(settings, sizes);
  const ProgramFigures program_runs = gas::benchmark::measure_program(program_settings);
  gas::benchmark::write_program_csv(settings.out / "program.csv", program_runs);
  fs::remove_all(program_settings.scratch);

  // ---- 6. beside the best peer, and a million balls
  const gas::benchmark::PeerSettings peer_settings = peer_settings_for(settings, sizes);
  const gas::benchmark::PeerFigures peer_runs =
      gas::benchmark::measure_peer(peer_settings);
  gas::benchmark::write_peer_csv(settings.out / "peer.csv", peer_runs);
  fs::remove_all(peer_settings.scratch);

  // ---- 7. checkpoints: a dump written and read back
  const std::string dumps =
      gas::benchmark::dump_report(settings.smoke, settings.out, sizes.program_time_limit);

  // ---- the pictures
  progress("pictures: gnuplot");
  const std::string throughput_picture = gas::benchmark::picture_markdown(
      gas::benchmark::throughput_figure(settings.out, throughput, {dense, sparse},
                                        program_runs),
      "Collisions per second against N, log-log: each way of stage 4 at area fraction "
      "0.3 and 0.05, and the program");
  const std::string distance_picture = gas::benchmark::picture_markdown(
      gas::benchmark::distance_figure(settings.out, distance_rows),
      "The distance from the 113-bit run against collisions per ball, "
      "for each number type");

  // ---- the report
  progress("writing {}", (settings.out / "speed-against-error.md").string());
  const double grid_at_10k = cost(Strategy::grid, 10000, dense) > 0
                                 ? 1e9 / cost(Strategy::grid, 10000, dense)
                                 : 0;
  const double grid_growth =
      cost(Strategy::grid, 1000, dense) > 0 && cost(Strategy::grid, 100000, dense) > 0
          ? cost(Strategy::grid, 100000, dense) / cost(Strategy::grid, 1000, dense)
          : 0;
  const ProgramSpeed& chosen = program[0];
  const ProgramSpeed& scanned = program[1];
  const double default_ratio =
      (chosen.steps / chosen.seconds) / (scanned.steps / scanned.seconds);

  add("# Speed against error\n\n");
  add(fmt::format(
      "Written by `gas-benchmark`{} on {}. Regenerate it (from the top of the "
      "repository, minutes) with:\n\n"
      "```sh\napt-get update && apt-get install -y gnuplot-nox && cmake -S . -B build && "
      "cmake --build build -j2 --target gas gas-benchmark && "
      "build/tests/benchmark/gas-benchmark\n```\n\n"
      "(gnuplot draws the two pictures; without it the report has none.)\n\n",
      settings.smoke ? " --smoke (tiny sizes: a test of the benchmark, not a measurement)"
                     : "",
      now_utc()));
  add("| the machine and the build | |\n|---|---|\n");
  add(fmt::format("| CPU | {} ({} hardware threads; one used) |\n", cpu_model(),
                  std::thread::hardware_concurrency()));
  add(fmt::format("| memory | {} |\n", memory()));
  add(fmt::format("| compiler | {} (`{}`) |\n", GAS_CXX_COMPILER, __VERSION__));
  add(fmt::format("| build type | {} |\n", GAS_BUILD_TYPE));
  add(fmt::format("| flags | `{}` |\n", GAS_CXX_FLAGS));
  add(fmt::format("| run time | {:.0f} s |\n", seconds_since(began)));
  add(fmt::format(
      "| one read from memory, at random among 1 / 4 / 16 / 64 MiB | {} |\n\n",
      read_waits_text));
  if (std::string(GAS_BUILD_TYPE) != "Release")
    add("**Not a Release build: the times below do not measure the program.**\n\n");
  add("The CSV files beside this report hold every number measured; the tables "
      "below are chosen rows.\n\n");

  // Targets first: the headline.
  add("## Targets\n\n| target | measured | |\n|---|---|---|\n");
  add(fmt::format(
      "| the grid at N = 10^4, area fraction 0.3: at least 2 million "
      "collisions per second | {} | {} |\n",
      grid_at_10k > 0 ? count_text(grid_at_10k) + " collisions/s" : "not measured",
      yes_no(grid_at_10k >= 2e6)));
  add(fmt::format(
      "| the cost per collision grows at most 2x from N = 10^3 to N = 10^5 "
      "(grid) | {} | {} |\n",
      grid_growth > 0 ? fmt::format("{:.2f}x ({:.0f} ns to {:.0f} ns)", grid_growth,
                                    cost(Strategy::grid, 1000, dense),
                                    cost(Strategy::grid, 100000, dense))
                      : "not measured",
      yes_no(grid_growth > 0 && grid_growth <= 2)));
  add(fmt::format(
      "| the default scene runs no slower than with the article's scan | {:.3f} of "
      "the scan's display steps per second (the program keeps the scan for 7 balls) | "
      "{} |\n",
      default_ratio, yes_no(default_ratio >= 0.97)));
  add(gas::benchmark::program_targets(program_settings, program_runs));
  add(gas::benchmark::peer_targets(peer_runs));
  add("\n");
  add("(\"No slower\" allows 3 %: two runs of the very same code differ by that much "
      "on a shared machine.)\n\n");
  if (grid_at_10k < 2e6 || grid_growth > 2) {
    add("Why the grid falls short here: it does the same work per collision at every N "
        "— about 6 predictions, 1.3 cell crossings, 3.5 moves of a key in the calendar "
        "— but each event happens somewhere else on the table, so the rows, records "
        "and calendar entries it needs are at scattered places in memory, some 20 "
        "cache lines a collision. Up to about 10^4 balls (some 100 bytes each) they "
        "stay in the processor's caches; at 10^5 they come from main memory, and each "
        "read waits as long as the machine table's last figure says (measured as this "
        "report began; other programs sharing the cache change it from run to run). "
        "The cost per collision grows although the work does not.\n\n");
  }

  // 1.
  add("## 1. Throughput\n\n");
  add(fmt::format(
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
      sizes.most_balls_table));
  add("| N | dense: scan | table | grid | sparse: scan | table | grid |\n"
      "|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const std::size_t n : sizes.ball_counts) {
    std::string line = fmt::format("| {} |", n);
    for (const double fraction : {dense, sparse}) {
      for (const Strategy s : {Strategy::scan, Strategy::table, Strategy::grid}) {
        const double c = cost(s, n, fraction);
        line += c > 0 ? fmt::format(" {} ({:.0f} ns) |", count_text(1e9 / c), c) : " — |";
      }
    }
    add(line + "\n");
  }
  add("\n" + throughput_picture +
      "(The program's points: `build/gas` itself on the large scenes of section 5, "
      "timed as a process.)\n");
  auto at = [](double n) {
    if (n < 0) return fmt::format("N = {:.0f} (the smallest measured)", -n);
    return n > 0 ? fmt::format("N ≈ {:.0f}", n) : std::string("nowhere measured");
  };
  add(fmt::format(
      "\nThe scan costs about N²/2 predictions per collision, the table about 2N, the "
      "grid a handful whatever N (its calendar too); what grows with N is the wait for "
      "memory. In a sparse gas the grid does more cell crossings per collision. "
      "Crossovers (interpolated on log N), dense "
      "and sparse: the table beats the scan from {} and {}; the grid beats the scan "
      "from {} and {}, and the table from {} and {}. `gas` keeps the article's scan up "
      "to {} balls, the table up to {}, and the grid beyond (`strategy_for` in "
      "`stages/beyond/strategy.hpp`): the scan for a handful on purpose, so that "
      "`--trace` on the teaching scenes shows the article's own stage 4 (any way "
      "takes well under a microsecond a collision there); the table while it "
      "beats the grid on a sparse gas.\n\n",
      at(at_dense.scan_to_table), at(at_sparse.scan_to_table), at(at_dense.scan_to_grid),
      at(at_sparse.scan_to_grid), at(at_dense.table_to_grid), at(at_sparse.table_to_grid),
      gas::most_balls_for_scan, gas::most_balls_for_table));
  add("The default scene as `gas` runs it (`take_step` with T0 = 1: a picture's "
      "centres at every display step), the best of ten rounds:\n\n"
      "| stage 4 | display steps/s | collisions/s |\n|---|---:|---:|\n");
  for (const ProgramSpeed& s : program) {
    add(fmt::format("| {} | {} | {} |\n", s.how, count_text(s.steps / s.seconds),
                    count_text(s.collisions / s.seconds)));
  }
  add("\n");

  // 2.
  add("## 2. Accuracy against cost for the number type\n\n");
  add("The reference kernel of `tests/reference_gas.hpp` (the one suite `high-precision` "
      "uses: every ball moved at every event, the textbook root) in each number type, "
      "and "
      "the stages themselves (double, each ball's row written only at its collisions). "
      "The trajectory of the 113-bit `__float128` run is the reference. *Cost*: "
      "nanoseconds per collision of the kernel (O(N²) per collision: compare types, not "
      "programs). *Energy drift*: |E − E0| / E0 after the collisions shown. *Overlap*: "
      "the deepest overlap of two balls seen (sampled), as a fraction of 2a. *Same "
      "collisions*: how many collisions (K, N1, N2 in order) agree with the 113-bit run, "
      "per ball. *Trusted*: collisions per ball until some ball is a hundredth of a "
      "radius from where the 113-bit run has it.\n\n");
  add("| scene | type | bits | cost (ns) | collisions | energy drift | overlap | same "
      "collisions per ball | trusted per ball "
      "|\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const TypeFigures& f : types) {
    add(fmt::format("| {} | {} | {} | {:.0f} | {} | {:.2g} | {:.2g} | {} | {} |\n",
                    f.scene, f.type, f.bits, f.nanoseconds,
                    count_text(f.drift_collisions), f.energy_drift, f.largest_overlap,
                    f.horizon_per_ball >= 0 ? fmt::format("{:.1f}", f.horizon_per_ball)
                                            : "(the reference)",
                    f.trusted_per_ball >= 0 ? fmt::format("{:.1f}", f.trusted_per_ball)
                    : f.bits == 113         ? "(the reference)"
                                            : "beyond the run"));
  }
  add("\nThe distance from the 113-bit run as the run goes on (the largest distance of "
      "a ball from where the 113-bit run has it, in radii; every sample is in "
      "`number-types-distance.csv`):\n\n");
  for (const std::string scene : {"default", "crowd"}) {
    add(fmt::format(
        "Scene `{}`:\n\n| collisions per ball | float | double | long double | "
        "stages (double) |\n|---:|---:|---:|---:|---:|\n",
        scene));
    double shown = -1;  // the sample last shown (coarse samples may serve two marks)
    for (const double mark : {1.0, 2.0, 5.0, 10.0, 15.0, 20.0, 30.0, 40.0}) {
      // The first sample at or past the mark.
      std::string line;
      double reached = -1;
      for (const char* type : {"float", "double", "long double", "stages (double)"}) {
        for (const DistanceRow& r : distance_rows) {
          if (r.scene == scene && r.type == type && r.collisions_per_ball >= mark) {
            line += fmt::format(" {:.2g} |", r.error);
            reached = r.collisions_per_ball;
            break;
          }
        }
      }
      if (reached >= 0 && reached != shown)
        add(fmt::format("| {:.1f} |{}\n", reached, line));
      shown = reached;
    }
    add("\n");
  }
  add(distance_picture);
  add("The error grows geometrically, by a roughly constant factor per collision of "
      "two balls: each bit of mantissa buys a fixed number of collisions, so the "
      "trusted horizon grows in proportion to the bits, and no precision makes it "
      "infinite.\n\n");
  // The horizon the Lyapunov exponent predicts, beside the one measured.
  add("The factor is the largest Lyapunov exponent lambda (lesson 15), measured by "
      "the stages with the tangent dynamics of `stages/beyond/lyapunov.hpp` "
      "(renormalisations shown; `lyapunov.csv`). Collisions a ball are counted as "
      "above: every collision of the gas (walls and pairs), over N. An error of one "
      "unit in the last place of the coordinates, eps = 2^(floor(log2 max(A1, A2)) "
      "− digits + 1), grows as e^(lambda t) and reaches a hundredth of a radius after "
      "ln(a / (100 eps)) / lambda: the *predicted* trusted horizon, in collisions a "
      "ball, beside the *measured* one of the table above. Two predictions: from "
      "lambda, the average over a long run (what the statistics screen shows), and "
      "*along the run*: from the growth of one change followed from T = 0 along "
      "this very stretch of the motion, which a start far from equilibrium or the "
      "short stretch of a few balls makes differ from the average.\n\n");
  add("| scene | lambda per unit time | per collision a ball | renormalisations | float: "
      "predicted / along the run / measured | double | long double "
      "|\n|---|---:|---:|---:|---:|---:|---:|\n");
  auto measured_trusted = [&](const std::string& scene, const char* type) {
    for (const TypeFigures& f : types)
      if (f.scene == scene && f.type == type && f.trusted_per_ball >= 0)
        return fmt::format("{:.1f}", f.trusted_per_ball);
    return std::string(scene == "h-theorem" ? "not run" : "beyond the run");
  };
  auto with_error = [](double value, double error, const char* format) {
    const std::string shown = fmt::format(fmt::runtime(format), value);
    return std::isnan(error) ? shown + " (error not known)"
                             : shown + fmt::format(" ± {:.2g}", error);
  };
  for (std::size_t i = 0; i < exponents.size(); ++i) {
    const auto& e = exponents[i];
    add(fmt::format(
        "| {} | {} | {} | {} | {:.1f} / {:.1f} / {} | {:.1f} / {:.1f} / {} | "
        "{:.1f} / {:.1f} / {} |\n",
        e.scene, with_error(e.per_time, e.per_time_error, "{:.4g}"),
        with_error(e.per_ball, e.per_ball_error, "{:.3g}"), e.samples, e.single,
        along[i].single, measured_trusted(e.scene, "float"), e.twice, along[i].twice,
        measured_trusted(e.scene, "double"), e.extended, along[i].extended,
        measured_trusted(e.scene, "long double")));
  }
  add("\n(The H-theorem scene's 1024 balls are not run against the 113-bit kernel, "
      "whose every collision costs O(N²); section 3 measures its horizon by B.)\n\n");
  add(fmt::format(
      "The exponent's error bar, checked on {} independent gases like the crowd (48 "
      "random balls of radius 4 on the 256 × 192 table, `random 48 SEED 1.5`, "
      "SEED = 1 … {}, {} renormalisations each; each seed's lambda divided by its rms "
      "speed, which differs from seed to seed): lambda / v_rms {:.4g} per unit length "
      "on average, and the spread of (lambda_s − mean) / error_s is {:.2f} (1 for "
      "honest error bars; the mean's own share taken out).\n\n",
      seeds.size(), seeds.size(), sizes.lyapunov_samples, seeds_mean, seeds_spread));

  // 3.
  add("## 3. Time reversal\n\n");
  add("Run forward k collisions per ball, press B halfway to the next collision, run "
      "back as long: a perfect computation returns every ball to its start. The return "
      "error is the largest distance of a ball from its start, in radii (lesson 9).\n\n");
  for (const std::string scene : {"default", "crowd"}) {
    add(
        fmt::format("Scene `{}`:\n\n| k per ball | float | double | long double | "
                    "__float128 | stages (double) |\n|---:|---:|---:|---:|---:|---:|\n",
                    scene));
    for (const int k : sizes.reversal_k) {
      std::string line = fmt::format("| {} |", k);
      for (const char* type :
           {"float", "double", "long double", "__float128", "stages (double)"}) {
        std::string cell = " — |";
        for (const ReversalRow& r : reversal)
          if (r.scene == scene && r.per_ball == k && r.type == type)
            cell = fmt::format(" {:.2g} |", r.error);
        line += cell;
      }
      add(line + "\n");
    }
    add("\n");
  }
  add("Scene `h-theorem` (1024 balls; the stages only, the reference kernel being "
      "O(N²) a collision):\n\n| k per ball | stages (double) |\n|---:|---:|\n");
  for (const ReversalRow& r : reversal)
    if (r.scene == "h-theorem")
      add(fmt::format("| {} | {:.2g} |\n", r.per_ball, r.error));
  add("\n");
  add("An error that grows to the size of the table means the gas did not come back: "
      "the reversed run parted from the forward one somewhere on the way.\n\n");
  // How far back B brings the gas: predicted by the exponent, and measured.
  add("How far back B brings the gas, predicted and measured. The return error is "
      "that of the forward run at the turn, made when B is pressed, and grown "
      "again on the way back, e^(lambda t) eps: the prediction is the trusted "
      "horizon of section 2, ln(a / (100 eps)) / lambda collisions a ball for the "
      "stages' double (k counts collisions as section 2 does: every collision of the "
      "gas over N; lesson 12 counts a collision of two balls for both, about twice "
      "as many in the H-theorem scene). Measured: the largest k of the tables whose "
      "return error (stages, double) is below a hundredth of a radius, and the next "
      "k tried.\n\n"
      "| scene | predicted (double) | along the run | measured: back from | not from |\n"
      "|---|---:|---:|---:|---:|\n");
  for (std::size_t i = 0; i < exponents.size(); ++i) {
    const auto& e = exponents[i];
    int back = 0, not_back = 0;
    for (const ReversalRow& r : reversal) {
      if (r.scene != e.scene || r.type != "stages (double)") continue;
      if (r.error < 0.01 && not_back == 0) back = r.per_ball;
      if (r.error >= 0.01 && not_back == 0) not_back = r.per_ball;
    }
    add(fmt::format("| {} | {:.1f} | {:.1f} | {} | {} |\n", e.scene, e.twice,
                    along[i].twice, back > 0 ? fmt::format("{}", back) : "—",
                    not_back > 0 ? fmt::format("{}", not_back) : "—"));
  }
  add("\n");

  // 4.
  const double pressure_scale =
      1 / (sizes.stepped_end * 2 * (stepped_gas.width + stepped_gas.height));
  add("## 4. What an event-driven program buys\n\n");
  add(fmt::format(
      "{} balls (random, radius 1, area fraction 0.2, mean speed {:.3f}) run to model "
      "time {} two ways: the stages' event-driven loop (stage 4 by the {}), and the "
      "fixed time step a newcomer writes first (`tests/benchmark/time_stepped.cpp`: "
      "move every ball by v dt, reverse a velocity past a wall, exchange the velocity "
      "components of overlapping, approaching pairs; a grid finds the pairs). dt is "
      "given as the fraction of a diameter a ball of mean speed travels in one step. "
      "Pressure: the impulse given to the walls per unit time and length. The "
      "event-driven run's own statistical spread (ten stretches of its time): ±{:.1f} % "
      "in collisions, ±{:.1f} % in pressure.\n\n",
      sizes.stepped_balls, gas::mean_speed(stepped_gas), sizes.stepped_end,
      gas::strategy_name(gas::strategy_for(sizes.stepped_balls)),
      100 * events.collision_spread, 100 * events.impulse_spread));
  add("| method | dt | run time (s) | ball collisions | error | pressure | error | "
      "energy error | deepest overlap "
      "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  const auto& ev = events.record;
  add(fmt::format("| event-driven | — | {:.3f} | {} | — | {:.5g} | — | {:.1g} | 0 |\n",
                  ev.seconds, ev.ball_collisions, ev.wall_impulse * pressure_scale,
                  ev.energy_error));
  for (const auto& [per, r] : stepped) {
    add(fmt::format(
        "| time-stepped | {} | {:.3f} | {} | {:+.1f} % | {:.5g} | {:+.1f} % | {:.1g} | "
        "{:.2f} |\n",
        per, r.seconds, r.ball_collisions,
        100.0 * (static_cast<double>(r.ball_collisions) / ev.ball_collisions - 1),
        r.wall_impulse * pressure_scale, 100 * (r.wall_impulse / ev.wall_impulse - 1),
        r.energy_error, r.largest_overlap));
  }
  add("\nBoth conserve energy to rounding: exchanging velocity components along the "
      "line of centres keeps it whatever the positions. What the time step gets wrong "
      "is *what happened*: collisions seen late (balls up to |v| dt inside each "
      "other), counted at the wrong moments, or missed, and with them the pressure.\n\n");

  // 5.
  add(gas::benchmark::program_section(program_settings, program_runs));

  // 6.
  add(gas::benchmark::peer_section(peer_settings, peer_runs));

  // 7.
  add(dumps);

  {
    std::ofstream file(settings.out / "speed-against-error.md");
    if (!file)
      throw std::runtime_error(fmt::format("{}: cannot write", settings.out.string()));
    file << report;
  }
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
