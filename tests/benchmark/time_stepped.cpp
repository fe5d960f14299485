// The gas with a fixed time step. See time_stepped.hpp.
#include "time_stepped.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gas::benchmark {

GasRecord run_time_stepped(const Gas& start, double dt, double end) {
  struct State {
    double x, y, vx, vy;
  };
  std::vector<State> balls;
  for (const Ball& b : start.balls) balls.push_back({b.x, b.y, b.vx, b.vy});
  const auto n = balls.size();
  const double a = start.radius, diameter = 2 * a;
  const double right = start.width - a, top = start.height - a;
  auto energy = [&] {
    double twice = 0;
    for (const State& b : balls) twice += b.vx * b.vx + b.vy * b.vy;
    return twice / 2;
  };
  const double starting_energy = energy();

  // Cells at least 2a wide: overlapping balls are in the same or
  // neighbouring cells.
  const int columns = std::max(1, static_cast<int>(start.width / diameter));
  const int rows = std::max(1, static_cast<int>(start.height / diameter));
  const double cell_width = start.width / columns, cell_height = start.height / rows;
  std::vector<int> first_in_cell(static_cast<std::size_t>(columns * rows) + 1);
  std::vector<int> order(n), cell(n);

  GasRecord record;
  const double began = cpu_seconds();
  record.steps = std::llround(end / dt);
  for (long long step = 0; step < record.steps; ++step) {
    // Move, and bounce off the walls.
    for (State& b : balls) {
      b.x += b.vx * dt;
      b.y += b.vy * dt;
      if ((b.x < a && b.vx < 0) || (b.x > right && b.vx > 0)) {
        record.wall_impulse += 2 * std::fabs(b.vx);
        b.vx = -b.vx;
        ++record.wall_collisions;
      }
      if ((b.y < a && b.vy < 0) || (b.y > top && b.vy > 0)) {
        record.wall_impulse += 2 * std::fabs(b.vy);
        b.vy = -b.vy;
        ++record.wall_collisions;
      }
    }
    // Sort the balls into their cells (a counting sort).
    std::fill(first_in_cell.begin(), first_in_cell.end(), 0);
    for (std::size_t i = 0; i < n; ++i) {
      const int c = std::clamp(static_cast<int>(balls[i].x / cell_width), 0, columns - 1);
      const int r = std::clamp(static_cast<int>(balls[i].y / cell_height), 0, rows - 1);
      cell[i] = r * columns + c;
      ++first_in_cell[static_cast<std::size_t>(cell[i]) + 1];
    }
    for (std::size_t c = 1; c < first_in_cell.size(); ++c)
      first_in_cell[c] += first_in_cell[c - 1];
    {
      std::vector<int> fill(first_in_cell.begin(), first_in_cell.end() - 1);
      for (std::size_t i = 0; i < n; ++i)
        order[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell[i])]++)] =
            static_cast<int>(i);
    }
    // Overlapping and approaching pairs: the velocities along the line of
    // centres exchanged.
    for (std::size_t i = 0; i < n; ++i) {
      const int c = cell[i] % columns, r = cell[i] / columns;
      for (int rr = std::max(0, r - 1); rr <= std::min(rows - 1, r + 1); ++rr) {
        for (int cc = std::max(0, c - 1); cc <= std::min(columns - 1, c + 1); ++cc) {
          const auto k = static_cast<std::size_t>(rr * columns + cc);
          for (int s = first_in_cell[k]; s < first_in_cell[k + 1]; ++s) {
            const auto j = static_cast<std::size_t>(order[static_cast<std::size_t>(s)]);
            if (j <= i) continue;
            State& p = balls[i];
            State& q = balls[j];
            const double dx = q.x - p.x, dy = q.y - p.y;
            const double squared = dx * dx + dy * dy;
            if (squared >= diameter * diameter) continue;
            const double wx = q.vx - p.vx, wy = q.vy - p.vy;
            const double approach = dx * wx + dy * wy;
            record.largest_overlap =
                std::max(record.largest_overlap, 1 - std::sqrt(squared) / diameter);
            if (approach >= 0) continue;  // already parting
            const double vi = approach / squared;
            p.vx += vi * dx, q.vx -= vi * dx, p.vy += vi * dy, q.vy -= vi * dy;
            ++record.ball_collisions;
          }
        }
      }
    }
  }
  record.seconds = cpu_seconds() - began;
  record.energy_error = std::fabs(energy() - starting_energy) / starting_energy;
  return record;
}

}  // namespace gas::benchmark
