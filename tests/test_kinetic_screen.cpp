// The statistics screen of kinetic theory (stages/beyond/kinetic_screen.*):
// its layout (each figure at a fixed place, whatever its value), the
// histogram of speeds under the Maxwell-Boltzmann curve, and --csv's columns
// with numbers that read back bit for bit. The physics behind the figures:
// tests/test_kinetic_theory.cpp.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "beyond/kinetic_screen.hpp"
#include "support.hpp"

using gas::TextScreen;

TEST_SUITE("kinetic-theory") {
  TEST_CASE("draw_kinetic_figures puts each figure at a fixed place whatever its value") {
    // Two different sets of figures: every label starts at the same cell, and
    // the "average" and "theory" columns start at the same columns, on both
    // screens (lesson 12 has the layout); few balls say so in words.
    gas::Figures small;
    gas::Figures big = gas::testing::some_figures();
    big.time = 123456.75;
    big.wall_collisions = 1234567;
    gas::KineticFigures small_kinetic;
    gas::KineticFigures big_kinetic;
    big_kinetic.many_balls = true;
    big_kinetic.measured.bulk_z = {2.0625, 0.0125};
    big_kinetic.bulk_z_theory = {2.0637755, 0.0021};
    // The rows with a theory column, and where they are.
    const std::vector<std::pair<std::string, std::size_t>> labels = {
        {"mean speed", 8},      {"P walls' middles", 9}, {"Z bulk", 13},
        {"  g(2a) inside", 15}, {"kT n at walls", 16},   {"collisions/ball", 17},
        {"mean free path", 19}};
    const int average_column = 20, theory_column = 42;
    for (const auto& [f, k] :
         {std::pair{&small, &small_kinetic}, std::pair{&big, &big_kinetic}}) {
      TextScreen screen = gas::prepare_character_screen(80, 22);
      screen.at({40, 2}) = 'x';  // something left from before: wiped
      gas::draw_kinetic_figures(screen, *f, *k);
      CHECK(screen.lines[1].substr(2, 2) == "T ");
      CHECK(screen.lines[2].substr(2, 2) == "N ");
      CHECK(screen.lines[3].substr(2, 6) == "units:");
      CHECK(screen.lines[4].substr(2, 11) == "speeds now:");
      CHECK(screen.lines[5].substr(2, 2) == "H ");
      CHECK(screen.lines[7].substr(average_column, 7) == "average");
      CHECK(screen.lines[7].substr(theory_column, 6) == "theory");
      for (const auto& [label, row] : labels) {
        CAPTURE(label);
        const std::string& line = screen.lines[row];
        CHECK(line.substr(2, label.size()) == label);
        CHECK(line[1] == ' ');
        CHECK(line[theory_column - 1] == ' ');
        CHECK(line[theory_column] != ' ');  // a number, "-" or words
      }
      // The rows of two averages side by side: in the average and theory columns.
      CHECK(screen.lines[11].substr(2, 7) == "  Px, P");
      CHECK(screen.lines[12].substr(2, 12) == "Z box: walls");
      for (const std::size_t row : {11, 12}) {
        CHECK(screen.lines[row][average_column] != ' ');
        CHECK(screen.lines[row][theory_column] != ' ');
      }
      // The values read back: T with 6 decimals (so within 5e-7).
      CHECK(std::abs(std::stod(screen.lines[1].substr(4)) - f->time) <= 5e-7);
    }
    // The average with its error, in its column, and the theory with its own.
    TextScreen screen = gas::prepare_character_screen(80, 22);
    gas::draw_kinetic_figures(screen, big, big_kinetic);
    CHECK(screen.lines[13].substr(average_column, 21) == "2.0625 +- 0.013      ");
    CHECK(screen.lines[13].substr(theory_column, 16) == "2.0638 +- 0.0021");
    // A handful of balls: the bulk's theory in words, no number.
    gas::draw_kinetic_figures(screen, big, small_kinetic);
    CHECK(screen.lines[13].substr(theory_column, 16) == "needs many balls");
    CHECK(screen.lines[17].substr(theory_column, 16) == "needs many balls");
  }

  TEST_CASE(
      "draw_kinetic_figures on a small screen: one figure a row and cut at the border") {
    TextScreen screen =
        gas::prepare_character_screen(20, 8);  // 6 rows inside, 18 columns
    gas::draw_kinetic_figures(screen, gas::testing::some_figures(),
                              gas::KineticFigures{});
    CHECK(screen.lines[1].substr(0, 14) == "| T 12.500000 ");
    CHECK(screen.lines[5].substr(0, 4) == "| H ");
    for (const std::string& line : screen.lines) {
      CHECK(line.size() == 20);
      CHECK((line.back() == '|' || line.back() == '+'));
    }
    CHECK(screen.lines[7] == "+------------------+");
  }

  TEST_CASE(
      "draw_histogram: bars of the measured fractions under the Maxwell-Boltzmann "
      "curve") {
    // Measured fractions exactly the Maxwell-Boltzmann ones: every column's
    // '*' sits on top of its bar (the same height), and the axis reads 0 to
    // the last speed.
    gas::KineticFigures f;
    f.theory.kT = 1;
    f.theory.mean_speed = std::sqrt(3.14159265358979 / 2);
    f.measured.bin_width = 0.25;
    for (int b = 0; b < 14; ++b) {
      f.measured.speed_fractions.push_back(
          gas::maxwell_fraction_below(0.25 * (b + 1), 1) -
          gas::maxwell_fraction_below(0.25 * b, 1));
    }
    TextScreen screen = gas::prepare_character_screen(32, 14);  // 28 columns: 2 a bin
    gas::draw_histogram(screen, f, 1, 12);
    CHECK(screen.lines[1].substr(2, 8) == "speeds: ");
    CHECK(screen.lines[12].substr(2, 1) == "0");
    CHECK(screen.lines[12].substr(27, 3) == "3.5");  // 14 bins of 0.25
    for (int column = 2; column < 30; ++column) {
      CAPTURE(column);
      int top = 0;  // the highest row with anything in this column
      for (int row = 2; row < 12 && top == 0; ++row)
        if (screen.lines[static_cast<std::size_t>(row)]
                        [static_cast<std::size_t>(column)] != ' ')
          top = row;
      if (top == 0) continue;  // too small to draw
      CHECK(
          screen.lines[static_cast<std::size_t>(top)][static_cast<std::size_t>(column)] ==
          '*');
      for (int row = top + 1; row < 12; ++row)
        CHECK(screen.lines[static_cast<std::size_t>(row)]
                          [static_cast<std::size_t>(column)] == '#');
    }
    // A spike beyond the scale is cut with '^'.
    f.measured.speed_fractions[4] = 0.9;
    gas::draw_histogram(screen, f, 1, 12);
    CHECK(screen.lines[2][10] == '^');
  }

  TEST_CASE(
      "csv_header and csv_row: the article's nine columns then kinetic theory's and "
      "numbers that read back bit for bit") {
    CHECK(gas::csv_header().rfind(
              "T,T0,wall_collisions,ball_collisions,mean_speed,energy,energy_drift,px,py,"
              "kT,",
              0) == 0);
    gas::Figures f = gas::testing::some_figures();
    f.time = 37.0 / 3;  // numbers that need all 17 digits
    f.display_step = 0.1;
    gas::KineticFigures k;
    k.measured.bulk_z = {2.0 / 3, 1.0 / 7};
    k.bulk_z_theory = {1.0 / 9, 1.0 / 13};
    k.measured.h_now = 1.0 / 11;
    const std::string row = gas::csv_row(f, k);
    const std::vector<std::string> fields = gas::testing::fields_of(row);
    const std::vector<std::string> names = gas::testing::fields_of(gas::csv_header());
    REQUIRE(fields.size() == names.size());
    auto same = [](const std::string& text, double value) {
      return std::bit_cast<std::uint64_t>(std::strtod(text.c_str(), nullptr)) ==
             std::bit_cast<std::uint64_t>(value);
    };
    auto field = [&](const std::string& name) {
      const auto at = std::find(names.begin(), names.end(), name);
      REQUIRE(at != names.end());
      return fields[static_cast<std::size_t>(at - names.begin())];
    };
    CHECK(same(fields[0], f.time));
    CHECK(same(fields[1], f.display_step));
    CHECK(fields[2] == "4");
    CHECK(fields[3] == "3");
    CHECK(same(fields[4], f.mean_speed));
    CHECK(same(fields[5], f.energy));
    CHECK(same(fields[6], f.energy_drift));
    CHECK(same(fields[7], f.momentum.x));
    CHECK(same(fields[8], f.momentum.y));
    CHECK(same(field("Z"), k.measured.bulk_z.value));
    CHECK(same(field("Z_error"), k.measured.bulk_z.error));
    CHECK(same(field("Z_theory"), k.bulk_z_theory.value));
    CHECK(same(field("Z_theory_error"), k.bulk_z_theory.error));
    CHECK(same(field("H"), k.measured.h_now));
    CHECK(field("mean_speed_average") == "nan");  // not measured yet
    // One convention: every _error, _theory and _theory_error column names
    // a column that is there; the box's figures end in _box (data/README.md).
    for (const std::string& name : names) {
      CAPTURE(name);
      for (const std::string suffix : {"_theory_error", "_error", "_theory"}) {
        if (name.size() > suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
          const std::string base = name.substr(0, name.size() - suffix.size());
          CHECK(std::find(names.begin(), names.end(), base) != names.end());
          break;
        }
      }
    }
    for (const char* box :
         {"pressure_box", "collision_rate_box", "Z_box_walls", "Z_box_virial"})
      CHECK(std::find(names.begin(), names.end(), box) != names.end());
    // Names are unique.
    std::vector<std::string> sorted = names;
    std::sort(sorted.begin(), sorted.end());
    CHECK(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  }

  TEST_CASE(
      "H and its bins do not depend on the screen: --cols 40 and 160 write one CSV") {
    // The kinetic scene (200 balls) to T = 5: the same file whatever the
    // width (the histogram's bins are fixed; only its drawing follows the
    // screen).
    const gas::testing::Scratch scratch;
    std::string files[2];
    int k = 0;
    for (const char* columns : {"40", "160"}) {
      const std::string csv = scratch.file(fmt::format("h{}.csv", k));
      const auto run = gas::testing::run_program({"data/kinetic.scene", "--mode", "stats",
                                                  "--until", "5", "--csv", csv, "--cols",
                                                  columns, "--rows", "30"});
      REQUIRE(run.status == 0);
      files[k++] = gas::testing::read_file(csv);
    }
    CHECK(files[0] == files[1]);
    CHECK(files[0].find(",H,") != std::string::npos);
  }

  TEST_CASE("the key A restarts the averages at once and the CSV says since when") {
    // The kinetic scene (200 balls): the warm-up of L / lambda = 36
    // collisions of two balls a ball ends near T = 51; A pressed before the
    // step to T = 61 restarts the averages at T = 60, and they go on from
    // there.
    const gas::testing::Scratch scratch;
    const std::string csv = scratch.file("c.csv");
    const auto run = gas::testing::run_program({"data/kinetic.scene", "--mode", "none",
                                                "--until", "70", "--csv", csv, "--keys",
                                                std::string(60, '.') + "A"});
    REQUIRE(run.status == 0);
    std::vector<std::vector<std::string>> rows;
    for (const std::string& line : gas::testing::lines_of(gas::testing::read_file(csv)))
      rows.push_back(gas::testing::fields_of(line));
    REQUIRE(rows.size() == 71);  // the header and T = 1 ... 70
    const std::size_t since = static_cast<std::size_t>(
        std::find(rows[0].begin(), rows[0].end(), "averages_since") - rows[0].begin());
    REQUIRE(since < rows[0].size());
    CHECK(rows[1][since] == "nan");                    // T = 1: warming up
    CHECK(rows[50][since] == "nan");                   // T = 50: still
    const double warmed = std::stod(rows[60][since]);  // T = 60
    CHECK(warmed > 50);
    CHECK(warmed < 60);
    CHECK(rows[61][since] == "60");  // restarted before the step to T = 61
    CHECK(rows[70][since] == "60");
  }

}  // TEST_SUITE
