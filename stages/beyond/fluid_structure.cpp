// The structure of the fluid at one moment. See beyond/fluid_structure.hpp.
#include "beyond/fluid_structure.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "beyond/cell_layout.hpp"

namespace gas {
namespace {

constexpr double unknown = std::numeric_limits<double>::quiet_NaN();

// The value at contact of a quantity measured as q0 on [0, w) and q1 on
// [w, 2w) from contact: the straight line through the two middles, 1.5 q0 -
// 0.5 q1.
double at_contact(double q0, double q1) {
  return 1.5 * q0 - 0.5 * q1;
}

}  // namespace

// [anchor: contact-snapshot]
ContactSnapshot contact_snapshot(const Gas& gas, double time,
                                 const std::array<double, 4>& interior) {
  ContactSnapshot snapshot{unknown, unknown};
  const double a = gas.radius, shell = contact_shell_radii * a;
  const double x_min = interior[0], x_max = interior[1];
  const double y_min = interior[2], y_max = interior[3];
  if (!(x_max > x_min && y_max > y_min)) return snapshot;
  std::vector<Point> centres(gas.balls.size());
  for (std::size_t i = 0; i < centres.size(); ++i)
    centres[i] = centre_at(gas.balls[i], time);

  // The walls x = 0 and x = A1: the centres in the two strips of width
  // `shell` next to each wall's limit (x = a, x = A1 - a), for y inside the
  // interior's range; density = count / (2 walls x strip area).
  double strip[2] = {0, 0};
  for (const Point& p : centres) {
    if (p.y < y_min || p.y > y_max) continue;
    const double gap = std::min(p.x - a, gas.width - a - p.x);  // from the limit
    const double k = std::floor(gap / shell);
    if (k >= 0 && k < 2) strip[static_cast<int>(k)] += 1;
  }
  const double strip_area = 2 * (y_max - y_min) * shell;
  snapshot.wall_contact_density =
      at_contact(strip[0] / strip_area, strip[1] / strip_area);

  // Pairs: each ball of the interior with every ball at 2a ... 2a + 2 shells
  // from it, found in the cells around it; g in a shell is the count over
  // what a uniform gas of the interior's density would put there.
  const double reach = 2 * a + 2 * shell;
  const CellLayout cells = lay_out_cells(gas.width, gas.height, reach,
                                         static_cast<double>(centres.size()) + 16);
  std::vector<std::size_t> head(static_cast<std::size_t>(cells.columns * cells.rows), 0);
  std::vector<std::size_t> next(centres.size(), 0);
  auto cell = [&](int column, int row) {
    return static_cast<std::size_t>(row * cells.columns + column);
  };
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const std::size_t c = cell(cells.column_of(centres[i].x), cells.row_of(centres[i].y));
    next[i] = head[c];
    head[c] = i + 1;
  }
  double pairs[2] = {0, 0};
  double inside = 0;
  // The shells' edges, squared: 2a, 2a + shell, 2a + 2 shells.
  const double edge[3] = {4 * a * a, (2 * a + shell) * (2 * a + shell), reach * reach};
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Point& p = centres[i];
    if (p.x < x_min || p.x > x_max || p.y < y_min || p.y > y_max) continue;
    inside += 1;
    const int column = cells.column_of(p.x), row = cells.row_of(p.y);
    for (int r = std::max(0, row - 1); r <= std::min(cells.rows - 1, row + 1); ++r) {
      for (int c = std::max(0, column - 1); c <= std::min(cells.columns - 1, column + 1);
           ++c) {
        for (std::size_t j = head[cell(c, r)]; j != 0; j = next[j - 1]) {
          const double dx = centres[j - 1].x - p.x, dy = centres[j - 1].y - p.y;
          const double d2 = dx * dx + dy * dy;  // the ball itself: 0, in no shell
          if (d2 >= edge[0] && d2 < edge[1]) pairs[0] += 1;
          if (d2 >= edge[1] && d2 < edge[2]) pairs[1] += 1;
        }
      }
    }
  }
  if (inside > 0) {
    const double density = inside / ((x_max - x_min) * (y_max - y_min));
    auto shell_area = [&](int k) {
      const double r0 = 2 * a + k * shell, r1 = r0 + shell;
      return std::numbers::pi * (r1 * r1 - r0 * r0);
    };
    const double g0 = pairs[0] / (inside * density * shell_area(0));
    const double g1 = pairs[1] / (inside * density * shell_area(1));
    snapshot.pair_contact = at_contact(g0, g1);
  }
  return snapshot;
}
// [/anchor: contact-snapshot]

}  // namespace gas
