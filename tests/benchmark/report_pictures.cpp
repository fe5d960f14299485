// The report's two pictures. See report_pictures.hpp.
#include "report_pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "beyond/strategy.hpp"
#include "report_text.hpp"

namespace gas::benchmark {

Picture throughput_figure(const std::filesystem::path& out,
                          const std::vector<Throughput>& throughput,
                          const std::vector<double>& fractions,
                          const ProgramFigures& program) {
  Picture picture;
  picture.svg = out / "throughput.svg";
  picture.title =
      "Collisions per second against N: the engine, each way of stage 4 (lines), and "
      "the program build/gas (squares)";
  for (const double fraction : fractions) {
    const bool first = fraction == fractions.front();
    Panel panel;
    panel.title = fmt::format("area fraction {}{}", fraction,
                              first ? " (dense; the large scenes)" : " (sparse)");
    panel.x_label = "N (balls)";
    panel.y_label = "collisions per second";
    panel.log_x = panel.log_y = true;
    // Up to 10^10 a second: room for the key above the lines.
    panel.ranges = "set yrange [1:1e10]";
    panel.key = "top right";
    for (const Strategy s : {Strategy::scan, Strategy::table, Strategy::grid}) {
      Series series;
      series.title = fmt::format("engine: {}", strategy_name(s));
      for (const Throughput& t : throughput)
        if (t.strategy == s && t.fraction == fraction)
          series.points.push_back({static_cast<double>(t.balls), t.per_second()});
      panel.series.push_back(series);
    }
    if (first) {
      for (const auto& [label, title] :
           {std::pair{'a', "gas --mode none"}, std::pair{'b', "gas --mode stats --csv"},
            std::pair{'c', "gas --pictures collisions"}}) {
        Series series;
        series.title = title;
        series.joined = false;
        for (const ProgramRun& run : program.runs)
          if (run.label == label && run.per_second() > 0)
            series.points.push_back({static_cast<double>(run.balls), run.per_second()});
        panel.series.push_back(series);
      }
    }
    picture.panels.push_back(panel);
  }
  return picture;
}

Picture distance_figure(const std::filesystem::path& out,
                        const std::vector<DistanceRow>& rows) {
  Picture picture;
  picture.svg = out / "number-types-distance.svg";
  picture.title = "How far each number type's run is from the 113-bit run";
  for (const std::string scene : {"default", "crowd"}) {
    Panel panel;
    panel.title = fmt::format("scene {}", scene);
    panel.x_label = "collisions per ball";
    panel.y_label = "largest distance of a ball from the 113-bit run (radii)";
    panel.log_y = true;
    panel.key = "bottom right";
    for (const std::string type : {"float", "double", "long double", "stages (double)"}) {
      Series series;
      series.title = type;
      for (const DistanceRow& r : rows)
        if (r.scene == scene && r.type == type)
          series.points.push_back({r.collisions_per_ball, r.error});
      panel.series.push_back(series);
    }
    // The growth is all there is to see: up to twice the collisions per ball
    // at which the last type is a radius off (the rest is the size of the table).
    double last_off = 0;
    bool all_off = true;
    for (const Series& series : panel.series) {
      const auto off = std::find_if(series.points.begin(), series.points.end(),
                                    [](const auto& point) { return point.second >= 1; });
      if (off == series.points.end()) {
        all_off = false;
      } else {
        last_off = std::max(last_off, off->first);
      }
    }
    if (all_off && last_off > 0)
      panel.ranges = fmt::format("set xrange [0:{:g}]", 2 * last_off);
    picture.panels.push_back(panel);
  }
  return picture;
}

std::string picture_markdown(const Picture& picture, const std::string& caption) {
  const std::string name = picture.svg.filename().string();
  const std::string why_not = draw(picture);
  if (!why_not.empty()) {
    progress("  no picture {}: {}", name, why_not);
    return fmt::format("*(No picture `{}`: {}.)*\n\n", name, why_not);
  }
  progress("  {}", picture.svg.string());
  return fmt::format("![{}]({})\n\n", caption, name);
}

}  // namespace gas::benchmark
