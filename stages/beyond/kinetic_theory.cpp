// Stage 6 — kinetic theory and running averages. See beyond/kinetic_theory.hpp
// and lessons/11-kinetic-theory.md for where each formula comes from.
#include "beyond/kinetic_theory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gas {

namespace {

// Blocks for the errors: at most this many are kept; when they are full,
// neighbours are merged in pairs and each new block takes twice as many
// records. The error is given once there are at least `fewest_blocks`.
constexpr std::size_t most_blocks = 32;
constexpr std::size_t fewest_blocks = 8;

// Histogram range, in units of v_rms: the 2D Maxwell-Boltzmann fraction
// beyond 2.5 v_rms is exp(-6.25) = 0.2 %.
constexpr double histogram_range = 2.5;

}  // namespace

// [anchor: kinetic-formulas]
// 2D Maxwell-Boltzmann (unit mass, k = 1): a velocity is two independent
// normal components of variance kT, so its speed has the Rayleigh density
// f(v) = (v / kT) exp(-v^2 / (2 kT)), mean sqrt(pi kT / 2), mean square 2 kT.
double maxwell_density(double speed, double kT) {
  return speed / kT * std::exp(-speed * speed / (2 * kT));
}

double maxwell_fraction_below(double speed, double kT) {
  return -std::expm1(-speed * speed / (2 * kT));
}

// D. Henderson, "A simple equation of state for hard discs", Molecular
// Physics 30, 971 (1975): Z = P A / (N kT) = (1 + eta^2 / 8) / (1 - eta)^2,
// within about 1 % of simulations of the fluid up to eta ~ 0.65.
double henderson_compressibility(double eta) {
  return (1 + eta * eta / 8) / ((1 - eta) * (1 - eta));
}

// The virial theorem for hard discs of diameter s = 2a (2D):
// Z = 1 + (pi / 2) n s^2 g(s) = 1 + 2 eta g(s), so Henderson's Z gives
// g(s) = (Z - 1) / (2 eta) = (1 - 7 eta / 16) / (1 - eta)^2.
double henderson_contact_value(double eta) {
  return (1 - 7 * eta / 16) / ((1 - eta) * (1 - eta));
}
// [/anchor: kinetic-formulas]

double measured_area(const Gas& gas) {
  return std::max(0.0, gas.width - 2 * gas.radius) *
         std::max(0.0, gas.height - 2 * gas.radius);
}

KineticTheory kinetic_theory(const Gas& gas) {
  KineticTheory t;
  const auto n_balls = static_cast<double>(gas.balls.size());
  if (gas.balls.empty()) return t;
  const double pi = std::numbers::pi;
  const double diameter = 2 * gas.radius;
  t.kT = kinetic_energy(gas) / n_balls;
  t.mean_speed = std::sqrt(pi * t.kT / 2);
  t.rms_speed = std::sqrt(2 * t.kT);
  const double table = gas.width * gas.height;
  t.area_fraction = n_balls * pi * gas.radius * gas.radius / table;
  t.contact_value = henderson_contact_value(t.area_fraction);
  t.compressibility = henderson_compressibility(t.area_fraction);
  const double area = measured_area(gas);
  t.pressure = area > 0 ? t.compressibility * n_balls * t.kT / area : not_known;
  // Enskog's collision rate per ball in 2D: a ball meets the others at
  // contact distance s = 2a across a "cross-section" of length 2s, at the
  // mean relative speed sqrt(pi kT) (that of two Maxwellian velocities), and
  // the density at contact is g(s) times the mean: rate = 2 s n g(s)
  // sqrt(pi kT), n = N / (A1 A2). (Chapman and Cowling's dilute rate with
  // Enskog's factor g; in 2D, e.g. Gass, J. Chem. Phys. 54, 1898 (1971).)
  const double density = n_balls / table;
  t.collision_rate = 2 * diameter * density * t.contact_value * std::sqrt(pi * t.kT);
  t.mean_free_path = t.collision_rate > 0 ? t.mean_speed / t.collision_rate : not_known;
  return t;
}

void WallPush::before_collision(const Gas& gas, const Collision& c) {
  const Ball& first = gas.balls[static_cast<std::size_t>(c.first - 1)];  // N1
  if (c.kind == CollisionKind::horizontal_wall) horizontal += 2 * std::abs(first.vy);
  if (c.kind == CollisionKind::vertical_wall) vertical += 2 * std::abs(first.vx);
}

Tallies tallies(const Control& control, const WallPush& push) {
  return {control.gas.time, push.horizontal, push.vertical, control.ball_collisions};
}

void GasStatistics::Sums::add(const Sums& other) {
  duration += other.duration;
  mean_speed_time += other.mean_speed_time;
  push += other.push;
  ball_collisions += other.ball_collisions;
}

GasStatistics::GasStatistics(const Gas& gas, const Tallies& now, int bins)
    : balls_(gas.balls.size()),
      width_(gas.width - 2 * gas.radius),
      height_(gas.height - 2 * gas.radius),
      last_(now) {
  kT_ = balls_ > 0 ? kinetic_energy(gas) / static_cast<double>(balls_) : 0.0;
  const int count = std::max(bins, 1);
  bin_width_ = histogram_range * std::sqrt(2 * kT_) / count;
  speed_time_.assign(static_cast<std::size_t>(count), 0.0);
  record(gas, now);  // takes the first speeds; adds no time
}

