// The measured side of the statistics screen (beyond the article): time
// averages of a running gas, with honest error bars.
//
// What this file does: keeps, collision by collision through stage 7's one
// hook (CollisionObserver), the sums the statistics screen needs — the time
// integral of the speeds, a histogram of speeds, the push on each pair of
// walls, the collision virial of the whole box and of its interior, the time
// the balls spend in the interior — and turns them into averages. A
// collision costs a few operations whatever the number of balls; reading the
// figures, and closing a sample for the error bars every N collisions,
// walks the balls once. Nothing depends on when pictures are taken.
// Article: "Gas on the display", stage 6, the third screen ("print some
// properties of the gas, the mean speed for example"); all the rest is
// beyond the article.
// Lesson: lessons/13-box-and-bulk.md; its error bars: lessons/14-error-bars.md
//
// Assumptions: unit mass and k = 1 (kT = E / N); the energy is fixed (the
// hook is the only way velocities change, besides B, which keeps speeds).
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "beyond/blocking.hpp"
#include "beyond/fluid_structure.hpp"
#include "stage1_data.hpp"
#include "stage4_first_collision.hpp"
#include "stage7_control.hpp"

namespace gas {

inline constexpr double not_known = std::numeric_limits<double>::quiet_NaN();

// A time average and its statistical error (one standard error, from a
// blocking analysis, or from a theory until the batches are long enough:
// from_theory); the error is not known (NaN) until one of them gives it,
// the value not known before the averages start. While the error is
// blank, `why_no_error` may say why in a few words, which the statistics
// screen shows in its place: "few samples" (fewer than the blocking's 16),
// "not yet" (its batches are shorter than the table's heat time, or still
// look correlated: the run must go on).
struct Average {
  double value = not_known;
  double error = not_known;
  const char* why_no_error = nullptr;  // a short reason, or none
  // Why the error is not known, or that it is (beyond/blocking.hpp).
  ErrorStatus status = ErrorStatus::few_samples;
  // What the batches alone would claim (BlockingAnalysis::batch_error): the
  // error once it is known; before, a figure too short to trust.
  double batch_error = not_known;
  double batch_time = not_known;  // the length of those batches, model time
  double batches = 0;             // and how many there are
  // The error is a theory's, not the batches' (still too short): the box's
  // heat and sound for the interior's eta, kT, Z, collision rate and mean
  // free path (beyond/box_modes.hpp),
  // the fluid's friction and the box's sound for the push on the walls'
  // middles (beyond/wall_push.hpp), kinetic theory's for the mean speed
  // (beyond/speed_relaxation.hpp).
  bool from_theory = false;
};

// The mean of `samples` times `scale`, with its error by the blocking rule,
// and while that is not known the reason (few samples, or not yet).
Average average_with_error(const BlockingAnalysis& samples, double scale = 1);

// The warm-up: how many collisions of two balls, per ball, are left out of
// the averages (each such collision counts for both its balls). A start on a
// lattice or at random places has no layers at the walls yet; as they form,
// the interior's density settles, and that takes about as long as a ball at
// the mean speed needs to cross the table (one to three passes of sound, from
// eta = 0.1 to 0.5): in collisions a ball, the table's longer side over the
// mean free path of kinetic theory at N / (A1 A2), L / lambda, and never fewer
// than fewest_warm_up_collisions (the speeds' own relaxation; lesson 14). No
// warm-up for one ball: nothing relaxes.
inline constexpr long long fewest_warm_up_collisions = 10;
long long warm_up_collisions_a_ball(const Gas& gas);
// The mean speed's shortest batch, in pair collisions per ball. The
// autocorrelation of the mean speed over one time unit falls to 1/e in 2.6
// pair collisions per ball over 40 gases like data/large-1000.scene (eta =
// 0.3; data/reports/kinetic-seeds.md, section speeds-fold), in 2 to 4 over 8
// of 1024 balls at 0.1 and 0.5, and to nothing within 20 time units (nothing
// follows the heat: averages over 30 ... 1300 time units scatter 1.9 to 2.5
// times as much as uncorrelated ones, section speeds-windows). Twenty-five
// make a batch some ten of those times long, where batch means lose a few
// per cent of the error.
inline constexpr double speeds_batch_collisions = 25;
// The interior: centres at least this many radii from every wall. Density
// oscillations at a wall die out within a few diameters (lesson 13); at
// eta = 0.45 what is left of them 8 radii out still lowers an interior's Z
// by 0.05 % beyond the 1/N shift at N = 1024, while 12 radii out it is
// within the closed box's seed errors from eta = 0.1 to 0.45 (lesson 13,
// "The gas's own N"; data/reports/kinetic-seeds.md, section closed).
inline constexpr double interior_margin_radii = 12;

// The figures measured since the averages started, as of one moment.
struct MeasuredFigures {
  bool warming_up = true;            // the first collisions, left out
  long long warm_up_collisions = 0;  // of two balls, per ball, left out
  double since = not_known;          // T at which the averages started
  double duration = 0;               // the time averaged over
  Average mean_speed;                // of the balls, over time
  Average pressure_box;    // on the whole walls: push per unit time per unit length
  Average pressure_box_x;  // on the walls x = 0 and x = A1 alone
  Average pressure_box_y;  // on the walls y = 0 and y = A2 alone
  Average box_z_walls;     // Z of the box: P A_c / (N kT), from the walls
  Average box_z_virial;    // the same from the collision virial
  Average bulk_z;          // Z of the interior: P_int / (n_int kT)
  Average
      bulk_z_minus_theory;  // Z - Z_ref(eta_int), sample by sample: its error combined
  Average interior_area_fraction;  // eta_int = n_int pi a^2, n_int over time
  Average interior_kT;             // the interior's own kT: <v^2> / 2 of its balls
  Average
      collision_rate_box;  // per ball per unit time: 2 (collisions of two balls) / (N t)
  Average
      collision_rate;  // the same in the interior: 2 (its collisions) / (its ball-time)
  Average collision_rate_minus_theory;  // the interior's rate - Enskog's at eta_int,
                                        // sample by sample
  Average mean_free_path;               // the interior's mean speed / its rate (a length)
  Average pair_contact;                 // g(2a+) among the balls of the interior
  Average pair_contact_minus_theory;    // g(2a+) - the reference's at the snapshot's
                                        // eta_int, snapshot by snapshot
  Average wall_contact_pressure;  // kT n(contact) at the walls x = 0, A1 (their middles)
  Average wall_middle_pressure;   // the push on those middles: P there
  Average pressure_minus_theory;  // P there - Z_ref n kT of the strips beside them,
                                  // sample by sample
  Average beside_walls_eta;       // eta of those strips (n pi a^2)
  Average beside_walls_kT;        // their own kT
  Average mean_free_path_minus_theory;  // the interior's path - Enskog's at eta_int,
                                        // sample by sample
  std::vector<double> speed_fractions;  // the histogram: ball-time fractions per bin
  double bin_width = 0;                 // of its bins
  double fraction_beyond = 0;           // faster than its last bin
  double h_now = not_known;             // Boltzmann's H of the speeds now
};

class GasStatistics final : public CollisionObserver {
 public:
  // Speeds are counted in `bins` equal bins from 0 to 2.5 v_rms (v_rms of the
  // gas as it is now; the energy does not change); faster ones apart. The
  // averages start after warm_up_collisions_a_ball(gas) collisions of two
  // balls per ball from now (`warm_up` false: at once). `structure_curves`:
  // keep the whole g(r) and wall profile too (--structure;
  // beyond/fluid_structure.hpp).
  GasStatistics(const Gas& gas, int bins, bool warm_up = true,
                bool structure_curves = false);

