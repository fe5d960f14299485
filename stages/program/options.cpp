// The command line of `gas`. See options.hpp.
#include "program/options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string_view>

#include "stage3_screen.hpp"

namespace gas {
namespace {

// A whole number; one written right but beyond what a long long holds is
// said to be too large (the option takes at most `most`) or too small.
long long whole_number(const std::string& option, const std::string& text,
                       long long most = std::numeric_limits<long long>::max()) {
  std::size_t used = 0;
  long long value = 0;
  try {
    value = std::stoll(text, &used);
  } catch (const std::out_of_range&) {
    throw UsageError(text.starts_with('-') ? fmt::format("{} {}: too small", option, text)
                                           : fmt::format("{} {}: too large (at most {})",
                                                         option, text, most));
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
  } catch (const std::out_of_range&) {
    // Beyond a double's largest, or nearer to zero than its smallest.
    if (std::fabs(std::strtod(text.c_str(), nullptr)) > 1) {
      throw UsageError(fmt::format("{} {}: too large (a double holds none beyond +-{:g})",
                                   option, text, std::numeric_limits<double>::max()));
    }
    throw UsageError(
        fmt::format("{} {}: too near zero (a double holds none nearer than {:g})", option,
                    text, std::numeric_limits<double>::denorm_min()));
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || text.empty() || !std::isfinite(value)) {
    throw UsageError(fmt::format("{} takes a finite number, not '{}'", option, text));
  }
  return value;
}

// The command line, read one argument at a time. An option's value is either
// attached to it ("--frames=5") or the argument after it ("--frames 5").
class ArgumentReader {
 public:
  explicit ArgumentReader(const std::vector<std::string>& arguments)
      : arguments_(arguments) {}

  // Moves to the next argument; false when none is left.
  bool next() {
    if (next_ >= arguments_.size()) return false;
    name_ = arguments_[next_++];
    attached_.reset();
    if (name_.rfind("--", 0) == 0) {
      if (const auto equals = name_.find('='); equals != std::string::npos) {
        attached_ = name_.substr(equals + 1);
        name_.resize(equals);
      }
    }
    return true;
  }

  // The argument without its attached value: an option's name, or a scene.
  const std::string& name() const { return name_; }

  // The option's value: the attached one, else the next argument.
  std::string value() {
    if (attached_) return *attached_;
    if (next_ >= arguments_.size())
      throw UsageError(fmt::format("{} needs a value", name_));
    return arguments_[next_++];
  }

  // A flag takes no value: an attached one is refused.
  void no_value() const {
    if (attached_) throw UsageError(fmt::format("{} takes no value", name_));
  }

 private:
  const std::vector<std::string>& arguments_;
  std::size_t next_ = 0;                 // the first argument not yet read
  std::string name_;                     // the argument being read
  std::optional<std::string> attached_;  // its "=value", if any
};

// Reads one option (its value, if it takes one) into the options.
using OptionReader = void (*)(ArgumentReader&, Options&);

// A flag: --step, --trace, --bell, --help, --version.
template <bool Options::*flag>
void read_flag(ArgumentReader& reader, Options& options) {
  reader.no_value();
  options.*flag = true;
}

// The name of a file to write: --events, --dump, --csv, --structure.
template <std::optional<std::string> Options::*path>
void read_path(ArgumentReader& reader, Options& options) {
  options.*path = reader.value();
  if ((options.*path)->empty())
    throw UsageError(
        fmt::format("{} takes a file name, not an empty one", reader.name()));
}

// --keys KEYS: one key a display step, each a key of the keyboard's (upper or
// lower case) or '.' for none; nothing else.
void read_keys(ArgumentReader& reader, Options& options) {
  const std::string keys = reader.value();
  const std::string_view known = "SRB><0EA.";
  for (const char key : keys) {
    const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(key)));
    if (known.find(upper) == std::string_view::npos) {
      throw UsageError(fmt::format(
          "--keys takes the keys S R B > < 0 E A (upper or lower case) and '.' for none, "
          "not '{}'",
          key));
    }
  }
  options.keys = keys;
}

// --frames N: a whole number of display steps, not negative.
void read_frames(ArgumentReader& reader, Options& options) {
  const std::string text = reader.value();
  const long long frames = whole_number(reader.name(), text);
  if (frames < 0)
    throw UsageError(fmt::format("--frames must not be negative, not {}", frames));
  options.frames = frames;
}

