// Tangent dynamics (beyond the article). See beyond/tangent_dynamics.hpp.
#include "beyond/tangent_dynamics.hpp"

#include <cmath>
#include <random>

namespace gas {

void move_tangent_to(BallTangent& t, double time) {
  const Point dq = tangent_dq_at(t, time);
  t.qx = dq.x;
  t.qy = dq.y;
  t.since = time;
}

// [anchor: reflect-tangent]
void reflect_tangent(BallTangent& t, CollisionKind kind) {
  if (kind == CollisionKind::horizontal_wall) {  // K = 1: the wall is y = const
    t.qy = -t.qy;
    t.py = -t.py;
  } else if (kind == CollisionKind::vertical_wall) {  // K = 2: x = const
    t.qx = -t.qx;
    t.px = -t.px;
  }
}
// [/anchor: reflect-tangent]

// [anchor: collide-tangents]
void collide_tangents(BallTangent& i, BallTangent& j, Point qi, Point qj, Point vi,
                      Point vj) {
  const double dx = qi.x - qj.x, dy = qi.y - qj.y;    // q_ij, of length 2a at contact
  const double sigma = std::sqrt(dx * dx + dy * dy);  // no overflow at table sizes
  const double nx = dx / sigma, ny = dy / sigma;      // n, the line of centres
  const double vx = vi.x - vj.x, vy = vi.y - vj.y;    // v_ij
  const double vn = vx * nx + vy * ny;                // v_ij . n (< 0: approaching)
  // The relative change, and its part along n.
  const double qx = i.qx - j.qx, qy = i.qy - j.qy;  // dq_ij
  const double px = i.px - j.px, py = i.py - j.py;  // dp_ij
  const double qn = qx * nx + qy * ny;              // dq_ij . n
  const double pn = px * nx + py * ny;              // dp_ij . n
  // The time shift: the changed balls touch dt_c later (dq_ij + v_ij dt_c
  // has no part along n), and the normal they touch along is turned by dn.
  const double shift = -qn / vn;                     // dt_c
  const double nx_turn = (qx + vx * shift) / sigma;  // dn, perpendicular to n
  const double ny_turn = (qy + vy * shift) / sigma;
  const double v_turn = vx * nx_turn + vy * ny_turn;  // v_ij . dn
  // Positions: the part of dq_ij along n is exchanged, like the velocities.
  i.qx -= qn * nx;
  i.qy -= qn * ny;
  j.qx += qn * nx;
  j.qy += qn * ny;
  // Momenta: the change of (v_ij . n) n, from dp, from the turn of n twice.
  const double change_x = pn * nx + v_turn * nx + vn * nx_turn;
  const double change_y = pn * ny + v_turn * ny + vn * ny_turn;
  i.px -= change_x;
  i.py -= change_y;
  j.px += change_x;
  j.py += change_y;
}
// [/anchor: collide-tangents]

TangentDynamics::TangentDynamics(const Gas& gas, std::uint64_t seed)
    : balls_(gas.balls.size()) {
  restart(gas.time, seed);
}

void TangentDynamics::restart(double time, std::uint64_t seed) {
  // Gaussian components: a direction uniform on the sphere of 4N dimensions.
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal;
  for (BallTangent& t : balls_)
    t = {normal(random), normal(random), normal(random), normal(random), time};
  const double norm = norm_at(time);
  if (norm > 0) scale_at(time, 1 / norm);
}

void TangentDynamics::before_collision(const Gas& gas, const Collision& collision) {
  if (collision.kind == CollisionKind::none) return;
  const auto first = static_cast<std::size_t>(collision.first - 1);
  BallTangent& i = balls_[first];
  move_tangent_to(i, collision.time);
  if (collision.kind != CollisionKind::balls) {
    reflect_tangent(i, collision.kind);
    return;
  }
  const auto second = static_cast<std::size_t>(collision.second - 1);
  BallTangent& j = balls_[second];
  move_tangent_to(j, collision.time);
  const Ball& p = gas.balls[first];
  const Ball& q = gas.balls[second];
  collide_tangents(i, j, centre_at(p, collision.time), centre_at(q, collision.time),
                   {p.vx, p.vy}, {q.vx, q.vy});
}

double TangentDynamics::norm_at(double time) const {
  double sum = 0;
  for (const BallTangent& t : balls_) {
    const Point dq = tangent_dq_at(t, time);
    sum += dq.x * dq.x + dq.y * dq.y + t.px * t.px + t.py * t.py;
  }
  return std::sqrt(sum);
}

void TangentDynamics::scale_at(double time, double factor) {
  for (BallTangent& t : balls_) {
    move_tangent_to(t, time);
    t.qx *= factor;
    t.qy *= factor;
    t.px *= factor;
    t.py *= factor;
  }
}

void TangentDynamics::reverse_at(double time) {
  for (BallTangent& t : balls_) {
    move_tangent_to(t, time);
    t.px = -t.px;
    t.py = -t.py;
  }
}

}  // namespace gas
