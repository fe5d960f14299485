// The report's pictures, drawn by gnuplot.
//
// A picture is one or more panels side by side, each a few series of points
// (joined by lines or not) on linear or logarithmic axes. The benchmark
// writes a gnuplot script with the numbers inside it (as data blocks) and
// feeds it to gnuplot, run as a child process, which writes an SVG file.
// Nothing else needs gnuplot: without it (Debian's gnuplot-nox) the report
// says why it has no pictures.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace gas::benchmark {

struct Series {
  std::string title;
  std::vector<std::pair<double, double>> points;  // (x, y)
  bool joined = true;                             // lines and points, or points only
  std::vector<double> errors;  // y's error bars, one a point; none: no bars
  std::string style;           // gnuplot's "with ..." words; none: as `joined` says
};

struct Panel {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  std::vector<Series> series;
  std::string key = "bottom left";  // where the key goes (gnuplot's words)
  std::string ranges;               // gnuplot's set xrange, set yrange; none: all data
};

struct Picture {
  std::filesystem::path svg;  // the file to write
  std::string title;
  std::vector<Panel> panels;
  int width = 1000, height = 500;  // in SVG units
};

// The gnuplot script that draws the picture, numbers included. Points that a
// logarithmic axis cannot show (0 or less) are left out.
std::string gnuplot_script(const Picture& picture);

// Draws the picture with gnuplot; returns "" if it did, else why not.
std::string draw(const Picture& picture);

}  // namespace gas::benchmark
