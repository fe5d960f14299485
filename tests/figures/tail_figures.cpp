// gas-tail-figures: lesson 16 in pictures, from runs of build/gas.
//
// Runs the program itself (build/gas, as a child process, two at a time),
// reads the files it writes (--vacf, --dump), and draws with gnuplot
// (tests/benchmark/plots.hpp) three pictures for lessons/16-long-time-tail.md,
// with the numbers behind each as CSV:
//
//   vacf.svg        rho(t) on log-log axes, four gases of data/long-time-tail.scene
//                   (seeds 1970 ... 1973) averaged, beside Enskog's exponential
//                   and the mode-coupling tail
//   t-rho.svg       t rho(t) over the mode-coupling value (1 for the pure tail)
//   diffusion.svg   D(t) over Enskog's D_E against ln t
//
// and two checks, in summary.csv and independent.csv:
//
//   - the initial slope, (1 - rho) / (1 - exp(-t / tau_E)) at the first lags,
//     and t rho(t) over mode coupling averaged over 20 ... 40 tau_E;
//   - the function computed again, independently, from --dump files: 10^5
//     balls at area fraction 0.3 (data/large-100000.scene) run to T = 50 and
//     dumped, then from the dump to T = 250 with --vacf; and along the same
//     path (a dump continues exactly, bit for bit) a chain of runs that dump
//     the gas at origins 8 tau_E apart and at nine lags after each, from
//     which this program sums v(0) . v(t) itself over the balls at least the
//     same margin from every wall. The two estimates share the trajectory
//     but not the origins: they agree within their combined errors.
//
// The errors of the four seeds are checked against their spread (the rms of
// (rho_seed - mean of the others) / combined error, in summary.csv).
//
// Usage:  gas-tail-figures [--out DIR] [--smoke] [--keep]
//   --out     where to write (default: data/reports/long-time-tail of the source tree)
//   --smoke   small gases, short runs, no pictures (the test suite runs this)
//   --keep    reuse the runs whose files are in DIR already (tail-SEED.csv,
//             independent-program.csv, independent-samples.csv): to redraw
// About six processor-minutes (two cores: three to four minutes); progress on
// standard error. Beyond the article.
// Lesson: lessons/16-long-time-tail.md ("The pictures").
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "beyond/enskog_transport.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/velocity_autocorrelation.hpp"
#include "child_process.hpp"
#include "plots.hpp"

namespace fs = std::filesystem;
using gas::benchmark::Panel;
using gas::benchmark::Picture;
using gas::benchmark::Series;

namespace {

constexpr double pi = std::numbers::pi;
constexpr int processes = 2;  // runs at a time: the machine is shared

void say(const std::string& text) {
  fmt::print(stderr, "gas-tail-figures: {}\n", text);
}

// Runs build/gas with `arguments`; stops the program if it fails.
void run_gas(const std::vector<std::string>& arguments) {
  const auto run = gas::benchmark::run_child(GAS_PROGRAM, arguments, "", 7200);
  if (!run.succeeded()) {
    say(fmt::format("FAILED: {}: {}", fmt::join(arguments, " "), run.failure()));
    std::exit(1);
  }
  say(fmt::format("ran {} ({:.1f} s)", fmt::join(arguments, " "), run.cpu_seconds));
}

// The same without a line on standard error (the chain of dumps runs
// hundreds).
void run_quietly(const std::vector<std::string>& arguments) {
  const auto run = gas::benchmark::run_child(GAS_PROGRAM, arguments, "", 3600);
  if (!run.succeeded()) {
    say(fmt::format("FAILED: {}: {}", fmt::join(arguments, " "), run.failure()));
    std::exit(1);
  }
}

// Runs every argument list, `processes` at a time.
void run_all(const std::vector<std::vector<std::string>>& jobs) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) run_gas(jobs[i]);
  };
  std::vector<std::thread> threads;
  for (int p = 0; p < processes; ++p) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
}

double number(const std::string& text) {
  return std::strtod(text.c_str(), nullptr);
}

