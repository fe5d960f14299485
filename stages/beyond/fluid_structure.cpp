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
ContactSnapshot contact_snapshot(const Gas& gas, double time, const Region& interior) {
  ContactSnapshot snapshot{unknown, unknown};
  if (interior.empty()) return snapshot;
  const double a = gas.radius, shell = contact_shell_radii * a;
  std::vector<Point> centres(gas.balls.size());
  for (std::size_t i = 0; i < centres.size(); ++i)
    centres[i] = centre_at(gas.balls[i], time);

  // The walls x = 0 and x = A1: the centres in the two strips of width
  // `shell` next to each wall's limit (x = a, x = A1 - a), for y inside the
  // interior's range; density = count / (2 walls x strip area).
  double strip[2] = {0, 0};
  for (const Point& p : centres) {
    if (p.y < interior.y_min || p.y > interior.y_max) continue;
    const double gap = std::min(p.x - a, gas.width - a - p.x);  // from the limit
    const double k = std::floor(gap / shell);
    if (k >= 0 && k < 2) strip[static_cast<int>(k)] += 1;
  }
  const double strip_area = 2 * (interior.y_max - interior.y_min) * shell;
  snapshot.wall_contact_density =
      at_contact(strip[0] / strip_area, strip[1] / strip_area);

  // Pairs: each ball of the interior with every ball at 2a ... 2a + 2 shells
  // from it, found in the cells around it; g in a shell is the count over
  // what a uniform gas of the interior's density would put there.
  const double reach = 2 * a + 2 * shell;
  CellLists cells(lay_out_cells(gas.width, gas.height, reach,
                                static_cast<double>(centres.size()) + 16),
                  centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i)
    cells.file(i, centres[i].x, centres[i].y);
  // The shells' edges, squared: 2a, 2a + shell, 2a + 2 shells.
  const double edge[3] = {4 * a * a, (2 * a + shell) * (2 * a + shell), reach * reach};
  double pairs[2] = {0, 0};
  double inside = 0;
  for (const Point& p : centres) {
    if (!interior.contains(p.x, p.y)) continue;
    inside += 1;
    cells.visit_near(p.x, p.y, [&](std::size_t j) {
      const double dx = centres[j].x - p.x, dy = centres[j].y - p.y;
      const double d2 = dx * dx + dy * dy;  // the ball itself: 0, in no shell
      if (d2 >= edge[0] && d2 < edge[1]) pairs[0] += 1;
      if (d2 >= edge[1] && d2 < edge[2]) pairs[1] += 1;
      return true;
    });
  }
  if (inside > 0) {
    const double density = inside / interior.area();
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