// --until T: a moment of model time, not negative.
void read_until(ArgumentReader& reader, Options& options) {
  const std::string text = reader.value();
  const double until = real_number(reader.name(), text);
  if (until < 0)
    throw UsageError(fmt::format("--until must not be negative, not {}", until));
  options.until = until;
}

// --mode M: one of the three screens of stage 6, or none.
void read_mode(ArgumentReader& reader, Options& options) {
  const std::string name = reader.value();
  options.drawn = name != "none";
  if (!options.drawn) return;
  for (const ScreenMode mode :
       {ScreenMode::balls, ScreenMode::trails, ScreenMode::stats}) {
    if (name == mode_name(mode)) {
      options.mode = mode;
      return;
    }
  }
  throw UsageError(
      fmt::format("--mode takes balls, trails, stats or none, not '{}'", name));
}

// --cols N, --rows N: the screen's size in characters, from `smallest` to 10000.
template <std::optional<int> Options::*size, int smallest>
void read_screen_size(ArgumentReader& reader, Options& options) {
  const std::string text = reader.value();
  const long long value = whole_number(reader.name(), text, 10000);
  if (value < smallest || value > 10000) {
    throw UsageError(fmt::format("{} takes a number from {} to 10000, not {}",
                                 reader.name(), smallest, value));
  }
  options.*size = static_cast<int>(value);
}

// --strategy S: how stage 4 finds the first collision.
void read_strategy(ArgumentReader& reader, Options& options) {
  const std::string name = reader.value();
  options.strategy = strategy_named(name);
  if (!options.strategy)
    throw UsageError(fmt::format("--strategy takes scan, table or grid, not '{}'", name));
}

// --pictures P: where pictures are taken.
void read_pictures(ArgumentReader& reader, Options& options) {
  const std::string name = reader.value();
  options.pictures = picture_rule_named(name);
  if (!options.pictures) {
    throw UsageError(fmt::format("--pictures takes collisions or steps, not '{}'", name));
  }
}

// Every option of the command line, and how it is read.
struct KnownOption {
  std::string_view name;
  OptionReader read;
};
constexpr KnownOption known_options[] = {
    {"--frames", read_frames},
    {"--until", read_until},
    {"--keys", read_keys},
    {"--mode", read_mode},
    {"--events", read_path<&Options::events_path>},
    {"--dump", read_path<&Options::dump_path>},
    {"--csv", read_path<&Options::csv_path>},
    {"--structure", read_path<&Options::structure_path>},
    {"--vacf", read_path<&Options::vacf_path>},
    {"--cols", read_screen_size<&Options::columns, smallest_columns>},
    // The screen's rows and two more: the status line, and the cursor below.
    {"--rows", read_screen_size<&Options::rows, smallest_rows + 2>},
    {"--strategy", read_strategy},
    {"--pictures", read_pictures},
    {"--step", read_flag<&Options::step>},
    {"--trace", read_flag<&Options::trace>},
    {"--bell", read_flag<&Options::bell>},
    {"--help", read_flag<&Options::help>},
    {"-h", read_flag<&Options::help>},
    {"--version", read_flag<&Options::version>},
};

// The named option, or none for a name that is no option's.
const KnownOption* option_named(const std::string& name) {
  for (const KnownOption& option : known_options) {
    if (option.name == name) return &option;
  }
  return nullptr;
}

// An argument that is no option's name: the scene, or a mistyped option.
void read_scene_path(const std::string& argument, Options& options) {
  if (argument.size() > 1 && argument[0] == '-')
    throw UsageError(fmt::format("unknown option '{}'", argument));
  if (argument.empty())
    throw UsageError("an empty scene name: give a scene file or a teaching scene's name");
  if (options.scene_path) {
    throw UsageError(
        fmt::format("one scene only: '{}' and '{}'", *options.scene_path, argument));
  }
  options.scene_path = argument;
}

}  // namespace

Options parse_options(const std::vector<std::string>& arguments) {
  Options options;
  ArgumentReader reader(arguments);
  // An option given twice is refused, whatever its values: which one would
  // count is not for the reader to guess (-h is --help).
  std::vector<std::string_view> given;
  while (reader.next()) {
    if (const KnownOption* option = option_named(reader.name())) {
      const std::string_view name = option->name == "-h" ? "--help" : option->name;
      if (std::find(given.begin(), given.end(), name) != given.end())
        throw UsageError(fmt::format("{} is given twice", name));
      given.push_back(name);
      option->read(reader, options);
    } else {
      read_scene_path(reader.name(), options);
    }
  }
  if (options.frames && options.until)
    throw UsageError("--frames and --until exclude each other");
  if (!options.drawn && !options.frames && !options.until)
    throw UsageError("--mode none draws nothing: give it --until or --frames");
  return options;
}