// A --vacf file's rows, by column.
struct VacfFile {
  std::vector<double> t, rho, rho_error, enskog, tail, d, d_error, d_enskog;
  double time_unit = 0;         // tau_E, from Enskog's exponential at the first lag
  double tail_coefficient = 0;  // t times the tail
  double diffusion = 0;         // D_E, Enskog's limit
};

VacfFile read_vacf(const fs::path& path) {
  VacfFile f;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::vector<double> x;
    std::stringstream s(line);
    for (std::string field; std::getline(s, field, ',');) x.push_back(number(field));
    if (x.size() != 8) continue;
    f.t.push_back(x[0]);
    f.rho.push_back(x[1]);
    f.rho_error.push_back(x[2]);
    f.enskog.push_back(x[3]);
    f.tail.push_back(x[4]);
    f.d.push_back(x[5]);
    f.d_error.push_back(x[6]);
    f.d_enskog.push_back(x[7]);
  }
  if (f.t.size() > 1) {
    f.time_unit = -f.t[1] / std::log(f.enskog[1]);
    f.tail_coefficient = f.t[1] * f.tail[1];
    f.diffusion = f.d_enskog[1] / -std::expm1(-f.t[1] / f.time_unit);
  }
  return f;
}

// The scene of data/long-time-tail.scene with another seed (and, for the
// smoke run, fewer balls on a table kept at area fraction 0.3).
fs::path tail_scene(const fs::path& work, int seed, int balls) {
  const double side = std::sqrt(balls * pi / 0.3);
  const fs::path path = work / fmt::format("tail-{}.scene", seed);
  std::ofstream(path) << fmt::format(
      "# gas-tail-figures: data/long-time-tail.scene, seed {0}\n"
      "a 1\nT0 1\nA1 {1:.2f}\nA2 {1:.2f}\nN {2}\nrandom {2} {0} 1\n",
      seed, balls == 100000 ? 1023.32 : side, balls);
  return path;
}

// The rows of several files of one plan (the same lags in units of tau_E),
// averaged. Two errors of the mean: from the files' own errors (each run's
// blocking over its origins), and from the files' spread about their mean;
// the larger is the one used. One run cannot see a slow flow of the whole
// table that outlasts it (a shear wave a table long decays in L^2 / nu, some
// 10^5 time units here): it shifts that run's rho at long lags by the same
// amount at every origin, and only the seeds' spread shows it. `spread`:
// the rms over the files of (rho - the others' mean) / (its own error and
// the others' mean's, from their errors), 1 when the runs' own errors hold.
struct Combined {
  std::vector<double> s;            // t / tau_E
  std::vector<double> rho;          // rho, averaged
  std::vector<double> own_error;    // its error from the runs' own errors
  std::vector<double> seeds_error;  // from their spread (nan with one file)
  std::vector<double> rho_error;    // the larger of the two
  std::vector<double> d, d_error;   // D / D_E, its error (the runs' own)
  std::vector<double> spread;       // see above (nan with fewer than 2 files)
};

Combined combine(const std::vector<VacfFile>& files) {
  Combined c;
  std::size_t rows = files[0].t.size();
  for (const VacfFile& f : files) rows = std::min(rows, f.t.size());
  const auto n = static_cast<double>(files.size());
  for (std::size_t k = 0; k < rows; ++k) {
    double s = 0, rho = 0, squares = 0, e2 = 0, d = 0, de2 = 0;
    for (const VacfFile& f : files) {
      s += f.t[k] / f.time_unit;
      rho += f.rho[k];
      squares += f.rho[k] * f.rho[k];
      e2 += f.rho_error[k] * f.rho_error[k];
      d += f.d[k] / f.diffusion;
      de2 += std::pow(f.d_error[k] / f.diffusion, 2);
    }
    const double mean = rho / n;
    c.s.push_back(s / n);
    c.rho.push_back(mean);
    c.own_error.push_back(std::sqrt(e2) / n);
    c.seeds_error.push_back(
        n > 1 ? std::sqrt(std::max(squares / n - mean * mean, 0.0) / (n - 1)) : NAN);
    c.rho_error.push_back(n > 1 ? std::max(c.own_error.back(), c.seeds_error.back())
                                : c.own_error.back());
    c.d.push_back(d / n);
    c.d_error.push_back(std::sqrt(de2) / n);
    double z2 = 0;
    int count = 0;
    for (std::size_t i = 0; i < files.size() && files.size() > 1; ++i) {
      double others = 0, others_e2 = 0;
      for (std::size_t j = 0; j < files.size(); ++j) {
        if (j == i) continue;
        others += files[j].rho[k];
        others_e2 += files[j].rho_error[k] * files[j].rho_error[k];
      }
      others /= n - 1;
      const double e2_i =
          std::pow(files[i].rho_error[k], 2) + others_e2 / ((n - 1) * (n - 1));
      if (!(e2_i > 0)) continue;
      z2 += std::pow(files[i].rho[k] - others, 2) / e2_i;
      ++count;
    }
    c.spread.push_back(count > 0 ? std::sqrt(z2 / count) : NAN);
  }
  return c;
}

