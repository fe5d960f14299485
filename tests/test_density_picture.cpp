// A gas with more balls than the screen has cells, drawn as the density of
// its centres in shades (stages/beyond/density_picture.hpp).
//
// - The ramp: no centre is blank, then nine shades for 0 to 2x the mean, the
//   mean in the middle of '+', the middle of the ramp.
// - The picture: a cell's centres against the mean for the part of the cell
//   where centres can be (so cells cut by the table's edge are not lighter);
//   the balls screen holds one picture, the trails screen every picture since
//   it was made (one picture counted once); the legend in the bottom border,
//   whole, or the ramp alone, or nothing.
// - The switch: images up to one centre a character cell on average, shades
//   beyond, for the scene on the screen it is drawn on; the program draws the
//   shades and the legend on a large scene, not on the small ones, on the
//   balls and trails screens, with no colour on them.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "beyond/density_picture.hpp"
#include "beyond/random_placement.hpp"
#include "stage3_screen.hpp"
#include "stage6_output.hpp"
#include "support.hpp"

namespace {

using gas::testing::run_program;
using gas::testing::source_path;

// The middle of the k-th shade's band (k = 1 ... 9), in times the mean.
double band_middle(int k) {
  return (k - 0.5) * 2.0 / 9.0;
}

// A gas of `count` balls of radius 1 on a 40 x 30 table (where they are does
// not matter: the picture counts the centres it is given), and its screen of
// 22 x 10 characters: cells 2 wide and 4 tall, 20 x 8 inside, the top row
// cut by the table's edge at y = 30 (half of it on the table).
gas::Gas gas_of(std::size_t count) {
  gas::Gas gas = gas::testing::table_with({});
  gas.balls.assign(count, gas::Ball{20, 15, 0, 0, 0});
  return gas;
}

// `count` centres inside the cell (column, row) of `screen`, spread over it.
void put(std::vector<gas::Point>& centres, const gas::TextScreen& screen, int column,
         int row, int count) {
  const gas::Point middle = screen.middle_of({column, row});
  for (int k = 0; k < count; ++k) {
    const double spread = (k + 0.5) / count - 0.5;  // -0.5 .. 0.5
    centres.push_back({middle.x + 0.8 * spread * screen.column_width,
                       middle.y + 0.3 * spread * screen.row_height});
  }
}

// The lines of `frame` (printed whole) that are a table's bottom border.
std::vector<std::string> bottom_borders(const std::string& frames) {
  std::vector<std::string> borders;
  const std::vector<std::string> lines = gas::testing::lines_of(frames);
  for (std::size_t k = 1; k < lines.size(); ++k) {
    if (lines[k].rfind("+-", 0) == 0 && lines[k - 1].rfind("|", 0) == 0)
      borders.push_back(lines[k]);
  }
  return borders;
}

}  // namespace

