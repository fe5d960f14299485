// gas-figures: the pictures of the statistics lessons, from runs of build/gas.
//
// Runs the program itself (build/gas, as a child process, two at a time),
// reads the files it writes (--csv, --structure, --dump), and draws with
// gnuplot (tests/benchmark/plots.hpp) five pictures, each into the folder of
// the lesson that shows it, with the numbers behind each as CSV:
//
// lesson-12/ (lessons/12-statistics-screen.md):
//   h-theorem.svg     Boltzmann's H of the speeds against T, B pressed at
//                     T = 10 and at T = 30 (Loschmidt: data/h-theorem.scene)
//   speeds.svg        the distribution of speeds against 2D Maxwell-Boltzmann
//                     (data/large-10000.scene, four dumps 50 apart)
// lesson-13/ (lessons/13-box-and-bulk.md):
//
//   eos.svg           the bulk's Z against the interior's area fraction,
//                     0.05 ... 0.69, with error bars, against Kolafa-Rottner
//                     and Henderson; and its relative difference from
//                     Kolafa-Rottner for a closed box of 1024 balls (the
//                     fixed-N shift of beyond/kinetic_theory.hpp)
//   pair-correlation.svg   g(r) at area fractions 0.1, 0.3, 0.5, 0.65 (--structure)
//   wall-profile.svg  the density of centres beside a wall, same runs
//
// Every gas is 1024 balls of radius 1 on a 32 x 32 lattice, every speed 1
// (kT = 1/2), or a scene of data/. The averages start at a restart (the key A,
// pressed by --keys) after a quarter of the run: a warm-up in which a dense gas
// started on a lattice relaxes (lesson 14), longer than the program's own.
//
// Usage:  gas-figures [--out DIR] [--smoke]
//   --out     where to write: DIR/lesson-12 and DIR/lesson-13 (default: DIR is
//             data/reports of the source tree)
//   --smoke   runs a hundred times shorter, no pictures (the test suite runs this)
// About a processor-minute; progress on standard error. Beyond the article.
// Lesson: lessons/12-statistics-screen.md, lessons/13-box-and-bulk.md
// ("Lesson 13 in pictures").
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "beyond/boltzmann_h.hpp"
#include "beyond/hard_disc_fluid.hpp"
#include "beyond/kinetic_theory.hpp"
#include "beyond/random_placement.hpp"
#include "child_process.hpp"
#include "plots.hpp"

namespace fs = std::filesystem;
using gas::benchmark::Panel;
using gas::benchmark::Picture;
using gas::benchmark::Series;

namespace {

constexpr double pi = std::numbers::pi;
constexpr int lattice_balls = 1024;
constexpr int processes = 2;  // runs at a time: the machine is shared

void say(const std::string& text) {
  fmt::print(stderr, "gas-figures: {}\n", text);
}

// One run of build/gas: its arguments, and whether it went well.
struct Job {
  explicit Job(std::vector<std::string> a) : arguments(std::move(a)) {}
  std::vector<std::string> arguments;
  bool succeeded = false;
  std::string failure;
};

// Runs the jobs, `processes` at a time.
void run_all(std::vector<Job>& jobs) {
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) {
      const auto run =
          gas::benchmark::run_child(GAS_PROGRAM, jobs[i].arguments, "", 3600);
      jobs[i].succeeded = run.succeeded();
      jobs[i].failure = run.succeeded() ? "" : run.failure();
      say(fmt::format("{} {}", run.succeeded() ? "ran" : "FAILED:",
                      fmt::join(jobs[i].arguments, " ")));
    }
  };
  std::vector<std::thread> threads;
  for (int p = 0; p < processes; ++p) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
}

// The lattice scene at area fraction eta: a square table, T0 as given.
void write_lattice_scene(const fs::path& path, double eta, double display_step) {
  const double side = std::sqrt(lattice_balls * pi / eta);
  std::ofstream(path) << fmt::format(
      "# gas-figures: {0} balls on a lattice at area fraction {1}\n"
      "a 1\nT0 {2}\nA1 {3:.9f}\nA2 {3:.9f}\nN {0}\nlattice {0} 1989 1\n",
      lattice_balls, eta, display_step, side);
}

