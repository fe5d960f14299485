// The console program `gas`. See console.hpp.
#include "program/console.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "beyond/random_placement.hpp"
#include "program/terminal.hpp"
#include "stage2_input.hpp"
#include "stage7_control.hpp"

namespace gas {
namespace {

// Real-time pacing on a terminal: one display step T0 per frame, 25 frames a
// second; a shorter step (up to a collision) takes its share of a frame.
constexpr double frame_seconds = 0.04;
// A run whose frames go to a file or a pipe, with no other limit, stops after
// this many frames rather than filling the disk.
constexpr long long default_plain_frames = 100;
// The bell rings at most this often, so that a crowd does not buzz.
constexpr double bell_interval_seconds = 0.15;

long long whole_number(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty()) {
    throw UsageError(fmt::format("{} takes a whole number, not '{}'", option, text));
  }
  return value;
}

double real_number(const std::string& option, const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(value)) {
    throw UsageError(fmt::format("{} takes a finite number, not '{}'", option, text));
  }
  return value;
}

// A file to write, opened before the run starts so that a bad path fails early.
struct OutputFile {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file{nullptr, std::fclose};
  void open(const std::optional<std::string>& path) {
    if (!path) return;
    file.reset(std::fopen(path->c_str(), "w"));
    if (!file) throw std::runtime_error(fmt::format("{}: cannot write this file", *path));
  }
  explicit operator bool() const { return file != nullptr; }
  std::FILE* get() const { return file.get(); }
};

}  // namespace

std::string help_text() {
  return R"(gas - the billiard-ball gas of "Gas on the display" (Kvant 1989), in a terminal

usage: gas [SCENE] [--frames N | --until T] [--keys KEYS] [--mode balls|trails|stats]
           [--events FILE] [--dump FILE] [--csv FILE] [--cols N] [--rows N]
           [--step] [--trace] [--bell] [--strategy scan|table|grid] [--help]

  SCENE            a scene file (see data/README.md); none: the built-in default scene
  --frames N       take N display steps, then exit
  --until T        run until model time T exactly, then exit
  --keys KEYS      press one key per display step ('.' for none) instead of the keyboard
  --mode M         the screen: balls (moving balls), trails (trajectories),
                   stats (figures only); default balls
  --events FILE    write every collision to FILE as CSV: T,K,N1,N2
  --dump FILE      at exit, write the gas to FILE as a scene file
  --csv FILE       write the statistics of every display step to FILE as CSV
  --cols N         screen width in characters (default: the terminal's, else 80)
  --rows N         screen height in characters (default: the terminal's, else 24)
  --step           wait for Enter after every display step (a line may hold keys)
  --trace          print each stage of the article as it runs, with T, T1, TC, K, N1, N2
  --bell           ring the terminal bell on collisions
  --strategy S     how stage 4 finds the first collision: scan (the article's),
                   table (each ball's next event) or grid (cells and an event
                   queue); the same collisions, at different speeds. Default:
                   scan up to )" +
         std::to_string(most_balls_for_scan) + R"( balls, table up to )" +
         std::to_string(most_balls_for_table) + R"(, grid beyond
  --help           show this text

keys (in a terminal, without Enter): S stop, R run, B reverse all velocities,
  > double T0, < halve T0, 0 redraw the screen, E end.
When the output is not a terminal, every frame is printed whole, headed by a
status line; with no --frames or --until the run stops after 100 frames (or
as many as --keys has keys, if more).
Exit status: 0 success, 2 bad usage or bad scene, 1 any other failure.
)";
}

Options parse_options(const std::vector<std::string>& arguments) {
  Options options;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    std::string argument = arguments[i];
    std::optional<std::string> attached;  // --option=value
    if (argument.rfind("--", 0) == 0) {
      if (const auto equals = argument.find('='); equals != std::string::npos) {
        attached = argument.substr(equals + 1);
        argument.resize(equals);
      }
    }
    auto value = [&]() -> std::string {
      if (attached) return *attached;
      if (i + 1 >= arguments.size())
        throw UsageError(fmt::format("{} needs a value", argument));
      return arguments[++i];
    };
    auto flag = [&](bool& target) {
      if (attached) throw UsageError(fmt::format("{} takes no value", argument));
      target = true;
    };
    if (argument == "--frames") {
      const long long frames = whole_number(argument, value());
      if (frames < 0)
        throw UsageError(fmt::format("--frames must not be negative, not {}", frames));
      options.frames = frames;
    } else if (argument == "--until") {
      const double until = real_number(argument, value());
      if (until < 0)
        throw UsageError(fmt::format("--until must not be negative, not {}", until));
      options.until = until;
    } else if (argument == "--keys") {
      options.keys = value();
    } else if (argument == "--mode") {
      const std::string mode = value();
      if (mode == "balls") {
        options.mode = ScreenMode::balls;
      } else if (mode == "trails") {
        options.mode = ScreenMode::trails;
      } else if (mode == "stats") {
        options.mode = ScreenMode::stats;
      } else {
        throw UsageError(
            fmt::format("--mode takes balls, trails or stats, not '{}'", mode));
      }
    } else if (argument == "--events") {
      options.events_path = value();
    } else if (argument == "--dump") {
      options.dump_path = value();
    } else if (argument == "--csv") {
      options.csv_path = value();
    } else if (argument == "--cols" || argument == "--rows") {
      const long long size = whole_number(argument, value());
      const int smallest = argument == "--cols" ? smallest_columns : smallest_rows + 2;
      if (size < smallest || size > 10000) {
        throw UsageError(fmt::format("{} takes a number from {} to 10000, not {}",
                                     argument, smallest, size));
      }
      (argument == "--cols" ? options.columns : options.rows) = static_cast<int>(size);
    } else if (argument == "--strategy") {
      const std::string name = value();
      options.strategy = strategy_named(name);
      if (!options.strategy) {
        throw UsageError(
            fmt::format("--strategy takes scan, table or grid, not '{}'", name));
      }
    } else if (argument == "--step") {
      flag(options.step);
    } else if (argument == "--trace") {
      flag(options.trace);
    } else if (argument == "--bell") {
      flag(options.bell);
    } else if (argument == "--help" || argument == "-h") {
      flag(options.help);
    } else if (argument.size() > 1 && argument[0] == '-') {
      throw UsageError(fmt::format("unknown option '{}'", argument));
    } else if (options.scene_path) {
      throw UsageError(
          fmt::format("one scene only: '{}' and '{}'", *options.scene_path, argument));
    } else {
      options.scene_path = argument;
    }
  }
  if (options.frames && options.until)
    throw UsageError("--frames and --until exclude each other");
  return options;
}

