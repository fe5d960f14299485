// gnuplot scripts and their pictures. See plots.hpp.
#include "plots.hpp"

#include <fmt/format.h>

#include "child_process.hpp"
#include "report_text.hpp"

namespace gas::benchmark {
namespace {

// A text as a gnuplot string: in double quotes, with \ and " escaped.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '\\' || c == '"') out += '\\';
    out += c;
  }
  return out + "\"";
}

bool shown(const Panel& panel, std::pair<double, double> point) {
  return (!panel.log_x || point.first > 0) && (!panel.log_y || point.second > 0);
}

// The axis settings of one panel.
std::string axes(const Panel& panel) {
  std::string script;
  for (const auto& [axis, log] : {std::pair{"x", panel.log_x}, {"y", panel.log_y}}) {
    if (log) {
      script += fmt::format("set logscale {0} 10\nset format {0} \"10^{{%L}}\"\n", axis);
    } else {
      script += fmt::format("unset logscale {0}\nset format {0} \"%g\"\n", axis);
    }
  }
  return script;
}

}  // namespace

std::string gnuplot_script(const Picture& picture) {
  std::string script = fmt::format(
      "# Written by tests/benchmark/plots.cpp (gas-benchmark, gas-figures): {}\n"
      "set terminal svg size {},{} dynamic enhanced font \"sans,13\" "
      "background rgb \"white\"\n"
      "set output {}\n"
      "set encoding utf8\n",
      picture.title, picture.width, picture.height, quoted(picture.svg.string()));
  // The numbers, one data block per series.
  for (std::size_t p = 0; p < picture.panels.size(); ++p) {
    const Panel& panel = picture.panels[p];
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      script += fmt::format("$data_{}_{} << EOD\n", p, s);
      const Series& series = panel.series[s];
      for (std::size_t i = 0; i < series.points.size(); ++i) {
        const auto& point = series.points[i];
        if (!shown(panel, point)) continue;
        script += fmt::format("{:.9g} {:.9g}", point.first, point.second);
        if (!series.errors.empty()) script += fmt::format(" {:.9g}", series.errors[i]);
        script += "\n";
      }
      script += "EOD\n";
    }
  }
  script += fmt::format("set multiplot layout 1,{} title {} noenhanced\n",
                        picture.panels.size(), quoted(picture.title));
  script += "set grid\nset mxtics\nset mytics\n";
  for (std::size_t p = 0; p < picture.panels.size(); ++p) {
    const Panel& panel = picture.panels[p];
    script += fmt::format(
        "set title {} noenhanced\nset xlabel {} noenhanced\nset ylabel {} noenhanced\n"
        "set key {} box opaque noenhanced\n",
        quoted(panel.title), quoted(panel.x_label), quoted(panel.y_label), panel.key);
    script += axes(panel);
    script += "set xrange [*:*]\nset yrange [*:*]\n" + panel.ranges + "\n";
    std::vector<std::string> plots;
    for (std::size_t s = 0; s < panel.series.size(); ++s) {
      const Series& series = panel.series[s];
      bool any = false;
      for (const auto& point : series.points) any = any || shown(panel, point);
      if (!any) continue;
      // The same colour for the same place in every panel.
      std::string with = series.joined
                             ? "linespoints linewidth 1.5 pointtype 7 pointsize 0.5"
                             : "points pointtype 5 pointsize 1.2";
      if (!series.errors.empty()) with = "yerrorbars pointtype 7 pointsize 0.5";
      if (!series.style.empty()) with = series.style;
      plots.push_back(fmt::format("$data_{}_{} using {} with {} linetype {} title {}", p,
                                  s, series.errors.empty() ? "1:2" : "1:2:3", with, s + 1,
                                  quoted(series.title)));
    }
    if (plots.empty()) {
      script +=
          "unset logscale\nset label 1 \"no data\" at graph 0.5,0.5 center\n"
          "plot [0:1] [0:1] NaN notitle\nunset label 1\n";
      continue;
    }
    script += "plot ";
    for (std::size_t i = 0; i < plots.size(); ++i)
      script += (i ? ", \\\n     " : "") + plots[i];
    script += "\n";
  }
  script += "unset multiplot\nset output\n";
  return script;
}

std::string draw(const Picture& picture) {
  if (!on_path("gnuplot"))
    return "gnuplot is not installed (Debian: apt-get install -y gnuplot-nox)";
  std::error_code ignored;
  std::filesystem::remove(picture.svg, ignored);  // no old picture taken for the new
  const ChildRun run = run_child("gnuplot", {}, gnuplot_script(picture), 120);
  const std::string said = run.error.substr(0, run.error.find('\n'));
  if (!run.succeeded()) return fmt::format("gnuplot failed ({})", run.failure());
  if (std::filesystem::file_size(picture.svg, ignored) == 0 || ignored)
    return fmt::format("gnuplot wrote no picture{}", said.empty() ? "" : ": " + said);
  if (!said.empty())
    progress("gnuplot, for {}: {}", picture.svg.filename().string(), said);
  return "";
}

}  // namespace gas::benchmark
