// Stage 6 of the article, "output to the screen".
//
// - ball_image: a small ball is one glyph; a big one covers exactly the cells
//   whose middles lie within its radius, and looks round (a row is twice as
//   tall as a column is wide, so it is about twice as many columns wide as
//   rows high).
// - draw_balls erases every old image before drawing the new ones;
//   draw_trails draws a connected segment from the old centre to the new one
//   and erases nothing; draw_figures puts each line of figures at a fixed
//   place. (The statistics screen's own layout, the histogram and --csv are
//   kinetic theory's: tests/test_kinetic_screen.cpp.)
// - status_line: its format.
// - Display: plain frames (status line + screen) when not a terminal; on a
//   terminal, only what changed (checked by replaying the output on a small
//   model of an ANSI terminal); in a smaller window, nothing outside it, and
//   notice()'s one line.
// - Golden frames of the default scene at a few model times.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "beyond/random_placement.hpp"
#include "stage6_output.hpp"
#include "stage7_control.hpp"
#include "support.hpp"

namespace {

using gas::Cell;
using gas::Point;
using gas::TextScreen;

// Sets of cells, in reading order.
struct ReadingOrder {
  bool operator()(const Cell& p, const Cell& q) const {
    return p.row != q.row ? p.row < q.row : p.column < q.column;
  }
};
using CellSet = std::set<Cell, ReadingOrder>;

CellSet as_set(const std::vector<Cell>& cells) {
  return CellSet(cells.begin(), cells.end());
}

// Every cell of the screen whose character is `c`.
CellSet cells_showing(const TextScreen& screen, char c) {
  CellSet cells;
  for (int row = 0; row < screen.rows; ++row) {
    for (int column = 0; column < screen.columns; ++column) {
      if (screen.lines[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] ==
          c) {
        cells.insert({column, row});
      }
    }
  }
  return cells;
}

// A character screen 60 x 24: one model length per column, two per row.
TextScreen screen_60x24() {
  return gas::prepare_character_screen(60, 24);
}

// The cells a disc of `radius` at `centre` covers, found by looking at
// every inside cell (not only a bounding box, as ball_image does).
CellSet disc_by_brute_force(const TextScreen& screen, Point centre, double radius) {
  CellSet cells{screen.cell_of(centre)};
  for (int row = 1; row < screen.rows - 1; ++row) {
    for (int column = 1; column < screen.columns - 1; ++column) {
      const Point m = screen.middle_of({column, row});
      if (std::hypot(m.x - centre.x, m.y - centre.y) <= radius)
        cells.insert({column, row});
    }
  }
  return cells;
}

// Everything written to a FILE* opened by tmpfile().
std::string contents(std::FILE* file) {
  std::fflush(file);
  std::rewind(file);
  std::string text;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, n);
  return text;
}

// A small model of an ANSI terminal, enough to replay what Display sends:
// cursor moves ESC[r;cH, ESC[H, clear ESC[2J, erase a line ESC[2K, colours
// (ESC[...m: which cells were printed coloured), and the escapes it ignores
// (cursor shown/hidden). It counts the characters it prints.
struct Terminal {
  std::vector<std::string> lines = std::vector<std::string>(40, std::string(100, ' '));
  std::vector<std::vector<bool>> coloured =
      std::vector<std::vector<bool>>(40, std::vector<bool>(100, false));
  int row = 0, column = 0;
  int printed = 0;
  bool colour_on = false;

