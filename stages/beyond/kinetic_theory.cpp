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
// collisions. The error is given once there are at least `fewest_blocks`.
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

void GasStatistics::Sums::add(const Sums& other) {
  duration += other.duration;
  speed_time += other.speed_time;
  push += other.push;
  ball_collisions += other.ball_collisions;
}

GasStatistics::Sums GasStatistics::Sums::minus(const Sums& earlier) const {
  return {duration - earlier.duration, speed_time - earlier.speed_time,
          push - earlier.push, ball_collisions - earlier.ball_collisions};
}

GasStatistics::GasStatistics(const Gas& gas, int bins)
    : balls_(gas.balls.size()),
      width_(gas.width - 2 * gas.radius),
      height_(gas.height - 2 * gas.radius),
      start_(gas.time),
      last_time_(gas.time) {
  kT_ = balls_ > 0 ? kinetic_energy(gas) / static_cast<double>(balls_) : 0.0;
  const int count = std::max(bins, 1);
  bin_width_ = histogram_range * std::sqrt(2 * kT_) / count;
  // One entry per bin and one for the speeds beyond the last.
  bin_count_.assign(static_cast<std::size_t>(count) + 1, 0);
  bin_time_.assign(bin_count_.size(), 0.0);
  bin_since_.assign(bin_count_.size(), start_);
  for (const Ball& ball : gas.balls) put_in(ball, start_);
  // A block of about one collision per ball to begin with (lesson 11).
  collisions_per_block_ = std::max<long long>(1, static_cast<long long>(balls_));
}

int GasStatistics::bin_of(double speed) const {
  const double bin = bin_width_ > 0 ? std::floor(speed / bin_width_) : 0.0;
  return static_cast<int>(std::min(bin, static_cast<double>(bins())));
}

void GasStatistics::take_out(const Ball& ball, double time) {
  const double speed = std::hypot(ball.vx, ball.vy);
  speed_sum_ -= speed;
  const auto b = static_cast<std::size_t>(bin_of(speed));
  bin_time_[b] += static_cast<double>(bin_count_[b]) * (time - bin_since_[b]);
  bin_since_[b] = time;
  --bin_count_[b];
}

void GasStatistics::put_in(const Ball& ball, double time) {
  const double speed = std::hypot(ball.vx, ball.vy);
  speed_sum_ += speed;
  const auto b = static_cast<std::size_t>(bin_of(speed));
  bin_time_[b] += static_cast<double>(bin_count_[b]) * (time - bin_since_[b]);
  bin_since_[b] = time;
  ++bin_count_[b];
}

// [anchor: wall-push]
void GasStatistics::before_collision(const Gas& gas, const Collision& c) {
  // The sums up to TC, with the speeds held until then.
  const double t = c.time;
  sums_.duration += t - last_time_;
  sums_.speed_time += speed_sum_ * (t - last_time_);
  last_time_ = t;
  // A bounce reverses the velocity's component across the wall: the wall
  // receives 2 |v_normal| (unit mass). Weighted so that push / duration is
  // the pressure: per unit length of the walls it hits (two walls of length
  // A2 - 2a for K = 2, of A1 - 2a for K = 1), averaged over the two
  // directions (lesson 11). A bounce keeps the speed.
  const Ball& first = gas.balls[static_cast<std::size_t>(c.first - 1)];  // N1
  if (width_ > 0 && height_ > 0) {
    if (c.kind == CollisionKind::horizontal_wall)
      sums_.push += 2 * std::abs(first.vy) / (4 * width_);
    if (c.kind == CollisionKind::vertical_wall)
      sums_.push += 2 * std::abs(first.vx) / (4 * height_);
  }
  if (c.kind == CollisionKind::balls) {
    take_out(first, t);
    take_out(gas.balls[static_cast<std::size_t>(c.second - 1)], t);  // N2
  }
}
// [/anchor: wall-push]