  // Stage 7's hook: before a collision the sums are brought up to TC and the
  // colliding balls' old speeds and flights taken out; after it their new
  // speeds go in, with the collision's virial.
  void before_collision(const Gas& gas, const Collision& collision) override;
  void after_collision(const Gas& gas, const Collision& collision) override;

  // The averages start again now, with no warm-up (the key A).
  void restart(const Gas& gas);

  // Stage 7's hook again: every ball's row is about to be written at the
  // gas's time T, not by a collision (the key B): each flight so far ends
  // now, and the time it spent in the interior is counted.
  void before_rows_rewritten(const Gas& gas) override;

  // The figures at the gas's time T (walks the balls once).
  MeasuredFigures measured(const Gas& gas) const;

  // The structure's snapshots and curves (beyond/fluid_structure.hpp).
  const FluidStructure& structure() const { return structure_; }

  int bins() const { return static_cast<int>(bin_count_.size()) - 1; }
  std::size_t balls() const { return balls_; }
  double bin_width() const { return bin_width_; }

 private:
  // The sums over a stretch of time.
  struct Sums {
    double duration = 0;
    double speed_time = 0;       // integral over time of the sum of the speeds
    double push_x = 0;           // 2 |vx| over K = 2, per unit of wall length
    double push_y = 0;           // 2 |vy| over K = 1, per unit of wall length
    double push_x_middle = 0;    // push_x for bounces with y inside the interior's range
    double virial = 0;           // d . dv over K = 3 (d = r1 - r2 at contact)
    double interior_virial = 0;  // the same, for contacts inside the interior
    double interior_time = 0;    // ball-time spent inside the interior
    double interior_energy = 0;  // integral over that time of v^2 (2 kT per ball)
    double interior_speed = 0;   // and of v
    double beside_time = 0;      // ball-time in the two strips beside the walls' middles
    double beside_energy = 0;    // integral over that time of v^2
    long long ball_collisions = 0;
    long long interior_collisions =
        0;  // of two balls, their midpoint inside the interior
    Sums minus(const Sums& earlier) const;
  };
  // The quantities averaged, each a function of a stretch's sums.
  enum Quantity {
    mean_speed_q,
    pressure_box_q,
    pressure_box_x_q,
    pressure_box_y_q,
    box_z_walls_q,
    box_z_virial_q,
    bulk_z_q,
    bulk_z_minus_theory_q,
    interior_eta_q,
    interior_kT_q,
    collision_rate_box_q,
    collision_rate_q,
    collision_rate_minus_theory_q,
    mean_free_path_q,
    wall_middle_pressure_q,
    pressure_minus_theory_q,
    mean_free_path_minus_theory_q,
    beside_walls_eta_q,
    beside_walls_kT_q,
    quantity_count
  };
  double value_of(Quantity q, const Sums& s) const;
  // Does the quantity wander with the table's heat (measured: its blocking
  // curve still rises past the sound's crossing time), so that its error
  // waits for batches as long as table_heat_time? The differences from
  // theory, taken sample by sample, do not; nor does the whole box's
  // collision rate (the energy and the count are fixed), nor the mean speed
  // (only the shape of the speeds' distribution moves it, and that forgets
  // itself within a few pair collisions per ball; lesson 14). The
  // interior's rate does: it follows the interior's density and kT.
  static bool follows_table_heat(Quantity q);
  // Does the quantity follow the shape of the speeds' distribution (the mean
  // speed), so that its error waits for batches of
  // speeds_batch_collisions pair collisions per ball?
  static bool follows_speeds(Quantity q);
  static Average& average_of(MeasuredFigures& m, Quantity q);