  void replay(const std::string& out) {
    printed = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (out[i] == '\x1b') {
        REQUIRE(i + 1 < out.size());
        REQUIRE(out[i + 1] == '[');
        std::size_t end = i + 2;
        while (end < out.size() && !std::isalpha(static_cast<unsigned char>(out[end])))
          ++end;
        REQUIRE(end < out.size());
        const std::string arguments = out.substr(i + 2, end - i - 2);
        const char command = out[end];
        if (command == 'H') {
          int r = 1, c = 1;
          if (!arguments.empty())
            REQUIRE(std::sscanf(arguments.c_str(), "%d;%d", &r, &c) == 2);
          row = r - 1;
          column = c - 1;
        } else if (command == 'J') {
          for (std::string& line : lines) line.assign(line.size(), ' ');
        } else if (command == 'K') {
          lines.at(static_cast<std::size_t>(row)).assign(100, ' ');
        } else if (command == 'm') {
          colour_on = !(arguments.empty() || arguments == "0");
        }  // 'l', 'h' (cursor): nothing to model
        i = end;
      } else {
        lines.at(static_cast<std::size_t>(row)).at(static_cast<std::size_t>(column)) =
            out[i];
        coloured.at(static_cast<std::size_t>(row)).at(static_cast<std::size_t>(column)) =
            colour_on;
        ++column;
        ++printed;
      }
    }
  }
  // Does the terminal show the status line and the screen, at the top left?
  bool shows(const std::string& status, const TextScreen& screen) const {
    std::vector<std::string> want{status};
    want.insert(want.end(), screen.lines.begin(), screen.lines.end());
    for (std::size_t r = 0; r < lines.size(); ++r) {
      std::string expected = r < want.size() ? want[r] : "";
      expected.resize(lines[r].size(), ' ');
      if (lines[r] != expected) return false;
    }
    return true;
  }
};

}  // namespace

