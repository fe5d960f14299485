// The largest Lyapunov exponent (beyond the article). See beyond/lyapunov.hpp.
#include "beyond/lyapunov.hpp"

#include <algorithm>
#include <cmath>

namespace gas {

LyapunovExponent::LyapunovExponent(const Gas& gas, std::uint64_t seed)
    : seed_(seed), tangent_(gas, seed), balls_(gas.balls.size()) {
  start_warm_up(gas.time);
}

void LyapunovExponent::start_warm_up(double time) {
  warm_up_start_ = time;
  warm_up_until_ =
      collisions_ + warm_up_collisions_per_ball * static_cast<long long>(balls_);
  interval_ = 0;
  batches_.clear();
  clear_at_next_ = false;
}

// [anchor: benettin]
void LyapunovExponent::sample_at(double time) {
  // Benettin's step: the norm the change has grown to in dT, then back to 1.
  const double norm = tangent_.norm_at(time);
  tangent_.scale_at(time, 1 / norm);
  if (clear_at_next_) {  // the key A: averages from here on
    batches_.clear();
    clear_at_next_ = false;
  }
  // The collisions of the stretch averaged: from the T_k that began it.
  if (batches_.count() == 0) first_collision_ = last_collision_;
  batches_.add(std::log(norm) / interval_);
  last_collision_ = collisions_;
}

void LyapunovExponent::before_collision(const Gas& gas, const Collision& collision) {
  if (collision.kind == CollisionKind::none) return;
  // The moments T_k passed before this collision: the changes fly to T_k.
  while (interval_ > 0 && collision.time >= next_) {
    sample_at(next_);
    next_ += interval_;
  }
  tangent_.before_collision(gas, collision);
  ++collisions_;
  if (interval_ > 0) return;
  // The warm-up: the change turns towards the fastest direction; brought
  // back to norm 1 every N collisions (no sample), and at its end dT set.
  if (collisions_ % static_cast<long long>(std::max<std::size_t>(balls_, 1)) == 0)
    tangent_.scale_at(collision.time, 1 / tangent_.norm_at(collision.time));
  if (collisions_ >= warm_up_until_ && collision.time > warm_up_start_) {
    interval_ = (collision.time - warm_up_start_) / warm_up_collisions_per_ball;
    tangent_.scale_at(collision.time, 1 / tangent_.norm_at(collision.time));
    next_ = collision.time + interval_;
    batches_.clear();
    first_collision_ = last_collision_ = collisions_;
  }
}
// [/anchor: benettin]

void LyapunovExponent::before_rows_rewritten(const Gas& gas) {
  ++seed_;
  tangent_.restart(gas.time, seed_);
  start_warm_up(gas.time);
}

void LyapunovExponent::restart() {
  if (interval_ > 0) clear_at_next_ = true;
}

LyapunovFigures LyapunovExponent::measured(const Gas& /*gas*/) const {
  LyapunovFigures f;
  f.warming_up = interval_ == 0;
  f.samples = static_cast<long long>(batches_.count());
  if (f.samples == 0) return f;
  f.exponent.value = batches_.mean();
  f.exponent.error = batches_.error();
  if (std::isnan(f.exponent.error)) {
    f.exponent.status = ErrorStatus::short_batches;
    f.exponent.why_no_error = "not yet";
  } else {
    f.exponent.status = ErrorStatus::known;
  }
  const double duration = static_cast<double>(f.samples) * interval_;
  f.collision_rate = static_cast<double>(last_collision_ - first_collision_) / duration;
  if (!(f.collision_rate > 0)) return f;
  f.per_collision = f.exponent.value / f.collision_rate;
  const auto n = static_cast<double>(balls_);
  f.per_collision_per_ball = f.per_collision * n;
  f.per_collision_per_ball_error = f.exponent.error / f.collision_rate * n;
  return f;
}

double precision_horizon(double per_collision_per_ball, double distance, double epsilon) {
  return std::log(distance / epsilon) / per_collision_per_ball;
}

double coordinate_ulp(const Gas& gas, int mantissa_digits) {
  const double size = std::max(gas.width, gas.height);
  return std::ldexp(1.0, std::ilogb(size) - mantissa_digits + 1);
}

}  // namespace gas
