// The console program `gas`. See console.hpp.
#include "program/console.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "beyond/display_steps.hpp"
#include "beyond/kinetic_screen.hpp"
#include "beyond/lyapunov_screen.hpp"
#include "beyond/observer_list.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "program/key_source.hpp"
#include "program/run_outputs.hpp"
#include "program/scene_lookup.hpp"
#include "program/terminal.hpp"
#include "program/version.hpp"
#include "stage2_input.hpp"
#include "stage7_control.hpp"

namespace gas {
namespace {

// A run whose frames go to a file or a pipe, with no other limit, stops after
// this many frames rather than filling the disk.
constexpr long long default_plain_frames = 100;

// The grid of stage 3, in characters.
struct GridSize {
  int columns = 0;
  int rows = 0;
  bool too_small = false;  // the window has no room for it: the smallest grid instead
};

// The grid for a run: --cols and --rows, else the terminal's size (else 80 x
// 24), less two rows: the status line, and the cursor below the screen. A
// window too small for the smallest grid is a usage error, unless the frames
// are drawn `in_place` on it: then the window may yet grow (too_small).
GridSize grid_size(const Options& options, bool in_place) {
  const TerminalSize size = terminal_size().value_or(TerminalSize{});
  GridSize grid{options.columns.value_or(size.columns),
                options.rows.value_or(size.rows) - 2};
  if (grid.columns < smallest_columns || grid.rows < smallest_rows) {
    if (!in_place) {
      throw UsageError(fmt::format("the screen is too small: at least {} x {} characters",
                                   smallest_columns, smallest_rows + 2));
    }
    grid = {std::max(grid.columns, smallest_columns), std::max(grid.rows, smallest_rows),
            true};
  }
  return grid;
}

// How many frames a run may take: --frames; with no --frames or --until, a run
// printed to a file or a pipe takes 100 (or as many as --keys has keys).
std::optional<long long> frame_limit(const Options& options, bool terminal) {
  if (options.frames || options.until || terminal) return options.frames;
  const long long keys = options.keys ? static_cast<long long>(options.keys->size()) : 0;
  return std::max(default_plain_frames, keys);
}

// --trace, before the loop: what stages 1, 2 and 3 have set up — the
// article's variables with their values, where the scene was read from, the
// limits G1 and G2 of the centres, and the screen.
void trace_preparation(const Control& control, const std::string& scene_name,
                       const TextScreen& screen, ScreenMode mode, bool drawn,
                       PictureRule rule) {
  const Gas& gas = control.gas;
  const CentreLimits& limits = control.limits;  // stage 3's, kept by stage 7
  const std::size_t n = gas.balls.size();
  fmt::print("stage 1  variables and data: N={} a={} A1={} A2={} T={} T0={}\n", n,
             gas.radius, gas.width, gas.height, gas.time, gas.display_step);
  fmt::print("stage 2  input: {} ball{} from {}\n", n, n == 1 ? "" : "s", scene_name);
  fmt::print(
      "stage 3  screen preparation: a={} <= x <= G1=A1-a={}, a <= y <= G2=A2-a={}\n",
      limits.x_min, limits.x_max, limits.y_max);
  fmt::print("stage 3  screen preparation: {} x {} characters, border included\n",
             screen.columns, screen.rows);
  if (!drawn) {
    fmt::print("stage 3  screen preparation: nothing drawn (--mode none)\n");
  } else if (mode == ScreenMode::stats) {
    fmt::print("stage 3  screen preparation: figures only, no table\n");
  } else {
    fmt::print("stage 3  screen preparation: column {}, row {}\n", screen.column_width,
               screen.row_height);
  }
  // The article's loop needs no word; the other rule does.
  if (rule == PictureRule::display_steps) {
    fmt::print(
        "stage 7  model control: pictures only at T + T0, not at the collisions "
        "between\n");
  }
}

// The figures of the gas now (stage 6), for the status line and the screens.
Figures figures_of(const Control& control) {
  return measure(control.gas, control.starting_energy, control.wall_collisions,
                 control.ball_collisions);
}

// The statistics screen's histogram of speeds, and Boltzmann's H with it:
// the same bins whatever the screen's width (H and its noise depend on the
// bins, and --csv must not depend on --cols); draw_histogram merges or
// spreads them over the columns it has. 36 bins of 2.5 v_rms / 36: two
// columns each on an 80-column screen.
constexpr int histogram_bins = 36;

// Does the run draw the table of balls (the picture's centres), or only
// figures (--mode stats) or nothing (--mode none)?
bool draws_table(const Options& options) {
  return options.drawn && options.mode != ScreenMode::stats;
}

// One run of the program: stage 7's loop, with stage 6 drawing every step.
class ConsoleRun {
 public:
  ConsoleRun(const Options& options, Gas gas)
      : options_(options),
        terminal_(is_terminal(1) && !options.trace && options.drawn),
        rule_(options.pictures.value_or(picture_rule_for(gas.balls.size()))),
        keyboard_(terminal_ && is_terminal(0) && !options.keys && !options.step),
        control_(start_control_for(std::move(gas), options.strategy)),
        display_(stdout, terminal_, terminal_ && std::getenv("NO_COLOR") == nullptr),
        grid_(grid_size(options, terminal_)),
        frame_limit_(frame_limit(options, terminal_)),
        outputs_(options, display_),
        keeps_{draws_table(options), options.events_path.has_value() || options.bell},
        screen_(prepare()) {
    // No table drawn: the centres stage 7 started the picture with are
    // never read (a display step keeps none, keeps_).
    if (!keeps_.picture) control_.picture = Picture{};
    // Kinetic theory only for a run that shows or writes its figures: the
    // statistics screen, --csv or --structure. It hears of each collision
    // through stage 7's one hook (`statistics_` is made in place and never
    // moves).
    if ((options.drawn && options.mode == ScreenMode::stats) || options.csv_path ||
        options.structure_path) {
      statistics_.emplace(control_.gas, histogram_bins, true,
                          options.structure_path.has_value());
      control_.observer = &*statistics_;
    }
    // The Lyapunov exponent beside them, on the same hook, where it is shown
    // or written: the statistics screen or --csv, not --structure alone
    // (lesson 15).
    if ((options.drawn && options.mode == ScreenMode::stats) || options.csv_path) {
      lyapunov_.emplace(control_.gas);
      observers_.emplace(std::vector<CollisionObserver*>{&*statistics_, &*lyapunov_});
      control_.observer = &*observers_;
    }
    // Drawn in place: the frame fits the window, and fits it again when it
    // changes size (resize()).
    if (const auto size = terminal_size(); terminal_ && size)
      display_.fit_window(size->columns, size->rows);
    if (terminal_) install_resize_flag();
  }

