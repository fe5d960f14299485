// Where the keys of each tick of the main loop come from.
//
// Serves stage 7 of the article, "model control": while the model runs, a
// key pressed makes it do something (「押せば何らかの操作をさせられる」);
// the article does not say how a key is read, and gives no program text
// (lessons/README.md, glossary). Ours has three sources of keys — the
// keyboard, pressed without Enter; a script given with --keys, one key per
// tick; and with --step, the line typed before each Enter — and the loop
// asks this one object, whichever it is.
// Lesson: lessons/7-model-control.md ("Aside: the program around the loop")
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "program/options.hpp"
#include "program/terminal.hpp"

namespace gas {

// The keys for the main loop: the script's (--keys), the Enter lines' (--step)
// and, on an interactive terminal, the keyboard's. While it lives with the
// keyboard, the terminal delivers keys at once and without echo.
class KeySource {
 public:
  // The sources `options` name; the keyboard too if `keyboard` (the program
  // runs on a terminal with no --keys and no --step).
  KeySource(const Options& options, bool keyboard);

  // The keys of this tick, in the order pressed: those left from the last
  // step, then the script's next key, or what was typed (waiting up to a
  // tenth of a second for a key while the model is stopped).
  std::string take(bool stopped);

  // Are the keys typed live on the keyboard (so that a stopped model is
  // drawn again after each key)?
  bool from_keyboard() const { return keyboard_.has_value(); }

  // While the model is stopped: can a key still come that starts it again?
  // The keyboard: yes; the script: while it has keys left; --step: waits for
  // the next line. False ends the run.
  bool wait_while_stopped();

  // After a display step of `share_of_frame` frames (its T1 / T0): --step
  // waits for Enter, and the keyboard waits until the step's share of a
  // frame has passed since the last frame (computing and drawing included),
  // keeping the keys typed meanwhile. False at the end of --step's input.
  bool wait_after_step(double share_of_frame);

 private:
  // --step: waits for Enter; the line typed before it holds keys. False at the
  // end of the input.
  bool read_enter_line();

  std::optional<std::string> script_;  // --keys
  std::size_t next_in_script_ = 0;     // the script's next key
  bool enter_lines_ = false;           // --step
  std::optional<RawKeys> keyboard_;
  std::string pending_;  // keys pressed and not yet carried out
  std::chrono::steady_clock::time_point next_frame_;  // when the next frame is due
};

}  // namespace gas
