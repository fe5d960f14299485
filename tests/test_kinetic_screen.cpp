// The statistics screen of kinetic theory (stages/beyond/kinetic_screen.*):
// its layout (each figure at a fixed place, whatever its value; on a short
// screen the lines needed first, and one line naming the rest; a blank
// error's reason; a second measurement labelled in its line), the histogram
// of speeds under the Maxwell-Boltzmann curve, and --csv's columns
// (stages/beyond/kinetic_csv.*) with numbers that read back bit for bit. The physics
// behind the figures: tests/test_kinetic_theory.cpp.
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

#include "beyond/kinetic_csv.hpp"
#include "beyond/kinetic_screen.hpp"
#include "support.hpp"

using gas::TextScreen;

namespace {

// Where the table's columns start on the screen (the border and a blank
// before the label's 17 characters, then 25 for the measured average, 19
// for the theory).
constexpr std::size_t measured_column = 19, theory_column = 44, source_column = 63;

// Figures of a gas with many balls: the bulk's theories apply.
gas::KineticFigures many_balls() {
  gas::KineticFigures k;
  k.many_balls = true;
  k.measured.bulk_z = {2.0625, 0.0125};
  k.bulk_z_theory = {2.0637755, 0.0021};
  k.bulk_z_henderson = 2.0624;
  return k;
}

// The same with a histogram to draw: 20 bins of 0.125 at kT = 1.
gas::KineticFigures with_histogram(gas::KineticFigures k) {
  k.theory.kT = 1;
  k.theory.mean_speed = 1.25;
  k.measured.speed_fractions.assign(20, 0.05);
  k.measured.bin_width = 0.125;
  return k;
}

}  // namespace