namespace {

// The main loop of the program around stage 7.
class ConsoleRun {
 public:
  ConsoleRun(const Options& options, Gas gas)
      : options_(options),
        terminal_(is_terminal(1) && !options.trace),
        interactive_(terminal_ && is_terminal(0) && !options.keys && !options.step),
        control_(start_control(std::move(gas), options.strategy)),
        display_(stdout, terminal_, terminal_ && std::getenv("NO_COLOR") == nullptr) {
    const TerminalSize size = terminal_size().value_or(TerminalSize{});
    columns_ = options.columns.value_or(size.columns);
    rows_ =
        options.rows.value_or(size.rows) - 2;  // the status line, and the cursor below
    if (columns_ < smallest_columns || rows_ < smallest_rows) {
      throw UsageError(fmt::format("the screen is too small: at least {} x {} characters",
                                   smallest_columns, smallest_rows + 2));
    }
    frame_limit_ = options.frames;
    if (!frame_limit_ && !options.until && !terminal_) {
      const long long keys =
          options.keys ? static_cast<long long>(options.keys->size()) : 0;
      frame_limit_ = std::max(default_plain_frames, keys);
    }
    // The statistics screen's averages start now; a histogram bin for every two
    // columns, at most 40.
    statistics_.emplace(control_.gas, tallies(), std::clamp(columns_ / 2 - 2, 1, 40));
    events_.open(options.events_path);
    csv_.open(options.csv_path);
    if (events_) fmt::print(events_.get(), "T,K,N1,N2\n");
    if (csv_) fmt::print(csv_.get(), "{}\n", csv_header());
    screen_ = prepare();
  }

  int run() {
    if (terminal_) install_interrupt_flag();
    std::optional<RawKeys> raw_keys;
    if (interactive_) raw_keys.emplace();
    std::string pending;  // keys pressed and not yet carried out
    std::size_t next_key = 0;
    long long frames_done = 0;
    const double time_limit = options_.until.value_or(never);
    int status = 0;

    while (true) {
      if (interrupted()) {
        status = 1;
        break;
      }
      if (frame_limit_ && frames_done >= *frame_limit_) break;
      if (options_.until && control_.gas.time >= *options_.until) break;

      // The keys of this tick: the script's next one, or what was typed.
      if (options_.keys) {
        if (next_key < options_.keys->size()) pending += (*options_.keys)[next_key++];
      } else if (raw_keys) {
        pending += raw_keys->poll(control_.stopped ? 100 : 0);
      }
      const bool had_keys = !pending.empty();
      if (!press_all(pending)) break;
      if (control_.stopped) {
        if (raw_keys) {
          if (had_keys) show();
          continue;
        }
        if (options_.keys && next_key < options_.keys->size()) continue;
        if (options_.step && wait_for_enter(pending)) continue;
        break;  // nothing could start the model again
      }

      // One pass of the article's loop: stages 4, 5 and 7, then stage 6.
      const Step step =
          take_step(control_, time_limit, options_.trace ? stdout : nullptr);
      ++frames_done;
      record(step);
      show();
      if (options_.step && !wait_for_enter(pending)) break;
      if (raw_keys) {
        const double share = step.length / control_.gas.display_step;
        pending +=
            raw_keys->poll(static_cast<int>(std::lround(1000 * frame_seconds * share)));
      }
    }
    display_.finish();
    if (options_.dump_path) {
      OutputFile dump;
      dump.open(options_.dump_path);
      fmt::print(dump.get(), "{}", scene_text(control_.gas));
    }
    return status;
  }