TEST_SUITE("pictures") {
  TEST_CASE("the ramp: blank for no centre and nine shades up to 2x the mean") {
    CHECK(gas::density_shades == " .:-=+*#%@");
    CHECK(gas::shade_of(0) == ' ');
    CHECK(gas::shade_of(-1) == ' ');
    CHECK(gas::shade_of(std::numeric_limits<double>::quiet_NaN()) == ' ');
    CHECK(gas::shade_of(1e-12) == '.');  // one centre in a crowd is not blank
    for (int k = 1; k <= 9; ++k) {
      CAPTURE(k);
      CHECK(gas::shade_of(band_middle(k)) ==
            gas::density_shades[static_cast<std::size_t>(k)]);
    }
    CHECK(gas::shade_of(2) == '@');
    CHECK(gas::shade_of(1e9) == '@');
    // The mean in the middle of '+', the middle of the ramp: '+' from 8/9 to
    // 10/9 of the mean, '=' below, '*' above.
    CHECK(gas::shade_of(1) == '+');
    CHECK(gas::density_shades.find('+') == 5);
    CHECK(gas::shade_of(8.0 / 9 + 1e-9) == '+');
    CHECK(gas::shade_of(10.0 / 9 - 1e-9) == '+');
    CHECK(gas::shade_of(8.0 / 9 - 1e-9) == '=');
    CHECK(gas::shade_of(10.0 / 9 + 1e-9) == '*');
  }

  TEST_CASE("the picture: each cell against the mean for its room and the legend") {
    // 1064 centres on the 38 x 28 where centres can be: 8 a whole cell.
    const gas::Gas gas = gas_of(1064);
    gas::TextScreen screen = gas::prepare_screen(gas, 22, 10);
    REQUIRE(screen.columns == 22);
    REQUIRE(screen.rows == 10);
    REQUIRE(screen.column_width == 2);
    CHECK(gas::centres_a_cell(gas, screen) == doctest::Approx(8).epsilon(1e-12));

    std::vector<gas::Point> centres;
    put(centres, screen, 5, 4, 8);   // the mean: '+'
    put(centres, screen, 6, 4, 16);  // twice: '@'
    put(centres, screen, 7, 4, 4);   // half: 4.5 / 2 -> the third shade, '-'
    put(centres, screen, 8, 4, 1);   // one eighth: '.'
    put(centres, screen, 1, 5, 4);   // column 1 is x = 0 .. 2, centres at 1 .. 2:
                                     // half its room, so 4 is the mean: '+'
    put(centres, screen, 10, 1, 2);  // the top row, y = 28 .. 32: room y = 28
                                     // .. 29, a quarter: 2 is the mean: '+'
    gas::DensityPicture density(gas, screen);
    density.add(screen, centres, 0);
    density.draw(screen);
    CHECK(screen.at({5, 4}) == '+');
    CHECK(screen.at({6, 4}) == '@');
    CHECK(screen.at({7, 4}) == '-');
    CHECK(screen.at({8, 4}) == '.');
    CHECK(screen.at({1, 5}) == '+');
    CHECK(screen.at({10, 1}) == '+');
    CHECK(screen.at({9, 4}) == ' ');  // none

    CHECK(density.legend() == "[ .:-=+*#%@] 0 to 2x mean; '+' mean: 8 a cell");
  }

  TEST_CASE("the picture: the balls screen now and the trails screen every picture") {
    const gas::Gas gas = gas_of(1064);  // 8 centres a whole cell
    gas::TextScreen screen = gas::prepare_screen(gas, 22, 10);
    std::vector<gas::Point> mean, twice;
    put(mean, screen, 5, 4, 8);
    put(twice, screen, 5, 4, 16);
    gas::DensityPicture density(gas, screen);
    gas::Picture picture;

    // The balls screen: the picture now only.
    picture.centres = twice;
    gas::draw_table(screen, gas::ScreenMode::balls, picture, 1, 1, gas::shades_tone,
                    &density);
    CHECK(screen.at({5, 4}) == '@');
    picture.centres = mean;
    gas::draw_table(screen, gas::ScreenMode::balls, picture, 2, 1, gas::shades_tone,
                    &density);
    CHECK(screen.at({5, 4}) == '+');
    CHECK(density.legend().find("pictures") == std::string::npos);

    // The trails screen: every picture since, each counted once: 16 + 8 in
    // two pictures is 1.5 the mean, '#'; the same picture again changes
    // nothing; a third with none there makes 24 in three, the mean, '+'.
    picture.centres = twice;
    gas::draw_table(screen, gas::ScreenMode::trails, picture, 3, 1, gas::shades_tone,
                    &density);
    CHECK(screen.at({5, 4}) == '#');
    CHECK(density.legend() ==
          "[ .:-=+*#%@] 0 to 2x mean; '+' mean: 8 a cell x 2 pictures");
    gas::draw_table(screen, gas::ScreenMode::trails, picture, 3, 1, gas::shades_tone,
                    &density);
    CHECK(screen.at({5, 4}) == '#');
    picture.centres = {};
    gas::draw_table(screen, gas::ScreenMode::trails, picture, 4, 1, gas::shades_tone,
                    &density);
    CHECK(screen.at({5, 4}) == '+');
    CHECK(density.legend().find("x 3 pictures") != std::string::npos);
  }

  TEST_CASE("the legend in the bottom border: whole or the ramp alone or nothing") {
    const gas::Gas gas = gas_of(1064);
    gas::TextScreen wide = gas::prepare_screen(gas, 64, 40);
    REQUIRE(wide.columns == 64);
    gas::DensityPicture whole(gas, wide);
    whole.add(wide, {}, 0);
    whole.draw(wide);
    const std::string legend = whole.legend();
    CHECK(wide.lines.back() ==
          fmt::format("+- {} {}+", legend, std::string(64 - 5 - legend.size(), '-')));
    // Narrower: the ramp alone, its corners kept; then nothing.
    for (const auto& narrow :
         {std::pair{18, "+- [ .:-=+*#%@] -+"}, std::pair{16, "+--------------+"}}) {
      // Plain names, not a structured binding: Clang 14 does not let
      // CAPTURE's lambda capture one.
      const int columns = narrow.first;
      const std::string border = narrow.second;
      CAPTURE(columns);
      gas::TextScreen screen = gas::prepare_screen(gas, columns, 12);
      REQUIRE(screen.columns == columns);
      gas::DensityPicture density(gas, screen);
      density.add(screen, {}, 0);
      density.draw(screen);
      CHECK(screen.lines.back() == border);
    }
  }

  TEST_CASE("the switch: images up to one centre a character cell and shades beyond") {
    const gas::Gas crowd = gas::read_scene_file(source_path("data/crowd.scene"));
    const gas::Gas thousand = gas::read_scene_file(source_path("data/large-1000.scene"));
    const gas::Gas ten_thousand =
        gas::read_scene_file(source_path("data/large-10000.scene"));
    auto drawing = [](const gas::Gas& gas, int columns, int rows) {
      return gas::table_drawing_for(gas, gas::prepare_screen(gas, columns, rows));
    };
    CHECK(drawing(crowd, 80, 22) == gas::TableDrawing::images);
    CHECK(drawing(thousand, 100, 28) == gas::TableDrawing::images);  // 0.58 a cell
    CHECK(drawing(thousand, 80, 22) == gas::TableDrawing::images);   // 0.98 a cell
    CHECK(drawing(thousand, 40, 12) == gas::TableDrawing::shades);
    CHECK(drawing(ten_thousand, 80, 22) == gas::TableDrawing::shades);
    CHECK(drawing(ten_thousand, 300, 100) == gas::TableDrawing::images);

    // At the bound: exactly one centre a cell is images, a ball more shades.
    gas::Gas gas = gas_of(133);  // 133 * 8 / 1064 = 1
    const gas::TextScreen screen = gas::prepare_screen(gas, 22, 10);
    CHECK(gas::centres_a_cell(gas, screen) == 1);
    CHECK(gas::table_drawing_for(gas, screen) == gas::TableDrawing::images);
    gas.balls.push_back(gas.balls.back());
    CHECK(gas::table_drawing_for(gas, screen) == gas::TableDrawing::shades);
  }

  TEST_CASE(
      "the program: shades and the legend for a large scene and images for a small one") {
    const auto large = run_program(
        {"data/large-10000.scene", "--frames", "2", "--cols", "100", "--rows", "30"});
    REQUIRE(large.status == 0);
    CHECK(large.out.find('O') == std::string::npos);
    const std::vector<std::string> borders = bottom_borders(large.out);
    REQUIRE(borders.size() == 2);
    for (const std::string& border : borders)
      CHECK(border.find("[ .:-=+*#%@] 0 to 2x mean; '+' mean: 5.617 a cell ") == 3);

    const auto trails =
        run_program({"data/large-10000.scene", "--frames", "3", "--cols", "100", "--rows",
                     "30", "--mode", "trails", "--keys", ".0."});
    REQUIRE(trails.status == 0);
    // The key 0 prepares the screen again: its counts start afresh.
    const std::vector<std::string> trail_borders = bottom_borders(trails.out);
    REQUIRE(trail_borders.size() == 3);
    CHECK(trail_borders[0].find("pictures") == std::string::npos);
    CHECK(trail_borders[1].find("pictures") == std::string::npos);
    CHECK(trail_borders[2].find("x 2 pictures") != std::string::npos);

    const auto traced = run_program({"data/large-10000.scene", "--frames", "1", "--cols",
                                     "100", "--rows", "30", "--trace"});
    CHECK(traced.out.find("stage 6  output: the balls screen in shades (5.617 centres a "
                          "character cell)\n") != std::string::npos);

    const auto small = run_program({"data/crowd.scene", "--frames", "2"});
    REQUIRE(small.status == 0);
    CHECK(small.out.find('O') != std::string::npos);
    CHECK(small.out.find("mean") == std::string::npos);
  }

  TEST_CASE("Display sends the shades with no colour") {
    const gas::Gas gas = gas_of(1064);
    gas::TextScreen screen = gas::prepare_screen(gas, 22, 10);
    std::vector<gas::Point> centres;
    for (int column = 1; column <= 20; ++column)
      put(centres, screen, column, 4, column);  // every shade, '.' to '@'
    gas::DensityPicture density(gas, screen);
    density.add(screen, centres, 0);
    density.draw(screen);
    // What a terminal with colour gets for the screen in `tone`.
    auto sent = [&](const gas::Tone& tone) {
      std::FILE* file = std::tmpfile();
      REQUIRE(file != nullptr);
      gas::Display display(file, true, true);
      display.show(screen, "T=1.5", &tone);
      std::fflush(file);
      std::rewind(file);
      std::string out;
      char buffer[4096];
      for (std::size_t n = 0; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;)
        out.append(buffer, n);
      std::fclose(file);
      return out;
    };
    const std::regex colour("\x1b\\[1;[0-9]+m");
    CHECK(sent(gas::shades_tone).find('@') != std::string::npos);
    CHECK_FALSE(std::regex_search(sent(gas::shades_tone), colour));
    // (The balls' tone would colour its glyphs among the shades.)
    CHECK(std::regex_search(sent(gas::tones[1]), colour));
  }
}  // TEST_SUITE
