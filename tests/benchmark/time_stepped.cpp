// The gas with a fixed time step. See time_stepped.hpp.
#include "time_stepped.hpp"

#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "engine.hpp"
#include "report_text.hpp"
#include "stage5_new_coordinates.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace gas::benchmark {

namespace {

// The balls with a fixed time step, and the cells that find overlapping
// pairs.
class SteppedGas {
 public:
  explicit SteppedGas(const Gas& start)
      : a_(start.radius),
        right_(start.width - a_),
        top_(start.height - a_),
        // Cells at least 2a wide: overlapping balls are in the same or
        // neighbouring cells.
        columns_(std::max(1, static_cast<int>(start.width / (2 * a_)))),
        rows_(std::max(1, static_cast<int>(start.height / (2 * a_)))),
        cell_width_(start.width / columns_),
        cell_height_(start.height / rows_),
        first_in_cell_(static_cast<std::size_t>(columns_ * rows_) + 1) {
    for (const Ball& b : start.balls) balls_.push_back({b.x, b.y, b.vx, b.vy});
    order_.resize(balls_.size());
    cell_.resize(balls_.size());
  }

  double energy() const {
    double twice = 0;
    for (const State& b : balls_) twice += b.vx * b.vx + b.vy * b.vy;
    return twice / 2;
  }

  // Move, and bounce off the walls.
  void move(double dt, GasRecord& record) {
    for (State& b : balls_) {
      b.x += b.vx * dt;
      b.y += b.vy * dt;
      if ((b.x < a_ && b.vx < 0) || (b.x > right_ && b.vx > 0)) {
        record.wall_impulse += 2 * std::fabs(b.vx);
        b.vx = -b.vx;
        ++record.wall_collisions;
      }
      if ((b.y < a_ && b.vy < 0) || (b.y > top_ && b.vy > 0)) {
        record.wall_impulse += 2 * std::fabs(b.vy);
        b.vy = -b.vy;
        ++record.wall_collisions;
      }
    }
  }

  // Sort the balls into their cells (a counting sort).
  void sort_into_cells() {
    std::fill(first_in_cell_.begin(), first_in_cell_.end(), 0);
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      const int c =
          std::clamp(static_cast<int>(balls_[i].x / cell_width_), 0, columns_ - 1);
      const int r =
          std::clamp(static_cast<int>(balls_[i].y / cell_height_), 0, rows_ - 1);
      cell_[i] = r * columns_ + c;
      ++first_in_cell_[static_cast<std::size_t>(cell_[i]) + 1];
    }
    for (std::size_t c = 1; c < first_in_cell_.size(); ++c)
      first_in_cell_[c] += first_in_cell_[c - 1];
    std::vector<int> fill(first_in_cell_.begin(), first_in_cell_.end() - 1);
    for (std::size_t i = 0; i < balls_.size(); ++i)
      order_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_[i])]++)] =
          static_cast<int>(i);
  }

  // Overlapping and approaching pairs: the velocities along the line of
  // centres exchanged.
  void collide(GasRecord& record) {
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      const int c = cell_[i] % columns_, r = cell_[i] / columns_;
      for (int rr = std::max(0, r - 1); rr <= std::min(rows_ - 1, r + 1); ++rr) {
        for (int cc = std::max(0, c - 1); cc <= std::min(columns_ - 1, c + 1); ++cc) {
          const auto k = static_cast<std::size_t>(rr * columns_ + cc);
          for (int s = first_in_cell_[k]; s < first_in_cell_[k + 1]; ++s) {
            const auto j = static_cast<std::size_t>(order_[static_cast<std::size_t>(s)]);
            if (j > i) collide_pair(balls_[i], balls_[j], record);
          }
        }
      }
    }
  }

 private:
  struct State {
    double x, y, vx, vy;
  };

  void collide_pair(State& p, State& q, GasRecord& record) const {
    const double diameter = 2 * a_;
    const double dx = q.x - p.x, dy = q.y - p.y;
    const double squared = dx * dx + dy * dy;
    if (squared >= diameter * diameter) return;
    const double wx = q.vx - p.vx, wy = q.vy - p.vy;
    const double approach = dx * wx + dy * wy;
    record.largest_overlap =
        std::max(record.largest_overlap, 1 - std::sqrt(squared) / diameter);
    if (approach >= 0) return;  // already parting
    const double vi = approach / squared;
    p.vx += vi * dx, q.vx -= vi * dx, p.vy += vi * dy, q.vy -= vi * dy;
    ++record.ball_collisions;
  }

  double a_, right_, top_;
  int columns_, rows_;
  double cell_width_, cell_height_;
  std::vector<State> balls_;
  std::vector<int> first_in_cell_, order_, cell_;
};

}  // namespace