  // The article's stage 7: the keys of the tick; then, unless stopped, stages
  // 4 and 5 take one display step (back to stage 4 at every collision); then
  // stage 6 draws it. Returns the exit status.
  int run() {
    if (options_.trace) {
      trace_preparation(control_, scene_name(), screen_, options_.mode, options_.drawn,
                        rule_);
    }
    install_interrupt_flag();  // Ctrl-C, SIGTERM, SIGHUP: end the run as E would
    KeySource keys(options_, keyboard_);
    std::FILE* const trace = options_.trace ? stdout : nullptr;
    long long frames_done = 0;
    while (true) {
      if (interrupted() || outputs_.failure()) break;
      if (frame_limit_ && frames_done >= *frame_limit_) break;
      if (options_.until && control_.gas.time >= *options_.until) break;
      if (terminal_ && take_resize()) resize();  // stage 3 again, at the new size

      // Stage 7: the keys of this tick; E ends the run.
      const std::string pressed = keys.take(control_.stopped);
      if (!press_all(pressed)) break;
      if (control_.stopped) {
        // No step; on the keyboard, the status line shows what a key did.
        if (keys.from_keyboard() && !pressed.empty()) show(figures_of(control_));
        if (keys.wait_while_stopped()) continue;
        break;  // nothing could start the model again
      }

      // Stages 4 and 5 (and stage 7 going back to stage 4 at a collision), up
      // to the next picture: the first collision, or T + T0 (the rule).
      const Step step =
          take_step_by(rule_, control_, options_.until.value_or(never), trace, keeps_);
      ++frames_done;
      outputs_.record(step);
      // The picture and its figures (each a pass over the balls).
      if (options_.drawn || outputs_.writes_csv()) {
        const Figures figures = figures_of(control_);
        std::optional<KineticFigures> kinetic;  // worked out once, for both uses
        if (statistics_)
          kinetic = kinetic_figures(control_.gas, *statistics_, figures.energy);
        if (kinetic && outputs_.writes_csv()) {
          outputs_.write_csv(figures, *kinetic,
                             lyapunov_csv_row(lyapunov_->measured(control_.gas)));
        }
        if (options_.drawn) {
          show(figures, kinetic ? &*kinetic : nullptr,
               rule_ == PictureRule::every_collision && !step.collisions.empty());
        }
      }
      if (!keys.wait_after_step(step.length / control_.gas.display_step)) break;
    }
    // However the run ends: the terminal put back, the files closed whole.
    display_.finish();
    outputs_.finish(control_.gas, statistics_ ? &*statistics_ : nullptr);
    return ending();
  }

