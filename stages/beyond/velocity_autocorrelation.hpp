// The velocity autocorrelation function of the running gas (beyond the
// article), and the diffusion coefficient that is its running integral.
//
// What this file does: measures
//   rho(t) = <v(0) . v(t)> / <v(0)^2>,
//   D(t) = (1/2) integral from 0 to t of <v(0) . v(s)> ds
// for the balls of the bulk, through stage 7's hook. At moments T_0, T_0 + dT,
// T_0 + 2 dT, ... (the time origins) it notes the velocity and centre of
// every ball far from the walls (the counted balls); at each lag t of a fixed
// list it walks those balls again and sums v(0) . v(t) and v(0) . (r(t) -
// r(0)). The second sum is the running integral exactly, with no quadrature:
// the integral of a ball's velocity is its displacement, D(t) = <v(0) .
// (r(t) - r(0))> / 2. Each origin gives one sample of rho and of D at each
// lag; their mean over the origins is the answer, and their spread, by the
// blocking analysis of the statistics screen (beyond/blocking.hpp), its
// error. A collision costs one comparison (a wall bounce two); an origin
// walks every ball once, and each of its readings its counted balls.
// Article: none; the article averages nothing. Everything here is beyond it.
// Lesson: lessons/16-long-time-tail.md
//
// Keeping the walls out: a ball's velocity at t is felt by the walls only
// through the fluid (a sound wave that leaves the ball, is thrown back by a
// wall and returns: 2 d / c for a ball d from the wall, c the speed of
// sound) or by reaching the wall itself. Balls are counted only if their
// centre is at least `margin` = 8a + c L from every wall at the origin, L
// the longest lag: an echo needs twice the longest lag to come back, and a
// ball that wanders that far at the diffusion's pace takes far longer. Every
// counted ball that meets a wall within its lags is counted (walls_met); the
// tests and the lesson show it stays 0.
//
// Assumptions: unit mass; each ball's column of R is current at every reading (a
// reading due at t is taken before the first collision after t, with the
// gas as stage 7 hands it to the hook: a reading at t includes every
// collision at time <= t, as a --dump at t does). The key B starts the
// origins afresh (the reversed gas retraces its path: velocities after B do
// not follow from before it by the equations of motion); readings already
// taken stay.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <queue>
#include <string>
#include <vector>

#include "beyond/blocking.hpp"
#include "beyond/enskog_transport.hpp"
#include "beyond/gas_statistics.hpp"
#include "stage1_data.hpp"
#include "stage4_first_collision.hpp"
#include "stage7_control.hpp"

namespace gas {

// How a gas's velocity autocorrelation is measured: the lags, which balls
// count, and when the origins are.
struct VacfPlan {
  // tau_E of the whole table at its area fraction N pi a^2 / (A1 A2) and its
  // kT = E / N: the unit of the lags and of the origins' spacing.
  double time_unit = 0;
  std::vector<double> lags;    // in model time, lags[0] = 0, increasing
  std::size_t short_lags = 0;  // lags[1 .. short_lags]: the first, up to 0.1 tau_E
  double margin = 0;           // counted: centres at least this far from every wall
  double warm_up = 0;          // the first origin this long after the observer starts
  double spacing = 0;          // from one origin to the next
  long long long_every = 1;    // every this many origins one reads every lag; the
                               // others only the short ones
};

// The plan for a gas: lags out to `longest_lag_in_time_units` tau_E or as far
// as the table keeps the walls out with a counted region at least half the
// table across each way (margin <= min(A1, A2) / 4); an origin every
// tau_E / 4, every fourth of them read at every lag (a ball's velocity is
// forgotten in about one tau_E: closer origins add little to the long lags,
// and cost a walk of the balls a lag), or fewer if the noted balls would take
// more than `vacf_memory` bytes; warm-up 10 tau_E (about ten pair collisions
// per ball: local equilibrium, Maxwell's speeds). A table too small for any lag
// gets only the lag 0.
inline constexpr double longest_lag_in_time_units = 100;
inline constexpr double vacf_memory = 64.0 * 1024 * 1024;
VacfPlan plan_vacf(const Gas& gas);

// One lag of the answer: rho and D with their errors (the spread of the
// origins' samples), and the theory at the counted balls' own density and kT.
struct VacfRow {
  double lag = 0;         // t, model time
  Average vacf;           // rho(t)
  Average diffusion;      // D(t) = (1/2) integral of <v(0) . v(s)> ds to t
  long long origins = 0;  // samples averaged
};

class VelocityAutocorrelation final : public CollisionObserver {
 public:
  // Measures `gas` from its time T on, by `plan` (by default plan_vacf(gas)).
  explicit VelocityAutocorrelation(const Gas& gas);
  VelocityAutocorrelation(const Gas& gas, VacfPlan plan);

