// The velocity autocorrelation function. See beyond/velocity_autocorrelation.hpp
// and lessons/16-long-time-tail.md.
#include "beyond/velocity_autocorrelation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

namespace gas {

namespace {

// The first lags, in units of tau_E: close together, where rho falls from 1
// along its initial slope, and read by every origin; from 0.1 on, ten a
// decade (a factor 1.26), read by every fourth.
constexpr double first_lags[] = {0.01, 0.02, 0.03, 0.05, 0.07, 0.1};
constexpr double lags_a_decade = 10;
// Origins this many a tau_E, and every this many of them read every lag.
constexpr double origins_a_time_unit = 4;
constexpr long long fewest_long_every = 4;
// The first origin this many tau_E after the start: about ten pair collisions
// per ball, enough for the speeds to be Maxwell's and the neighbourhoods
// settled.
constexpr double warm_up_time_units = 10;
// The bulk starts this many radii from a wall (the layers at a wall die out
// within a few diameters: lesson 13). Lesson 16's runs were measured with
// 8; the statistics' interior starts at 12 (gas_statistics.hpp), where
// the last of the layers no longer shows in Z.
constexpr double layers = 8;
// Bytes a noted ball takes (Noted).
constexpr double noted_bytes = 20;

}  // namespace

// [anchor: vacf-plan]
VacfPlan plan_vacf(const Gas& gas) {
  VacfPlan plan;
  const auto n = static_cast<double>(gas.balls.size());
  const double kT = gas.balls.empty() ? 0 : kinetic_energy(gas) / n;
  const double eta =
      n * std::numbers::pi * gas.radius * gas.radius / (gas.width * gas.height);
  const EnskogTransport theory = enskog_transport(eta, gas.radius, kT);
  plan.lags = {0};
  if (!(theory.velocity_time > 0) || !std::isfinite(theory.velocity_time)) return plan;
  const double unit = plan.time_unit = theory.velocity_time;
  // The longest lag: 100 tau_E, or what keeps a sound wave's echo from the
  // walls out with a counted region at least half the table across.
  const double shorter_side = std::min(gas.width, gas.height);
  const double longest =
      std::min(longest_lag_in_time_units * unit,
               (shorter_side / 4 - layers * gas.radius) / theory.sound_speed);
  plan.margin = layers * gas.radius + theory.sound_speed * std::max(longest, 0.0);
  for (const double lag : first_lags)
    if (lag * unit <= longest) plan.lags.push_back(lag * unit);
  plan.short_lags = plan.lags.size() - 1;
  for (int k = 1;; ++k) {
    const double lag = 0.1 * std::pow(10.0, k / lags_a_decade) * unit;
    if (lag > longest) break;
    plan.lags.push_back(lag);
  }
  plan.warm_up = warm_up_time_units * unit;
  plan.spacing = unit / origins_a_time_unit;
  // Every fourth origin reads every lag, unless the noted balls of those in
  // progress (the longest lag over their spacing of them) would take more
  // than vacf_memory: then fewer.
  const double counted = std::max(gas.width - 2 * plan.margin, 0.0) *
                         std::max(gas.height - 2 * plan.margin, 0.0) /
                         (gas.width * gas.height) * n;
  const double in_progress = vacf_memory / (counted * noted_bytes);
  plan.long_every = std::max(
      fewest_long_every,
      static_cast<long long>(std::ceil(plan.lags.back() / (in_progress * plan.spacing))));
  return plan;
}
// [/anchor: vacf-plan]

VelocityAutocorrelation::VelocityAutocorrelation(const Gas& gas)
    : VelocityAutocorrelation(gas, plan_vacf(gas)) {}

VelocityAutocorrelation::VelocityAutocorrelation(const Gas& gas, VacfPlan plan)
    : plan_(std::move(plan)),
      radius_(gas.radius),
      width_(gas.width),
      height_(gas.height),
      next_origin_(plan_.spacing > 0 ? gas.time + plan_.warm_up : never),
      counted_until_(gas.balls.size(), -never),
      vacf_(plan_.lags.size()),
      diffusion_(plan_.lags.size()) {}

// [anchor: vacf-hook]
void VelocityAutocorrelation::before_collision(const Gas& gas,
                                               const Collision& collision) {
  if (collision.kind == CollisionKind::none) return;  // nothing more will collide
  if (collision.time > next_due()) take_due(gas, collision.time, false);
  // A counted ball at a wall within its lags: the margin was too small.
  if (collision.kind == CollisionKind::horizontal_wall ||
      collision.kind == CollisionKind::vertical_wall) {
    if (collision.time < counted_until_[collision.first - 1]) ++walls_met_;
  }
}
// [/anchor: vacf-hook]

void VelocityAutocorrelation::before_rows_rewritten(const Gas& gas) {
  take_due(gas, gas.time, true);
  for (Origin& origin : active_)
    if (!origin.balls.empty()) spare_.push_back(std::move(origin.balls));
  first_active_ = next_number_;
  active_.clear();
  due_ = {};
  std::fill(counted_until_.begin(), counted_until_.end(), -never);
  if (plan_.spacing > 0) next_origin_ = gas.time + plan_.spacing;
}

void VelocityAutocorrelation::catch_up(const Gas& gas) {
  take_due(gas, gas.time, true);
}

double VelocityAutocorrelation::next_due() const {
  return due_.empty() ? next_origin_ : std::min(next_origin_, due_.top().time);
}

void VelocityAutocorrelation::take_due(const Gas& gas, double time, bool inclusive) {
  const auto is_due = [&](double t) { return inclusive ? t <= time : t < time; };
  while (true) {
    // Whichever comes first: a new origin or a reading (an origin first at a
    // tie: its lag 0 before anything later).
    if (is_due(next_origin_) && (due_.empty() || next_origin_ <= due_.top().time)) {
      start_origin(gas, next_origin_);
      next_origin_ += plan_.spacing;
    } else if (!due_.empty() && is_due(due_.top().time)) {
      const long long number = due_.top().origin;
      due_.pop();
      read(gas, number);
    } else {
      return;
    }
  }
}

// [anchor: vacf-origin]
void VelocityAutocorrelation::start_origin(const Gas& gas, double time) {
  const long long number = next_number_++;
  if (active_.empty()) first_active_ = number;
  Origin& origin = active_.emplace_back();
  origin.time = time;
  origin.last_lag =
      number % plan_.long_every == 0 ? plan_.lags.size() - 1 : plan_.short_lags;
  if (!spare_.empty()) {
    origin.balls = std::move(spare_.back());
    origin.balls.clear();
    spare_.pop_back();
  }
  // Note every ball whose centre is at least `margin` from every wall now.
  const double low = plan_.margin, right = width_ - plan_.margin,
               top = height_ - plan_.margin;
  const double until = time + plan_.lags[origin.last_lag];
  for (std::size_t i = 0; i < gas.balls.size(); ++i) {
    const Ball& ball = gas.balls[i];
    const Point centre = centre_at(ball, time);
    if (centre.x < low || centre.x > right || centre.y < low || centre.y > top) continue;
    origin.balls.push_back({static_cast<std::uint32_t>(i), static_cast<float>(ball.vx),
                            static_cast<float>(ball.vy), static_cast<float>(centre.x),
                            static_cast<float>(centre.y)});
    counted_until_[i] = std::max(counted_until_[i], until);
  }
  if (origin.balls.empty()) {  // a table with no room for counted balls
    finish(origin);
    return;
  }
  for (const Noted& b : origin.balls)
    origin.square_sum += double{b.vx} * b.vx + double{b.vy} * b.vy;
  // Lag 0: rho = 1 exactly, D = 0.
  vacf_[0].add(1.0);
  diffusion_[0].add(0.0);
  const double count = static_cast<double>(origin.balls.size());
  const double region = (right - low) * (top - low);
  area_fraction_sum_ += count * std::numbers::pi * radius_ * radius_ / region;
  kT_sum_ += origin.square_sum / (2 * count);
  ++origins_done_;
  if (origin.last_lag == 0) {
    finish(origin);
    return;
  }
  due_.push({time + plan_.lags[1], number});
}
// [/anchor: vacf-origin]

// [anchor: vacf-read]
void VelocityAutocorrelation::read(const Gas& gas, long long number) {
  Origin& origin = active_[static_cast<std::size_t>(number - first_active_)];
  const std::size_t k = origin.next_lag;
  const double time = origin.time + plan_.lags[k];
  // Sum v(0) . v(t) and v(0) . (r(t) - r(0)) over the origin's counted balls.
  double velocities = 0, displacements = 0;
  for (const Noted& b : origin.balls) {
    const Ball& ball = gas.balls[b.ball];
    const Point centre = centre_at(ball, time);
    velocities += b.vx * ball.vx + b.vy * ball.vy;
    displacements += b.vx * (centre.x - b.x) + b.vy * (centre.y - b.y);
  }
  vacf_[k].add(velocities / origin.square_sum);
  diffusion_[k].add(displacements / (2 * static_cast<double>(origin.balls.size())));
  if (k < origin.last_lag) {
    ++origin.next_lag;
    due_.push({origin.time + plan_.lags[k + 1], number});
  } else {
    finish(origin);
  }
}
// [/anchor: vacf-read]

void VelocityAutocorrelation::finish(Origin& origin) {
  spare_.push_back(std::move(origin.balls));
  origin.balls.clear();
  origin.last_lag = 0;
  origin.next_lag = 0;  // done
  // The oldest origins done leave the list.
  while (!active_.empty() && active_.front().next_lag == 0) {
    active_.pop_front();
    ++first_active_;
  }
}

std::vector<VacfRow> VelocityAutocorrelation::rows() const {
  std::vector<VacfRow> rows;
  for (std::size_t k = 0; k < plan_.lags.size(); ++k) {
    if (vacf_[k].count() == 0) break;
    rows.push_back({plan_.lags[k],
                    {vacf_[k].mean(), vacf_[k].error()},
                    {diffusion_[k].mean(), diffusion_[k].error()},
                    static_cast<long long>(vacf_[k].count())});
  }
  return rows;
}

double VelocityAutocorrelation::area_fraction() const {
  return origins_done_ == 0 ? not_known
                            : area_fraction_sum_ / static_cast<double>(origins_done_);
}

double VelocityAutocorrelation::kT() const {
  return origins_done_ == 0 ? not_known : kT_sum_ / static_cast<double>(origins_done_);
}

EnskogTransport VelocityAutocorrelation::theory() const {
  return enskog_transport(area_fraction(), radius_, kT());
}

// [anchor: vacf-csv]
std::string vacf_csv(const VelocityAutocorrelation& vacf) {
  fmt::memory_buffer text;
  fmt::format_to(std::back_inserter(text),
                 "t,vacf,vacf_error,vacf_enskog,vacf_tail,diffusion,diffusion_error,"
                 "diffusion_enskog\n");
  const EnskogTransport theory = vacf.theory();
  for (const VacfRow& row : vacf.rows()) {
    fmt::format_to(std::back_inserter(text), "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},",
                   row.lag, row.vacf.value, row.vacf.error, theory.vacf(row.lag),
                   theory.tail(row.lag));
    fmt::format_to(std::back_inserter(text), "{:.17g},{:.17g},{:.17g}\n",
                   row.diffusion.value, row.diffusion.error,
                   theory.diffusion_by(row.lag));
  }
  return fmt::to_string(text);
}
// [/anchor: vacf-csv]

}  // namespace gas
