// Stage 2 — input, the 'random' line: random sequential placement. See
// beyond/random_placement.hpp for the contract and data/README.md for the
// rules of the line.
#include "beyond/random_placement.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "beyond/cell_layout.hpp"
#include "beyond/overlap_cells.hpp"

namespace gas {
namespace {

// Refuses the scene's 'random' line: "FILE:LINE: what is wrong".
[[noreturn]] void fail(const SceneDescription& scene, const std::string& what) {
  throw SceneError(fmt::format("{}:{}: {}", scene.file_name, scene.random->line, what));
}

// A number in [0, 1) from the top 53 bits of one draw of the generator:
// exactly the same on every machine (std::uniform_real_distribution's
// output is not specified bit for bit, so two libraries may differ).
double unit_interval(std::mt19937_64& generator) {
  return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

// The balls on the table so far, filed by cell. The cells are at least 2a
// across, so a place is checked only against the balls of the 3 x 3 cells
// around it; and not many more cells than balls.
class PlacedBalls {
 public:
  // Cells for up to `most_balls` balls of `gas`, its balls so far filed.
  PlacedBalls(const Gas& gas, std::size_t most_balls)
      : gas_(gas),
        diameter_(2 * gas.radius),
        cells_(lay_out_cells(gas.width, gas.height, diameter_,
                             2 * static_cast<double>(most_balls) + 16),
               most_balls) {
    for (std::size_t i = 0; i < gas.balls.size(); ++i) file(i);
  }

  // Files ball `index` of the gas in its cell (where its centre is at the
  // scene's T: a 'ball' line may give its row at an earlier SINCE).
  void file(std::size_t index) {
    const Point centre = centre_at(gas_.balls[index], gas_.time);
    cells_.file(index, centre.x, centre.y);
  }

  // Is (x, y) a free place: a centre there at least 2a from every ball?
  bool free(double x, double y) const {
    return cells_.visit_near(x, y, [&](std::size_t k) {
      const Point centre = centre_at(gas_.balls[k], gas_.time);
      const double dx = centre.x - x, dy = centre.y - y;
      return dx * dx + dy * dy >= diameter_ * diameter_;
    });
  }

 private:
  const Gas& gas_;
  double diameter_;
  CellLists cells_;
};

// The centres: each ball in turn at a random point of the table (a <= x <=
// A1 - a, a <= y <= A2 - a), tried again until the place is free.
void place_centres(const SceneDescription& scene, double covered,
                   std::mt19937_64& generator, Gas& gas) {
  const std::size_t count = scene.random->count;
  const std::size_t total = gas.balls.size() + count;
  const double diameter = 2 * gas.radius;
  PlacedBalls placed(gas, total);
  for (std::size_t k = 0; k < count; ++k) {
    bool found = false;
    for (int tries = 0; tries < most_tries_per_random_ball && !found; ++tries) {
      const double x = gas.radius + (gas.width - diameter) * unit_interval(generator);
      const double y = gas.radius + (gas.height - diameter) * unit_interval(generator);
      if (placed.free(x, y)) {
        gas.balls.push_back(Ball{x, y, 0, 0, gas.time});  // its row written at T
        placed.file(gas.balls.size() - 1);
        found = true;
      }
    }
    if (!found) {
      fail(scene,
           fmt::format("'random' found no free place for ball {} in {} tries ({} "
                       "balls would cover {:.3g} of the table; random placement "
                       "rarely gets past 0.5)",
                       gas.balls.size() + 1, most_tries_per_random_ball, total, covered));
    }
  }
}

// 'lattice': the centres on a lattice of columns x rows points filling the
// table (a point every A1 / columns across and A2 / rows down, the first
// half a spacing from the walls), as square as the table allows, filled row
// by row. Refused if two neighbours would touch or a point is not free of
// the 'ball' lines' balls.
void place_on_lattice(const SceneDescription& scene, Gas& gas) {
  const std::size_t count = scene.random->count;
  const auto n = static_cast<double>(count);
  const double across = std::ceil(std::sqrt(n * gas.width / gas.height));
  const double down = std::ceil(n / across);
  const double dx = gas.width / across, dy = gas.height / down;
  const double diameter = 2 * gas.radius;
  if (dx <= diameter * (1 + contact_tolerance) ||
      dy <= diameter * (1 + contact_tolerance)) {
    fail(scene,
         fmt::format("'lattice' cannot place {} balls of radius {} on a {} x {} "
                     "table: {} x {} points are {:.4g} x {:.4g} apart, less than "
                     "a diameter",
                     count, gas.radius, gas.width, gas.height, across, down, dx, dy));
  }
  PlacedBalls placed(gas, gas.balls.size() + count);
  for (std::size_t k = 0; k < count; ++k) {
    const double column = std::fmod(static_cast<double>(k), across);
    const double row = std::floor(static_cast<double>(k) / across);
    const double x = (column + 0.5) * dx, y = (row + 0.5) * dy;
    if (!placed.free(x, y)) {
      fail(scene, fmt::format("'lattice' point ({}, {}) for ball {} is taken by a 'ball' "
                              "line's ball",
                              x, y, gas.balls.size() + 1));
    }
    gas.balls.push_back(Ball{x, y, 0, 0, gas.time});  // its row written at T
    placed.file(gas.balls.size() - 1);
  }
}

// The velocities of balls `first` on: a direction uniform on the circle (a
// point drawn in the square [-1, 1)^2 until it falls inside the unit disc), a
// speed uniform in [0.5, 1.5) SPEED, or SPEED itself if `same_speed`. A
// component too small to compute with is 0.
void give_velocities(double speed, bool same_speed, std::size_t first,
                     std::mt19937_64& generator, Gas& gas) {
  for (std::size_t k = first; k < gas.balls.size(); ++k) {
    double u = 0, v = 0, square = 0;
    do {
      u = 2 * unit_interval(generator) - 1;
      v = 2 * unit_interval(generator) - 1;
      square = u * u + v * v;
    } while (square == 0 || square > 1);
    const double length = std::sqrt(square);
    const double drawn = same_speed ? speed : speed * (0.5 + unit_interval(generator));
    Ball& ball = gas.balls[k];
    ball.vx = drawn * (u / length);
    ball.vy = drawn * (v / length);
    if (std::fabs(ball.vx) < smallest_magnitude) ball.vx = 0;
    if (std::fabs(ball.vy) < smallest_magnitude) ball.vy = 0;
  }
}

}  // namespace

Gas place_random_balls(const SceneDescription& scene) {
  SceneDescription copy = scene;
  return place_random_balls(std::move(copy));
}

Gas place_random_balls(SceneDescription&& scene) {
  Gas gas = std::move(scene.gas);
  if (!scene.random) return gas;
  const RandomBalls& random = *scene.random;

  // First the check that needs no placing: no packing of discs covers more.
  const double total = static_cast<double>(gas.balls.size() + random.count);
  const double covered =
      total * std::numbers::pi * gas.radius * gas.radius / (gas.width * gas.height);
  if (covered > densest_packing) {
    fail(scene,
         fmt::format("'{}' cannot place {} balls of radius {} on a {} x {} table: "
                     "they would cover {:.3g} of it, more than any packing of discs "
                     "({:.4f})",
                     random.lattice ? "lattice" : "random", random.count, gas.radius,
                     gas.width, gas.height, covered, densest_packing));
  }

  std::mt19937_64 generator(random.seed);
  const std::size_t first = gas.balls.size();
  // R's rows at once, no more: grown ball by ball, the rows would take up to
  // twice their room, and three times while being moved to a larger block.
  gas.balls.reserve(first + random.count);
  if (random.lattice) {
    place_on_lattice(scene, gas);
  } else {
    place_centres(scene, covered, generator, gas);
  }
  give_velocities(random.speed, random.lattice, first, generator, gas);
  return gas;
}

Gas parse_scene(std::string_view text, const std::string& file_name) {
  return place_random_balls(
      parse_scene_description(text, file_name, first_overlap_by_cells));
}

Gas read_scene_file(const std::string& path) {
  return place_random_balls(read_scene_description(path, first_overlap_by_cells));
}

}  // namespace gas
