// The terminal. See terminal.hpp.
#include "program/terminal.hpp"

#include <poll.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <string_view>

namespace gas {
namespace {

volatile std::sig_atomic_t interrupt_arrived = 0;  // the signal's number, or 0
termios saved_settings;
volatile std::sig_atomic_t settings_saved = 0;

// What the escape sequences and termios changed, undone with calls that are
// safe inside a signal handler.
void restore_terminal() {
  if (settings_saved) tcsetattr(STDIN_FILENO, TCSANOW, &saved_settings);
}

extern "C" void on_interrupt(int signal) {
  if (interrupt_arrived == 0) interrupt_arrived = signal;  // the first one counts
}

volatile std::sig_atomic_t resize_arrived = 0;

extern "C" void on_resize(int) {
  resize_arrived = 1;
}

}  // namespace

bool is_terminal(int file_descriptor) {
  return isatty(file_descriptor) == 1;
}

bool understands_escapes() {
  const char* const term = std::getenv("TERM");
  return term != nullptr && *term != '\0' && std::string_view(term) != "dumb";
}

std::optional<TerminalSize> terminal_size() {
  winsize size{};
  if (!is_terminal(STDOUT_FILENO) || ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) != 0 ||
      size.ws_col == 0 || size.ws_row == 0) {
    return std::nullopt;
  }
  return TerminalSize{size.ws_col, size.ws_row};
}

void install_interrupt_flag() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  // While the handler runs, the other two wait. Else of two signals that
  // arrive together (Ctrl-C, then SIGTERM) the kernel would start the first
  // one's handler and then the second's on top of it, which would set the
  // flag first, and the second signal would decide.
  sigemptyset(&action.sa_mask);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&action.sa_mask, signal);
  action.sa_flags = 0;  // no SA_RESTART: a waiting poll() returns at once
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaction(signal, &action, nullptr);
}

bool interrupted() {
  return interrupt_arrived != 0;
}

int interrupting_signal() {
  return interrupt_arrived;
}

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
  }
  return "a signal";
}

void install_resize_flag() {
  struct sigaction action {};
  action.sa_handler = on_resize;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: a read that waits for --step's Enter goes on waiting (a
  // resize must not end the run); poll() returns early all the same (Linux
  // never restarts it), so the keyboard's loop redraws at once.
  action.sa_flags = SA_RESTART;
  sigaction(SIGWINCH, &action, nullptr);
}

bool take_resize() {
  if (resize_arrived == 0) return false;
  resize_arrived = 0;
  return true;
}

RawKeys::RawKeys() {
  if (!is_terminal(STDIN_FILENO) || tcgetattr(STDIN_FILENO, &saved_settings) != 0) return;
  settings_saved = 1;
  termios raw = saved_settings;
  raw.c_lflag &= ~static_cast<tcflag_t>(ICANON | ECHO);  // keys at once, not echoed
  raw.c_cc[VMIN] = 0;
  raw.c_cc[VTIME] = 0;
  active_ = tcsetattr(STDIN_FILENO, TCSANOW, &raw) == 0;
}

RawKeys::~RawKeys() {
  if (active_) restore_terminal();
  settings_saved = 0;
}

std::string RawKeys::poll(int wait_ms) {
  std::string keys;
  pollfd input{STDIN_FILENO, POLLIN, 0};
  if (::poll(&input, 1, wait_ms) <= 0 || (input.revents & POLLIN) == 0) return keys;
  char buffer[64];
  const ssize_t count = read(STDIN_FILENO, buffer, sizeof buffer);
  if (count > 0) keys.assign(buffer, static_cast<std::size_t>(count));
  return keys;
}

}  // namespace gas