void GasStatistics::record(const Gas& gas, const Tallies& now) {
  Sums step;
  step.duration = now.time - last_.time;
  // The speeds held since the last record.
  step.mean_speed_time = last_mean_speed_ * step.duration;
  for (const int bin : last_bin_) {
    if (bin < bins()) {
      speed_time_[static_cast<std::size_t>(bin)] += step.duration;
    } else {
      beyond_time_ += step.duration;
    }
  }
  // The wall push, weighted so that push / duration is the pressure: half
  // the push on the two walls x = 0, x = A1 per unit of their length A2 - 2a
  // plus the same for y, averaged over the two directions (lesson 11).
  if (width_ > 0 && height_ > 0) {
    step.push = (now.vertical_wall_push - last_.vertical_wall_push) / (4 * height_) +
                (now.horizontal_wall_push - last_.horizontal_wall_push) / (4 * width_);
  }
  step.ball_collisions = now.ball_collisions - last_.ball_collisions;
  last_ = now;

  // The speeds from now on.
  last_bin_.resize(gas.balls.size());
  double speed_sum = 0;
  for (std::size_t i = 0; i < gas.balls.size(); ++i) {
    const double speed = std::hypot(gas.balls[i].vx, gas.balls[i].vy);
    speed_sum += speed;
    const double bin = bin_width_ > 0 ? std::floor(speed / bin_width_) : 0.0;
    last_bin_[i] = static_cast<int>(std::min(bin, static_cast<double>(bins())));
  }
  last_mean_speed_ = balls_ > 0 ? speed_sum / static_cast<double>(balls_) : 0.0;

  if (step.duration <= 0 && step.push == 0 && step.ball_collisions == 0) return;
  total_.add(step);
  block_.add(step);
  if (++block_records_ == records_per_block_) {
    blocks_.push_back(block_);
    block_ = Sums{};
    block_records_ = 0;
    if (blocks_.size() == most_blocks) {  // merge pairs: half as many, twice as long
      for (std::size_t i = 0; i < most_blocks / 2; ++i) {
        blocks_[i] = blocks_[2 * i];
        blocks_[i].add(blocks_[2 * i + 1]);
      }
      blocks_.resize(most_blocks / 2);
      records_per_block_ *= 2;
    }
  }
}

// The time average of a quantity q = (a sum) / duration, over everything
// recorded; its error from the spread of the finished blocks' averages: for
// B blocks of durations w_b and averages q_b, the standard error of the
// weighted mean, sqrt(B / (B - 1) * sum w_b^2 (q_b - q)^2) / sum w_b. The
// blocks must be longer than the time over which q stays correlated; blocks
// that grow with the run ensure it in the end (lesson 11).
Average GasStatistics::average(double (*of)(const Sums&, const GasStatistics&)) const {
  Average result;
  if (total_.duration <= 0) return result;
  result.value = of(total_, *this);
  if (blocks_.size() < fewest_blocks) return result;
  Sums finished;
  for (const Sums& b : blocks_) finished.add(b);
  const double mean = of(finished, *this);
  double spread = 0;
  for (const Sums& b : blocks_) {
    if (b.duration <= 0) return result;
    const double deviation = of(b, *this) - mean;
    spread += b.duration * b.duration * deviation * deviation;
  }
  const auto count = static_cast<double>(blocks_.size());
  result.error = std::sqrt(count / (count - 1) * spread) / finished.duration;
  return result;
}

Average GasStatistics::mean_speed() const {
  return average(
      [](const Sums& s, const GasStatistics&) { return s.mean_speed_time / s.duration; });
}

Average GasStatistics::pressure() const {
  return average([](const Sums& s, const GasStatistics&) { return s.push / s.duration; });
}

Average GasStatistics::compressibility() const {
  return average([](const Sums& s, const GasStatistics& g) {
    const double balls = static_cast<double>(g.balls_);
    return s.push / s.duration * g.width_ * g.height_ / (balls * g.kT_);
  });
}

Average GasStatistics::collision_rate() const {
  return average([](const Sums& s, const GasStatistics& g) {
    return 2 * static_cast<double>(s.ball_collisions) /
           (static_cast<double>(g.balls_) * s.duration);
  });
}

std::vector<double> GasStatistics::speed_fractions() const {
  std::vector<double> fractions(speed_time_.size(), 0.0);
  const double ball_time = total_.duration * static_cast<double>(balls_);
  if (ball_time <= 0) return fractions;
  for (std::size_t i = 0; i < fractions.size(); ++i)
    fractions[i] = speed_time_[i] / ball_time;
  return fractions;
}

double GasStatistics::fraction_beyond() const {
  const double ball_time = total_.duration * static_cast<double>(balls_);
  return ball_time > 0 ? beyond_time_ / ball_time : 0.0;
}

}  // namespace gas