  void start_averages(const Gas& gas);
  // The interior's eta and kT, Z and the push on the walls' middles, while
  // their batches are short: their errors from the box's heat and sound
  // and the fluid's friction over the time averaged (lesson 14).
  void add_box_theory(MeasuredFigures& m) const;
  // The mean speed's, while its batches are short: kinetic theory's.
  void add_speeds_theory(MeasuredFigures& m) const;
  // Closes a sample for the error bars at `time` (every N collisions).
  void take_sample(const Gas& gas, double time);
  Sums sums_at(const Gas& gas, double now) const;  // with the flights in progress
  int bin_of(double speed) const;                  // bins() for the faster ones
  // Ball number `i` (from 0) gets a new speed at `time`: it comes into the
  // sums and counted_. Or its speed leaves the sums at `time`:
  // the one it came in with (a bounce or the key B keeps a speed).
  void speed_enters(std::size_t i, const Ball& ball, double time);
  void speed_leaves(std::size_t i, double time);
  // A bin's ball-time brought up to `time`, and its count changed.
  void count_in_bin(std::size_t bin, double time, long long change);
  // How long the ball's present flight keeps its centre in `region`.
  double time_in(const Region& region, const Ball& ball, double until) const;
  // Ball number `i`'s flight: its time inside, and v^2 and v times it, into
  // the sums `s`.
  void add_interior_flight(Sums& s, std::size_t i, const Ball& ball, double until) const;
  bool clear_of_strips(const Ball& ball, double until) const;

  std::size_t balls_ = 0;
  double kT_ = 0;
  double radius_ = 0;
  double width_ = 0, height_ = 0;  // A1 - 2a, A2 - 2a: the box the centres move in
  Region interior_;  // the centres at least interior_margin_radii from every wall
  // The strips of the interior beside the walls x = 0 and x = A1, as high
  // as the walls' middles: the bulk that pushes on those middles.
  Region beside_left_, beside_right_;
  double bin_width_ = 0;
  long long collisions_per_sample_ = 1;
  double heat_time_ = 0;  // table_heat_time: the shortest batch, in model time
  // The shortest batch for the mean speed, in model time: speeds_batch_collisions
  // over Enskog's rate per ball at N / (A1 A2) and the start's kT.
  double speeds_time_ = 0;

  // The state as of the last collision.
  long long collisions_ = 0;        // since this object was made
  long long ball_collisions_ = 0;   // of two balls, since this object was made
  long long warm_up_per_ball_ = 0;  // collisions of two balls a ball, left out
  long long warm_up_until_ = 0;  // the collision of two balls after which averages start
  bool averaging_ = false;
  double start_ = 0;                  // T when the averages started
  double last_time_ = 0;              // the last collision's TC
  double speed_sum_ = 0;              // the sum of the speeds since then
  std::array<double, 2> before_v_{};  // N1's velocity before the collision
  Sums sums_;                         // since the averages started
  std::vector<long long> bin_count_;  // balls in each bin now, the last for beyond
  std::vector<double> bin_time_;      // ball-time in each bin, up to bin_since_
  std::vector<double> bin_since_;
  // Each ball's speed and its bin, as counted in the sums now: a speed
  // changes only at a collision of two balls, so it is worked out once then
  // and not again when it leaves (every bit the same as afresh).
  struct CountedSpeed {
    double speed = 0;   // v, as speed_of works it out
    double square = 0;  // v^2 = vx^2 + vy^2
    std::size_t bin = 0;
  };
  std::vector<CountedSpeed> counted_;  // by ball

  // The error bars: a sample every collisions_per_sample_ collisions, each
  // quantity's value over it fed to a blocking analysis.
  Sums sample_start_;
  long long sample_collisions_ = 0;
  std::array<BlockingAnalysis, quantity_count> blocking_;
  // And the structure, from snapshots at fixed moments of time.
  FluidStructure structure_;
};

}  // namespace gas