std::string help_text() {
  return R"(gas - the billiard-ball gas of "Gas on the display" (1989), in a terminal

usage: gas [SCENE] [--frames N | --until T] [--keys KEYS]
           [--mode balls|trails|stats|none] [--events FILE] [--dump FILE]
           [--csv FILE] [--structure FILE] [--vacf FILE]
           [--cols N] [--rows N] [--step] [--trace] [--bell]
           [--strategy scan|table|grid] [--pictures collisions|steps]
       gas --help | --version

  SCENE            a scene file (format: data/README.md or `man gas`), or a
                   teaching scene's name: crowd, crowd.scene, hard/corner; a
                   name that is no file here is looked for in
                   share/gas-on-the-display beside the program's bin/ (for a
                   program in its build folder: the source tree's data/);
                   none: the built-in default scene
  --frames N       take N display steps, then exit
  --until T        run until model time T, then exit (absolute: a --dump
                   starts at its T)
  --keys KEYS      press one key per display step instead of the keyboard:
                   the keys below, or '.' for none
  --mode M         the screen: balls (moving balls), trails (trajectories),
                   stats (figures only), or none (nothing drawn: a batch run
                   for --events, --csv, --dump; needs --until or --frames);
                   default balls
  --events FILE    write every collision to FILE as CSV: T,K,N1,N2
  --dump FILE      at exit, write the gas to FILE as a scene file
  --csv FILE       write the statistics of every picture to FILE as CSV
  --structure FILE at exit, write the structure of the gas to FILE as CSV,
                   averaged like the statistics: g(r) out to r = 5a among the
                   balls of the interior, and the density of centres near the
                   walls x = 0, A1; a line per bin 0.05a wide:
                   curve,from,to,value,error (curve: pair or wall)
  --vacf FILE      at exit, write the velocity autocorrelation function of
                   the balls far from the walls to FILE as CSV, a line per
                   lag t: t,vacf,vacf_error,vacf_enskog,vacf_tail,
                   diffusion,diffusion_error,diffusion_enskog (Enskog's
                   exponential and the mode-coupling tail beside it)
  --cols N         screen width in characters (default: the terminal's,
                   else 80)
  --rows N         screen height in characters (default: the terminal's,
                   else 24)
  --step           wait for Enter after every display step (a line may
                   hold keys)
  --trace          print each stage of the article as it runs, with T, T1,
                   TC, K, N1, N2; stage 6 says when the picture is frozen at
                   a collision
  --bell           ring the terminal bell on collisions
  --strategy S     how stage 4 finds the first collision: scan (the article's),
                   table (each ball's next event) or grid (cells and an event
                   queue); the same collisions, at different speeds. Default:
                   scan up to )" +
         std::to_string(most_balls_for_scan) + R"( balls, table up to )" +
         std::to_string(most_balls_for_table) + R"(, grid beyond
  --pictures P     where pictures are taken: collisions (the article's: at
                   every collision and at least every T0) or steps (only at
                   T, T + T0, T + 2 T0, ...; the collisions between are not
                   drawn); the same collisions either way. Default: collisions
                   up to )" +
         std::to_string(most_balls_for_every_collision) +
         R"( balls, steps beyond
  --help, -h       show this text
  --version        show the program's version and the git commit it is
                   built from
An option given twice is refused.

keys (in a terminal, without Enter, in either case): S stop, R run, B reverse
  all velocities and run on (a stopped model too), > double T0, < halve T0,
  0 redraw the screen, E end; beyond the article, A restarts the averages of
  the statistics (--mode stats, --csv). A line under the table lists them.
In a terminal, a resized window gets the screen prepared again at its size
(--cols and --rows keep theirs, cut to the window); a window too small for
the table says so until it grows.
When the output is not a terminal, or TERM is dumb, every frame is printed
whole, headed by a status line, with no escape sequence; with no --frames or
--until a run into a file or a pipe stops after 100 frames (or as many as
--keys has keys, if more), and ticks in which the model stands stopped are
marked by one status line, ending [stopped N ticks].
Ctrl-C, SIGTERM and SIGHUP end the run as E does: files whole, the dump written.
Exit status: 0 success, 2 bad usage or bad scene, 1 any other failure (a file
that cannot be written, say); after a signal 128 + its number (130 for Ctrl-C,
143 for SIGTERM, 129 for SIGHUP).
)";
}

}  // namespace gas
