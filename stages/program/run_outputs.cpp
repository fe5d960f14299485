// What a run leaves behind besides its frames. See run_outputs.hpp.
#include "program/run_outputs.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "stage2_input.hpp"

namespace gas {

bool bell_may_ring(std::chrono::steady_clock::time_point last,
                   std::chrono::steady_clock::time_point now) {
  return now - last >= std::chrono::duration<double>(bell_interval_seconds);
}

OutputFile::OutputFile(const std::optional<std::string>& path) {
  if (!path) return;
  file_.reset(std::fopen(path->c_str(), "w"));
  if (!file_) throw std::runtime_error(fmt::format("{}: cannot write this file", *path));
}

RunOutputs::RunOutputs(const Options& options, Display& display)
    : events_(options.events_path),
      csv_(options.csv_path),
      dump_path_(options.dump_path),
      bell_(options.bell),
      display_(display) {
  if (events_) fmt::print(events_.get(), "T,K,N1,N2\n");
  if (csv_) fmt::print(csv_.get(), "{}\n", csv_header());
}

void RunOutputs::record(const Step& step) {
  if (events_) {
    for (const Collision& c : step.collisions) {
      fmt::print(events_.get(), "{:.17g},{},{},{}\n", c.time, static_cast<int>(c.kind),
                 c.first, c.second);
    }
  }
  if (bell_ && !step.collisions.empty()) ring_bell();
}

void RunOutputs::write_csv(const Figures& figures, const KineticFigures& kinetic) {
  if (csv_) fmt::print(csv_.get(), "{}\n", csv_row(figures, kinetic));
}

void RunOutputs::finish(const Gas& gas) const {
  if (!dump_path_) return;
  const OutputFile dump(dump_path_);
  fmt::print(dump.get(), "{}", scene_text(gas));
}

void RunOutputs::ring_bell() {
  const auto now = std::chrono::steady_clock::now();
  if (bell_may_ring(last_bell_, now)) {
    display_.bell();
    last_bell_ = now;
  }
}

}  // namespace gas
