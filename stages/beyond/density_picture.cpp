// The density of centres in shades. See beyond/density_picture.hpp.
#include "beyond/density_picture.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace gas {
namespace {

// How much of the stretch [from, to] lies within [low, high].
double overlap(double from, double to, double low, double high) {
  return std::max(0.0, std::min(to, high) - std::max(from, low));
}

}  // namespace

double centres_a_cell(const Gas& gas, const TextScreen& screen) {
  const double room = (gas.width - 2 * gas.radius) * (gas.height - 2 * gas.radius);
  return static_cast<double>(gas.balls.size()) * screen.column_width * screen.row_height /
         room;
}

// [anchor: shade-of]
char shade_of(double ratio) {
  if (!(ratio > 0)) return density_shades[0];
  const double ninths = std::floor(4.5 * ratio);  // each shade 2/9 of the mean
  const auto last = static_cast<double>(density_shades.size() - 1);
  return density_shades[static_cast<std::size_t>(std::clamp(1 + ninths, 1.0, last))];
}
// [/anchor: shade-of]

DensityPicture::DensityPicture(const Gas& gas, const TextScreen& screen)
    : columns_(screen.columns - 2),
      rows_(screen.rows - 2),
      room_(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_)),
      counts_(room_.size(), 0),
      mean_(centres_a_cell(gas, screen)) {
  // Each cell's share of the box where centres can be, a <= x <= A1 - a,
  // a <= y <= A2 - a: inside row 0 is the top of the table.
  const double a = gas.radius, across = screen.column_width, down = screen.row_height;
  for (int row = 0; row < rows_; ++row) {
    const double bottom = (rows_ - 1 - row) * down;
    const double tall = overlap(bottom, bottom + down, a, gas.height - a) / down;
    for (int column = 0; column < columns_; ++column) {
      const double wide =
          overlap(column * across, (column + 1) * across, a, gas.width - a);
      room_[static_cast<std::size_t>(row * columns_ + column)] = tall * wide / across;
    }
  }
}

void DensityPicture::add(const TextScreen& screen, const std::vector<Point>& centres,
                         double time) {
  if (last_time_ == time) return;
  last_time_ = time;
  ++pictures_;
  for (const Point& centre : centres) {
    const Cell cell = screen.cell_of(centre);
    ++counts_[static_cast<std::size_t>((cell.row - 1) * columns_ + cell.column - 1)];
  }
}

void DensityPicture::clear() {
  std::fill(counts_.begin(), counts_.end(), 0);
  pictures_ = 0;
  last_time_.reset();
}

void DensityPicture::draw(TextScreen& screen) const {
  // A cell's density against the mean: its centres over those a whole cell
  // holds on average in as many pictures, for the part of it centres can be.
  const double expected = mean_ * static_cast<double>(pictures_);
  for (int row = 0; row < rows_; ++row) {
    for (int column = 0; column < columns_; ++column) {
      const auto k = static_cast<std::size_t>(row * columns_ + column);
      const double ratio =
          counts_[k] == 0 ? 0.0 : static_cast<double>(counts_[k]) / (expected * room_[k]);
      screen.at({column + 1, row + 1}) = shade_of(ratio);
    }
  }
  // The legend in the bottom border, from its third character and clear of
  // its last two: whole, or if it has no room the ramp alone, or nothing.
  std::string& border = screen.lines.back();
  for (const std::string& text :
       {fmt::format(" {} ", legend()), fmt::format(" [{}] ", density_shades)}) {
    if (text.size() + 4 <= border.size()) {
      border.replace(2, text.size(), text);
      break;
    }
  }
}

std::string DensityPicture::legend() const {
  std::string text = fmt::format("[{}] 0 to 2x mean; '{}' mean: {:.4g} a cell",
                                 density_shades, shade_of(1), mean_);
  if (pictures_ > 1) text += fmt::format(" x {} pictures", pictures_);
  return text;
}

void draw_table(TextScreen& screen, ScreenMode mode, const Picture& picture, double time,
                double radius, const Tone& tone, DensityPicture* density) {
  if (density == nullptr) {
    if (mode == ScreenMode::balls) draw_balls(screen, picture, radius, tone);
    if (mode == ScreenMode::trails) draw_trails(screen, picture, tone);
    return;
  }
  if (mode == ScreenMode::balls) density->clear();  // the balls screen: now only
  density->add(screen, picture.centres, time);
  density->draw(screen);
}

}  // namespace gas