// The two checks of a --vacf file, as lines of summary.csv: the initial
// slope, (1 - rho) / (1 - exp(-t / tau_E)) at each lag up to 0.1 tau_E (1
// if rho starts down Enskog's slope), and t rho(t) over mode coupling's
// value, averaged over the lags from 20 to 40 tau_E with weights 1 / error^2.
void summarize(const std::string& name, const std::vector<double>& s,
               const std::vector<double>& rho, const std::vector<double>& error,
               double alpha, std::ostream& summary) {
  for (std::size_t k = 1; k < s.size() && s[k] < 0.11; ++k) {
    const double enskog = -std::expm1(-s[k]);
    summary << fmt::format("{}_slope_ratio_at_{:.2f}_tau,{:.5f},{:.5f}\n", name, s[k],
                           (1 - rho[k]) / enskog, error[k] / enskog);
  }
  double sum = 0, weights = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k] < 19 || s[k] > 41 || !(error[k] > 0)) continue;
    const double w = 1 / std::pow(s[k] * error[k] / alpha, 2);
    sum += w * s[k] * rho[k] / alpha;
    weights += w;
  }
  summary << fmt::format("{}_t_vacf_over_tail_20_to_40_tau,{:.4f},{:.4f}\n", name,
                         sum / weights, 1 / std::sqrt(weights));
}

void draw(const Picture& picture, bool smoke) {
  if (smoke) return;
  const std::string why = gas::benchmark::draw(picture);
  say(why.empty() ? "drew " + picture.svg.string() : "no picture: " + why);
}

// --- The tail ---------------------------------------------------------------

