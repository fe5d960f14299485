// The push on the walls' middles (beyond the article): how far its time
// average wanders, from the fluid's viscosity and its sound.
//
// What this file does: predicts the standard error of the statistics
// screen's pressure, the push P on the middles of the walls x = 0 and
// x = A1 (the stretches beside the interior) averaged over a run of
// duration W, without looking at the run. Bounce by bounce the push is
// noisy, but each hard push sends sound across the table that pushes less
// later: over a few crossings the noise all but cancels (on
// data/large-1000.scene an average over hundreds of time units scatters
// 0.3 times as much as independent time units would). What is left follows
// from the fluctuation-dissipation theorem: the push's spectrum at zero
// frequency is 2 kT times the friction the fluid puts up against the
// middles moved slowly inward, a flow that squeezes the whole gas (bulk
// viscosity) and shears it near the middles' ends (shear viscosity). On top
// of that the box's sound waves ring in the average for a few crossings.
// Article: none (the article's character screen and its figures:
// beyond/gas_statistics.hpp). That the article takes no time averages and
// gives them no errors is our reading.
// Lesson: lessons/14-error-bars.md
//
// Assumptions: unit mass and k = 1; linear hydrodynamics with walls that
// turn balls back like mirrors (no flow through them, no shear stress on
// them); the waves and the shear flow resolved down to one radius (wave
// numbers up to 1 / a, as beyond/box_modes.hpp); viscosities from the caller
// (Enskog's: beyond/enskog_transport.hpp). Measured on 40 gases like
// data/large-1000.scene (data/reports/kinetic-seeds.md, speeds-push): the
// seeds' scatter over the error, 1.01 to 1.16 for W from 100 to 1300 time
// units; nothing in it is fitted to them.
#pragma once

#include "beyond/box_modes.hpp"

namespace gas {

// The fluid's viscosities, in momentum per unit length (2D).
struct Viscosities {
  double shear = 0;  // eta_s
  double bulk = 0;   // zeta (kappa in beyond/enskog_transport.hpp)
};

// The stretch of the walls x = 0 and x = A1 whose push is measured: centres
// with from <= y <= to (table coordinates), on both walls.
struct WallMiddles {
  double from = 0, to = 0;
};

// The friction Re Z(0) of the fluid on the two middles moved slowly inward
// together, force per unit speed (momentum per unit time per unit speed);
// the push's total force on both middles then has the spectrum 2 kT Re Z(0)
// at zero frequency. For balls of `radius` on a table width x height.
double middles_friction(const Viscosities& viscosities, double radius, double width,
                        double height, const WallMiddles& middles,
                        double max_wave_number = 0);

// The standard error of the push per unit length on the middles averaged
// over `duration`: (2 kT Re Z(0) / W + the box's sound ringing) / (2 l)^2,
// l the length of one middle. NaN for no duration, no middles, or a state
// without sound.
double middles_push_wander(const BoxHydrodynamics& fluid, const Viscosities& viscosities,
                           double radius, double width, double height,
                           const WallMiddles& middles, double duration,
                           double max_wave_number = 0);

}  // namespace gas
