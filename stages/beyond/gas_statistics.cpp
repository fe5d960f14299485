// The measured side of the statistics screen. See beyond/gas_statistics.hpp
// and lessons/13-box-and-bulk.md.
#include "beyond/gas_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "beyond/boltzmann_h.hpp"
#include "beyond/box_modes.hpp"
#include "beyond/enskog_transport.hpp"
#include "beyond/fluid_structure.hpp"
#include "beyond/hard_disc_fluid.hpp"
#include "beyond/kinetic_theory.hpp"
#include "beyond/speed_relaxation.hpp"
#include "beyond/wall_push.hpp"

namespace gas {
namespace {

// Histogram range, in units of v_rms: the 2D Maxwell-Boltzmann fraction
// beyond 2.5 v_rms is exp(-6.25) = 0.2 %.
constexpr double histogram_range = 2.5;

// A ball's speed. (Not std::hypot, which guards against overflow at several
// times the cost: stage 2 keeps velocities below 1e75, whose squares a
// double holds.)
double speed_of(const Ball& ball) {
  return std::sqrt(ball.vx * ball.vx + ball.vy * ball.vy);
}

}  // namespace

// [anchor: warm-up]
long long warm_up_collisions_a_ball(const Gas& gas) {
  const auto n = static_cast<double>(gas.balls.size());
  if (gas.balls.size() < 2) return 0;
  // The mean free path of kinetic theory at N / (A1 A2): lambda = <v> / rate,
  // Enskog's rate (beyond/kinetic_theory.hpp); kT drops out.
  const double eta =
      n * std::numbers::pi * gas.radius * gas.radius / (gas.width * gas.height);
  const double path = enskog_mean_free_path(eta, gas.radius);
  const double crossing = std::max(gas.width, gas.height) / path;  // L / lambda
  if (!std::isfinite(crossing)) return fewest_warm_up_collisions;
  return std::max(fewest_warm_up_collisions, static_cast<long long>(std::ceil(crossing)));
}
// [/anchor: warm-up]

GasStatistics::Sums GasStatistics::Sums::minus(const Sums& earlier) const {
  return {duration - earlier.duration,
          speed_time - earlier.speed_time,
          push_x - earlier.push_x,
          push_y - earlier.push_y,
          push_x_middle - earlier.push_x_middle,
          virial - earlier.virial,
          interior_virial - earlier.interior_virial,
          interior_time - earlier.interior_time,
          interior_energy - earlier.interior_energy,
          interior_speed - earlier.interior_speed,
          beside_time - earlier.beside_time,
          beside_energy - earlier.beside_energy,
          ball_collisions - earlier.ball_collisions,
          interior_collisions - earlier.interior_collisions};
}

GasStatistics::GasStatistics(const Gas& gas, int bins, bool warm_up,
                             bool structure_curves)
    : balls_(gas.balls.size()),
      radius_(gas.radius),
      width_(gas.width - 2 * gas.radius),
      height_(gas.height - 2 * gas.radius),
      last_time_(gas.time) {
  const auto n = static_cast<double>(balls_);
  kT_ = balls_ > 0 ? kinetic_energy(gas) / n : 0.0;
  // The interior: centres at least interior_margin_radii from every wall.
  const double margin = interior_margin_radii * gas.radius;
  interior_ = {margin, gas.width - margin, margin, gas.height - margin};
  // The strips beside the walls' middles: the interior's first
  // interior_margin_radii a along each of the two walls (its layers by the
  // wall are left out with the margin). The push on a wall's middle follows
  // the pressure of the gas just in front of it, slow sound waves included;
  // the interior as a whole averages those waves away (lesson 14).
  const double strip = std::min(margin, (interior_.x_max - interior_.x_min) / 4);
  beside_left_ = {interior_.x_min, interior_.x_min + strip, interior_.y_min,
                  interior_.y_max};
  beside_right_ = {interior_.x_max - strip, interior_.x_max, interior_.y_min,
                   interior_.y_max};
  structure_ = FluidStructure(gas, interior_, structure_curves);
  const int count = std::max(bins, 1);
  bin_width_ = histogram_range * std::sqrt(2 * kT_) / count;
  // One entry per bin and one for the speeds beyond the last.
  bin_count_.assign(static_cast<std::size_t>(count) + 1, 0);
  bin_time_.assign(bin_count_.size(), 0.0);
  bin_since_.assign(bin_count_.size(), gas.time);
  counted_.assign(balls_, CountedSpeed{});
  for (std::size_t i = 0; i < balls_; ++i) speed_enters(i, gas.balls[i], gas.time);
  // A sample for the error bars every N collisions: about two a ball.
  collisions_per_sample_ = std::max<long long>(1, static_cast<long long>(balls_));
  heat_time_ = table_heat_time(gas);
  speeds_time_ = speeds_batch_time(gas);
  // The warm-up, in collisions of two balls: each counts for two balls.
  warm_up_per_ball_ = warm_up ? warm_up_collisions_a_ball(gas) : 0;
  warm_up_until_ = (warm_up_per_ball_ * static_cast<long long>(balls_) + 1) / 2;
  if (warm_up_until_ == 0) start_averages(gas);
}

int GasStatistics::bin_of(double speed) const {
  // floor(speed / width), at most bins(): a speed is never negative, so
  // cutting off the fraction (after the bound, which keeps the number small
  // enough for an int) is the floor, and cheaper.
  const double bin = bin_width_ > 0 ? speed / bin_width_ : 0.0;
  return static_cast<int>(std::min(bin, static_cast<double>(bins())));
}

void GasStatistics::count_in_bin(std::size_t bin, double time, long long change) {
  // The bin's ball-time up to now, with the count it had; then the new count.
  bin_time_[bin] += static_cast<double>(bin_count_[bin]) * (time - bin_since_[bin]);
  bin_since_[bin] = time;
  bin_count_[bin] += change;
}

void GasStatistics::speed_enters(std::size_t i, const Ball& ball, double time) {
  const double speed = speed_of(ball);
  const auto bin = static_cast<std::size_t>(bin_of(speed));
  counted_[i] = {speed, ball.vx * ball.vx + ball.vy * ball.vy, bin};
  speed_sum_ += speed;
  count_in_bin(bin, time, +1);
}

void GasStatistics::speed_leaves(std::size_t i, double time) {
  speed_sum_ -= counted_[i].speed;
  count_in_bin(counted_[i].bin, time, -1);
}

// [anchor: interior-time]
// How long the ball's present flight, from its row's moment SINCE (or the
// start of the averages, if later) to `until`, keeps its centre inside
// `region` (the interior, say): the straight line x + vx s, y + vy s cut by
// the region's four sides (for each axis the times between its two sides,
// then the overlap).
double GasStatistics::time_in(const Region& region, const Ball& ball,
                              double until) const {
  const double from = std::max(ball.since, start_);
  // (A table too small has an empty interior: no time in it.)
  if (!(until > from) || region.empty()) return 0;
  double first = 0, last = until - from;  // s, from `from`
  const double x = ball.x + ball.vx * (from - ball.since);
  const double y = ball.y + ball.vy * (from - ball.since);
  // Most flights start and end inside: all of the flight, no cutting. (The
  // region is convex, so a straight flight with both ends in it stays in.)
  if (region.contains(x, y) && region.contains(x + ball.vx * last, y + ball.vy * last))
    return last;
  // Along one axis, the times between the two sides low ... high.
  auto cut = [&](double position, double velocity, double low, double high) {
    if (velocity == 0) {
      if (position < low || position > high) last = -1;  // never inside
      return;
    }
    const double enter = (low - position) / velocity,
                 leave = (high - position) / velocity;
    first = std::max(first, std::min(enter, leave));
    last = std::min(last, std::max(enter, leave));
  };
  cut(x, ball.vx, region.x_min, region.x_max);
  cut(y, ball.vy, region.y_min, region.y_max);
  return std::max(0.0, last - first);
}
// [/anchor: interior-time]

// Does the flight (as time_in takes it) keep its x between the two strips
// beside the walls' middles, clear of both by 1e-9 of the table's width?
// Then time_in gives exactly 0 for each: its roundings move a time by a few
// 1e-16 of the table's width over the speed, far less than the clearance
// (so the answer saves the two cuts and changes no bit).
bool GasStatistics::clear_of_strips(const Ball& ball, double until) const {
  const double from = std::max(ball.since, start_);
  const double x = ball.x + ball.vx * (from - ball.since);
  const double end = x + ball.vx * (until - from);
  const double clearance = 1e-9 * beside_right_.x_max;
  return std::min(x, end) > beside_left_.x_max + clearance &&
         std::max(x, end) < beside_right_.x_min - clearance;
}

// A flight's time inside the interior, and its v^2 and v times that time
// (the speed is constant along a flight: the one counted_ keeps).
void GasStatistics::add_interior_flight(Sums& s, std::size_t i, const Ball& ball,
                                        double until) const {
  const double inside = time_in(interior_, ball, until);
  if (inside == 0) return;
  s.interior_time += inside;
  s.interior_energy += counted_[i].square * inside;
  s.interior_speed += counted_[i].speed * inside;
  // And in the strips beside the walls' middles (inside the interior); most
  // flights keep clear of both, and spend no time in them.
  if (clear_of_strips(ball, until)) return;
  const double beside =
      time_in(beside_left_, ball, until) + time_in(beside_right_, ball, until);
  s.beside_time += beside;
  s.beside_energy += counted_[i].square * beside;
}

// [anchor: collision-sums]
void GasStatistics::before_collision(const Gas& gas, const Collision& c) {
  // The structure's snapshots due before TC, while the flights still reach them.
  const double t = c.time;
  if (averaging_) structure_.catch_up(gas, t);
  // The sums up to TC, with the speeds held until then.
  sums_.duration += t - last_time_;
  sums_.speed_time += speed_sum_ * (t - last_time_);
  last_time_ = t;
  // A bounce reverses the velocity's component across the wall: the two
  // walls of a pair, each (A2 - 2a) or (A1 - 2a) long for the centres,
  // receive 2 |v_normal| (unit mass). A bounce keeps the speed.
  const Ball& first = gas.balls[static_cast<std::size_t>(c.first - 1)];  // N1
  if (c.kind == CollisionKind::vertical_wall && height_ > 0) {
    sums_.push_x += 2 * std::abs(first.vx) / (2 * height_);
    // The middles of these walls, away from the corners (the contact theorem).
    const double y = centre_at(first, t).y;
    const double middle = interior_.y_max - interior_.y_min;
    if (middle > 0 && y >= interior_.y_min && y <= interior_.y_max)
      sums_.push_x_middle += 2 * std::abs(first.vx) / (2 * middle);
  }
  if (c.kind == CollisionKind::horizontal_wall && width_ > 0)
    sums_.push_y += 2 * std::abs(first.vy) / (2 * width_);
  // The flights that end here, and the speeds that change.
  add_interior_flight(sums_, static_cast<std::size_t>(c.first - 1), first, t);
  if (c.kind == CollisionKind::balls) {
    const Ball& second = gas.balls[static_cast<std::size_t>(c.second - 1)];  // N2
    add_interior_flight(sums_, static_cast<std::size_t>(c.second - 1), second, t);
    speed_leaves(static_cast<std::size_t>(c.first - 1), t);  // the old speeds leave
    speed_leaves(static_cast<std::size_t>(c.second - 1), t);
    before_v_ = {first.vx, first.vy};
  }
}

void GasStatistics::after_collision(const Gas& gas, const Collision& c) {
  if (c.kind == CollisionKind::balls) {
    const Ball& p = gas.balls[static_cast<std::size_t>(c.first - 1)];
    const Ball& q = gas.balls[static_cast<std::size_t>(c.second - 1)];
    speed_enters(static_cast<std::size_t>(c.first - 1), p, c.time);  // the new come in
    speed_enters(static_cast<std::size_t>(c.second - 1), q, c.time);
    // The collision virial: the push one ball gave the other, dv of N1,
    // along d = r1 - r2 at contact: d . dv = 2a |dv| (positive).
    const double dx = p.x - q.x, dy = p.y - q.y;  // both written at TC
    const double virial = dx * (p.vx - before_v_[0]) + dy * (p.vy - before_v_[1]);
    sums_.virial += virial;
    if (interior_.contains((p.x + q.x) / 2, (p.y + q.y) / 2)) {
      sums_.interior_virial += virial;
      ++sums_.interior_collisions;
    }
    ++sums_.ball_collisions;
    ++ball_collisions_;
  }
  // Every N collisions the sum of the speeds is added up afresh, so that the
  // round-off of taking out and putting in never accumulates.
  if (++collisions_ % static_cast<long long>(std::max<std::size_t>(balls_, 1)) == 0) {
    speed_sum_ = 0;
    for (const CountedSpeed& counted : counted_) speed_sum_ += counted.speed;
  }
  if (!averaging_) {
    if (ball_collisions_ >= warm_up_until_) start_averages(gas);
    return;
  }
  // Every N collisions, a sample for the error bars.
  if (++sample_collisions_ < collisions_per_sample_) return;
  take_sample(gas, c.time);
}
// [/anchor: collision-sums]

// [anchor: error-samples]
// A sample for the error bars: each quantity over the last N collisions, to
// its blocking analysis. The quantities that follow the table's heat get
// batches at least table_heat_time long (blocking.hpp, rule 2), the mean
// speed batches of speeds_batch_collisions per ball: in samples of the mean
// length so far.
void GasStatistics::take_sample(const Gas& gas, double time) {
  const Sums now = sums_at(gas, time);
  const Sums sample = now.minus(sample_start_);
  sample_start_ = now;
  sample_collisions_ = 0;
  if (!(sample.duration > 0)) return;
  const auto samples = static_cast<double>(blocking_[mean_speed_q].count() + 1);
  const double sample_time = now.duration / samples;  // model time a sample
  auto in_samples = [sample_time](double batch_time) {
    const double batch = std::isfinite(batch_time) ? batch_time / sample_time : 1;
    return static_cast<std::size_t>(std::max(1.0, std::ceil(batch)));
  };
  const std::size_t heat_batch = in_samples(heat_time_);
  const std::size_t speeds_batch = in_samples(speeds_time_);
  for (int q = 0; q < quantity_count; ++q) {
    BlockingAnalysis& blocking = blocking_[static_cast<std::size_t>(q)];
    if (follows_table_heat(static_cast<Quantity>(q)))
      blocking.set_shortest_batch(heat_batch);
    if (follows_speeds(static_cast<Quantity>(q)))
      blocking.set_shortest_batch(speeds_batch);
    const double value = value_of(static_cast<Quantity>(q), sample);
    if (std::isfinite(value)) blocking.add(value);
  }
}
// [/anchor: error-samples]

void GasStatistics::start_averages(const Gas& gas) {
  averaging_ = true;
  // Flights and the histogram count from now; the speeds held until now
  // are forgotten.
  start_ = last_time_ = gas.time;
  sums_ = Sums{};
  std::fill(bin_time_.begin(), bin_time_.end(), 0.0);
  std::fill(bin_since_.begin(), bin_since_.end(), start_);
  sample_start_ = Sums{};
  sample_collisions_ = 0;
  for (BlockingAnalysis& b : blocking_) b.clear();
  structure_.restart(start_);
}

void GasStatistics::restart(const Gas& gas) {
  start_averages(gas);
}

void GasStatistics::before_rows_rewritten(const Gas& gas) {
  if (averaging_) structure_.catch_up(gas, gas.time);
  for (std::size_t i = 0; i < balls_; ++i)
    add_interior_flight(sums_, i, gas.balls[i], gas.time);
}

GasStatistics::Sums GasStatistics::sums_at(const Gas& gas, double now) const {
  Sums s = sums_;
  s.duration += now - last_time_;
  s.speed_time += speed_sum_ * (now - last_time_);
  for (std::size_t i = 0; i < balls_; ++i) add_interior_flight(s, i, gas.balls[i], now);
  return s;
}

// [anchor: measured-quantities]
double GasStatistics::value_of(Quantity q, const Sums& s) const {
  const double n = static_cast<double>(balls_), t = s.duration;
  const double pressure_x = s.push_x / t, pressure_y = s.push_y / t;
  // The interior: its eta from the ball-time inside; its own kT from the
  // balls' v^2 there (<v^2> = 2 kT); Z = P / (n kT) from its virial at that
  // kT; the rate per ball from its collisions (both balls) per ball-time
  // inside. (The interior's kT is the box's on average, but it wanders
  // slowly, heat crossing the table, and its density with it: measured at
  // its own kT the interior's Z follows its own eta, and the difference from
  // the theory at eta_int loses that slow wandering; lesson 14.)
  const double a2 = radius_ * radius_;
  const double eta = s.interior_time / t / interior_.area() * std::numbers::pi * a2;
  const double kT_inside = s.interior_energy / (2 * s.interior_time);
  const double bulk_z = 1 + s.interior_virial / (2 * kT_inside * s.interior_time);
  const double rate = 2 * static_cast<double>(s.interior_collisions) / s.interior_time;
  switch (q) {
    case mean_speed_q:
      return s.speed_time / (t * n);
    case pressure_box_q:  // the two directions averaged
      return (pressure_x + pressure_y) / 2;
    case pressure_box_x_q:
      return pressure_x;
    case pressure_box_y_q:
      return pressure_y;
    case box_z_walls_q:  // P A_c / (N kT), A_c = (A1 - 2a)(A2 - 2a)
      return (pressure_x + pressure_y) / 2 * width_ * height_ / (n * kT_);
    case box_z_virial_q:  // P A_c = N kT + (sum of d . dv) / (2 t), in 2D
      return 1 + s.virial / (2 * t * n * kT_);
    case bulk_z_q:  // the same for the interior, N_int t = its ball-time
      return bulk_z;
    case bulk_z_minus_theory_q:  // against the reference at this stretch's eta,
                                 // for a closed box of N balls
      return bulk_z - fixed_count_compressibility(eta, balls_);
    case interior_eta_q:  // n_int pi a^2
      return eta;
    case interior_kT_q:
      return kT_inside;
    case collision_rate_box_q:
      return 2 * static_cast<double>(s.ball_collisions) / (n * t);
    case collision_rate_q:
      return rate;
    case collision_rate_minus_theory_q:
      return rate - enskog_collision_rate(eta, radius_, kT_inside) *
                        fixed_count_rate_factor(eta, balls_);
    case mean_free_path_q:  // the interior's mean speed over its rate
      return s.interior_speed / s.interior_time / rate;
    case wall_middle_pressure_q:
      return s.push_x_middle / t;
    case pressure_minus_theory_q: {  // against the bulk's P = Z n kT in front
      // of the middles, at this stretch's eta and kT there, Z for N balls
      const double eta_beside = value_of(beside_walls_eta_q, s);
      return s.push_x_middle / t - fixed_count_compressibility(eta_beside, balls_) *
                                       eta_beside * value_of(beside_walls_kT_q, s) /
                                       (std::numbers::pi * a2);
    }
    case beside_walls_eta_q:
      return s.beside_time / t / (beside_left_.area() + beside_right_.area()) *
             std::numbers::pi * a2;
    case beside_walls_kT_q:
      return s.beside_energy / (2 * s.beside_time);
    case mean_free_path_minus_theory_q:
      return s.interior_speed / s.interior_time / rate -
             enskog_mean_free_path(eta, radius_) / fixed_count_rate_factor(eta, balls_);
    case quantity_count:
      break;
  }
  return not_known;
}
// [/anchor: measured-quantities]

bool GasStatistics::follows_table_heat(Quantity q) {
  switch (q) {
    case mean_speed_q:
    case bulk_z_minus_theory_q:
    case collision_rate_minus_theory_q:
    case pressure_minus_theory_q:
    case mean_free_path_minus_theory_q:
    case collision_rate_box_q:
    case quantity_count:
      return false;
    default:
      return true;
  }
}

bool GasStatistics::follows_speeds(Quantity q) {
  return q == mean_speed_q;
}

// Where each quantity goes among the figures (a switch, so that the compiler
// names any quantity left out).
Average& GasStatistics::average_of(MeasuredFigures& m, Quantity q) {
  switch (q) {
    case mean_speed_q:
      return m.mean_speed;
    case pressure_box_q:
      return m.pressure_box;
    case pressure_box_x_q:
      return m.pressure_box_x;
    case pressure_box_y_q:
      return m.pressure_box_y;
    case box_z_walls_q:
      return m.box_z_walls;
    case box_z_virial_q:
      return m.box_z_virial;
    case bulk_z_q:
      return m.bulk_z;
    case bulk_z_minus_theory_q:
      return m.bulk_z_minus_theory;
    case interior_eta_q:
      return m.interior_area_fraction;
    case interior_kT_q:
      return m.interior_kT;
    case collision_rate_box_q:
      return m.collision_rate_box;
    case collision_rate_q:
      return m.collision_rate;
    case collision_rate_minus_theory_q:
      return m.collision_rate_minus_theory;
    case mean_free_path_q:
      return m.mean_free_path;
    case wall_middle_pressure_q:
      return m.wall_middle_pressure;
    case pressure_minus_theory_q:
      return m.pressure_minus_theory;
    case beside_walls_eta_q:
      return m.beside_walls_eta;
    case beside_walls_kT_q:
      return m.beside_walls_kT;
    case mean_free_path_minus_theory_q:
      return m.mean_free_path_minus_theory;
    case quantity_count:
      break;
  }
  throw std::logic_error("GasStatistics: no such quantity");
}

Average average_with_error(const BlockingAnalysis& samples, double scale) {
  Average average{scale * samples.mean(), scale * samples.error()};
  average.status = samples.status();
  average.batch_error = scale * samples.batch_error();
  if (std::isnan(average.error)) {
    average.why_no_error =
        average.status == ErrorStatus::few_samples ? "few samples" : "not yet";
  }
  return average;
}

namespace {

// A theory's error in place of the batches', while they are too short.
void take_theory_error(Average& average, double error) {
  if (average.status != ErrorStatus::short_batches || !std::isfinite(error)) return;
  average.error = error;
  average.why_no_error = nullptr;
  average.from_theory = true;
}

}  // namespace

// [anchor: box-theory-errors]
// The slow figures of the interior wander with the box's longest waves of
// heat and sound, which the batches cannot see until they are as long as
// the table's heat time (blocking.hpp, rule 2). Until then their errors
// come from linear hydrodynamics at the interior's own eta and the gas's
// kT, with Enskog's transport (beyond/box_modes.hpp), over the time
// averaged, its short part replaced by what the run's own batches see
// (corrected_by_batches: hydrodynamics is short of the truth within a free
// time or two, where the balls do not yet move as a fluid). Z follows
// eta_int (Z - Z_ref(eta_int) forgets within a few collisions a ball): its
// error is dZ/deta times eta_int's, beside that difference's own. Once the
// batches are long enough, or if the test sees them correlated, the
// blocking rule speaks, and the sums over the waves are not needed. The
// interior's collision rate and free path follow eta_int and kT_int
// (Enskog's rate goes as eta g(2a+) sqrt(kT), the free path as 1 / (eta
// g)): their slow errors come from those two's and their correlation. The
// push on the walls' middles takes the theory alone (beyond/wall_push.hpp):
// its short batches see the noise of single bounces, which the sound they
// send cancels over a few crossings of the table.
void GasStatistics::add_box_theory(MeasuredFigures& m) const {
  auto short_batches = [](const Average& a) {
    return a.status == ErrorStatus::short_batches;
  };
  const bool interior_short = short_batches(m.interior_area_fraction) ||
                              short_batches(m.interior_kT) || short_batches(m.bulk_z) ||
                              short_batches(m.collision_rate) ||
                              short_batches(m.mean_free_path);
  const bool push_short = short_batches(m.wall_middle_pressure);
  if (!interior_short && !push_short) return;
  const double eta = m.interior_area_fraction.value;
  const EnskogTransport e = enskog_transport(eta, radius_, kT_);
  BoxHydrodynamics fluid;
  fluid.density = e.density;
  fluid.kT = kT_;
  fluid.structure_factor = 1 / (hard_disc_fluid_compressibility(eta) +
                                eta * hard_disc_fluid_compressibility_slope(eta));
  fluid.heat_capacity_ratio = e.heat_capacity_ratio;
  fluid.sound_speed = e.sound_speed;
  fluid.thermal_diffusivity = e.thermal_diffusivity;
  fluid.sound_attenuation = e.sound_attenuation;
  const double width = width_ + 2 * radius_, height = height_ + 2 * radius_;  // A1, A2
  if (interior_short) {
    auto wander = [&](double duration) {
      return interior_wander(fluid, radius_, width, height, interior_, duration);
    };
    // eta_int and kT_int come from the same samples: the same batches.
    const Average& eta_int = m.interior_area_fraction;
    const InteriorWander whole = wander(m.duration), one = wander(eta_int.batch_time),
                         all = wander(eta_int.batches * eta_int.batch_time);
    take_theory_error(
        m.interior_area_fraction,
        corrected_by_batches(whole.area_fraction, one.area_fraction, all.area_fraction,
                             eta_int.batches, eta_int.batch_error));
    take_theory_error(m.interior_kT,
                      corrected_by_batches(whole.kT, one.kT, all.kT, eta_int.batches,
                                           m.interior_kT.batch_error));
    const double slope = hard_disc_fluid_compressibility_slope(eta);
    take_theory_error(m.bulk_z, std::hypot(slope * m.interior_area_fraction.error,
                                           m.bulk_z_minus_theory.error));
    // The rate and the free path, each over its own batches: d ln rate =
    // (1 + eta g' / g) d ln eta_int + d ln kT_int / 2; the free path, the
    // interior's mean speed over the rate, loses the kT.
    const double eta_power = 1 + eta * hard_disc_fluid_contact_value_slope(eta) /
                                     hard_disc_fluid_contact_value(eta);
    // Both are sampled with eta_int and wait for the same heat-time batches,
    // so eta_int's batches are theirs: the sums above serve.
    auto follow = [&](Average& figure, double power_of_eta, double power_of_kT) {
      auto relative = [&](const InteriorWander& w) {
        return std::abs(figure.value) *
               following_wander(w, eta, kT_, power_of_eta, power_of_kT);
      };
      take_theory_error(
          figure, corrected_by_batches(relative(whole), relative(one), relative(all),
                                       figure.batches, figure.batch_error));
    };
    follow(m.collision_rate, eta_power, 0.5);
    follow(m.mean_free_path, -eta_power, 0);
  }
  if (push_short) {
    const Viscosities viscosities{e.shear_viscosity, e.bulk_viscosity};
    take_theory_error(
        m.wall_middle_pressure,
        middles_push_wander(fluid, viscosities, radius_, width, height,
                            {interior_.y_min, interior_.y_max}, m.duration));
  }
}
// [/anchor: box-theory-errors]

// The mean speed forgets within a few collisions a ball, but its batches
// wait for 25 pair collisions per ball (speeds_batch_collisions); until 16
// of them fit, its error is kinetic theory's (beyond/speed_relaxation.hpp:
// the speeds' shape at fixed energy, erased by Enskog's collisions) at the
// whole table's eta, where the balls it averages are.
void GasStatistics::add_speeds_theory(MeasuredFigures& m) const {
  const double table = (width_ + 2 * radius_) * (height_ + 2 * radius_);
  const double eta =
      static_cast<double>(balls_) * std::numbers::pi * radius_ * radius_ / table;
  take_theory_error(m.mean_speed,
                    mean_speed_wander(eta, radius_, kT_, balls_, m.duration).error);
}

MeasuredFigures GasStatistics::measured(const Gas& gas) const {
  MeasuredFigures m;
  // H of the speeds now: from the histogram's counts.
  std::vector<double> counts(bin_count_.begin(), bin_count_.end() - 1);
  m.h_now = boltzmann_h(counts, static_cast<double>(bin_count_.back()), bin_width_, kT_);
  m.speed_fractions.assign(static_cast<std::size_t>(bins()), 0.0);
  m.bin_width = bin_width_;
  m.warming_up = !averaging_;
  m.warm_up_collisions = warm_up_per_ball_;
  if (!averaging_) return m;
  const double now = gas.time;
  const Sums s = sums_at(gas, now);
  m.since = start_;
  m.duration = s.duration;
  if (!(s.duration > 0)) return m;
  for (int q = 0; q < quantity_count; ++q) {
    Average& average = average_of(m, static_cast<Quantity>(q));
    const BlockingAnalysis& samples = blocking_[static_cast<std::size_t>(q)];
    average = average_with_error(samples);
    average.value = value_of(static_cast<Quantity>(q), s);
    if (const int level = samples.batch_level(); level >= 0) {
      average.batches = static_cast<double>(samples.batches());
      average.batch_time =
          std::ldexp(s.duration / static_cast<double>(samples.count()), level);
    }
  }
  add_box_theory(m);
  add_speeds_theory(m);
  // The snapshots' averages.
  m.pair_contact = average_with_error(structure_.pair_contact());
  m.pair_contact_minus_theory =
      average_with_error(structure_.pair_contact_minus_theory());
  m.wall_contact_pressure = average_with_error(structure_.wall_contact_density(), kT_);
  // The histogram: the ball-time fraction of each bin, to now.
  const double ball_time = s.duration * static_cast<double>(balls_);
  for (std::size_t b = 0; b < bin_count_.size(); ++b) {
    const double fraction =
        (bin_time_[b] + static_cast<double>(bin_count_[b]) * (now - bin_since_[b])) /
        ball_time;
    if (b + 1 < bin_count_.size()) {
      m.speed_fractions[b] = fraction;
    } else {
      m.fraction_beyond = fraction;
    }
  }
  return m;
}

}  // namespace gas
