// Stage 6 — output, for a gas with more balls than the screen has cells: the
// density of centres drawn in shades (beyond the article).
//
// What this file does: picks how the balls and trails screens draw the table
// — each ball's image, as the article does, or, once a character cell holds
// more than one centre on average, the number of centres in each cell in
// shades of ` .:-=+*#%@`, scaled so that the mean density sits in the middle
// of the ramp — and draws the shades with a legend in the table's bottom
// border. The balls screen shows the density now; the trails screen, which
// erases nothing, the density summed over every picture since the screen was
// prepared (the density averaged over time).
// Beyond the article: its screens draw each ball's image. With 10^6 balls on
// 100 x 30 characters every cell holds hundreds of centres and the images
// are a wall of 'O'; the shades show where the gas is denser or thinner (a
// gas spreading into an empty part of the table, the crowding against a
// wall where a cell is narrow enough to see it).
// Lesson: lessons/6-output.md (the screens); lessons/7-model-control.md
// (pictures where the scene needs them).
//
// Assumptions: the screen is stage 3's table of `gas` (prepare_screen); a
// cell's density is its centres over the part of the cell where centres can
// be (a <= x <= A1 - a, a <= y <= A2 - a), so cells cut by the table's edge
// are not lighter than they should be.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage5_new_coordinates.hpp"
#include "stage6_output.hpp"

namespace gas {

// The shades, from no centre at all to twice the mean density and more.
inline constexpr std::string_view density_shades = " .:-=+*#%@";

// How the balls and trails screens draw the table.
enum class TableDrawing {
  images,  // as the article draws: each ball's image, or its trail
  shades,  // the density of centres per character cell, in density_shades
};

// The most centres a character cell may hold on average for the images to
// be drawn: beyond one, most cells would hold a ball's image (at a mean of 2,
// 86 % of them) and the picture would be a wall of them.
inline constexpr double most_centres_a_cell_for_images = 1;

// How many centres a whole character cell of `screen` holds on average: N
// times the cell's area over the area where centres can be, (A1 - 2a)(A2 - 2a).
double centres_a_cell(const Gas& gas, const TextScreen& screen);

// The drawing for `gas` on `screen` (stage 3's table of it): the images up to
// most_centres_a_cell_for_images centres a cell, the shades beyond.
// [anchor: table-drawing-for]
inline TableDrawing table_drawing_for(const Gas& gas, const TextScreen& screen) {
  return centres_a_cell(gas, screen) <= most_centres_a_cell_for_images
             ? TableDrawing::images
             : TableDrawing::shades;
}
// [/anchor: table-drawing-for]

// The shade of a cell whose density is `ratio` times the mean: ' ' for no
// centre, then nine shades for 0 to 2 times the mean, each 2/9 of the mean
// wide: '.' below 2/9, ':' below 4/9, '-', '=', then '+' from 8/9 to 10/9
// (the mean in its middle, the middle of the ramp), '*', '#', '%', and '@'
// from 16/9 up. A gas of even density is an even '+', whatever its N.
char shade_of(double ratio);

// The centres counted cell by cell over one or more pictures, and drawn in
// shades.
class DensityPicture {
 public:
  // For stage 3's table `screen` of `gas`: nothing counted yet.
  DensityPicture(const Gas& gas, const TextScreen& screen);

  // Counts the centres of the picture taken at model time `time` (a picture
  // already counted, at the same time, is not counted again).
  void add(const TextScreen& screen, const std::vector<Point>& centres, double time);
  // Forgets every picture counted.
  void clear();
  // Draws every inside cell of `screen` in the shade of its density against
  // the mean of the pictures counted, and the legend in the bottom border.
  void draw(TextScreen& screen) const;
  // The legend: the ramp, its scale and the mean, e.g.
  // "[ .:-=+*#%@] 0 to 2x mean; '+' mean: 555.4 a cell", and for more than
  // one picture " x 12 pictures".
  std::string legend() const;
  // The centres a whole cell holds on average in one picture.
  double mean() const { return mean_; }

 private:
  int columns_ = 0, rows_ = 0;       // the inside cells, across and down
  std::vector<double> room_;         // by cell: its area where centres can be,
                                     // in whole cells' areas (0 to 1)
  std::vector<long long> counts_;    // by cell: the centres counted
  double mean_ = 0;                  // centres a whole cell holds on average
  long long pictures_ = 0;           // the pictures counted
  std::optional<double> last_time_;  // the time of the last picture counted
};

// The tone a shaded table is sent to the terminal with: glyphs no screen
// holds, so no shade is coloured (a shade in the balls' bold colour would
// look darker than its neighbours).
inline constexpr Tone shades_tone{'\0', '\0', 0};

// Stage 6 for the balls or trails screen (`mode`): with no `density`, the
// article's images (draw_balls, draw_trails); else the shades of `density`,
// which for the balls screen holds only the picture now and for the trails
// screen every picture since it was made (the picture taken at `time`).
void draw_table(TextScreen& screen, ScreenMode mode, const Picture& picture, double time,
                double radius, const Tone& tone, DensityPicture* density);

}  // namespace gas