// The model time of `collisions` collisions of two balls in a lattice gas
// at eta (Enskog's rate, kT = 1/2: rate per ball 2 (2a) n g sqrt(pi kT)).
double time_for(double eta, double collisions) {
  const double rate =
      4 * (eta / pi) * gas::hard_disc_fluid_contact_value(eta) * std::sqrt(pi / 2);
  return collisions / (lattice_balls * rate / 2);
}

// A run of `until`, T0 = until / steps, the averages restarted (A) after a
// quarter: its arguments.
std::vector<std::string> averaged_run(const fs::path& scene, double until, int steps) {
  return {scene.string(),
          "--until",
          fmt::format("{:.9g}", until),
          "--mode",
          "none",
          "--pictures",
          "steps",
          "--keys",
          std::string(static_cast<std::size_t>(steps / 4), '.') + "A"};
}

// The runs of 1024-ball lattice scenes at each area fraction, about
// `collisions` collisions of two balls each in 400 display steps, averaged
// from a quarter of the run, each writing --csv work/NAME-ETA.csv.
std::vector<Job> lattice_runs(const std::vector<double>& fractions,
                              const std::string& name, double collisions,
                              const fs::path& work) {
  std::vector<Job> jobs;
  for (const double eta : fractions) {
    const fs::path scene = work / fmt::format("{}-{}.scene", name, eta);
    const double until = time_for(eta, collisions);
    write_lattice_scene(scene, eta, until / 400);
    Job job(averaged_run(scene, until, 400));
    job.arguments.insert(
        job.arguments.end(),
        {"--csv", (work / fmt::format("{}-{}.csv", name, eta)).string()});
    jobs.push_back(job);
  }
  return jobs;
}

// The last row of a --csv file, by column name.
std::map<std::string, double> last_row(const fs::path& path) {
  std::ifstream in(path);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::map<std::string, double> row;
  std::stringstream names(header), values(last);
  std::string name, value;
  while (std::getline(names, name, ',') && std::getline(values, value, ','))
    row[name] = std::strtod(value.c_str(), nullptr);
  return row;
}

