// Kinetic theory (beyond the article): the statistics screen's physics, and
// the running averages that are compared with it.
//
// What this file does: predicts, from the number of balls, their radius, the
// table and the energy alone, what kinetic theory says the gas should show —
// the 2D Maxwell-Boltzmann speeds, the pressure of a hard-disk fluid, the
// collision rate and the mean free path — and keeps the measured figures the
// screen sets beside them: the push on the walls (fed by stage 7's one hook,
// CollisionObserver), a speed histogram, and time averages with their
// statistical errors.
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

// The momentum the walls have received (unit mass), added up collision by
// collision through stage 7's hook: a bounce reverses the velocity's
// component across the wall, so the wall receives 2 |v_normal|.
// [anchor: wall-push]
class WallPush final : public CollisionObserver {
 public:
  void before_collision(const Gas& gas, const Collision& collision) override;
  double horizontal = 0;  // K = 1: the sum of 2 |vy| (walls y = 0, y = A2)
  double vertical = 0;    // K = 2: the sum of 2 |vx| (walls x = 0, x = A1)
};
// [/anchor: wall-push]

// What has been counted since the start: the momentum given to the walls
// and the collisions of two balls (unit mass).
struct Tallies {
  double time = 0;                  // T
  double horizontal_wall_push = 0;  // sum of 2 |vy| over K = 1 (walls y = 0, y = A2)
  double vertical_wall_push = 0;    // sum of 2 |vx| over K = 2 (walls x = 0, x = A1)
  long long ball_collisions = 0;    // K = 3
};

// The tallies of a run: stage 7's clock and count of K = 3, and the push that
// `push`, its observer, has added up.
Tallies tallies(const Control& control, const WallPush& push);

// A time average and its statistical error (one standard error, from block
// averages); the error is not known (NaN) before there are enough blocks.
struct Average {
  double value = not_known;
  double error = not_known;
};

// The figures measured over a run, from the moment this object is made:
// time averages, taken step by step (`record` after every display step, or
// at any moments one likes), and the histogram of speeds.
class GasStatistics {
 public:
  // Speeds are counted in `bins` equal bins from 0 to 2.5 v_rms (v_rms of the
  // gas as it is now; the energy does not change); faster ones apart.
  GasStatistics(const Gas& gas, const Tallies& now, int bins);

  // Adds the time from the last call to now. The speeds counted for it are
  // those the balls had at the last call: the state after its collisions,
  // which lasted until the next one (so each speed counts for as long as it
  // was held, and recording on every collision biases nothing).
  void record(const Gas& gas, const Tallies& now);

  double duration() const { return total_.duration; }
  // Time averages since the start.
  Average mean_speed() const;
  Average pressure() const;         // wall push per time per unit length of wall
  Average compressibility() const;  // P * measured_area / (N kT)
  Average collision_rate() const;   // per ball: 2 * (collisions of two balls) / (N t)

  // The histogram: for each bin the fraction of ball-time spent at speeds in
  // it; with the fraction beyond the last bin, the fractions sum to 1.
  int bins() const { return static_cast<int>(speed_time_.size()); }
  double bin_width() const { return bin_width_; }
  std::vector<double> speed_fractions() const;
  double fraction_beyond() const;

 private:
  // The sums over a stretch of time; a block is a run of records.
  struct Sums {
    double duration = 0;
    double mean_speed_time = 0;  // integral of the mean speed over time
    double push = 0;             // wall push, weighted per unit length (below)
    long long ball_collisions = 0;
    void add(const Sums& other);
  };
  Average average(double (*of)(const Sums&, const GasStatistics&)) const;

  std::size_t balls_ = 0;
  double kT_ = 0;
  double width_ = 0;   // A1 - 2a
  double height_ = 0;  // A2 - 2a
  double bin_width_ = 0;
  Tallies last_;
  double last_mean_speed_ = 0;
  std::vector<int> last_bin_;       // each ball's bin at the last record
  std::vector<double> speed_time_;  // ball-time spent in each bin
  double beyond_time_ = 0;          // ball-time faster than the last bin
  Sums total_;
  Sums block_;                   // the block being filled
  long long block_records_ = 0;  // records in it
  long long records_per_block_ = 1;
  std::vector<Sums> blocks_;  // finished blocks, all of records_per_block_
};

}  // namespace gas
