// Sections 2 and 3 of the report: accuracy against cost for the number
// type, and time reversal. See section_accuracy.hpp.
#include "section_accuracy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <type_traits>
#include <utility>

#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "engine.hpp"
#include "reference_gas.hpp"
#include "report_text.hpp"
#include "stage2_input.hpp"
#include "stage5_new_coordinates.hpp"
#include "stage7_control.hpp"
#include "time_stepped.hpp"

namespace gas::benchmark {
namespace {

using gas::reference::ReferenceGas;

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

// The stages themselves (double) on `gas`: their cost and energy drift over
// `drift` collisions, the deepest overlap at the end, and how long they agree
// with the 113-bit run.
TypeFigures stages_figures(const std::string& name, const Gas& gas, long long drift,
                           const std::vector<gas::reference::Event>& exact, int events) {
  TypeFigures stages{name, "stages (double)", 53};
  EventLoop loop(gas, strategy_for(gas.balls.size()));
  const double start_energy = kinetic_energy(gas);
  const double start = cpu_seconds();
  for (long long i = 0; i < drift; ++i) loop.step();
  stages.nanoseconds = 1e9 * cpu_since(start) / static_cast<double>(drift);
  stages.drift_collisions = drift;
  stages.energy_drift = std::fabs(kinetic_energy(loop.gas) - start_energy) / start_energy;
  double overlap = 0;
  for (std::size_t i = 0; i < gas.balls.size(); ++i) {
    for (std::size_t j = i + 1; j < gas.balls.size(); ++j) {
      const Point p = centre_at(loop.gas.balls[i], loop.gas.time);
      const Point q = centre_at(loop.gas.balls[j], loop.gas.time);
      overlap =
          std::max(overlap, 1 - std::hypot(p.x - q.x, p.y - q.y) / (2 * gas.radius));
    }
  }
  stages.largest_overlap = overlap;
  stages.horizon_events = agreement_up_to_ties(stage_events(gas, events), exact);
  stages.horizon_per_ball = stages.horizon_events / static_cast<double>(gas.balls.size());
  return stages;
}

// number-types.csv and number-types-distance.csv.
void write_type_csvs(const std::filesystem::path& out, const NumberTypeFigures& figures) {
  Csv csv(out / "number-types.csv",
          "scene,type,mantissa_bits,ns_per_collision,drift_collisions,energy_drift,"
          "largest_overlap,horizon_collisions,horizon_collisions_per_ball,"
          "trusted_collisions_per_ball");
  for (const TypeFigures& f : figures.types) {
    csv.row("{},{},{},{:.6g},{},{:.3g},{:.3g},{},{:.4g},{:.4g}", f.scene, f.type, f.bits,
            f.nanoseconds, f.drift_collisions, f.energy_drift, f.largest_overlap,
            f.horizon_events, f.horizon_per_ball, f.trusted_per_ball);
  }
  Csv distance_csv(out / "number-types-distance.csv",
                   "scene,type,collisions_per_ball,time,largest_error_in_radii");
  for (const DistanceRow& r : figures.distances)
    distance_csv.row("{},{},{:.4g},{:.6g},{:.4g}", r.scene, r.type, r.collisions_per_ball,
                     r.time, r.error);
}

// The exponent's error bar against independent gases: crowds of 48 random
// balls (the crowd's table, radius and speeds), one seed each; the spread
// of (lambda_s - their mean) / error_s should be about 1. Each seed has its
// own energy, and lambda scales with the speeds (the same paths, run c
// times as fast, have c times the exponent): lambda / v_rms is compared.
void measure_seeds(const Sizes& sizes, NumberTypeFigures& figures) {
  std::vector<ExponentFigures> seeds;
  for (int seed = 1; seed <= sizes.lyapunov_seeds; ++seed) {
    const Gas crowd_like = parse_scene(
        fmt::format("a 4\nT0 1\nA1 256\nA2 192\nrandom 48 {} 1.5\n", seed), "crowd-like");
    seeds.push_back(measure_exponent(fmt::format("seed {}", seed), crowd_like,
                                     sizes.lyapunov_samples));
    const double rms_speed = std::sqrt(2 * kinetic_energy(crowd_like) /
                                       static_cast<double>(crowd_like.balls.size()));
    seeds.back().per_time /= rms_speed;
    seeds.back().per_time_error /= rms_speed;
  }
  double mean = 0, spread = 0;
  int known = 0;
  for (const auto& e : seeds) mean += e.per_time / static_cast<double>(seeds.size());
  for (const auto& e : seeds) {
    if (std::isnan(e.per_time_error)) continue;
    const double z = (e.per_time - mean) / e.per_time_error;
    spread += z * z;
    ++known;
  }
  // The mean of the seeds is one of the terms: (n - 1) / n of the variance.
  spread = known > 1 ? std::sqrt(spread / known * static_cast<double>(seeds.size()) /
                                 static_cast<double>(seeds.size() - 1))
                     : std::numeric_limits<double>::quiet_NaN();
  progress("  the exponent's error bar over {} seeds: spread {:.2f}", seeds.size(),
           spread);
  figures.seeds = seeds.size();
  figures.seeds_mean = mean;
  figures.seeds_spread = spread;
}

// The Lyapunov exponent of each scene and the horizons it predicts, and its
// error bar; lyapunov.csv.
void measure_exponents(const Sizes& sizes, const std::filesystem::path& out,
                       NumberTypeFigures& figures) {
  for (const auto& [name, gas] : {std::pair{std::string("default"), default_gas()},
                                  std::pair{std::string("crowd"), crowd_gas()},
                                  std::pair{std::string("h-theorem"), h_theorem_gas()}}) {
    progress("  {}: the Lyapunov exponent, {} renormalisations", name,
             sizes.lyapunov_samples);
    figures.exponents.push_back(measure_exponent(name, gas, sizes.lyapunov_samples));
    figures.along.push_back(horizons_along_the_run(gas, 60));
  }
  measure_seeds(sizes, figures);
  Csv csv(out / "lyapunov.csv",
          "scene,lyapunov,lyapunov_error,per_collision_per_ball,"
          "per_collision_per_ball_error,samples,predicted_float,predicted_double,"
          "predicted_long_double,along_run_float,along_run_double,"
          "along_run_long_double");
  for (std::size_t i = 0; i < figures.exponents.size(); ++i) {
    const auto& e = figures.exponents[i];
    const auto& along = figures.along[i];
    csv.row("{},{:.6g},{:.3g},{:.6g},{:.3g},{},{:.4g},{:.4g},{:.4g},{:.4g},{:.4g},{:.4g}",
            e.scene, e.per_time, e.per_time_error, e.per_ball, e.per_ball_error,
            e.samples, e.single, e.twice, e.extended, along.single, along.twice,
            along.extended);
  }
}

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

}  // namespace

NumberTypeFigures measure_number_types(const Sizes& sizes,
                                       const std::filesystem::path& out) {
  progress("2/6 number types: float, double, long double against __float128");
  NumberTypeFigures figures;
  measure_exponents(sizes, out, figures);
  for (const auto& [name, gas, drift] :
       {std::tuple{std::string("default"), default_gas(), sizes.drift_collisions},
        std::tuple{std::string("crowd"), crowd_gas(), sizes.drift_collisions / 20}}) {
    const int events =
        name == "default" ? sizes.horizon_events : sizes.horizon_events / 2;
    progress("  {}: the 113-bit run, {} collisions", name, events);
    const auto exact = gas::reference::reference_events<__float128>(gas, events);
    auto& types = figures.types;
    progress("  {}: float", name);
    types.push_back(number_type<float>(name, gas, drift, exact, events));
    progress("  {}: double", name);
    types.push_back(number_type<double>(name, gas, drift, exact, events));
    progress("  {}: long double", name);
    types.push_back(number_type<long double>(name, gas, drift, exact, events));
    progress("  {}: __float128 (cost only)", name);
    types.push_back(number_type<__float128>(
        name, gas, std::max<long long>(drift / 500, 200), exact, events));
    types.push_back(stages_figures(name, gas, drift, exact, events));
    progress("  {}: distances from the 113-bit run", name);
    distances(name, gas, events, sizes.distance_samples, figures.distances, types);
  }
  write_type_csvs(out, figures);
  return figures;
}

namespace {

// Section 2's first table: every type's cost, drift, overlap and horizons.
std::string types_table(const NumberTypeFigures& figures) {
  std::string report;
  auto add = [&](const std::string& text) { report += text; };
  const auto& types = figures.types;
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
  return report;
}

// The distance from the 113-bit run as each run goes on, a table a scene.
std::string distance_tables(const NumberTypeFigures& figures,
                            const std::string& picture) {
  std::string report;
  auto add = [&](const std::string& text) { report += text; };
  const auto& distance_rows = figures.distances;
  const auto& distance_picture = picture;
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
  return report;
}

// The horizon the Lyapunov exponent predicts, beside the one measured.
std::string exponent_tables(const NumberTypeFigures& figures, const Sizes& sizes) {
  std::string report;
  auto add = [&](const std::string& text) { report += text; };
  const auto& types = figures.types;
  const auto& exponents = figures.exponents;
  const auto& along = figures.along;
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
      figures.seeds, figures.seeds, sizes.lyapunov_samples, figures.seeds_mean,
      figures.seeds_spread));

  return report;
}

}  // namespace

std::string number_types_section(const Sizes& sizes, const NumberTypeFigures& figures,
                                 const std::string& picture) {
  return types_table(figures) + distance_tables(figures, picture) +
         exponent_tables(figures, sizes);
}

std::vector<ReversalRow> measure_time_reversal(const Sizes& sizes,
                                               const std::filesystem::path& out) {
  progress("3/6 time reversal: forward k collisions per ball, B, back as long");
  std::vector<ReversalRow> reversal;
  {
    Csv csv(out / "time-reversal.csv",
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

  return reversal;
}

std::string time_reversal_section(const Sizes& sizes,
                                  const std::vector<ReversalRow>& reversal,
                                  const NumberTypeFigures& types) {
  std::string report;
  auto add = [&](const std::string& text) { report += text; };
  const auto& exponents = types.exponents;
  const auto& along = types.along;
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
      "gas over N; the statistics screen, lesson 12, counts a collision of two balls for "
      "both, about twice "
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

  return report;
}

}  // namespace gas::benchmark