void tail(const fs::path& out, const fs::path& work, bool smoke, bool keep) {
  const std::vector<int> seeds = smoke ? std::vector<int>{1970, 1971, 1972}
                                       : std::vector<int>{1970, 1971, 1972, 1973};
  const int balls = smoke ? 3000 : 100000;
  const std::string until = smoke ? "60" : "1000";
  std::vector<std::vector<std::string>> jobs;
  for (const int seed : seeds) {
    const fs::path file = out / fmt::format("tail-{}.csv", seed);
    if (keep && fs::exists(file)) continue;
    jobs.push_back({tail_scene(work, seed, balls).string(), "--mode", "none", "--until",
                    until, "--vacf", file.string()});
  }
  run_all(jobs);
  std::vector<VacfFile> files;
  for (const int seed : seeds)
    files.push_back(read_vacf(out / fmt::format("tail-{}.csv", seed)));
  const Combined c = combine(files);
  const VacfFile& f = files[0];

  const double alpha = f.tail_coefficient / f.time_unit;  // rho = alpha / (t / tau)
  std::ofstream csv(out / "tail.csv");
  csv << "t_over_tau,vacf,vacf_error,vacf_own_error,vacf_seeds_error,vacf_enskog,"
         "vacf_tail,t_vacf_over_tail,t_vacf_over_tail_error,diffusion_over_enskog,"
         "diffusion_over_enskog_error,seeds_spread\n";
  for (std::size_t k = 0; k < c.s.size(); ++k) {
    csv << fmt::format(
        "{:.6g},{:.9g},{:.3g},{:.3g},{:.3g},{:.9g},{:.6g},{:.6g},{:.3g},{:.6g},{:.3g},{:."
        "3g}\n",
        c.s[k], c.rho[k], c.rho_error[k], c.own_error[k], c.seeds_error[k],
        std::exp(-c.s[k]), alpha / c.s[k], c.s[k] * c.rho[k] / alpha,
        c.s[k] * c.rho_error[k] / alpha, c.d[k], c.d_error[k], c.spread[k]);
  }

  // The summary: the initial slope, t rho over 20 ... 40 tau_E, the spread.
  std::ofstream summary(out / "summary.csv");
  summary << "quantity,value,error\n";
  summarize("tail", c.s, c.rho, c.rho_error, alpha, summary);
  double squares = 0;
  int spread_count = 0;
  for (std::size_t k = 1; k < c.s.size(); ++k) {
    if (!std::isfinite(c.spread[k])) continue;
    squares += c.spread[k] * c.spread[k];
    ++spread_count;
  }
  summary << fmt::format("tail_seeds_rms_deviation_over_own_error,{:.3f},{}\n",
                         std::sqrt(squares / spread_count), spread_count);
  // The same below 10 tau_E and from there on.
  for (const bool far : {false, true}) {
    double sq = 0;
    int count = 0;
    for (std::size_t k = 1; k < c.s.size(); ++k) {
      if ((c.s[k] >= 10) != far || !std::isfinite(c.spread[k])) continue;
      sq += c.spread[k] * c.spread[k];
      ++count;
    }
    summary << fmt::format("tail_seeds_rms_deviation_over_own_error_{},{:.3f},{}\n",
                           far ? "from_10_tau" : "below_10_tau", std::sqrt(sq / count),
                           count);
  }
  summary << fmt::format("tail_tau_E,{:.6f},\ntail_alpha,{:.6f},\ntail_D_E,{:.6f},\n",
                         f.time_unit, f.tail_coefficient / f.time_unit, f.diffusion);

  // The pictures.
  const double last = c.s.back();
  Series measured{"measured (4 gases of 10^5 balls)", {}, false, {}, ""};
  Series t_rho{"measured", {}, false, {}, ""};
  Series diffusion{"measured", {}, false, {}, ""};
  for (std::size_t k = 1; k < c.s.size(); ++k) {
    measured.points.emplace_back(c.s[k], c.rho[k]);
    measured.errors.push_back(std::isfinite(c.rho_error[k]) ? c.rho_error[k] : 0);
    t_rho.points.emplace_back(c.s[k], c.s[k] * c.rho[k] / alpha);
    t_rho.errors.push_back(std::isfinite(c.rho_error[k]) ? c.s[k] * c.rho_error[k] / alpha
                                                         : 0);
    diffusion.points.emplace_back(c.s[k], c.d[k]);
    diffusion.errors.push_back(c.d_error[k]);
  }
  // The counted balls' area fraction, from the file's own theory: kT = D_E /
  // tau_E, and 1 / tau_E = 2 sqrt(pi) n g(eta) s sqrt(kT) fixes eta (by
  // bisection: n g rises with eta); then Enskog's nu_E there.
  const double kT = f.diffusion / f.time_unit;
  double low = 0.01, high = 0.69;
  for (int i = 0; i < 60; ++i) {
    const double mid = (low + high) / 2;
    (gas::enskog_transport(mid, 1, kT).velocity_time > f.time_unit ? low : high) = mid;
  }
  const gas::EnskogTransport theory = gas::enskog_transport(low, 1, kT);
  say(fmt::format(
      "counted balls: area fraction {:.5f}, kT {:.5f}, D_E {:.5f}, nu_E {:.5f}", low, kT,
      theory.diffusion, theory.kinematic_viscosity));
  // Mode coupling with the measured D(t) in D_E's place (nu kept at nu_E):
  // the tail's amplitude over its Enskog value, (D_E + nu_E) / (D(t) + nu_E).
  Series grown{"mode coupling with the measured D(t) for D_E", {}, true, {}, ""};
  for (std::size_t k = 1; k < c.s.size(); ++k) {
    if (c.s[k] < 1) continue;
    const double d = c.d[k] * f.diffusion;
    grown.points.emplace_back(c.s[k], (theory.diffusion + theory.kinematic_viscosity) /
                                          (d + theory.kinematic_viscosity));
  }
  Series enskog{"Enskog: exp(-t / tau_E)", {}, true, {}, "lines linewidth 2"};
  Series mode{
      "mode coupling: 1 / (8 pi n (D_E + nu_E) t)", {}, true, {}, "lines linewidth 2"};
  Series enskog_t{
      "Enskog: t exp(-t / tau_E), same scale", {}, true, {}, "lines linewidth 2"};
  Series mode_t{"mode coupling (1)", {}, true, {}, "lines linewidth 2"};
  Series enskog_d{"Enskog", {}, true, {}, "lines linewidth 2"};
  // The tail's integral: D grows by kT alpha tau_E ln t = D_E alpha ln t, a
  // line of slope alpha against ln t, drawn through the measured D at 10 tau_E.
  std::size_t ten = 1;
  for (std::size_t k = 1; k < c.s.size(); ++k)
    if (std::abs(std::log(c.s[k] / 10)) < std::abs(std::log(c.s[ten] / 10))) ten = k;
  Series mode_d{fmt::format("slope alpha = {:.3f}, through 10 tau_E", alpha),
                {},
                true,
                {},
                "lines linewidth 2"};
  for (int i = 0; i <= 200; ++i) {
    const double s = 0.01 * std::pow(last / 0.01, i / 200.0);
    enskog.points.emplace_back(s, std::exp(-s));
    mode.points.emplace_back(s, alpha / s);
    enskog_t.points.emplace_back(s, s * std::exp(-s) / alpha);
    mode_t.points.emplace_back(s, 1);
    enskog_d.points.emplace_back(s, -std::expm1(-s));
    if (s >= 3) mode_d.points.emplace_back(s, c.d[ten] + alpha * std::log(s / c.s[ten]));
  }
  Panel loglog{"the velocity autocorrelation, area fraction 0.3",
               "t / tau_E (mean free times)",
               "rho(t)",
               true,
               true,
               {measured, enskog, mode},
               "bottom left",
               "set yrange [1e-4:1.2]"};
  draw({out / "vacf.svg", "", {loglog}, 800, 560}, smoke);
  Panel flat{"t rho(t) over mode coupling's value: flat for a pure 1/t tail",
             "t / tau_E (mean free times)",
             "t rho(t) / (t rho_tail(t))",
             true,
             false,
             {t_rho, enskog_t, mode_t, grown},
             "top right",
             "set yrange [0:2.8]"};
  draw({out / "t-rho.svg", "", {flat}, 800, 560}, smoke);
  Panel grows{"D(t) = (1/2) integral of <v(0).v(s)> to t, over Enskog's D_E",
              "t / tau_E (log scale: ln t)",
              "D(t) / D_E",
              true,
              false,
              {diffusion, enskog_d, mode_d},
              "bottom right",
              ""};
  draw({out / "diffusion.svg", "", {grows}, 800, 560}, smoke);
}

