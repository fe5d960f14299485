// Where the keys of each tick come from. See key_source.hpp.
#include "program/key_source.hpp"

#include <chrono>
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
    : script_(options.keys),
      enter_lines_(options.step),
      next_frame_(std::chrono::steady_clock::now()) {
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
    // The frame's moment on a steady clock: its share of a frame after the
    // last one, so that the time spent computing and drawing counts as part
    // of the wait. A frame that took longer than its share starts the clock
    // afresh (no hurrying to catch up).
    using namespace std::chrono;
    const auto now = steady_clock::now();
    next_frame_ += duration_cast<steady_clock::duration>(
        duration<double>(frame_seconds * share_of_frame));
    if (next_frame_ < now) next_frame_ = now;
    const auto wait_ms = duration_cast<milliseconds>(next_frame_ - now).count();
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
