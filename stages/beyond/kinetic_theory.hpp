// Kinetic theory (beyond the article): the statistics screen's physics, and
// the running averages that are compared with it.
//
// What this file does: predicts, from the number of balls, their radius, the
// table and the energy alone, what kinetic theory says the gas should show —
// the 2D Maxwell-Boltzmann speeds, the pressure of a hard-disk fluid, the
// collision rate and the mean free path — and keeps the measured figures the
// screen sets beside them: the push on the walls, a speed histogram, and time
// averages with their statistical errors, all fed collision by collision
// through stage 7's one hook, CollisionObserver.
// Article: "Gas on the display", stage 6, the third screen ("print some
// properties of the gas, the mean speed for example"). The theory is beyond
// the article.
// Lesson: lessons/11-kinetic-theory.md
//
// Assumptions: unit mass and k = 1, so kT is an energy per ball (in 2D,
// E = N kT); every formula is for equilibrium; the pressure is measured on
// the walls and referred to the box the centres move in (below).
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include "stage1_data.hpp"
#include "stage4_first_collision.hpp"
#include "stage7_control.hpp"

namespace gas {

inline constexpr double not_known = std::numeric_limits<double>::quiet_NaN();

// What kinetic theory predicts for a gas, from N, a, A1, A2 and E only.
// [anchor: kinetic-theory]
struct KineticTheory {
  double kT = 0;               // E / N: two degrees of freedom per ball, unit mass
  double mean_speed = 0;       // 2D Maxwell-Boltzmann: <v> = sqrt(pi kT / 2)
  double rms_speed = 0;        // sqrt(<v^2>) = sqrt(2 kT), fixed by E alone
  double area_fraction = 0;    // eta = N pi a^2 / (A1 A2)
  double contact_value = 0;    // g(2a), Henderson: (1 - 7 eta / 16) / (1 - eta)^2
  double compressibility = 0;  // Z, Henderson: (1 + eta^2 / 8) / (1 - eta)^2
  double pressure = 0;         // P = Z N kT / (the centres' area), see measured_area
  double collision_rate = 0;   // per ball, Enskog: 2 (2a) n g(2a) sqrt(pi kT)
  double mean_free_path = 0;   // <v> / collision rate
};
// [/anchor: kinetic-theory]

KineticTheory kinetic_theory(const Gas& gas);

// The 2D Maxwell-Boltzmann distribution of speeds at temperature kT (unit
// mass): the density f(v) = (v / kT) exp(-v^2 / (2 kT)) and its integral
// F(v) = 1 - exp(-v^2 / (2 kT)), the fraction of balls slower than v.
double maxwell_density(double speed, double kT);
double maxwell_fraction_below(double speed, double kT);

// The Henderson equation of state of hard discs and its contact value g(2a),
// as functions of the area fraction.
double henderson_compressibility(double area_fraction);
double henderson_contact_value(double area_fraction);

// The area the pressure is referred to: the box (A1 - 2a) x (A2 - 2a) that
// the centres move in. With it an ideal gas (a -> 0 collisions, or one ball)
// has P * area = N kT exactly, walls and all (lesson 11).
double measured_area(const Gas& gas);

// A time average and its statistical error (one standard error, from block
// averages); the error is not known (NaN) before there are enough blocks.
struct Average {
  double value = not_known;
  double error = not_known;
};

// The figures measured over a run, from the moment this object is made:
// time averages of the speeds, of the push on the walls and of the
// collisions, and the histogram of speeds. It is kept up to date through
// stage 7's hook (Control::observer = &statistics), with a few operations at
// each collision whatever the number of balls: each figure is a running sum
// that a collision changes only for the one or two balls it concerns. So the
// figures do not depend on when pictures are taken, and reading them at any
// moment (the *_at functions) walks no ball.
class GasStatistics final : public CollisionObserver {
 public:
  // Speeds are counted in `bins` equal bins from 0 to 2.5 v_rms (v_rms of the
  // gas as it is now; the energy does not change); faster ones apart. The
  // averages start at the gas's time T.
  GasStatistics(const Gas& gas, int bins);

  // Stage 7's hook: the speeds of the balls that collide are taken out of
  // the sums at TC, and their new speeds put in; a wall receives its push.
  void before_collision(const Gas& gas, const Collision& collision) override;
  void after_collision(const Gas& gas, const Collision& collision) override;

  // Time averages from the start to the moment `now` (no earlier than the
  // last collision).
  double duration_at(double now) const { return now - start_; }
  Average mean_speed_at(double now) const;
  Average pressure_at(double now) const;         // wall push per time per unit length
  Average compressibility_at(double now) const;  // P * measured_area / (N kT)
  Average collision_rate_at(double now) const;   // per ball: 2 (ball collisions) / (N t)

  // The histogram at `now`: for each bin the fraction of ball-time spent at
  // speeds in it; with the fraction beyond the last bin, they sum to 1.
  int bins() const { return static_cast<int>(bin_count_.size()) - 1; }
  double bin_width() const { return bin_width_; }
  std::vector<double> speed_fractions_at(double now) const;
  double fraction_beyond_at(double now) const;

 private:
  // Sums from the start up to a moment.
  struct Sums {
    double duration = 0;
    double speed_time = 0;  // integral over time of the sum of the speeds
    double push = 0;        // wall push, weighted per unit length (below)
    long long ball_collisions = 0;
    void add(const Sums& other);
    Sums minus(const Sums& earlier) const;  // the sums between `earlier` and these
  };
  Sums sums_at(double now) const;  // the sums up to `now`
  Average average(double now, double (*of)(const Sums&, const GasStatistics&)) const;
  int bin_of(double speed) const;                // bins() for the faster ones
  void take_out(const Ball& ball, double time);  // a ball's speed leaves the sums
  void put_in(const Ball& ball, double time);    // and comes back, new

  std::size_t balls_ = 0;
  double kT_ = 0;
  double width_ = 0;   // A1 - 2a
  double height_ = 0;  // A2 - 2a
  double start_ = 0;   // T when the averages started
  double bin_width_ = 0;

  // The running sums, as of the last collision.
  Sums sums_;                 // duration and speed_time up to last_time_
  double last_time_ = 0;      // the moment of the last collision
  double speed_sum_ = 0;      // the sum of the speeds since then
  long long collisions_ = 0;  // all kinds, to refresh speed_sum_ (below)
  // The histogram: for each bin (and beyond, the last entry) the balls in it
  // now, and the ball-time it has held up to the moment it last changed.
  std::vector<long long> bin_count_;
  std::vector<double> bin_time_;
  std::vector<double> bin_since_;

  // Blocks for the errors: the sums at the start of the block being filled,
  // and the finished blocks' own sums. A block is a run of collisions, so
  // that the blocks too are the same whenever pictures are taken.
  Sums block_start_;
  long long block_collisions_ = 0;  // in the block being filled
  long long collisions_per_block_ = 1;
  std::vector<Sums> blocks_;
};

}  // namespace gas
