// The console program `gas`. See console.hpp.
#include "program/console.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "beyond/density_picture.hpp"
#include "beyond/display_steps.hpp"
#include "beyond/kinetic_screen.hpp"
#include "beyond/lyapunov_screen.hpp"
#include "beyond/observer_list.hpp"
#include "beyond/random_placement.hpp"
#include "beyond/strategy.hpp"
#include "beyond/velocity_autocorrelation.hpp"
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

// The line of keys under the table (Display::keys_below), for keys typed
// live: stage 7's keys, and A where the averages are shown; a short form
// for a narrow window.
std::vector<std::string> key_line_forms(bool averages) {
  return {fmt::format("keys: S stop  R run  B reverse  > T0x2  < T0/2  0 redraw  E end{}",
                      averages ? "  A new averages" : ""),
          fmt::format("keys: S R B > < 0 E{} (gas --help)", averages ? " A" : "")};
}

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
        in_place_(terminal_ && understands_escapes()),
        rule_(options.pictures.value_or(picture_rule_for(gas.balls.size()))),
        keyboard_(terminal_ && is_terminal(0) && !options.keys && !options.step),
        control_(start_control_for(std::move(gas), options.strategy)),
        display_(stdout, in_place_, in_place_ && std::getenv("NO_COLOR") == nullptr),
        grid_(grid_size(options, in_place_)),
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
    // The velocity autocorrelation (--vacf, lesson 16) on the same hook, with
    // the others if there are any; nothing of it without --vacf.
    if (options.vacf_path) {
      vacf_.emplace(control_.gas);
      std::vector<CollisionObserver*> all;
      if (statistics_) all.push_back(&*statistics_);
      if (lyapunov_) all.push_back(&*lyapunov_);
      all.push_back(&*vacf_);
      observers_.emplace(all);
      control_.observer =
          all.size() == 1 ? &*vacf_ : static_cast<CollisionObserver*>(&*observers_);
    }
    // Drawn in place: the frame fits the window, and fits it again when it
    // changes size (resize()).
    if (const auto size = terminal_size(); in_place_ && size)
      display_.fit_window(size->columns, size->rows);
    if (in_place_) install_resize_flag();
    choose_table_drawing();
    // Keys typed live: the line under the table says which.
    if (keyboard_) display_.keys_below(key_line_forms(options.mode == ScreenMode::stats));
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
      if (in_place_ && take_resize()) resize();  // stage 3 again, at the new size

      // Stage 7: the keys of this tick; E ends the run.
      const std::string pressed = keys.take(control_.stopped);
      if (!press_all(pressed)) break;
      if (control_.stopped) {
        // No step. On a terminal the status line shows what a key did;
        // printed whole, the ticks are counted, to be marked by one line.
        if (keys.from_keyboard() || in_place_) {
          if (!pressed.empty()) show(figures_of(control_));
        } else {
          ++stopped_ticks_;
        }
        if (keys.wait_while_stopped()) continue;
        break;  // nothing could start the model again
      }
      mark_stopped_ticks();

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
    mark_stopped_ticks();
    display_.finish();
    if (vacf_) vacf_->catch_up(control_.gas);  // the readings due by the end
    outputs_.finish(control_.gas, statistics_ ? &*statistics_ : nullptr,
                    vacf_ ? &*vacf_ : nullptr);
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

  // Printed whole, a stretch of ticks in which the model stood stopped
  // (keys of --keys or --step lines) is marked by one line: the status line
  // of the gas as it stands, and how many ticks.
  void mark_stopped_ticks() {
    if (stopped_ticks_ == 0) return;
    if (options_.drawn) {
      display_.status_only(
          fmt::format("{} [stopped {} tick{}]",
                      status_line(figures_of(control_), options_.mode, false),
                      stopped_ticks_, stopped_ticks_ == 1 ? "" : "s"));
    }
    stopped_ticks_ = 0;
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
    choose_table_drawing();
    display_.invalidate();
  }

  // For the balls and trails screens, the images or, when a character cell
  // holds more than one centre, the density in shades (beyond/density_picture.hpp),
  // counted afresh on each screen stage 3 prepares.
  void choose_table_drawing() {
    density_.reset();
    if (draws_table(options_) &&
        table_drawing_for(control_.gas, screen_) == TableDrawing::shades)
      density_.emplace(control_.gas, screen_);
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
    if (grid_.too_small) {  // until the window grows: a notice, no frame
      display_.notice({"window", "too", "small:", "at", "least",
                       fmt::format("{} x {}", smallest_columns, smallest_rows + 2)});
      return;
    }
    const Tone& tone = density_ ? shades_tone : tones[control_.tone];
    if (options_.trace) {
      fmt::print("stage 6  output: the {} screen{}{}\n", mode_name(options_.mode),
                 density_ ? fmt::format(" in shades ({:.4g} centres a character cell)",
                                        density_->mean())
                          : "",
                 at_collision ? fmt::format(", frozen at the collision T = TC = {}",
                                            control_.gas.time)
                              : "");
    }
    switch (options_.mode) {
      case ScreenMode::balls:
      case ScreenMode::trails:
        draw_table(screen_, options_.mode, control_.picture, control_.gas.time,
                   control_.gas.radius, tone, density_ ? &*density_ : nullptr);
        break;
      case ScreenMode::stats:
        draw_kinetic_figures(
            screen_, figures,
            kinetic ? *kinetic
                    : kinetic_figures(control_.gas, *statistics_, figures.energy),
            lyapunov_lines(control_.gas, lyapunov_->measured(control_.gas)));
        break;
    }
    // Colour for a table's glyphs; none on a screen of figures.
    display_.show(screen_, status_line(figures, options_.mode, control_.stopped),
                  options_.mode == ScreenMode::stats ? nullptr : &tone);
    if (options_.trace) trace_decision(control_, stdout);
  }

  const Options& options_;
  bool terminal_;     // frames shown on a terminal, in real time and with no frame limit
  bool in_place_;     // ... drawn in place with escapes (not a dumb terminal)
  PictureRule rule_;  // pictures at every collision, or at display steps only
  bool keyboard_;     // keys typed live on the keyboard
  Control control_;
  Display display_;
  GridSize grid_;
  std::optional<long long> frame_limit_;
  RunOutputs outputs_;
  StepKeeps keeps_;  // what a display step keeps: the centres, the collisions
  std::optional<GasStatistics> statistics_;      // for --mode stats, --csv, --structure
  std::optional<LyapunovExponent> lyapunov_;     // with them (lesson 15)
  std::optional<VelocityAutocorrelation> vacf_;  // for --vacf (lesson 16)
  std::optional<ObserverList> observers_;        // all of them on stage 7's hook
  long long stopped_ticks_ = 0;  // printed whole: ticks stopped, not yet marked
  TextScreen screen_;
  std::optional<DensityPicture> density_;  // the table in shades, if so drawn
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
