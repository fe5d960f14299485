// Stage 1 of the article, "variables and data": what a ball's row R(4, N)
// means and the sums over the balls. Checks centre_at (free flight from the
// moment `since` the row was written), centres_at, kinetic_energy,
// total_momentum and mean_speed, on hand-made states and on random ones.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "stage1_data.hpp"

namespace {

using gas::Ball;
using gas::Gas;

// Three balls whose values are small binary fractions, so every sum and
// product below is exact and the hand results can be compared with ==.
// No two velocities are mirror images, so a lost sign changes the result.
Gas three_balls() {
  Gas gas;
  gas.balls = {{1, 2, 3, -4, 5}, {0.5, 8, 0, -2, 0}, {10, 10, -5, 12, 2.5}};
  return gas;
}

// Random balls (fixed seed) with coordinates and velocities of either sign.
Gas random_gas(std::mt19937_64& rng, int count) {
  std::uniform_real_distribution<double> position(0, 100), velocity(-10, 10), time(0, 50);
  Gas gas;
  for (int i = 0; i < count; ++i) {
    gas.balls.push_back(
        {position(rng), position(rng), velocity(rng), velocity(rng), time(rng)});
  }
  return gas;
}

}  // namespace

TEST_SUITE("stage1") {
  TEST_CASE("stage1 centre_at flies freely from the moment `since`") {
    const Ball ball{1, 2, 3, -4, 5};  // written at time 5
    SUBCASE("at `since` the centre is the stored one") {
      CHECK(gas::centre_at(ball, 5).x == 1);
      CHECK(gas::centre_at(ball, 5).y == 2);
    }
    SUBCASE("two time units later it has moved by 2 v") {
      CHECK(gas::centre_at(ball, 7).x == 7);
      CHECK(gas::centre_at(ball, 7).y == -6);
    }
    SUBCASE("before `since` it is where it came from") {
      CHECK(gas::centre_at(ball, 4).x == -2);
      CHECK(gas::centre_at(ball, 4).y == 6);
    }
    SUBCASE("random balls agree with the flight computed in long double") {
      std::mt19937_64 rng(11);
      std::uniform_real_distribution<double> flight(0.1, 20);
      for (const Ball& b : random_gas(rng, 200).balls) {
        const double time = b.since + flight(rng);
        const gas::Point c = gas::centre_at(b, time);
        const long double x = b.x + b.vx * (static_cast<long double>(time) - b.since);
        const long double y = b.y + b.vy * (static_cast<long double>(time) - b.since);
        // Why 1e-12 (absolute): coordinates stay below ~400, and double
        // rounds them to ~6e-14; the three roundings of centre_at stay under
        // ~2e-13. A flight measured from 0 instead of `since` would be off by
        // |v| * since, i.e. by units, not by 1e-12.
        CHECK(std::abs(c.x - x) < 1e-12);
        CHECK(std::abs(c.y - y) < 1e-12);
      }
    }
  }

  TEST_CASE("stage1 centres_at gives every ball's centre at one time") {
    const Gas gas = three_balls();
    const std::vector<gas::Point> centres = gas::centres_at(gas, 6);
    REQUIRE(centres.size() == 3);
    // Hand values: ball 1 flew 1, ball 2 flew 6, ball 3 flew 3.5 time units.
    CHECK(centres[0].x == 4);
    CHECK(centres[0].y == -2);
    CHECK(centres[1].x == 0.5);
    CHECK(centres[1].y == -4);
    CHECK(centres[2].x == -7.5);
    CHECK(centres[2].y == 52);
    CHECK(gas::centres_at(Gas{}, 6).empty());
  }

  TEST_CASE("stage1 kinetic energy total momentum and mean speed of hand-made balls") {
    const Gas gas = three_balls();
    // Speeds 5, 2, 13 (3-4-5 and 5-12-13 triangles).
    CHECK(gas::kinetic_energy(gas) == (25 + 4 + 169) / 2.0);
    CHECK(gas::total_momentum(gas).x == -2);
    CHECK(gas::total_momentum(gas).y == 6);
    // Why 1e-15: (5 + 2 + 13) / 3 needs one rounding of the division (and
    // hypot is exact here), so the error is below one ulp of 6.67.
    CHECK(gas::mean_speed(gas) == doctest::Approx(20.0 / 3).epsilon(1e-15));
  }

  TEST_CASE("stage1 sums over no balls are zero") {
    const Gas empty;
    CHECK(gas::kinetic_energy(empty) == 0);
    CHECK(gas::total_momentum(empty).x == 0);
    CHECK(gas::total_momentum(empty).y == 0);
    const double mean = gas::mean_speed(empty);  // must not divide 0 by 0
    CHECK_FALSE(std::isnan(mean));
    CHECK(mean == 0);
  }

  TEST_CASE("stage1 sums over random balls agree with long double sums") {
    std::mt19937_64 rng(12);
    const Gas gas = random_gas(rng, 500);
    long double energy = 0, px = 0, py = 0, speed = 0;
    for (const Ball& b : gas.balls) {
      const long double vx = b.vx, vy = b.vy;
      energy += (vx * vx + vy * vy) / 2;
      px += vx;
      py += vy;
      speed += std::sqrt(vx * vx + vy * vy);
    }
    // Why 1e-13: a sum of 500 terms in double has a relative error of at
    // most ~500 ulps (1e-13) in the worst case; sums of positive terms are far
    // better. The momentum sums terms of both signs, so its error is measured
    // against the sum of |v| (~2500), not against the small total itself.
    CHECK(gas::kinetic_energy(gas) ==
          doctest::Approx(static_cast<double>(energy)).epsilon(1e-13));
    CHECK(gas::mean_speed(gas) ==
          doctest::Approx(static_cast<double>(speed / 500)).epsilon(1e-13));
    CHECK(std::abs(gas::total_momentum(gas).x - px) < 1e-13 * 2500);
    CHECK(std::abs(gas::total_momentum(gas).y - py) < 1e-13 * 2500);
  }
}