  // Stage 7's hook: the origins and readings due before the collision; a
  // counted ball at a wall within its lags is counted.
  void before_collision(const Gas& gas, const Collision& collision) override;
  // The key B: the origins in progress are dropped.
  void before_rows_rewritten(const Gas& gas) override;
  // The origins and readings due at the gas's time T or before (at the end
  // of a run, before the answer is read).
  void catch_up(const Gas& gas);

  const VacfPlan& plan() const { return plan_; }
  // Every lag read at least once, in order.
  std::vector<VacfRow> rows() const;
  // The counted balls' area fraction (n pi a^2, n over the counted region)
  // and kT (<v^2> / 2), averaged over the origins; NaN before the first.
  double area_fraction() const;
  double kT() const;
  // Enskog's theory at that area fraction and kT.
  EnskogTransport theory() const;
  long long origins() const { return origins_done_; }
  long long walls_met() const { return walls_met_; }  // should stay 0
  double radius() const { return radius_; }

 private:
  // One counted ball at an origin: its number (from 0), velocity and centre
  // then. Floats: their 7 digits are far below the statistical error (the
  // samples' spread is 1e-3 of the values at best), and they halve the
  // memory (20 bytes a counted ball an origin).
  struct Noted {
    std::uint32_t ball = 0;
    float vx = 0, vy = 0, x = 0, y = 0;
  };
  struct Origin {
    double time = 0;
    std::size_t next_lag = 1;  // the next lag to read
    std::size_t last_lag = 0;  // the last lag it reads
    double square_sum = 0;     // sum of v(0)^2 over its counted balls
    std::vector<Noted> balls;  // emptied once its last lag is read
  };
  // A reading due: origin number `origin` (counted from 0 since the start)
  // at `time`.
  struct Due {
    double time = 0;
    long long origin = 0;
    bool operator>(const Due& other) const { return time > other.time; }
  };

  // Everything due strictly before `time` (or at it, if `inclusive`).
  void take_due(const Gas& gas, double time, bool inclusive);
  double next_due() const;
  void start_origin(const Gas& gas, double time);
  void read(const Gas& gas, long long number);
  void finish(Origin& origin);  // its list back to the spares

  VacfPlan plan_;
  double radius_ = 0, width_ = 0, height_ = 0;
  double next_origin_ = 0;      // T of the next origin
  long long next_number_ = 0;   // its number, counted from 0 since the start
  long long first_active_ = 0;  // the number of active_.front()
  std::deque<Origin> active_;   // the origins from the oldest still read, in order
  std::vector<std::vector<Noted>> spare_;  // lists of finished origins, for reuse
  std::priority_queue<Due, std::vector<Due>, std::greater<Due>> due_;
  std::vector<double> counted_until_;  // by ball: the end of its last origin's lags
  std::vector<BlockingAnalysis> vacf_, diffusion_;  // by lag
  long long origins_done_ = 0;
  double area_fraction_sum_ = 0, kT_sum_ = 0;
  long long walls_met_ = 0;
};

// The --vacf file: a header and one line a lag,
// t,vacf,vacf_error,vacf_enskog,vacf_tail,diffusion,diffusion_error,diffusion_enskog
// (t and the diffusion in model units; vacf_enskog exp(-t / tau_E), vacf_tail
// the mode-coupling tail, diffusion_enskog D_E (1 - exp(-t / tau_E)), all at
// the counted balls' area fraction and kT; `nan` for an error not known yet).
std::string vacf_csv(const VelocityAutocorrelation& vacf);

}  // namespace gas