GasRecord run_time_stepped(const Gas& start, double dt, double end) {
  SteppedGas gas(start);
  const double starting_energy = gas.energy();
  GasRecord record;
  const double began = cpu_seconds();
  record.steps = std::llround(end / dt);
  for (long long step = 0; step < record.steps; ++step) {
    gas.move(dt, record);
    gas.sort_into_cells();
    gas.collide(record);
  }
  record.seconds = cpu_seconds() - began;
  record.energy_error = std::fabs(gas.energy() - starting_energy) / starting_energy;
  return record;
}

namespace {

// The stages, event-driven, on `figures.gas` to model time `end`.
void run_event_driven(double end, TimeStepFigures& figures) {
  const Gas& start = figures.gas;
  GasRecord& r = figures.events;
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
  figures.collision_spread = spread(collisions, static_cast<double>(r.ball_collisions));
  figures.impulse_spread = spread(impulse, r.wall_impulse);
}

}  // namespace

TimeStepFigures measure_time_steps(const Sizes& sizes, const std::filesystem::path& out) {
  TimeStepFigures figures;
  figures.gas = random_gas(sizes.stepped_balls, 0.2, 7);
  progress("4/6 a fixed time step against the events: {} balls to T = {}",
           sizes.stepped_balls, sizes.stepped_end);
  run_event_driven(sizes.stepped_end, figures);
  const double mean_speed = gas::mean_speed(figures.gas);
  for (const double per_diameter : sizes.stepped_dt) {
    const double dt = per_diameter * 2 * figures.gas.radius / mean_speed;
    progress("  dt = {:.3g} ({} of a diameter at the mean speed)", dt, per_diameter);
    figures.stepped.push_back(
        {per_diameter, run_time_stepped(figures.gas, dt, sizes.stepped_end)});
  }
  Csv csv(out / "time-stepping.csv",
          "method,dt_in_diameters,steps,seconds,ball_collisions,wall_collisions,"
          "wall_impulse,energy_error,largest_overlap");
  auto row = [&](const std::string& method, double per, const GasRecord& r) {
    csv.row("{},{},{},{:.6f},{},{},{:.9g},{:.3g},{:.4g}", method, per, r.steps, r.seconds,
            r.ball_collisions, r.wall_collisions, r.wall_impulse, r.energy_error,
            r.largest_overlap);
  };
  row("event-driven", 0, figures.events);
  for (const auto& [per, r] : figures.stepped) row("time-stepped", per, r);
  return figures;
}

std::string time_steps_section(const Sizes& sizes, const TimeStepFigures& figures) {
  std::string report;
  auto add = [&](const std::string& text) { report += text; };
  const Gas& stepped_gas = figures.gas;
  const auto& stepped = figures.stepped;
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
      100 * figures.collision_spread, 100 * figures.impulse_spread));
  add("| method | dt | run time (s) | ball collisions | error | pressure | error | "
      "energy error | deepest overlap "
      "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  const GasRecord& ev = figures.events;
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
  return report;
}

}  // namespace gas::benchmark