// Every row of a CSV file as fields.
std::vector<std::vector<std::string>> rows_of(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream s(line);
    for (std::string f; std::getline(s, f, ',');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

double number(const std::string& text) {
  return std::strtod(text.c_str(), nullptr);
}

// A theory's curve: f at n + 1 points from x0 to x1.
template <typename F>
Series curve(const std::string& title, double x0, double x1, F f, int n = 200) {
  Series s{title, {}, true, {}, "lines linewidth 2"};
  for (int i = 0; i <= n; ++i) {
    const double x = x0 + (x1 - x0) * i / n;
    s.points.emplace_back(x, f(x));
  }
  return s;
}

void draw(const Picture& picture, bool smoke) {
  if (smoke) return;
  const std::string why = gas::benchmark::draw(picture);
  say(why.empty() ? "drew " + picture.svg.string() : "no picture: " + why);
}

// --- The equation of state -------------------------------------------------

const std::vector<double> eos_fractions = {0.05, 0.1,  0.15, 0.2,  0.25, 0.3,  0.35,
                                           0.4,  0.45, 0.5,  0.55, 0.6,  0.65, 0.69};

void equation_of_state(const fs::path& out, const fs::path& work, double scale,
                       bool smoke) {
  std::vector<Job> jobs = lattice_runs(eos_fractions, "eos", 1.5e6 * scale, work);
  run_all(jobs);
  std::ofstream table(out / "eos.csv");
  table << "eta_nominal,eta_interior,Z,Z_deviation_error,Z_kolafa_rottner,Z_fixed_N,"
           "Z_henderson,collisions\n";
  Series measured{"measured (interior of 1024 balls)", {}, false, {}, ""};
  Series relative{"measured", {}, false, {}, ""};
  for (const double eta : eos_fractions) {
    const auto row = last_row(work / fmt::format("eos-{}.csv", eta));
    if (!row.contains("Z")) continue;
    // The error bar: that of Z - Z_ref(eta_int), taken sample by sample (Z's
    // own blocking error often has no plateau: it wanders with eta_int,
    // lesson 14, "Errors that hold").
    const double e = row.at("eta_interior"), z = row.at("Z"),
                 error = row.at("Z_deviation_error");
    // The reference for the closed box of 1024 balls (what Z_deviation is
    // taken against), and the open bulk's beside it.
    const double reference = gas::fixed_count_compressibility(e, lattice_balls);
    table << fmt::format("{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.0f}\n", eta, e,
                         z, error, gas::hard_disc_fluid_compressibility(e), reference,
                         gas::henderson_compressibility(e),
                         row.at("wall_collisions") + row.at("ball_collisions"));
    measured.points.emplace_back(e, z);
    measured.errors.push_back(error);
    relative.points.emplace_back(e, 100 * (z / reference - 1));
    relative.errors.push_back(100 * error / reference);
  }
  const double top = gas::fluid_area_fraction_limit;
  Panel z{"Z = P / (n kT) of the bulk",
          "area fraction of the interior",
          "Z",
          false,
          false,
          {measured,
           curve("Kolafa-Rottner (2006)", 0, top, gas::hard_disc_fluid_compressibility),
           curve("Henderson (1975)", 0, top, gas::henderson_compressibility)},
          "top left",
          ""};
  // Each curve against Kolafa-Rottner for 1024 balls, in per cent.
  auto against_closed_box = [](double (*z)(double)) {
    return [z](double e) {
      return 100 * (z(e) / gas::fixed_count_compressibility(e, lattice_balls) - 1);
    };
  };
  Panel difference{
      "the same against Kolafa-Rottner for 1024 balls",
      "area fraction of the interior",
      "Z / Z_KR,N - 1, %",
      false,
      false,
      {relative, curve("Kolafa-Rottner, N = 1024", 0, top, [](double) { return 0.0; }),
       curve("Kolafa-Rottner, open bulk", 0, top,
             against_closed_box(gas::hard_disc_fluid_compressibility)),
       curve("Henderson", 0, top, against_closed_box(gas::henderson_compressibility))},
      "top left",
      "set yrange [-1:3]"};
  draw({out / "eos.svg",
        "The equation of state of hard discs: build/gas against the "
        "reference",
        {z, difference}},
       smoke);
}

// --- H and the B key -------------------------------------------------------

void h_theorem(const fs::path& out, const fs::path& work, bool smoke) {
  // data/h-theorem.scene: T0 = 0.25; B before the step after T = 10 (40
  // steps) or 30 (120), then as long again; H from the program's fixed speed
  // bins, whatever the width (the noise floor is the CSV's H_noise).
  const std::string scene = std::string(GAS_SOURCE_DIR) + "/data/h-theorem.scene";
  std::vector<Job> jobs;
  for (const int b : {10, 30}) {
    const int steps = 4 * b;
    jobs.emplace_back(
        std::vector<std::string>{scene, "--until", fmt::format("{}", 2 * b), "--mode",
                                 "none", "--pictures", "steps", "--cols", "80", "--keys",
                                 std::string(static_cast<std::size_t>(steps), '.') + "B",
                                 "--csv", (work / fmt::format("h-{}.csv", b)).string()});
  }
  run_all(jobs);
  std::ofstream table(out / "h-theorem.csv");
  table << "B_at,T,H\n";
  std::vector<Series> series;
  double floor = std::nan("");  // H's noise floor for 1024 speeds, as the program says
  for (const int b : {10, 30}) {
    Series s{fmt::format("B at T = {}", b), {}, true, {}, "lines linewidth 2"};
    const auto rows = rows_of(work / fmt::format("h-{}.csv", b));
    if (rows.empty()) continue;
    const auto h = static_cast<std::size_t>(
        std::find(rows[0].begin(), rows[0].end(), "H") - rows[0].begin());
    for (std::size_t i = 1; i < rows.size(); ++i) {
      if (h >= rows[i].size()) continue;
      s.points.emplace_back(number(rows[i][0]), number(rows[i][h]));
      table << fmt::format("{},{},{}\n", b, rows[i][0], rows[i][h]);
    }
    const auto noise = static_cast<std::size_t>(
        std::find(rows[0].begin(), rows[0].end(), "H_noise") - rows[0].begin());
    if (noise < rows.back().size()) floor = number(rows.back()[noise]);
    series.push_back(s);
  }
  series.push_back(curve(
      "the noise of 1024 speeds (H_noise)", 0, 60, [floor](double) { return floor; }, 2));
  draw({out / "h-theorem.svg",
        "Boltzmann's H of the speeds: data/h-theorem.scene, B pressed at T = 10 and at "
        "T = 30",
        {{"H falls; after B it climbs back, until round-off wins", "T", "H", false, true,
          series, "top right", ""}},
        900,
        500},
       smoke);
}

// --- The speeds ------------------------------------------------------------

void speeds(const fs::path& out, const fs::path& work, double scale, bool smoke) {
  // data/large-10000.scene to T = 50, dumped; from each dump 50 more.
  const int dumps = 4;
  const double stretch = std::max(1.0, 50 * scale);
  std::string scene = std::string(GAS_SOURCE_DIR) + "/data/large-10000.scene";
  std::vector<double> all;
  for (int d = 1; d <= dumps; ++d) {
    const fs::path dump = work / fmt::format("speeds-{}.scene", d);
    std::vector<Job> job = {Job({scene, "--until", fmt::format("{}", d * stretch),
                                 "--mode", "none", "--dump", dump.string()})};
    run_all(job);
    if (!job[0].succeeded) return;
    const gas::Gas g = gas::read_scene_file(dump.string());
    for (const gas::Ball& b : g.balls) all.push_back(std::hypot(b.vx, b.vy));
    scene = dump.string();
  }
  double kT = 0;
  for (const double v : all) kT += v * v / 2 / static_cast<double>(all.size());
  // 50 bins from 0 to 3 v_rms; a bin's density and its Poisson error.
  const int bins = 50;
  const double width = 3 * std::sqrt(2 * kT) / bins;
  std::vector<double> counts(bins, 0.0);
  for (const double v : all) {
    const auto k = static_cast<std::size_t>(v / width);
    if (k < counts.size()) counts[k] += 1;
  }
  std::ofstream table(out / "speeds.csv");
  table << "from,to,density,error,maxwell_boltzmann\n";
  Series measured{
      fmt::format("{} speeds (4 moments, 10000 balls)", all.size()), {}, false, {}, ""};
  const auto n = static_cast<double>(all.size());
  for (int k = 0; k < bins; ++k) {
    const double from = k * width, to = from + width;
    const double density = counts[k] / (n * width);
    const double error = std::sqrt(counts[k]) / (n * width);
    const double theory =
        (gas::maxwell_fraction_below(to, kT) - gas::maxwell_fraction_below(from, kT)) /
        width;
    table << fmt::format("{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}\n", from, to, density, error,
                         theory);
    measured.points.emplace_back((from + to) / 2, density);
    measured.errors.push_back(error);
  }
  draw({out / "speeds.svg",
        "The speeds of data/large-10000.scene against 2D Maxwell-Boltzmann",
        {{fmt::format("kT = {:.4f} (E / N)", kT),
          "speed",
          "density of balls per unit speed",
          false,
          false,
          {measured,
           curve("2D Maxwell-Boltzmann: (v / kT) exp(-v^2 / 2kT)", 0, bins * width,
                 [kT](double v) { return gas::maxwell_density(v, kT); })},
          "top right",
          ""}},
        900,
        500},
       smoke);
}

// --- g(r) and the wall ------------------------------------------------------

const std::vector<double> structure_fractions = {0.1, 0.3, 0.5, 0.65};

void structure(const fs::path& out, const fs::path& work, double scale, bool smoke) {
  std::vector<Job> jobs =
      lattice_runs(structure_fractions, "structure", 2e6 * scale, work);
  for (std::size_t i = 0; i < jobs.size(); ++i)
    jobs[i].arguments.insert(
        jobs[i].arguments.end(),
        {"--structure",
         (out / fmt::format("structure-{}.csv", structure_fractions[i])).string()});
  run_all(jobs);
  std::ofstream table(out / "structure-contact.csv");
  table << "eta_nominal,eta_interior,g_contact,g_contact_error,g_contact_theory,"
           "wall_contact_density,wall_contact_density_error,wall_middle_pressure_over_kT,"
           "wall_middle_pressure_over_kT_error,interior_density\n";
  std::vector<Series> pairs, walls;
  Series contact{"reference g(2a), Kolafa-Rottner",
                 {},
                 false,
                 {},
                 "points pointtype 6 pointsize 1.5"};
  Series theorem{"P on the walls' middles / kT (the contact theorem)",
                 {},
                 false,
                 {},
                 "points pointtype 6 pointsize 1.5"};
  for (const double eta : structure_fractions) {
    const auto row = last_row(work / fmt::format("structure-{}.csv", eta));
    if (!row.contains("eta_interior")) continue;
    const double e = row.at("eta_interior"), kT = row.at("kT"), n = e / pi;
    table << fmt::format(
        "{},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f},{:.6f}\n", eta, e,
        row.at("g_contact"), row.at("g_contact_error"), row.at("g_contact_theory"),
        row.at("wall_contact_pressure") / kT, row.at("wall_contact_pressure_error") / kT,
        row.at("pressure") / kT, row.at("pressure_error") / kT, n);
    contact.points.emplace_back(2, row.at("g_contact_theory"));
    theorem.points.emplace_back(0, row.at("pressure") / kT / n);
    Series g{fmt::format("eta = {:.3f}", e),
             {},
             true,
             {},
             "yerrorlines pointtype 7 pointsize 0.3"};
    Series w = g;
    for (const auto& r : rows_of(out / fmt::format("structure-{}.csv", eta))) {
      if (r.size() < 5 || r[0] == "curve") continue;
      const double middle = (number(r[1]) + number(r[2])) / 2;
      Series& s = r[0] == "pair" ? g : w;
      const double norm = r[0] == "pair" ? 1 : n;
      s.points.emplace_back(middle, number(r[3]) / norm);
      s.errors.push_back(number(r[4]) / norm);
    }
    pairs.push_back(g);
    walls.push_back(w);
  }
  pairs.push_back(contact);
  walls.push_back(theorem);
  draw({out / "pair-correlation.svg",
        "The pair correlation g(r) of the interior (--structure), 1024 balls",
        {{"g(r): the layers of neighbours", "r / a", "g(r)", false, false, pairs,
          "top right", "set xrange [1.9:5]"}},
        900,
        500},
       smoke);
  draw({out / "wall-profile.svg",
        "The density of centres beside a wall (--structure), 1024 balls",
        {{"n(d) / n of the interior, d from the wall's limit x = a", "d / a",
          "n(d) / n_interior", false, false, walls, "top right", "set xrange [-0.2:10]"}},
        900,
        500},
       smoke);
}

}  // namespace

int main(int argc, char** argv) {
  fs::path out = fs::path(GAS_SOURCE_DIR) / "data" / "reports";
  bool smoke = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--smoke") {
      smoke = true;
    } else if (a == "--out" && i + 1 < argc) {
      out = argv[++i];
    } else {
      fmt::print(stderr, "usage: gas-figures [--out DIR] [--smoke]\n");
      return 2;
    }
  }
  const double scale = smoke ? 0.01 : 1;
  // Each picture in the folder of the lesson that shows it.
  const fs::path screen = out / "lesson-12", bulk = out / "lesson-13";
  fs::create_directories(screen);
  fs::create_directories(bulk);
  const fs::path work =
      fs::temp_directory_path() / fmt::format("gas-figures-{}", getpid());
  fs::create_directories(work);
  equation_of_state(bulk, work, scale, smoke);
  h_theorem(screen, work, smoke);
  speeds(screen, work, scale, smoke);
  structure(bulk, work, scale, smoke);
  fs::remove_all(work);
  say("wrote " + screen.string() + " and " + bulk.string());
  return 0;
}