// --- The same function from --dump files -----------------------------------

// The balls of a dump at its time: centre and velocity.
struct Snapshot {
  double time = 0;
  std::vector<gas::Point> r, v;
};

Snapshot snapshot(const fs::path& path) {
  const gas::Gas g = gas::read_scene_file(path.string());
  Snapshot s;
  s.time = g.time;
  for (const gas::Ball& b : g.balls) {
    s.r.push_back(gas::centre_at(b, g.time));
    s.v.push_back({b.vx, b.vy});
  }
  return s;
}

void independent(const fs::path& out, const fs::path& work, bool smoke, bool keep) {
  // The gas: 10^5 balls (smoke: 2000) at 0.3, run to T = 50 and dumped.
  const fs::path source = fs::path(GAS_SOURCE_DIR) / "data" / "large-100000.scene";
  fs::path scene = source;
  if (smoke) {
    scene = work / "small.scene";
    std::ofstream(scene) << "a 1\nT0 1\nA1 161.8\nA2 121.4\nN 1875\nrandom 1875 1989 1\n";
  }
  const double start = 50, end = smoke ? 80 : 250;
  const fs::path begin = work / "d50.scene";
  const fs::path program_file = out / "independent-program.csv";
  const fs::path samples_file = out / "independent-samples.csv";
  run_gas({scene.string(), "--mode", "none", "--until", "50", "--dump", begin.string()});
  if (!(keep && fs::exists(program_file))) {
    run_gas({begin.string(), "--mode", "none", "--until", fmt::format("{}", end),
             "--vacf", program_file.string()});
  }
  const VacfFile program = read_vacf(program_file);
  {
    std::vector<double> ratio;
    for (const double t : program.t) ratio.push_back(t / program.time_unit);
    std::ofstream summary(out / "summary.csv", std::ios::app);
    summarize("independent", ratio, program.rho, program.rho_error,
              program.tail_coefficient / program.time_unit, summary);
  }

  // The plan the program made: its lags, margin and first origin.
  const gas::Gas first = gas::read_scene_file(begin.string());
  const gas::VacfPlan plan = gas::plan_vacf(first);
  const double tau = plan.time_unit;
  // Nine lags of its list (0.01, 0.1, 1, 3.16, 10, 20, 25, 32, 40 tau_E), and
  // origins 8 tau_E apart from its first (each a dump read and written: a
  // second of processor time at 10^5 balls).
  std::vector<std::size_t> lags;
  for (const double want : {0.01, 0.1, 1.0, 3.16, 10.0, 20.0, 25.1, 31.6, 39.8}) {
    std::size_t best = 0;
    for (std::size_t k = 0; k < plan.lags.size(); ++k)
      if (std::abs(plan.lags[k] / tau - want) < std::abs(plan.lags[best] / tau - want))
        best = k;
    if (std::abs(plan.lags[best] / tau - want) < 0.05 * want) lags.push_back(best);
  }
  std::vector<double> origins;
  for (double t0 = start + plan.warm_up; t0 + plan.lags[lags.back()] <= end;
       t0 += 8 * tau)
    origins.push_back(t0);
  struct Moment {
    double time;
    std::size_t origin, lag;  // lag: an index into `lags`, or lags.size() for the origin
  };
  std::vector<Moment> moments;
  for (std::size_t o = 0; o < origins.size(); ++o) {
    moments.push_back({origins[o], o, lags.size()});
    for (std::size_t j = 0; j < lags.size(); ++j)
      moments.push_back({origins[o] + plan.lags[lags[j]], o, j});
  }
  std::sort(moments.begin(), moments.end(),
            [](const Moment& a, const Moment& b) { return a.time < b.time; });
  say(fmt::format("{} origins, {} lags: a chain of {} dumps", origins.size(), lags.size(),
                  moments.size()));

  // The chain: each run continues from the last dump to the next moment.
  // Each origin's samples go to independent-samples.csv (with --keep, read
  // back from it instead of running the chain again).
  std::vector<std::vector<double>> rho(lags.size()), d(lags.size());
  if (keep && fs::exists(samples_file)) {
    std::ifstream in(samples_file);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
      std::vector<double> x;
      std::stringstream fields(line);
      for (std::string field; std::getline(fields, field, ',');)
        x.push_back(number(field));
      if (x.size() != 5) continue;
      const auto j = static_cast<std::size_t>(x[1]);
      rho[j].push_back(x[3]);
      d[j].push_back(x[4]);
    }
  } else {
    struct Noted {
      std::vector<std::size_t> balls;
      std::vector<gas::Point> v, r;
      double squares = 0;
    };
    std::vector<Noted> noted(origins.size());
    std::ofstream samples(samples_file);
    samples << "origin,lag,t,vacf,diffusion\n";
    fs::path previous = begin;
    for (std::size_t m = 0; m < moments.size(); ++m) {
      const fs::path next = work / fmt::format("chain-{}.scene", m % 2);
      run_quietly({previous.string(), "--mode", "none", "--until",
                   fmt::format("{:.17g}", moments[m].time), "--dump", next.string()});
      previous = next;
      const Snapshot s = snapshot(next);
      const Moment& at = moments[m];
      Noted& o = noted[at.origin];
      if (at.lag == lags.size()) {  // an origin: note the balls far from the walls
        for (std::size_t i = 0; i < s.r.size(); ++i) {
          if (s.r[i].x < plan.margin || s.r[i].x > first.width - plan.margin ||
              s.r[i].y < plan.margin || s.r[i].y > first.height - plan.margin)
            continue;
          o.balls.push_back(i);
          o.v.push_back(s.v[i]);
          o.r.push_back(s.r[i]);
          o.squares += s.v[i].x * s.v[i].x + s.v[i].y * s.v[i].y;
        }
        continue;
      }
      double vv = 0, vr = 0;
      for (std::size_t j = 0; j < o.balls.size(); ++j) {
        const gas::Point& v = s.v[o.balls[j]];
        const gas::Point& r = s.r[o.balls[j]];
        vv += o.v[j].x * v.x + o.v[j].y * v.y;
        vr += o.v[j].x * (r.x - o.r[j].x) + o.v[j].y * (r.y - o.r[j].y);
      }
      rho[at.lag].push_back(vv / o.squares);
      d[at.lag].push_back(vr / (2 * static_cast<double>(o.balls.size())));
      samples << fmt::format("{},{},{:.17g},{:.17g},{:.17g}\n", at.origin, at.lag,
                             plan.lags[lags[at.lag]], rho[at.lag].back(),
                             d[at.lag].back());
      if (m % 20 == 0) say(fmt::format("dump {} of {}", m, moments.size()));
    }
  }

  // The comparison: each lag's mean over the origins, its error the spread
  // over them (origins 8 tau_E apart: nearly independent), beside the
  // program's row at the same lag.
  std::ofstream csv(out / "independent.csv");
  csv << "t,t_over_tau,program,program_error,dumps,dumps_error,origins,z\n";
  for (std::size_t j = 0; j < lags.size(); ++j) {
    const auto n = static_cast<double>(rho[j].size());
    double mean = 0, squares = 0;
    for (const double x : rho[j]) mean += x;
    mean /= n;
    for (const double x : rho[j]) squares += (x - mean) * (x - mean);
    const double error = std::sqrt(squares / (n - 1) / n);
    const std::size_t k = lags[j];
    const double p = program.rho[k], pe = program.rho_error[k];
    csv << fmt::format("{:.9g},{:.4g},{:.9g},{:.3g},{:.9g},{:.3g},{},{:.2f}\n",
                       plan.lags[k], plan.lags[k] / tau, p, pe, mean, error,
                       rho[j].size(), (p - mean) / std::sqrt(pe * pe + error * error));
  }
  for (const fs::path& p : {work / "chain-0.scene", work / "chain-1.scene", begin})
    fs::remove(p);
}

}  // namespace

int main(int argc, char** argv) {
  fs::path out = fs::path(GAS_SOURCE_DIR) / "data" / "reports" / "long-time-tail";
  bool smoke = false, keep = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--smoke") {
      smoke = true;
    } else if (a == "--keep") {
      keep = true;
    } else if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else {
      fmt::print(stderr, "usage: gas-tail-figures [--out DIR] [--smoke] [--keep]\n");
      return 2;
    }
  }
  fs::create_directories(out);
  const fs::path work =
      fs::temp_directory_path() / fmt::format("gas-tail-figures-{}", getpid());
  fs::create_directories(work);
  tail(out, work, smoke, keep);
  independent(out, work, smoke, keep);
  fs::remove_all(work);
  say("wrote " + out.string());
  return 0;
}
