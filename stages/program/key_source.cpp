// Where the keys of each tick come from. See key_source.hpp.
#include "program/key_source.hpp"

#include <cmath>
#include <iostream>
#include <utility>

namespace gas {
namespace {

// Real-time pacing on a terminal: one display step T0 per frame, 25 frames a
// second; a shorter step (up to a collision) takes its share of a frame.
constexpr double frame_seconds = 0.04;

// How long a stopped model waits for a key before the loop goes round again.
constexpr int stopped_wait_ms = 100;

}  // namespace

KeySource::KeySource(const Options& options, bool keyboard)
    : script_(options.keys), enter_lines_(options.step) {
  if (keyboard) keyboard_.emplace();
}

std::string KeySource::take(bool stopped) {
  if (script_) {
    if (next_in_script_ < script_->size()) pending_ += (*script_)[next_in_script_++];
  } else if (keyboard_) {
    pending_ += keyboard_->poll(stopped ? stopped_wait_ms : 0);
  }
  return std::exchange(pending_, std::string());
}

bool KeySource::wait_while_stopped() {
  if (keyboard_) return true;  // the next take() waits for a key
  if (script_ && next_in_script_ < script_->size()) return true;
  return enter_lines_ && read_enter_line();
}

bool KeySource::wait_after_step(double share_of_frame) {
  if (enter_lines_ && !read_enter_line()) return false;
  if (keyboard_) {
    const long wait_ms = std::lround(1000 * frame_seconds * share_of_frame);
    pending_ += keyboard_->poll(static_cast<int>(wait_ms));
  }
  return true;
}

bool KeySource::read_enter_line() {
  std::string line;
  if (!std::getline(std::cin, line)) return false;
  pending_ += line;
  return true;
}

}  // namespace gas
