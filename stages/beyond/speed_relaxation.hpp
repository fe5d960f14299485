// How far the time-averaged mean speed of a gas at fixed energy wanders
// (beyond the article): kinetic theory's error bar for it.
//
// What this file does: predicts the standard error of the mean speed of the
// N balls averaged over a duration W, from the speed distribution's shape
// fluctuations and how fast collisions erase them, so that an error can be
// quoted before the run's own batches are long enough to measure one. The
// energy is fixed (specular walls, elastic collisions), so only the shape of
// the speed distribution wanders. Two numbers set the error:
//  - the static variance of the instantaneous mean speed, <psi^2> / N, with
//    psi = |v| minus its projection onto {1, v^2} under Maxwell's 2D
//    distribution: <psi^2> = (2 - 5 pi / 8) kT (exact);
//  - the integrated correlation time tau_int = <psi (-L)^-1 psi> / <psi^2>, L
//    Boltzmann's linearised collision operator for hard discs times Enskog's
//    g(2a), solved in the isotropic Sonine (Laguerre) polynomials L_p(x), x =
//    v^2 / (2 kT), p = 2 ... P, whose matrix elements <L_p (-L) L_q> are
//    exact (tabulated here from their derivation in speed_relaxation.cpp),
//    with the limit P -> infinity extrapolated from P = 8 ... 10.
// Then Var(average over W) = 2 tau_int <psi^2> / (N W) for W >> tau_int,
// and with the correlation modelled as exp(-t / tau_int) for any W.
// Everything is derived in speed_relaxation.cpp; tests/test_speed_relaxation.cpp
// checks the closed forms by quadrature and the matrix elements by Monte
// Carlo over colliding pairs.
// Article: none (the article's character screen and its figures:
// beyond/gas_statistics.hpp). That the article takes no time averages and
// gives them no errors is our reading.
// Everything here is beyond it.
// Lesson: lessons/14-error-bars.md
//
// Assumptions: unit mass and k = 1 (kT = E / N, an energy per ball, 2D); discs
// of radius a, diameter s = 2a; number density n = eta / (pi a^2); g(2a) from
// the reference fluid (beyond/hard_disc_fluid.hpp), so 0 < eta <= 0.70.
// Enskog's theory: uncorrelated collisions at the rate of the equilibrium
// fluid at contact; a bulk fluid (the walls, specular, do not change a
// speed); leading order in 1 / N. Ring collisions, the walls' layers and the
// box's slow heat flows are outside it.
#pragma once

#include <cstddef>

namespace gas {

// The highest Sonine order P whose matrix elements are tabulated.
inline constexpr int speed_sonine_order_limit = 10;

// <psi^2> / kT = 2 - 5 pi / 8 = 0.0365: the variance of a ball's speed left
// when its projection onto 1 and v^2 is taken away, over kT (no units).
double speed_shape_variance();

// The coefficient of |v| / sqrt(kT) on L_p(x), x = v^2 / (2 kT), under
// Maxwell's weight (the L_p are orthonormal there, weight e^-x):
// sqrt(pi / 2) (-1/2)_p / p! (no units). p >= 0; NaN for p < 0.
double speed_sonine_coefficient(int p);

// <L_p (-L) L_q> over n g s sqrt(kT): the linearised hard-disc collision
// operator in the Sonine polynomials (no units), exact, for 0 <= p, q <=
// speed_sonine_order_limit; zero when p or q is 0 or 1 (number and energy
// are conserved); NaN outside the table.
double sonine_collision_element(int p, int q);

// tau_int n g s sqrt(kT) in the P-th Sonine approximation (basis L_2 ... L_P,
// 2 <= P <= speed_sonine_order_limit; NaN otherwise). It is a lower bound
// that grows with P (the variational principle, speed_relaxation.cpp).
double speed_relaxation_sonine(int order);

// tau_int n g s sqrt(kT) for P -> infinity: the largest order's value plus
// the tail its last steps extrapolate to (speed_relaxation.cpp), and that
// tail (both no units).
struct SonineLimit {
  double value = 0;
  double tail = 0;  // value - speed_relaxation_sonine(speed_sonine_order_limit)
};
SonineLimit speed_relaxation_limit();

// The prediction for one gas.
struct MeanSpeedWander {
  double instant_spread =
      0;  // sqrt(<psi^2> / N): the instantaneous mean speed's, a speed
  double collision_time = 0;   // Enskog's mean free time 1 / (2 sqrt(pi) n g s sqrt(kT))
  double relaxation_time = 0;  // tau_int, a time
  // The standard error of the mean speed averaged over the duration W (a
  // speed), with the correlation exp(-|t| / tau_int):
  // sqrt(<psi^2> / N) sqrt((2 tau / W) (1 - (tau / W)(1 - exp(-W / tau)))).
  double error = 0;
  // Its long-time form sqrt(2 tau_int <psi^2> / (N W)), a speed.
  double long_time_error = 0;
};

// The predicted wander of the mean speed of `balls` discs of radius `radius`
// at area fraction eta and temperature kT, averaged over `duration` time
// units. Fields NaN where not defined: eta outside 0 < eta <= 0.70, radius
// or kT not positive, fewer than 2 balls; the two errors also for a duration
// not positive (at W -> 0 `error` tends to instant_spread).
MeanSpeedWander mean_speed_wander(double area_fraction, double radius, double kT,
                                  std::size_t balls, double duration);

}  // namespace gas