TEST_SUITE("kinetic-theory") {
  TEST_CASE("draw_kinetic_figures puts each figure at a fixed place whatever its value") {
    // Two different sets of figures: every label starts at the same cell, and
    // the "measured", "theory" and "which theory" columns start at the same
    // columns, on both screens; few balls say so in words.
    gas::Figures small;
    gas::Figures big = gas::testing::some_figures();
    big.time = 123456.75;
    big.wall_collisions = 1234567;
    gas::KineticFigures small_kinetic;
    gas::KineticFigures big_kinetic = many_balls();
    // The table's rows, and where they are on a screen of 30 rows.
    const std::vector<std::pair<std::string, std::size_t>> labels = {
        {"mean speed", 7},       {"P walls' middles", 8}, {"Z bulk", 9},
        {"  Z - reference", 10}, {"g(2a) inside", 11},    {"collision rate", 12},
        {"mean free path", 13}};
    for (const auto& [f, k] :
         {std::pair{&small, &small_kinetic}, std::pair{&big, &big_kinetic}}) {
      TextScreen screen = gas::prepare_character_screen(80, 30);
      screen.at({40, 2}) = 'x';  // something left from before: wiped
      gas::draw_kinetic_figures(screen, *f, *k);
      CHECK(screen.lines[1].substr(2, 2) == "N ");
      CHECK(screen.lines[2].substr(2, 11) == "speeds now:");
      CHECK(screen.lines[3].substr(2, 6) == "units:");
      CHECK(screen.lines[4].substr(2, 2) == "H ");
      CHECK(screen.lines[6].substr(measured_column, 17) == "measured +- error");
      CHECK(screen.lines[6].substr(theory_column, 15) == "theory +- error");
      CHECK(screen.lines[6].substr(source_column, 12) == "which theory");
      for (const auto& labelled : labels) {
        const std::string& label = labelled.first;
        const std::size_t row = labelled.second;
        CAPTURE(label);
        const std::string& line = screen.lines[row];
        CHECK(line.substr(2, label.size()) == label);
        CHECK(line[1] == ' ');
        CHECK(line[measured_column - 1] == ' ');
        CHECK(line[measured_column] != ' ');  // a number or "-"
        CHECK(line[theory_column - 1] == ' ');
        CHECK(line[theory_column] != ' ');  // a number, "-", "0" or words
      }
    }
    // The average with its error, in its column, and the theory with its own.
    TextScreen screen = gas::prepare_character_screen(80, 30);
    gas::draw_kinetic_figures(screen, big, big_kinetic);
    CHECK(screen.lines[9].substr(measured_column, 25) == "2.0625 +- 0.013          ");
    CHECK(screen.lines[9].substr(theory_column, 16) == "2.0638 +- 0.0021");
    CHECK(screen.lines[9].substr(source_column, 15) == "Henderson 2.062");
    // Henderson's Z not known yet (no interior density before the warm-up):
    // "-", like every figure not known, never "nan".
    gas::KineticFigures unknown_henderson = big_kinetic;
    unknown_henderson.bulk_z_henderson = gas::not_known;
    gas::draw_kinetic_figures(screen, big, unknown_henderson);
    CHECK(screen.lines[9].substr(source_column, 12) == "Henderson - ");
    // A handful of balls: the bulk's theory in words, no number.
    gas::draw_kinetic_figures(screen, big, small_kinetic);
    CHECK(screen.lines[9].substr(theory_column, 16) == "needs many balls");
    CHECK(screen.lines[12].substr(theory_column, 16) == "needs many balls");
  }

  TEST_CASE("draw_kinetic_figures: an error not known says why in its place") {
    gas::KineticFigures k = many_balls();
    k.measured.bulk_z = {2.0625, gas::not_known, "not yet"};
    k.measured.pair_contact = {1.75, gas::not_known, "few samples"};
    k.measured.mean_speed = {1.25, gas::not_known};  // no reason given: the value alone
    k.bulk_z_theory = {2.0637755, gas::not_known, "not yet"};
    TextScreen screen = gas::prepare_character_screen(80, 30);
    gas::draw_kinetic_figures(screen, gas::testing::some_figures(), k);
    CHECK(screen.lines[9].substr(measured_column, 17) == "2.0625 +- not yet");
    CHECK(screen.lines[9].substr(theory_column, 17) == "2.0638 +- not yet");
    CHECK(screen.lines[11].substr(measured_column, 19) == "1.75 +- few samples");
    CHECK(screen.lines[7].substr(measured_column, 6) == "1.25  ");
    // A theory whose reason would be cut short stands alone, never
    // "0.094784 +- few sa": the measured column beside it says why.
    k.pressure_theory = {0.094784, gas::not_known, "few samples"};
    gas::draw_kinetic_figures(screen, gas::testing::some_figures(), k);
    CHECK(screen.lines[8].substr(theory_column, 19) == "0.094784           ");
  }

  TEST_CASE(
      "draw_kinetic_figures: a second measurement has its own label and no theory "
      "column") {
    // The box's P and its x and y parts, its Z from the walls and from the
    // collisions, the contact theorem's two sides: each labelled in its line.
    gas::KineticFigures k = many_balls();
    k.measured.pressure_box = {0.110, 0.001};
    k.measured.pressure_box_x = {0.111, 0.002};
    k.measured.pressure_box_y = {0.109, 0.002};
    k.measured.box_z_walls = {2.07, 0.03};
    k.measured.box_z_virial = {2.08, 0.003};
    k.measured.wall_contact_pressure = {0.104, 0.004};
    k.measured.wall_middle_pressure = {0.109, 0.0004};
    TextScreen screen = gas::prepare_character_screen(80, 30);
    gas::draw_kinetic_figures(screen, gas::testing::some_figures(), k);
    auto line_with = [&](const std::string& text) {
      for (const std::string& line : screen.lines)
        if (line.find(text) != std::string::npos) return line;
      return std::string();
    };
    CHECK(line_with("Px ").find(
              "| box: P 0.11 +- 0.001  Px 0.111 +- 0.002  Py 0.109 +- 0.002") == 0);
    CHECK(line_with("from walls")
              .find("| box: Z from walls 2.07 +- 0.03  from collisions 2.08 +- 0.003") ==
          0);
    CHECK(line_with("kT n").find(
              "| contact theorem at walls: kT n 0.104 +- 0.004 = P 0.109 +- 0.0004") ==
          0);
    CHECK(line_with("inside: eta").rfind("| inside: eta ", 0) == 0);
  }

  TEST_CASE(
      "draw_kinetic_figures at 80 x 24: the lines needed first and the histogram and "
      "what "
      "is left out") {
    // A window of 80 x 24: the grid 80 x 22, 20 rows inside the border.
    const gas::KineticFigures k = with_histogram(many_balls());
    TextScreen screen = gas::prepare_character_screen(80, 22);
    gas::draw_kinetic_figures(screen, gas::testing::some_figures(), k,
                              {"Lyapunov one", "  Lyapunov two"});
    const std::vector<std::string> starts = {"| N ",
                                             "| speeds now:",
                                             "| units:",
                                             "| H ",
                                             "| warming up",
                                             "|              ",
                                             "| mean speed",
                                             "| P walls' middles",
                                             "| Z bulk",
                                             "|   Z - reference",
                                             "| g(2a) inside",
                                             "| collision rate",
                                             "| mean free path",
                                             "| speeds: # measured"};
    for (std::size_t row = 0; row < starts.size(); ++row) {
      CAPTURE(row);
      CHECK(screen.lines[row + 1].rfind(starts[row], 0) == 0);
    }
    // 4 rows of bars, the axis, and the last row inside names the rest and
    // the rows that show it all (18 lines and the exponent's 2, 6 of
    // histogram, the border, the status line and the keys: 30).
    CHECK(screen.lines[19].rfind("| 0-", 0) == 0);
    CHECK(screen.lines[20].rfind("| more with 30 rows: inside, contact, box, Lyapunov  ",
                                 0) == 0);
    // A screen of 31 rows less the status line and the keys: everything, a
    // blank row, and the histogram below; nothing left out.
    TextScreen tall = gas::prepare_character_screen(80, 29);
    gas::draw_kinetic_figures(tall, gas::testing::some_figures(), k,
                              {"Lyapunov one", "  Lyapunov two"});
    CHECK(tall.lines[19].rfind("| Lyapunov one", 0) == 0);
    CHECK(tall.lines[20].rfind("|   Lyapunov two", 0) == 0);
    CHECK(tall.lines[21] == "|" + std::string(78, ' ') + "|");
    CHECK(tall.lines[22].rfind("| speeds: # measured", 0) == 0);
    CHECK(tall.lines[27].rfind("| 0-", 0) == 0);
    for (const std::string& line : tall.lines)
      CHECK(line.find("more with") == std::string::npos);
  }

  TEST_CASE(
      "draw_kinetic_figures on short screens: the lowest ranks and the histogram when it "
      "fits") {
    const gas::KineticFigures k = with_histogram(many_balls());
    auto screen_of = [&](int rows) {
      TextScreen screen = gas::prepare_character_screen(80, rows);
      gas::draw_kinetic_figures(screen, gas::testing::some_figures(), k);
      return screen;
    };
    // 11 rows inside (lesson 6's --rows 13): no room for the histogram; the
    // gas now, the averages' line, the header and the table's first rows.
    const TextScreen short_one = screen_of(11);
    const std::vector<std::string> starts = {
        "| N ",
        "| speeds now:",
        "| warming up",
        "|              ",
        "| mean speed",
        "| P walls' middles",
        "| Z bulk",
        "| collision rate",
        "| more with 28 rows: free path, histogram, H, units"};
    for (std::size_t row = 0; row < starts.size(); ++row) {
      CAPTURE(row);
      CHECK(short_one.lines[row + 1].rfind(starts[row], 0) == 0);
    }
    // The shortest screen with the histogram: the nine lines needed first,
    // 6 rows of histogram and the line of the rest: 16 rows inside.
    CHECK(screen_of(18).lines[10].rfind("| speeds: # measured", 0) == 0);
    const TextScreen one_less = screen_of(17);
    for (const std::string& line : one_less.lines) CHECK(line.rfind("| speeds:", 0) != 0);
    // Every screen: lines cut at the border, and the border whole.
    for (int rows = 5; rows < 40; ++rows) {
      const TextScreen screen = screen_of(rows);
      for (const std::string& line : screen.lines) {
        CHECK(line.size() == 80);
        CHECK((line.back() == '|' || line.back() == '+'));
      }
      CHECK(screen.lines.back() == "+" + std::string(78, '-') + "+");
    }
  }

  TEST_CASE(
      "draw_kinetic_figures on a small screen: one figure a row and cut at the border") {
    TextScreen screen =
        gas::prepare_character_screen(20, 8);  // 6 rows inside, 18 columns
    gas::draw_kinetic_figures(screen, gas::testing::some_figures(),
                              gas::KineticFigures{});
    CHECK(screen.lines[1].substr(0, 4) == "| N ");
    CHECK(screen.lines[6].substr(0, 12) == "| more with ");
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
    // On 80 columns the title says what each mark is, and what share of the
    // ball-time went faster than the axis's last speed.
    f.measured.fraction_beyond = 0.0019;
    TextScreen wide = gas::prepare_character_screen(80, 14);
    gas::draw_histogram(wide, f, 1, 12);
    CHECK(wide.lines[1] ==
          "| speeds: # measured  * Maxwell-Boltzmann  ^ off scale  0.19% faster than 3.5 "
          " |");
    CHECK(wide.lines[12].find("3.5 ") != std::string::npos);  // the axis ends there
  }

  TEST_CASE(
      "csv_header and csv_row: stage 6's nine figures then kinetic theory's and "
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
