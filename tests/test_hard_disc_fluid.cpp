// Tests for the reference equation of state of the hard-disc fluid
// (stages/beyond/hard_disc_fluid.*, lessons/13-box-and-bulk.md):
//
// - Its virial expansion: the series of Kolafa and Rottner, expanded in eta,
//   gives the reduced virial coefficients b_n = 2^(n-1) B_n / B_2^(n-1):
//   b2 = 2, b3 exact, b4 ... b10 within the errors of Clisby and McCoy,
//   J. Stat. Phys. 122, 15 (2006), Table 1 (D = 2).
// - Its values at low density against that virial series.
// - Its values at the top of the fluid range against simulation data (Engel
//   et al. 2013, Li et al. 2022), within the 0.1 % it is meant for.
// - Henderson's error against it: the figures issue 14 quotes.
// - The contact value from the 2D virial theorem, the slope dZ/deta and the
//   curvature d^2Z/deta^2.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "beyond/hard_disc_fluid.hpp"

namespace {

constexpr double pi = std::numbers::pi;

// Binomial coefficient, exact in double for the small numbers used here.
double choose(int n, int k) {
  if (k < 0 || k > n) return 0;
  double c = 1;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

// The coefficient of eta^m in the reference's series: x^p = eta^p (1 -
// eta)^(-p) = sum_k C(p + k - 1, k) eta^(p + k), so eta^m gets C(m - 1, m - p)
// from each term of power 1 <= p <= m (and the constant term gives eta^0).
// Worked out here, from the terms, independently of the code's evaluation.
double series_coefficient(int m) {
  double b = 0;
  for (const gas::FluidTerm& term : gas::hard_disc_fluid_terms()) {
    if (m == 0 && term.power == 0) b += term.coefficient;
    if (m >= 1 && term.power >= 1 && term.power <= m) {
      b += term.coefficient * choose(m - 1, m - term.power);
    }
  }
  return b;
}

// The reduced virial coefficients of hard discs, b_n = 2^(n-1) B_n /
// B_2^(n-1), so that Z = 1 + sum_n b_n eta^(n-1): b2 = 2; b3 = 16/3 -
// 4 sqrt(3) / pi exactly (B3 / B2^2 = 4/3 - sqrt(3) / pi); b4 ... b10 from
// Clisby and McCoy (2006), Table 1, B_n / B_2^(n-1) for D = 2, with their
// standard errors in the last digits (b4 is exact; the table gives 8 digits).
struct Virial {
  int n;
  double ratio;  // B_n / B_2^(n-1)
  double error;  // its standard error
};
const std::vector<Virial> clisby_mccoy = {
    {4, 0.53223180, 1e-8},  {5, 0.33355604, 1e-8}, {6, 0.1988425, 42e-7},
    {7, 0.1148728, 43e-7},  {8, 0.0649930, 34e-7}, {9, 0.0362193, 35e-7},
    {10, 0.0199537, 80e-7},
};
const double b3_exact = 16.0 / 3 - 4 * std::sqrt(3.0) / pi;

// A simulation point: the pressure as beta P (2a)^2 at area fraction eta,
// with its error; Z = beta P / rho = beta P (2a)^2 pi / (4 eta).
struct Simulation {
  const char* source;
  double eta;
  double pressure;  // beta P (2a)^2
  double error;
};
double z_of(const Simulation& s) {
  return s.pressure * pi / (4 * s.eta);
}

}  // namespace

TEST_SUITE("kinetic-theory") {
  TEST_CASE("hard-disc fluid: the reference's virial expansion gives B2 ... B10") {
    // Z = 1 + 2 eta + ...: the ideal gas and B2 (the excluded area 2 pi a^2
    // per pair, half of it per ball: b2 = 2).
    CHECK(series_coefficient(0) == doctest::Approx(1).epsilon(1e-15));
    CHECK(series_coefficient(1) == doctest::Approx(2).epsilon(1e-15));
    // b3 exact to the 9 digits the coefficients carry.
    CHECK(std::abs(series_coefficient(2) - b3_exact) < 1e-8);
    // b4 ... b10 within two of Clisby and McCoy's standard errors (the fit
    // took them from Labik, Kolafa and Malijevsky 2005; the two agree). b4
    // and b5 are known to 8 digits, so this pins C_3 and C_4 to ~1e-7.
    for (const Virial& v : clisby_mccoy) {
      const double scale = std::pow(2.0, v.n - 1);
      const double expected = v.ratio * scale;
      const double tolerance = 2 * v.error * scale + 1e-7;  // + rounding of the table
      INFO("b" << v.n << ": series " << series_coefficient(v.n - 1) << ", Clisby-McCoy "
               << expected << " +- " << v.error * scale);
      CHECK(std::abs(series_coefficient(v.n - 1) - expected) < tolerance);
    }
  }

  TEST_CASE("hard-disc fluid: at low density the reference is the virial series") {
    // Z against 1 + sum_{n<=10} b_n eta^(n-1). What is left out, b11 eta^10
    // + ..., is about 11 eta^10 (1e-12 at eta = 0.05, 1.2e-9 at 0.1, 1.3e-6
    // at 0.2), and the fit's b6 differs from Clisby and McCoy's by 7e-5
    // (within their error), 2e-11 at 0.05. The tolerances are about three
    // times the larger.
    auto virial = [](double eta) {
      double z = 1 + 2 * eta + b3_exact * eta * eta;
      for (const Virial& v : clisby_mccoy) {
        z += v.ratio * std::pow(2.0, v.n - 1) * std::pow(eta, v.n - 1);
      }
      return z;
    };
    CHECK(std::abs(gas::hard_disc_fluid_compressibility(0.05) - virial(0.05)) < 1e-10);
    CHECK(std::abs(gas::hard_disc_fluid_compressibility(0.1) - virial(0.1)) < 5e-9);
    CHECK(std::abs(gas::hard_disc_fluid_compressibility(0.2) - virial(0.2)) < 5e-6);
    CHECK(gas::hard_disc_fluid_compressibility(0) == 1);
  }

  TEST_CASE(
      "hard-disc fluid: the reference agrees with simulations to 0.1 % up to 0.70") {
    // From the open data of B. Li et al., J. Chem. Phys. 157, 234111 (2022),
    // repository HistoricDisks: DigitizedData/Engel_2013/Engel_2013.csv (data
    // of Engel et al., Phys. Rev. E 87, 042134 (2013), given to Li et al. by
    // the authors) and DigitizedData/ThisWork.csv. The error bars (3e-6 of Z
    // and less) are far below what a fit claims, so the test asks for the
    // 0.1 % the reference is meant for. It is met with room: +0.03 % at 0.698
    // (N = 1024^2), +0.053 % at 0.700, 0.001 % at 0.670 and -0.04 % at 0.680
    // (N = 870, where the finite system is itself about 0.1 % low: N = 224
    // is 0.26 % lower still).
    const std::vector<Simulation> table = {
        {"Engel 2013, MPMC, N = 1024^2", 0.698, 9.169342, 0.000023},
        {"Engel 2013, MPMC, N = 1024^2", 0.700, 9.185405, 0.000085},
        {"Engel 2013, EDMD, N = 512^2", 0.698, 9.169588, 0.000091},
        {"Engel 2013, EDMD, N = 256^2", 0.698, 9.17059, 0.00018},
        {"Li 2022, ECMC, N = 870", 0.670, 7.986735, 0.000026},
        {"Li 2022, ECMC, N = 870", 0.680, 8.513233, 0.000037},
    };
    for (const Simulation& s : table) {
      const double reference = gas::hard_disc_fluid_compressibility(s.eta);
      INFO(s.source << " at eta = " << s.eta << ": Z = " << z_of(s) << ", reference "
                    << reference);
      CHECK(std::abs(reference / z_of(s) - 1) < 1e-3);
    }
  }

  TEST_CASE("hard-disc fluid: Henderson's error against the reference (issue 14)") {
    // Henderson is a hair low below eta = 0.23 and high above it.
    CHECK(gas::henderson_relative_error(0.1) < 0);
    CHECK(gas::henderson_relative_error(0.1) > -1e-4);
    for (int percent = 25; percent <= 70; percent += 5) {
      CHECK(gas::henderson_relative_error(percent / 100.0) > 0);
    }
    // Within 0.5 % up to 0.5 (0.45 % there, 0.5 % at 0.51), within 1 % up to
    // 0.58, 2.2 % high at 0.65, 8.1 % at 0.69, 14 % at 0.70.
    CHECK(gas::henderson_relative_error(0.50) < 0.005);
    CHECK(gas::henderson_relative_error(0.52) > 0.005);
    CHECK(gas::henderson_relative_error(0.58) < 0.01);
    CHECK(gas::henderson_relative_error(0.59) > 0.01);
    CHECK(gas::henderson_relative_error(0.65) == doctest::Approx(0.0222).epsilon(0.01));
    CHECK(gas::henderson_relative_error(0.69) == doctest::Approx(0.0808).epsilon(0.01));
    CHECK(gas::henderson_relative_error(0.70) == doctest::Approx(0.1436).epsilon(0.01));
  }

  TEST_CASE("hard-disc fluid: the pressure is Z N kT / A") {
    // N discs of radius a on an area A = N pi a^2 / eta: P A / (N kT) = Z.
    // (Equal within 1e-14: a handful of roundings of a number near 1.)
    const double n = 400, a = 1.5, kT = 0.7;
    for (double eta : {0.05, 0.3, 0.5, 0.7}) {
      const double area = n * std::numbers::pi * a * a / eta;
      CHECK(gas::hard_disc_fluid_pressure(eta, kT, a) * area / (n * kT) ==
            doctest::Approx(gas::hard_disc_fluid_compressibility(eta)).epsilon(1e-14));
    }
    CHECK(std::isnan(gas::hard_disc_fluid_pressure(0.75, kT, a)));
  }

  TEST_CASE("hard-disc fluid: contact value, slope and range") {
    // The 2D virial theorem, Z = 1 + 2 eta g(2a).
    for (double eta : {0.1, 0.3, 0.5, 0.65, 0.7}) {
      const double z = gas::hard_disc_fluid_compressibility(eta);
      CHECK(1 + 2 * eta * gas::hard_disc_fluid_contact_value(eta) ==
            doctest::Approx(z).epsilon(1e-14));
    }
    // g(2a) -> 1 as eta -> 0, and g = 1 + (b3 / 2) eta + ... at small eta.
    CHECK(gas::hard_disc_fluid_contact_value(0) == 1);
    CHECK(gas::hard_disc_fluid_contact_value(1e-4) ==
          doctest::Approx(1 + b3_exact / 2 * 1e-4).epsilon(1e-7));
    // The slope against a central difference (step 1e-6: its error, h^2 Z''' / 6
    // and rounding, is below 1e-9 of the slope).
    for (double eta : {0.05, 0.3, 0.5, 0.69}) {
      const double h = 1e-6;
      const double difference = (gas::hard_disc_fluid_compressibility(eta + h) -
                                 gas::hard_disc_fluid_compressibility(eta - h)) /
                                (2 * h);
      CHECK(gas::hard_disc_fluid_compressibility_slope(eta) ==
            doctest::Approx(difference).epsilon(1e-7));
    }
    CHECK(gas::hard_disc_fluid_compressibility_slope(0) == doctest::Approx(2));
    // The curvature Z'' (the closed box's shift needs it) against a central
    // difference of the slope (step 1e-5: h^2 Z'''' / 6 and rounding, some
    // 1e-12 / 1e-5 of Z', are below 1e-7 of Z''), and at 0 the series'
    // 2 b3 (Z = 1 + 2 eta + b3 eta^2 + ...).
    for (double eta : {0.05, 0.3, 0.5, 0.69}) {
      const double h = 1e-5;
      const double difference = (gas::hard_disc_fluid_compressibility_slope(eta + h) -
                                 gas::hard_disc_fluid_compressibility_slope(eta - h)) /
                                (2 * h);
      CAPTURE(eta);
      CHECK(gas::hard_disc_fluid_compressibility_curvature(eta) ==
            doctest::Approx(difference).epsilon(1e-7));
    }
    CHECK(gas::hard_disc_fluid_compressibility_curvature(0) ==
          doctest::Approx(2 * b3_exact).epsilon(1e-8));
    CHECK(std::isnan(gas::hard_disc_fluid_compressibility_curvature(0.75)));
    // The contact value's slope (g_contact_theory_error = |slope| x eta's
    // error) against a central difference of g, as above; at 0 the limit b3 / 2.
    for (double eta : {0.05, 0.3, 0.5, 0.69}) {
      const double h = 1e-6;
      const double difference = (gas::hard_disc_fluid_contact_value(eta + h) -
                                 gas::hard_disc_fluid_contact_value(eta - h)) /
                                (2 * h);
      CHECK(gas::hard_disc_fluid_contact_value_slope(eta) ==
            doctest::Approx(difference).epsilon(1e-7));
    }
    CHECK(gas::hard_disc_fluid_contact_value_slope(0) ==
          doctest::Approx(b3_exact / 2).epsilon(1e-8));
    CHECK(std::isnan(gas::hard_disc_fluid_contact_value_slope(0.75)));
    // No fluid reference outside 0 ... 0.70.
    CHECK(std::isnan(gas::hard_disc_fluid_compressibility(0.71)));
    CHECK(std::isnan(gas::hard_disc_fluid_compressibility(-0.1)));
    CHECK(std::isnan(gas::hard_disc_fluid_contact_value(0.8)));
    CHECK(std::isnan(gas::hard_disc_fluid_compressibility_slope(0.75)));
    CHECK(std::isnan(gas::henderson_relative_error(0.72)));
    CHECK(!std::isnan(
        gas::hard_disc_fluid_compressibility(gas::fluid_area_fraction_limit)));
  }
}