TEST_SUITE("stage6") {
  TEST_CASE(
      "ball_image: a ball smaller than a character is one glyph in its centre's cell") {
    const TextScreen screen = screen_60x24();
    for (const Point centre :
         {Point{10.5, 10}, Point{10.01, 10.01}, Point{33.99, 29.9}}) {
      CAPTURE(centre.x);
      const std::vector<Cell> image = gas::ball_image(screen, centre, 0.45);
      REQUIRE(image.size() == 1);
      CHECK(image[0] == screen.cell_of(centre));
    }
  }

  TEST_CASE("ball_image: a big ball covers the cells within its radius and looks round") {
    const TextScreen screen = screen_60x24();
    for (const double radius : {3.0, 6.0, 8.7}) {
      for (const Point centre : {Point{30, 22}, Point{30.5, 23}, Point{17.3, 20.9}}) {
        CAPTURE(radius);
        CAPTURE(centre.x);
        CAPTURE(centre.y);
        const std::vector<Cell> image = gas::ball_image(screen, centre, radius);
        CHECK(as_set(image).size() == image.size());  // no cell twice
        CHECK(as_set(image) == disc_by_brute_force(screen, centre, radius));

        // Its extent: a disc 2r across covers 2r columns of width 1 and
        // 2r / 2 = r rows of height 2, give or take one cell for where its
        // edges fall inside the first and last cells.
        int left = 1000, right = -1000, top = 1000, bottom = -1000;
        for (const Cell& cell : image) {
          left = std::min(left, cell.column);
          right = std::max(right, cell.column);
          top = std::min(top, cell.row);
          bottom = std::max(bottom, cell.row);
        }
        const int width = right - left + 1, height = bottom - top + 1;
        CHECK(std::abs(width - 2 * radius) <= 1);
        CHECK(std::abs(height - radius) <= 1);
      }
    }
  }

  TEST_CASE("ball_image: a ball at a wall stays inside the border") {
    const TextScreen screen = screen_60x24();
    for (const Point centre : {Point{3, 3}, Point{56, 40}, Point{0.5, 20}}) {
      const std::vector<Cell> image = gas::ball_image(screen, centre, 5);
      for (const Cell& cell : image) CHECK(screen.inside(cell));
    }
  }

  TEST_CASE("draw_balls erases every old image and then draws every new one") {
    TextScreen screen = screen_60x24();
    const gas::Tone& tone = gas::tones[0];
    const double radius = 3;
    // Ball 1 moves a little (its old and new images overlap); ball 2 moves
    // onto ball 3's old place, and ball 3 away: erasing ball 3's old image
    // after drawing ball 2 would wipe ball 2. A marker elsewhere must survive.
    gas::Picture picture;
    picture.old_centres = {{10, 10}, {25, 25}, {40, 30}};
    picture.centres = {{11.5, 11}, {40, 30}, {52, 38}};
    const Cell marker{55, 2};
    screen.at(marker) = 'x';
    for (const Point& p : picture.old_centres) {
      for (const Cell& cell : gas::ball_image(screen, p, radius))
        screen.at(cell) = tone.ball_glyph;
    }

    gas::draw_balls(screen, picture, radius, tone);

    CellSet drawn;
    for (const Point& p : picture.centres) {
      for (const Cell& cell : gas::ball_image(screen, p, radius)) drawn.insert(cell);
    }
    CHECK(cells_showing(screen, tone.ball_glyph) ==
          drawn);  // every new image, nothing else
    for (const Point& p : picture.old_centres) {
      for (const Cell& cell : gas::ball_image(screen, p, radius)) {
        if (drawn.count(cell) == 0) CHECK(screen.at(cell) == ' ');
      }
    }
    CHECK(screen.at(marker) == 'x');
    CHECK(cells_showing(screen, '+').size() == 4);  // the border is untouched
  }

  TEST_CASE("draw_balls draws in the tone it is given") {
    TextScreen screen = screen_60x24();
    gas::Picture picture;
    picture.old_centres = picture.centres = {{30, 20}};
    gas::draw_balls(screen, picture, 0.4, gas::tones[1]);
    CHECK(screen.at(screen.cell_of({30, 20})) == gas::tones[1].ball_glyph);
    CHECK(gas::tones[0].ball_glyph != gas::tones[1].ball_glyph);
  }

  TEST_CASE("draw_trails draws a connected segment from the old centre to the new one") {
    TextScreen screen = screen_60x24();
    const gas::Tone& tone = gas::tones[0];
    gas::Picture picture;
    picture.old_centres = {{5.5, 3}, {50, 40}, {55, 44}};
    picture.centres = {
        {40.2, 25.7}, {47, 12}, {55.3, 44.2}};  // long, steep, inside one cell
    gas::draw_trails(screen, picture, tone);

    const CellSet drawn = cells_showing(screen, tone.trail_glyph);
    CellSet expected_union;
    for (std::size_t i = 0; i < picture.centres.size(); ++i) {
      CAPTURE(i);
      const Cell from = screen.cell_of(picture.old_centres[i]);
      const Cell to = screen.cell_of(picture.centres[i]);
      CHECK(drawn.count(from) == 1);
      CHECK(drawn.count(to) == 1);
      // Walk from `from` to `to` through drawn cells that touch (a king's
      // move) and stay in the segment's bounding box: the segment is connected.
      const int low_c = std::min(from.column, to.column),
                high_c = std::max(from.column, to.column);
      const int low_r = std::min(from.row, to.row), high_r = std::max(from.row, to.row);
      CellSet reached{from};
      std::vector<Cell> queue{from};
      while (!queue.empty()) {
        const Cell c = queue.back();
        queue.pop_back();
        for (int dr = -1; dr <= 1; ++dr) {
          for (int dc = -1; dc <= 1; ++dc) {
            const Cell n{c.column + dc, c.row + dr};
            if (n.column < low_c || n.column > high_c || n.row < low_r || n.row > high_r)
              continue;
            if (drawn.count(n) == 1 && reached.insert(n).second) queue.push_back(n);
          }
        }
      }
      CHECK(reached.count(to) == 1);
      // And it is a thin line: one cell per step along its longer direction
      // (the other segments are drawn outside this one's box).
      int in_box = 0;
      for (const Cell& c : drawn) {
        in_box +=
            c.column >= low_c && c.column <= high_c && c.row >= low_r && c.row <= high_r;
      }
      if (i == 0) CHECK(in_box == std::max(high_c - low_c, high_r - low_r) + 1);
    }

    // Trails are never erased: a second step adds to the first.
    const CellSet before = drawn;
    picture.old_centres = picture.centres;
    picture.centres = {{55, 25.7}, {47, 3}, {55.3, 44.2}};
    gas::draw_trails(screen, picture, tone);
    const CellSet after = cells_showing(screen, tone.trail_glyph);
    CHECK(std::includes(after.begin(), after.end(), before.begin(), before.end(),
                        ReadingOrder{}));
    CHECK(after.size() > before.size());
    CHECK(cells_showing(screen, '+').size() == 4);
  }

  TEST_CASE("draw_figures wipes the inside and puts line i at row i, cut at the border") {
    TextScreen screen =
        gas::prepare_character_screen(20, 6);  // 4 rows inside, 18 columns
    screen.at({5, 3}) = 'x';                   // something left from before: wiped
    gas::draw_figures(screen, {"T 1.5", "N 7", "a line far longer than the screen"});
    CHECK(screen.lines[0] == "+------------------+");
    CHECK(screen.lines[1] == "| T 1.5            |");
    CHECK(screen.lines[2] == "| N 7              |");
    CHECK(screen.lines[3] == "| a line far longe |");  // cut, the border kept
    CHECK(screen.lines[4] == "|                  |");  // wiped
    CHECK(screen.lines[5] == "+------------------+");
    // More lines than rows: those beyond the last row inside are left out.
    gas::draw_figures(screen, {"1", "2", "3", "4", "5", "6"});
    CHECK(screen.lines[4] == "| 4                |");
    CHECK(screen.lines[5] == "+------------------+");
  }

  TEST_CASE(
      "status_line: T with 6 decimals then T0 and the collisions and the screen and "
      "stopped") {
    const gas::Figures f = gas::testing::some_figures();
    CHECK(gas::status_line(f, gas::ScreenMode::trails, false) ==
          "T=12.500000 T0=0.5 collisions=7 (walls 4, balls 3) screen=trails");
    CHECK(gas::status_line(f, gas::ScreenMode::balls, true) ==
          "T=12.500000 T0=0.5 collisions=7 (walls 4, balls 3) screen=balls [stopped]");
    CHECK(gas::status_line(f, gas::ScreenMode::stats, false).rfind("T=12.500000 ", 0) ==
          0);
  }

  TEST_CASE("measure: the figures of a gas") {
    gas::Gas g;
    g.radius = 1;
    g.width = g.height = 100;
    g.display_step = 0.25;
    g.time = 3;
    g.balls = {{10, 10, 3, 4, 0}, {50, 50, 0, -1, 0}};
    const gas::Figures f = gas::measure(g, 10, 5, 2);
    CHECK(f.time == 3);
    CHECK(f.display_step == 0.25);
    CHECK(f.mean_speed == 3);      // (5 + 1) / 2
    CHECK(f.energy == 13);         // (25 + 1) / 2
    CHECK(f.energy_drift == 0.3);  // (13 - 10) / 10
    CHECK(f.momentum.x == 3);
    CHECK(f.momentum.y == 3);
    CHECK(f.balls == 2);
    CHECK(gas::measure(g, 0, 0, 0).energy_drift ==
          0);  // no energy at the start: no drift
  }

  TEST_CASE(
      "Display not on a terminal: every frame whole and headed by its status line") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    TextScreen screen = gas::prepare_character_screen(12, 5);
    gas::Display display(file, false,
                         true);  // colour is asked for, but never used off a terminal
    display.show(screen, "status one", &gas::tones[0]);
    screen.at({3, 2}) = gas::tones[0].ball_glyph;
    display.show(screen, "status two", &gas::tones[0]);
    display.finish();
    std::string expected = "status one\n";
    for (const std::string& line : gas::prepare_character_screen(12, 5).lines)
      expected += line + "\n";
    expected += "status two\n";
    for (const std::string& line : screen.lines) expected += line + "\n";
    CHECK(contents(file) == expected);
    std::fclose(file);
  }

  TEST_CASE("Display on a terminal: the first frame whole and then only what changed") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    TextScreen screen = gas::prepare_character_screen(30, 10);
    const gas::Tone& tone = gas::tones[0];
    gas::Display display(file, true, false);
    Terminal terminal;
    long written = 0;
    auto show = [&](const std::string& status) {
      display.show(screen, status, &tone);
      const std::string all = contents(file);
      const std::string out = all.substr(static_cast<std::size_t>(written));
      written = static_cast<long>(all.size());
      std::fseek(file, 0, SEEK_END);
      terminal.replay(out);
      return out;
    };
    const std::string park = "\x1b[12;1H";  // the cursor below the frame: row 1 + 10 + 1

    const std::string first = show("T=0");
    CHECK(first.rfind("\x1b[?25l\x1b[H\x1b[2J", 0) ==
          0);  // cursor hidden, screen cleared
    CHECK(terminal.shows("T=0", screen));
    CHECK(terminal.printed == 3 + 30 * 10);

    SUBCASE("an unchanged frame: only the cursor moves") {
      CHECK(show("T=0") == park);
      CHECK(terminal.printed == 0);
    }
    SUBCASE("two cells changed: two characters sent") {
      screen.at({4, 3}) = tone.ball_glyph;
      screen.at({20, 7}) = tone.ball_glyph;
      const std::string out = show("T=0");
      CHECK(terminal.printed == 2);
      CHECK(terminal.shows("T=0", screen));
      CHECK(out.size() < 30);  // two cursor moves, two glyphs, the park
      CHECK(out.substr(out.size() - park.size()) == park);
    }
    SUBCASE("a shorter status line: its tail is blanked") {
      show("T=1 [stopped]");
      CHECK(terminal.shows("T=1 [stopped]", screen));
      show("T=1");
      // "[stopped]" becomes nine spaces; the space before it is one already.
      CHECK(terminal.printed == 9);
      CHECK(terminal.shows("T=1", screen));
    }
    SUBCASE("after invalidate(), the whole frame again") {
      display.invalidate();
      show("T=0");
      CHECK(terminal.printed == 3 + 30 * 10);
      CHECK(terminal.shows("T=0", screen));
    }
    std::fclose(file);
  }

  TEST_CASE(
      "Display in a window smaller than the frame: cut at its edges, and notice()") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    TextScreen screen = gas::prepare_character_screen(30, 10);
    gas::Display display(file, true, false);
    display.fit_window(20, 8);  // 20 columns; 7 rows of frame, the cursor's below
    const std::string status = "T=0 a status line longer than the window";
    display.show(screen, status, &gas::tones[0]);
    Terminal terminal;
    terminal.replay(contents(file));
    // The frame's top left, cut: the status line and six rows of the screen.
    CHECK(terminal.lines[0].substr(0, 21) == status.substr(0, 20) + " ");
    for (std::size_t r = 1; r < 7; ++r)
      CHECK(terminal.lines[r].substr(0, 21) == screen.lines[r - 1].substr(0, 20) + " ");
    for (std::size_t r = 7; r < terminal.lines.size(); ++r)
      CHECK(terminal.lines[r] == std::string(terminal.lines[r].size(), ' '));
    CHECK(terminal.printed == 20 * 7);

    // notice(): the screen cleared and the words fitted to the window, the
    // size kept whole; sent once.
    const std::vector<std::string> words = {
        "window", "too", "small:", "at", "least", "8 x 7"};
    const std::size_t before = contents(file).size();
    std::fseek(file, 0, SEEK_END);
    display.notice(words);
    terminal.replay(contents(file).substr(before));
    CHECK(terminal.lines[0].substr(0, 21) == "window too small: at ");
    CHECK(terminal.lines[1].substr(0, 21) == "least 8 x 7          ");
    for (std::size_t r = 2; r < terminal.lines.size(); ++r)
      CHECK(terminal.lines[r] == std::string(terminal.lines[r].size(), ' '));
    std::fseek(file, 0, SEEK_END);
    const long after = std::ftell(file);
    display.notice(words);
    std::fseek(file, 0, SEEK_END);
    CHECK(std::ftell(file) == after);
    std::fclose(file);
  }

  TEST_CASE(
      "Display on a terminal with colour: glyphs coloured and the picture the same") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    TextScreen screen = gas::prepare_character_screen(20, 6);
    screen.at({5, 2}) = gas::tones[1].ball_glyph;
    gas::Display display(file, true, true);
    display.show(screen, "T=0", &gas::tones[1]);
    const std::string out = contents(file);
    CHECK(out.find(fmt::format("\x1b[1;{}m{}\x1b[0m", gas::tones[1].ansi_colour,
                               gas::tones[1].ball_glyph)) != std::string::npos);
    Terminal terminal;
    terminal.replay(out);
    CHECK(terminal.shows("T=0", screen));
    std::fclose(file);
  }

  TEST_CASE(
      "Display colours the table's glyphs only: not the status line or border or keys or "
      "figures") {
    // Tone 1's trail glyph is '+', the border's corner; tone 0's is '.', a
    // decimal point: only the cells inside the table take their colour.
    for (const gas::Tone& tone : gas::tones) {
      CAPTURE(tone.trail_glyph);
      std::FILE* file = std::tmpfile();
      REQUIRE(file != nullptr);
      TextScreen screen = gas::prepare_character_screen(20, 6);
      screen.at({5, 2}) = tone.ball_glyph;
      screen.at({6, 2}) = tone.trail_glyph;
      gas::Display display(file, true, true);
      display.keys_below({"keys: S stop . + @ O"});
      display.show(screen, "T=1.5 +.O@ screen", &tone);
      Terminal terminal;
      terminal.replay(contents(file));
      for (std::size_t r = 0; r < 8; ++r) {
        for (std::size_t c = 0; c < 20; ++c) {
          CAPTURE(r);
          CAPTURE(c);
          const bool in_table = (r == 3 && (c == 5 || c == 6));
          CHECK(terminal.coloured[r][c] == in_table);
        }
      }
      CHECK(terminal.lines[7].substr(0, 20) == "keys: S stop . + @ O");
      std::fclose(file);
    }
    // A screen of figures: no tone, nothing coloured.
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    TextScreen screen = gas::prepare_character_screen(20, 6);
    gas::write_text(screen, 1, "P 0.5 +- 0.25 O @");
    gas::Display display(file, true, true);
    display.show(screen, "T=1.5", nullptr);
    CHECK_FALSE(std::regex_search(contents(file), std::regex("\x1b\\[[0-9;]*m")));
    std::fclose(file);
  }

  TEST_CASE(
      "Display's key line: under the frame where the window has the row, and wiped at "
      "the "
      "end") {
    const std::vector<std::string> forms = {"keys: S stop  R run  E end", "keys: S R E"};
    auto run = [&](int columns, int rows) {
      std::FILE* file = std::tmpfile();
      REQUIRE(file != nullptr);
      const TextScreen screen = gas::prepare_character_screen(20, 6);
      gas::Display display(file, true, false);
      display.fit_window(columns, rows);
      display.keys_below(forms);
      display.show(screen, "T=0", &gas::tones[0]);
      Terminal terminal;
      terminal.replay(contents(file));
      std::fclose(file);
      return terminal;
    };
    // A window of 30 x 8: the status line, the 6 rows of the frame, the keys.
    const Terminal wide = run(30, 8);
    CHECK(wide.lines[7].substr(0, 27) == "keys: S stop  R run  E end ");
    CHECK(wide.row == 7);  // the cursor parked on the key line, not below it
    // 20 columns: the short form.
    CHECK(run(20, 8).lines[7].substr(0, 12) == "keys: S R E ");
    // 8 columns: the short form cut.
    CHECK(run(8, 8).lines[7].substr(0, 9) == "keys: S  ");
    // 7 rows: the frame cut to the window but its last row, the keys there.
    const Terminal full = run(30, 7);
    CHECK(full.lines[6].substr(0, 12) == "keys: S stop");
    CHECK(full.lines[5].substr(0, 20) == "|                  |");  // the frame's 5th row
    // finish(): the key line wiped, for the shell's prompt.
    std::FILE* file = std::tmpfile();
    REQUIRE(file != nullptr);
    gas::Display display(file, true, false);
    display.fit_window(30, 8);
    display.keys_below(forms);
    display.show(gas::prepare_character_screen(20, 6), "T=0", &gas::tones[0]);
    display.finish();
    Terminal terminal;
    terminal.replay(contents(file));
    CHECK(terminal.lines[7] == std::string(100, ' '));
    CHECK(terminal.lines[6].substr(0, 20) == "+------------------+");
    std::fclose(file);
    // Printed whole: the key line after each frame, and a stopped tick's
    // status line alone.
    std::FILE* plain = std::tmpfile();
    REQUIRE(plain != nullptr);
    gas::Display printed(plain, false, true);
    printed.keys_below(forms);
    const TextScreen screen = gas::prepare_character_screen(12, 5);
    printed.show(screen, "T=0", &gas::tones[0]);
    printed.status_only("T=0 [stopped]");
    std::string expected = "T=0\n";
    for (const std::string& line : screen.lines) expected += line + "\n";
    expected += forms[0] + "\nT=0 [stopped]\n";
    CHECK(contents(plain) == expected);
    CHECK(contents(plain).find('\x1b') == std::string::npos);
    std::fclose(plain);
  }

  TEST_CASE(
      "fit_words: a line of words a row and the last words kept when rows are few") {
    const std::vector<std::string> words = {
        "window", "too", "small:", "at", "least", "8 x 7"};
    using Lines = std::vector<std::string>;
    CHECK(gas::fit_words(words, 80, 5) == Lines{"window too small: at least 8 x 7"});
    CHECK(gas::fit_words(words, 0, 0) == Lines{"window too small: at least 8 x 7"});
    CHECK(gas::fit_words(words, 20, 5) == Lines{"window too small: at", "least 8 x 7"});
    // A word is never split: "8 x 7" stays whole.
    CHECK(gas::fit_words(words, 10, 5) ==
          Lines{"window too", "small: at", "least", "8 x 7"});
    // Too few rows: words left out from the front, the size kept.
    CHECK(gas::fit_words(words, 10, 2) == Lines{"at least", "8 x 7"});
    CHECK(gas::fit_words(words, 10, 1) == Lines{"8 x 7"});
    CHECK(gas::fit_words(words, 5, 1) == Lines{"8 x 7"});
    // A word wider than the window is cut.
    CHECK(gas::fit_words(words, 3, 1) == Lines{"8 x"});
  }

  TEST_CASE(
      "golden frames: the default scene on an 80 x 22 screen at a few model times") {
    // As the program draws them: one screen, every step drawn onto it, so the
    // frames also show that no old image is ever left behind.
    gas::Control control = gas::start_control(
        gas::read_scene_file(gas::testing::source_path("data/default.scene")));
    TextScreen screen = gas::prepare_screen(control.gas, 80, 22);
    REQUIRE(screen.columns <= 80);
    REQUIRE(screen.rows == 22);
    const double radius = control.gas.radius;
    const gas::Tone& tone = gas::tones[0];
    gas::draw_balls(screen, control.picture, radius, tone);
    for (const double time : {0.0, 10.0, 50.0, 137.5}) {
      while (control.gas.time < time) {
        gas::take_step(control, time, nullptr);
        gas::draw_balls(screen, control.picture, radius, tone);
      }
      REQUIRE(control.gas.time == time);
      const gas::Figures figures =
          gas::measure(control.gas, control.starting_energy, control.wall_collisions,
                       control.ball_collisions);
      std::string frame = gas::status_line(figures, gas::ScreenMode::balls, false) + "\n";
      for (const std::string& line : screen.lines) frame += line + "\n";
      // A ball of diameter 8 spans 8 / 4.8 < 2 columns and 8 / 9.6 < 1 row
      // (this screen's cells are 4.8 x 9.6), so its image is one or two
      // glyphs side by side; together, at most two per ball.
      REQUIRE(screen.column_width == 4.8);
      const auto glyphs = static_cast<std::size_t>(
          std::count(frame.begin(), frame.end(), tone.ball_glyph));
      CHECK(glyphs >= 1);
      CHECK(glyphs <= 2 * control.gas.balls.size());
      gas::testing::check_golden(
          fmt::format("golden/frames/default-80x22-T{:g}.txt", time), frame);
    }
  }

}  // TEST_SUITE