void GasStatistics::after_collision(const Gas& gas, const Collision& c) {
  const double t = c.time;
  if (c.kind == CollisionKind::balls) {
    put_in(gas.balls[static_cast<std::size_t>(c.first - 1)], t);
    put_in(gas.balls[static_cast<std::size_t>(c.second - 1)], t);
    ++sums_.ball_collisions;
  }
  // Every N collisions the sum of the speeds is added up afresh, so that the
  // round-off of taking out and putting in never accumulates (one pass over
  // the balls per N collisions: a few operations per collision on average).
  if (++collisions_ % static_cast<long long>(std::max<std::size_t>(balls_, 1)) == 0) {
    speed_sum_ = 0;
    for (const Ball& ball : gas.balls) speed_sum_ += std::hypot(ball.vx, ball.vy);
  }
  // A block ends after collisions_per_block_ collisions.
  if (++block_collisions_ < collisions_per_block_) return;
  blocks_.push_back(sums_.minus(block_start_));
  block_start_ = sums_;
  block_collisions_ = 0;
  if (blocks_.size() == most_blocks) {  // merge pairs: half as many, twice as long
    for (std::size_t i = 0; i < most_blocks / 2; ++i) {
      blocks_[i] = blocks_[2 * i];
      blocks_[i].add(blocks_[2 * i + 1]);
    }
    blocks_.resize(most_blocks / 2);
    collisions_per_block_ *= 2;
  }
}

GasStatistics::Sums GasStatistics::sums_at(double now) const {
  Sums s = sums_;
  s.duration += now - last_time_;
  s.speed_time += speed_sum_ * (now - last_time_);
  return s;
}

// The time average of a quantity q = (a sum) / duration, over everything
// since the start; its error from the spread of the finished blocks'
// averages: for B blocks of durations w_b and averages q_b, the standard
// error of the weighted mean, sqrt(B / (B - 1) * sum w_b^2 (q_b - q)^2) /
// sum w_b. The blocks must be longer than the time over which q stays
// correlated; blocks that grow with the run ensure it in the end (lesson 11).
Average GasStatistics::average(double now,
                               double (*of)(const Sums&, const GasStatistics&)) const {
  Average result;
  const Sums total = sums_at(now);
  if (total.duration <= 0) return result;
  result.value = of(total, *this);
  if (blocks_.size() < fewest_blocks) return result;
  Sums finished;
  for (const Sums& b : blocks_) {
    if (b.duration <= 0) return result;
    finished.add(b);
  }
  const double mean = of(finished, *this);
  double spread = 0;
  for (const Sums& b : blocks_) {
    const double deviation = of(b, *this) - mean;
    spread += b.duration * b.duration * deviation * deviation;
  }
  const auto count = static_cast<double>(blocks_.size());
  result.error = std::sqrt(count / (count - 1) * spread) / finished.duration;
  return result;
}

Average GasStatistics::mean_speed_at(double now) const {
  return average(now, [](const Sums& s, const GasStatistics& g) {
    return s.speed_time / (s.duration * static_cast<double>(g.balls_));
  });
}

Average GasStatistics::pressure_at(double now) const {
  return average(now,
                 [](const Sums& s, const GasStatistics&) { return s.push / s.duration; });
}

Average GasStatistics::compressibility_at(double now) const {
  return average(now, [](const Sums& s, const GasStatistics& g) {
    const double balls = static_cast<double>(g.balls_);
    return s.push / s.duration * g.width_ * g.height_ / (balls * g.kT_);
  });
}

Average GasStatistics::collision_rate_at(double now) const {
  return average(now, [](const Sums& s, const GasStatistics& g) {
    return 2 * static_cast<double>(s.ball_collisions) /
           (static_cast<double>(g.balls_) * s.duration);
  });
}

std::vector<double> GasStatistics::speed_fractions_at(double now) const {
  std::vector<double> fractions(static_cast<std::size_t>(bins()), 0.0);
  const double ball_time = duration_at(now) * static_cast<double>(balls_);
  if (ball_time <= 0) return fractions;
  for (std::size_t b = 0; b < fractions.size(); ++b) {
    fractions[b] =
        (bin_time_[b] + static_cast<double>(bin_count_[b]) * (now - bin_since_[b])) /
        ball_time;
  }
  return fractions;
}

double GasStatistics::fraction_beyond_at(double now) const {
  const double ball_time = duration_at(now) * static_cast<double>(balls_);
  const std::size_t b = bin_count_.size() - 1;
  return ball_time > 0 ? (bin_time_[b] +
                          static_cast<double>(bin_count_[b]) * (now - bin_since_[b])) /
                             ball_time
                       : 0.0;
}

}  // namespace gas
