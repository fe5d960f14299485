// The largest Lyapunov exponent of the running gas (beyond the article), and
// the precision horizon it predicts.
//
// What this file does: follows one infinitesimal change of the gas's state
// along the exact motion (beyond/tangent_dynamics.hpp), through stage 7's
// hook, and measures how fast it grows: G. Benettin's method — at fixed
// moments T_k = T_0 + k dT its Euclidean norm (all 4N components) is
// measured and brought back to 1, and ln(norm) / dT is one sample of the
// exponent lambda. The samples' mean is lambda, per unit model time; its
// error comes from overlapping batches (beyond/overlapping_batches.hpp),
// long ones, as the samples are anticorrelated (below). From lambda follows
// how many collisions a ball a number type follows the exact motion: an
// error of one unit in the last place of the coordinates grows as
// e^(lambda t) and reaches a distance d after t = ln(d / eps) / lambda.
// Article: none; lesson 9 shows what the exponent predicts, B failing after
// some collisions. Everything here is beyond the article.
// Lesson: lessons/15-chaos.md
//
// Assumptions: unit mass; a collision costs O(1) (the changes fly lazily,
// like the balls' rows); each renormalisation walks the balls once, and
// comes about once per N collisions.
#pragma once

#include <cstdint>

#include "beyond/gas_statistics.hpp"
#include "beyond/overlapping_batches.hpp"
#include "beyond/tangent_dynamics.hpp"
#include "stage1_data.hpp"
#include "stage4_first_collision.hpp"
#include "stage7_control.hpp"

namespace gas {

// What the exponent's measurement says, as of the last renormalisation.
struct LyapunovFigures {
  bool warming_up = true;  // the change is still turning to its fastest direction
  Average exponent;        // lambda, per unit model time
  double collision_rate =
      not_known;  // collisions (walls and pairs) per unit time, meanwhile
  double per_collision = not_known;  // lambda / collision_rate: e-folds per collision
  double per_collision_per_ball = not_known;  // lambda N / collision_rate
  double per_collision_per_ball_error = not_known;
  long long samples = 0;  // renormalisations averaged
};

// The exponent's own warm-up, in collisions (walls and pairs) per ball: long
// enough for the change to turn towards the fastest-growing direction; its
// duration over this count is the renormalisation step dT (about N
// collisions). Not the statistics' warm-up (warm_up_collisions_a_ball), which
// waits for the density to settle.
inline constexpr long long warm_up_collisions_per_ball = 5;
// The exponent's error: overlapping batches (beyond/overlapping_batches.hpp),
// each a sixth of the samples and never fewer than 16 of them, so no error
// before 96 samples (T = 221 on data/large-1000.scene).
inline constexpr std::size_t lyapunov_batches_per_run = 6;
inline constexpr std::size_t lyapunov_shortest_batch = 16;

class LyapunovExponent final : public CollisionObserver {
 public:
  // The change starts in the direction drawn from `seed`, of norm 1. The
  // first warm_up_collisions_per_ball * N collisions turn it towards the
  // direction that grows fastest and are left out; their duration, divided by
  // warm_up_collisions_per_ball, is dT (about N collisions).
  explicit LyapunovExponent(const Gas& gas, std::uint64_t seed = 1989);

  // Stage 7's hook: the change carried through the collision; at every T_k
  // passed, a sample.
  void before_collision(const Gas& gas, const Collision& collision) override;
  // The key B: the reversed gas first retraces its path, along which the
  // change grown so far shrinks again; a fresh change, a fresh warm-up and
  // fresh averages.
  void before_rows_rewritten(const Gas& gas) override;

  // The key A: the averages start again at the next T_k, the change kept.
  void restart();

  LyapunovFigures measured(const Gas& gas) const;
  const TangentDynamics& tangent() const { return tangent_; }
  double interval() const { return interval_; }  // dT, 0 while warming up

 private:
  void start_warm_up(double time);
  void sample_at(double time);  // a renormalisation at `time`, and its sample

  std::uint64_t seed_;
  TangentDynamics tangent_;
  std::size_t balls_ = 0;
  long long collisions_ = 0;       // since this object was made
  long long warm_up_until_ = 0;    // the collision after which dT is known
  double warm_up_start_ = 0;       // T when the warm-up began
  double interval_ = 0;            // dT
  double next_ = 0;                // T_k, the next renormalisation
  bool clear_at_next_ = false;     // A: the samples so far dropped at the next T_k
  long long first_collision_ = 0;  // collisions_ at the first averaged T_k
  long long last_collision_ = 0;   // collisions_ at the last T_k
  // The samples ln(norm) / dT. Neighbours are anticorrelated: a stretch
  // that grew the change much leaves it less turned to the fastest
  // direction, and the next ones grow it less, over some 20 samples (40
  // time units on data/large-1000.scene). Separate batches of 16 samples
  // therefore make the error too large; batches a sixth of the run, taken
  // at every start, do not (lessons/15-chaos.md, "Is the error honest?",
  // with the measurements over 400 gases).
  OverlappingBatchMeans batches_{lyapunov_batches_per_run, lyapunov_shortest_batch};
};

// How many collisions a ball the motion is followed before an error `epsilon`
// grows to `distance`, for an exponent of `per_collision_per_ball` e-folds a
// collision a ball: ln(distance / epsilon) / per_collision_per_ball.
double precision_horizon(double per_collision_per_ball, double distance, double epsilon);

// One unit in the last place of a number type of `mantissa_digits` digits
// (float 24, double 53, x86 long double 64) at the size of the table
// (the largest coordinate, max(A1, A2)): 2^(floor(log2 size) - digits + 1).
double coordinate_ulp(const Gas& gas, int mantissa_digits);

}  // namespace gas