 private:
  // Carries out the keys in `keys`; false once E is pressed.
  bool press_all(std::string& keys) {
    for (const char key : keys) {
      const KeyEffect effect = press_key(control_, key);
      if (effect == KeyEffect::end) return false;
      if (effect == KeyEffect::redraw) {
        screen_ = prepare();  // back to stage 3
        display_.invalidate();
      }
    }
    keys.clear();
    return true;
  }

  // Stage 3: the table's screen, or for the figures a plain character screen.
  TextScreen prepare() const {
    return options_.mode == ScreenMode::stats
               ? prepare_character_screen(columns_, rows_)
               : prepare_screen(control_.gas, columns_, rows_);
  }

  // --step: waits for Enter; the line typed before it holds keys. False at
  // the end of the input.
  bool wait_for_enter(std::string& pending) {
    std::string line;
    if (!std::getline(std::cin, line)) return false;
    pending += line;
    return true;
  }

  // What stage 7 has counted, for the statistics (lesson 11).
  Tallies tallies() const {
    return {control_.gas.time, control_.horizontal_wall_push, control_.vertical_wall_push,
            control_.ball_collisions};
  }

  Figures figures() const {
    Figures f = measure(control_.gas, control_.starting_energy, control_.wall_collisions,
                        control_.ball_collisions);
    add_statistics(f, *statistics_);
    return f;
  }

  void record(const Step& step) {
    statistics_->record(control_.gas, tallies());
    if (events_) {
      for (const Collision& c : step.collisions) {
        fmt::print(events_.get(), "{:.17g},{},{},{}\n", c.time, static_cast<int>(c.kind),
                   c.first, c.second);
      }
    }
    if (csv_) fmt::print(csv_.get(), "{}\n", csv_row(figures()));
    if (options_.bell && !step.collisions.empty()) {
      const auto now = std::chrono::steady_clock::now();
      if (now - last_bell_ >= std::chrono::duration<double>(bell_interval_seconds)) {
        display_.bell();
        last_bell_ = now;
      }
    }
  }

  // Stage 6: draws the screen the options ask for and sends it out.
  void show() {
    const Figures figures = this->figures();
    const Tone& tone = tones[control_.tone];
    if (options_.trace)
      fmt::print("stage 6  output: the {} screen\n", mode_name(options_.mode));
    switch (options_.mode) {
      case ScreenMode::balls:
        draw_balls(screen_, control_.picture, control_.gas.radius, tone);
        break;
      case ScreenMode::trails:
        draw_trails(screen_, control_.picture, tone);
        break;
      case ScreenMode::stats:
        draw_figures(screen_, figures);
        break;
    }
    display_.show(screen_, status_line(figures, options_.mode, control_.stopped), tone);
    if (options_.trace) trace_decision(control_, stdout);
  }

  const Options& options_;
  bool terminal_;
  bool interactive_;
  Control control_;
  Display display_;
  int columns_ = 0;
  int rows_ = 0;
  std::optional<long long> frame_limit_;
  std::optional<GasStatistics> statistics_;
  OutputFile events_;
  OutputFile csv_;
  TextScreen screen_;
  std::chrono::steady_clock::time_point last_bell_{};
};

}  // namespace

int run_console(const std::vector<std::string>& arguments) {
  try {
    const Options options = parse_options(arguments);
    if (options.help) {
      fmt::print("{}", help_text());
      return 0;
    }
    Gas gas = options.scene_path ? read_scene_file(*options.scene_path)
                                 : parse_scene(default_scene_text, default_scene_name);
    ConsoleRun run(options, std::move(gas));
    return run.run();
  } catch (const UsageError& error) {
    fmt::print(stderr, "gas: {}\nTry 'gas --help'.\n", error.what());
    return 2;
  } catch (const SceneError& error) {
    fmt::print(stderr, "{}\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    fmt::print(stderr, "gas: {}\n", error.what());
    return 1;
  }
}

}  // namespace gas
