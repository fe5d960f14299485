// The box's sound and heat (beyond the article): how far the interior's time
// averages wander, from linear hydrodynamics in a closed box.
//
// What this file does: predicts the standard error of two time averages of
// the statistics screen, the interior's area fraction eta_int and its own
// kT, over a run of duration W, without looking at the run, and their
// correlation, from which follow the errors of figures that move with both
// (the interior's collision rate and free path). The gas's
// density and energy, written as the box's standing waves cos(m pi x / L1)
// cos(q pi y / L2) (the walls turn balls back like mirrors: no flow and no
// heat through them), fluctuate in equilibrium by amounts thermodynamics
// fixes, and each wave forgets its amplitude in two ways: by heat spreading,
// exp(-D_T k^2 t), and by sound ringing, cos(c k t) exp(-Gamma k^2 t). The
// interior's count of balls and its energy are those waves summed over the
// interior, so their time averages' variances follow wave by wave. The
// longest waves dominate: on data/large-1000.scene the error of eta_int
// averaged over 270 time units comes nine tenths from waves longer than 60
// radii, which heat takes some 40 to 80 time units to smooth. No run can
// see that in its own first few hundred time units (lesson 14); the theory
// can.
// Article: none (the article's character screen and its figures:
// beyond/gas_statistics.hpp). That the article takes no time averages and
// gives them no errors is our reading.
// Lesson: lessons/14-error-bars.md
//
// Assumptions: unit mass and k = 1; a fluid in equilibrium in a rectangular
// box, described by linear hydrodynamics for waves longer than a ball (the
// sum stops at k = 1/a; shorter waves add less than 1 % on
// data/large-1000.scene); the interior far enough from the walls that its
// fluid is the bulk's. The transport coefficients come from the caller
// (Enskog's: beyond/enskog_transport.hpp).
#pragma once

#include <limits>

#include "beyond/fluid_structure.hpp"

namespace gas {

// The bulk fluid as linear hydrodynamics needs it.
struct BoxHydrodynamics {
  double density = 0;              // n, balls per unit area
  double kT = 0;                   // energy per ball (unit mass, k = 1)
  double structure_factor = 0;     // S(0) = kT dn/dP = 1 / (Z + eta Z'): no unit
  double heat_capacity_ratio = 0;  // gamma = c_p / c_v (2 for a dilute gas of discs)
  double sound_speed = 0;          // c, length per unit time
  double thermal_diffusivity = 0;  // D_T = lambda / (n c_p), area per unit time
  double sound_attenuation = 0;    // Gamma: sound of wave number k decays as
                                   // exp(-Gamma k^2 t), area per unit time
};

// Standard errors of time averages of the interior's figures.
struct InteriorWander {
  double area_fraction = std::numeric_limits<double>::quiet_NaN();  // of eta_int
  double kT = std::numeric_limits<double>::quiet_NaN();             // of kT_int
  // The correlation of those two averages, -1 ... 1: where heat warms the
  // gas it thins it (-1 wave by wave), where sound warms it it packs it (+1).
  double correlation = std::numeric_limits<double>::quiet_NaN();
};

// The relative standard error of a figure f that follows the interior's
// density and warmth as d ln f = eta_power d ln eta_int + kT_power d ln
// kT_int (the collision rate: 1 + eta g'/g and 1/2), from their errors and
// correlation in `wander` at the interior's eta and kT.
double following_wander(const InteriorWander& wander, double eta, double kT,
                        double eta_power, double kT_power);

// The standard errors of eta_int and kT_int averaged over `duration` time
// units, for balls of `radius` on a table `width` x `height` (A1, A2; the
// centres move in (A1 - 2a) x (A2 - 2a)) whose interior is the rectangle of
// centres `interior` (table coordinates). The waves run up to wave number
// max_wave_number (1 / radius unless given). NaN for an empty interior, no
// duration, or a state without sound or heat.
InteriorWander interior_wander(const BoxHydrodynamics& fluid, double radius, double width,
                               double height, const Region& interior, double duration,
                               double max_wave_number = 0);

// The theory's standard error over W with its short part replaced by the
// run's own: hydrodynamics is right for the slow waves and short of the
// truth within a free time or two, which the run's batches do see. With n
// batches of length b whose means give batch_error, and the theory's errors
// over W, over b and over n b,
//   error^2 = theory(W)^2 + batch_error^2 - (theory(b)^2 - theory(n b)^2) / (n - 1),
// the last term being what the theory expects batch_error^2 to be (the
// batch means' sample variance over n: the variance of one, less the part
// common to all). NaN for fewer than 2 batches.
double corrected_by_batches(double theory_whole, double theory_batch,
                            double theory_batches, double batches, double batch_error);

// A standing wave along one side of the centres' box, 0 <= u <= length:
// the integral of cos(m pi u / length) over from <= u <= to, and the
// wave's norm, the integral of its square over the whole side.
struct WaveSide {
  double projection = 0;
  double norm = 0;
};
WaveSide side_wave(int m, double length, double from, double to);

// The variance of the time average over W of a correlation exp(-t / tau), in
// units of its value at t = 0: (2 / W^2) integral_0^W (W - t) exp(-t / tau) dt.
double averaged_decay(double tau, double duration);
// The same for a ringing correlation cos(omega t) exp(-alpha t).
double averaged_ringing(double alpha, double omega, double duration);

}  // namespace gas