 private:
  // The exit status, and what stderr says about an unusual end: a file that
  // could not be written (1), or a signal (128 + its number: 130 for SIGINT,
  // 143 for SIGTERM, 129 for SIGHUP, as shells expect).
  int ending() const {
    if (const auto failure = outputs_.failure()) {
      fmt::print(stderr, "gas: {} (at T = {:.17g})\n", *failure, control_.gas.time);
      return 1;
    }
    if (!interrupted()) return 0;
    const std::vector<std::string> files = outputs_.written();
    fmt::print(stderr, "gas: interrupted by {} at T = {:.17g} after {} collisions{}\n",
               signal_name(interrupting_signal()), control_.gas.time,
               control_.wall_collisions + control_.ball_collisions,
               files.empty()
                   ? std::string()
                   : fmt::format("; written whole: {}", fmt::join(files, ", ")));
    return 128 + interrupting_signal();
  }

  // Where stage 2 read the scene: its file, or the default scene built in.
  std::string scene_name() const {
    return options_.scene_path ? *options_.scene_path
                               : fmt::format("{} (built in)", default_scene_name);
  }

  // Carries out the keys in `keys`; false once E is pressed. Beyond the
  // article's keys, A restarts the statistics' averages (lesson 14).
  bool press_all(const std::string& keys) {
    for (const char key : keys) {
      if ((key == 'A' || key == 'a') && statistics_) {
        statistics_->restart(control_.gas);
        if (lyapunov_) lyapunov_->restart();
      }
      const KeyEffect effect = press_key(control_, key);
      if (effect == KeyEffect::end) return false;
      if (effect == KeyEffect::redraw) prepare_again();
    }
    return true;
  }

  // The window changed size: back to stage 3 at the new size, as the key 0
  // does, and the frame drawn whole at once, cut to the window (--cols and
  // --rows, if given, keep their size).
  void resize() {
    grid_ = grid_size(options_, true);
    if (const auto size = terminal_size()) display_.fit_window(size->columns, size->rows);
    prepare_again();
    show(figures_of(control_));
  }

  // Back to stage 3: the screen laid out afresh, and drawn whole next time.
  void prepare_again() {
    screen_ = prepare();
    display_.invalidate();
  }

  // Stage 3: the table's screen, or for the figures a plain character screen.
  TextScreen prepare() const {
    return options_.mode == ScreenMode::stats
               ? prepare_character_screen(grid_.columns, grid_.rows)
               : prepare_screen(control_.gas, grid_.columns, grid_.rows);
  }

  // Stage 6: draws the screen the options ask for and sends it out, with
  // kinetic theory's figures if the step has worked them out already. With
  // --trace it says when the step ended on a collision (T = TC): the
  // article's picture freezes there while stage 4 computes the next one.
  void show(const Figures& figures, const KineticFigures* kinetic = nullptr,
            bool at_collision = false) {
    if (grid_.too_small) {  // until the window grows: one line, no frame
      display_.notice(fmt::format("window too small: at least {} x {}", smallest_columns,
                                  smallest_rows + 2));
      return;
    }
    const Tone& tone = tones[control_.tone];
    if (options_.trace) {
      fmt::print("stage 6  output: the {} screen{}\n", mode_name(options_.mode),
                 at_collision ? fmt::format(", frozen at the collision T = TC = {}",
                                            control_.gas.time)
                              : "");
    }
    switch (options_.mode) {
      case ScreenMode::balls:
        draw_balls(screen_, control_.picture, control_.gas.radius, tone);
        break;
      case ScreenMode::trails:
        draw_trails(screen_, control_.picture, tone);
        break;
      case ScreenMode::stats:
        draw_kinetic_figures(
            screen_, figures,
            kinetic ? *kinetic
                    : kinetic_figures(control_.gas, *statistics_, figures.energy),
            lyapunov_lines(control_.gas, lyapunov_->measured(control_.gas)));
        break;
    }
    display_.show(screen_, status_line(figures, options_.mode, control_.stopped), tone);
    if (options_.trace) trace_decision(control_, stdout);
  }

  const Options& options_;
  bool terminal_;     // frames drawn in place on a terminal, not printed whole
  PictureRule rule_;  // pictures at every collision, or at display steps only
  bool keyboard_;     // keys typed live on the keyboard
  Control control_;
  Display display_;
  GridSize grid_;
  std::optional<long long> frame_limit_;
  RunOutputs outputs_;
  StepKeeps keeps_;  // what a display step keeps: the centres, the collisions
  std::optional<GasStatistics> statistics_;   // for --mode stats, --csv, --structure
  std::optional<LyapunovExponent> lyapunov_;  // with them (lesson 15)
  std::optional<ObserverList> observers_;     // both on stage 7's hook
  TextScreen screen_;
};

}  // namespace

int run_console(const std::vector<std::string>& arguments) {
  try {
    Options options = parse_options(arguments);
    if (options.help) {
      fmt::print("{}", help_text());
      return 0;
    }
    if (options.version) {
      fmt::print("{}", version_text());
      return 0;
    }
    // A scene named that is no file: a teaching scene (scene_lookup.hpp).
    if (options.scene_path)
      options.scene_path = find_scene(*options.scene_path, scene_folders());
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
