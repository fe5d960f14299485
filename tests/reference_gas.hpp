// An independent reference for the billiard-ball gas, in any number type.
//
// Written from the article's formulas, not from the stages: every ball is
// moved at every event (the article's way, not the stages' `since`), each
// event found by scanning all walls and pairs, the collision quadratic solved
// in its textbook form (-b - sqrt(D)) / (w.w). Templated on the number type:
// float, double, long double (64-bit mantissa on x86-64) and __float128
// (113-bit, soft float; its square root by Newton's method from the long
// double one, so no extra library).
//
// Used by the suite `high-precision` (how long double precision follows the
// exact motion; tests/test_high_precision.cpp) and by the benchmark's
// sections on number types and time reversal (tests/benchmark/).
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "stage1_data.hpp"

namespace gas::reference {

// One collision: K, N1, N2 and its time, rounded to long double.
struct Event {
  long double time;
  int kind;    // K
  int first;   // N1
  int second;  // N2
  // The same collision: the same K, N1, N2 (times are compared separately).
  bool operator==(const Event& o) const {
    return kind == o.kind && first == o.first && second == o.second;
  }
};

template <class Real>
long double to_long_double(Real x) {
  return static_cast<long double>(x);
}

// Square roots: float, double and long double have one; for __float128
// Newton's method from the long double root doubles the correct bits at each
// step (64 -> 113 in one step, a second one for safety).
template <class Real>
Real root(Real x) {
  return std::sqrt(x);
}
template <>
inline __float128 root(__float128 x) {
  if (x <= 0) return 0;
  __float128 r = std::sqrt(static_cast<long double>(x));
  for (int i = 0; i < 2; ++i) r = (r + x / r) / 2;
  return r;
}

// The gas in the number type Real, moved from event to event.
template <class Real>
class ReferenceGas {
 public:
  struct State {
    Real x, y, vx, vy;
  };
  // The next event: after `dt`, of kind K with balls N1, N2 (K = 0: none).
  struct Next {
    Real dt = -1;
    int kind = 0, first = 0, second = 0;
  };

  explicit ReferenceGas(const Gas& gas)
      : radius_(gas.radius),
        low_(radius_),
        right_(Real(gas.width) - radius_),
        top_(Real(gas.height) - radius_) {
    for (const Ball& b : gas.balls)
      balls_.push_back({Real(b.x), Real(b.y), Real(b.vx), Real(b.vy)});
  }

  Real time() const { return now_; }
  Real radius() const { return radius_; }
  const std::vector<State>& balls() const { return balls_; }

  // Scans every wall and every pair; the first event found wins a tie.
  Next next() const {
    Next best;
    auto offer = [&](Real dt, int k, int i, int j) {
      if (dt >= 0 && (best.dt < 0 || dt < best.dt)) best = {dt, k, i, j};
    };
    const auto n = static_cast<int>(balls_.size());
    for (int i = 0; i < n; ++i) {
      const State& b = balls_[static_cast<std::size_t>(i)];
      if (b.vy > 0) offer((top_ - b.y) / b.vy, 1, i + 1, 0);
      if (b.vy < 0) offer((low_ - b.y) / b.vy, 1, i + 1, 0);
      if (b.vx > 0) offer((right_ - b.x) / b.vx, 2, i + 1, 0);
      if (b.vx < 0) offer((low_ - b.x) / b.vx, 2, i + 1, 0);
    }
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        const State& p = balls_[static_cast<std::size_t>(i)];
        const State& q = balls_[static_cast<std::size_t>(j)];
        const Real dx = q.x - p.x, dy = q.y - p.y, wx = q.vx - p.vx, wy = q.vy - p.vy;
        const Real ww = wx * wx + wy * wy, b = dx * wx + dy * wy;
        const Real c = dx * dx + dy * dy - 4 * radius_ * radius_;
        const Real disc = b * b - ww * c;
        if (b < 0 && disc > 0) offer((-b - root(disc)) / ww, 3, i + 1, j + 1);
      }
    }
    return best;
  }

  // Every ball flies for dt.
  void advance(Real dt) {
    for (State& b : balls_) b.x += b.vx * dt, b.y += b.vy * dt;
    now_ += dt;
  }

  // The collision `e` at the present moment: a wall reverses one component,
  // two balls exchange their velocity components along the line of centres.
  void collide(const Next& e) {
    State& p = balls_[static_cast<std::size_t>(e.first - 1)];
    if (e.kind == 1) p.vy = -p.vy;
    if (e.kind == 2) p.vx = -p.vx;
    if (e.kind == 3) {
      State& q = balls_[static_cast<std::size_t>(e.second - 1)];
      const Real dx = q.x - p.x, dy = q.y - p.y;
      const Real vi = (dx * (q.vx - p.vx) + dy * (q.vy - p.vy)) / (dx * dx + dy * dy);
      p.vx += vi * dx, q.vx -= vi * dx, p.vy += vi * dy, q.vy -= vi * dy;
    }
  }

  // The next event, carried out. Throws if nothing will ever collide.
  Event step() {
    const Next e = next();
    if (e.kind == 0) throw std::runtime_error("the reference gas has no next event");
    advance(e.dt);
    collide(e);
    return {to_long_double(now_), e.kind, e.first, e.second};
  }

  // Every event up to model time `end`, then free flight to it.
  void advance_to(Real end) {
    for (Next e = next(); e.kind != 0 && now_ + e.dt <= end; e = next()) {
      advance(e.dt);
      collide(e);
    }
    advance(end - now_);
  }

  // The B key: every velocity reversed.
  void reverse() {
    for (State& b : balls_) b.vx = -b.vx, b.vy = -b.vy;
  }

  // Kinetic energy (unit mass).
  Real energy() const {
    Real twice = 0;
    for (const State& b : balls_) twice += b.vx * b.vx + b.vy * b.vy;
    return twice / 2;
  }

  // The largest overlap of two balls now, as a fraction of the diameter
  // (0 if none overlaps).
  Real largest_overlap() const {
    Real worst = 0;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
      for (std::size_t j = i + 1; j < balls_.size(); ++j) {
        const Real dx = balls_[j].x - balls_[i].x, dy = balls_[j].y - balls_[i].y;
        const Real gap = 1 - root(dx * dx + dy * dy) / (2 * radius_);
        if (gap > worst) worst = gap;
      }
    }
    return worst;
  }

 private:
  Real radius_, low_, right_, top_;
  std::vector<State> balls_;
  Real now_ = 0;
};

// The first `count` collisions of the gas in the number type Real.
template <class Real>
std::vector<Event> reference_events(const Gas& gas, int count) {
  ReferenceGas<Real> reference(gas);
  std::vector<Event> events;
  while (static_cast<int>(events.size()) < count) events.push_back(reference.step());
  return events;
}

// How many leading collisions two runs share (same K, N1, N2 in order).
inline int agreement(const std::vector<Event>& a, const std::vector<Event>& b) {
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  return static_cast<int>(i);
}

}  // namespace gas::reference
