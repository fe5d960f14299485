// The terminal: keys without Enter, its size, and putting it back as it was.
//
// Not one of the article's stages: the article leaves the program's language
// and machine to the reader (「適当な言語で」, lessons/README.md, glossary) and
// asks for keys that act while the model runs (stage 7) and a screen of
// points (stage 3); this file gives stage 7's console loop keys without Enter
// and a screen of characters of known size on a POSIX terminal.
// Lesson: lessons/7-model-control.md (the keys).
#pragma once

#include <optional>
#include <string>

namespace gas {

bool is_terminal(int file_descriptor);

// Does the terminal understand ANSI escapes (cursor moves, colours)? Not
// when the environment's TERM is unset, empty or "dumb" (a terminal that
// can only print lines, such as Emacs' shell): frames are then printed
// whole, with no escape byte.
bool understands_escapes();

// The terminal's size in characters, if standard output is a terminal.
struct TerminalSize {
  int columns = 80;
  int rows = 24;
};
std::optional<TerminalSize> terminal_size();

// While an object of this class lives, standard input delivers every key at
// once, without echo and without waiting for Enter. The terminal's settings
// are put back when it dies, and also if the program is interrupted (Ctrl-C)
// or terminated, so that a shell is never left without echo.
class RawKeys {
 public:
  RawKeys();
  ~RawKeys();
  RawKeys(const RawKeys&) = delete;
  RawKeys& operator=(const RawKeys&) = delete;
  // The keys pressed so far, waiting at most `wait_ms` milliseconds for one.
  std::string poll(int wait_ms);

 private:
  bool active_ = false;
};

// The ways a run is asked to end from outside: Ctrl-C (SIGINT), `kill` and
// job schedulers (SIGTERM), a closed terminal (SIGHUP). After
// install_interrupt_flag, such a signal only raises a flag: the loop sees it
// between two steps and ends the run as E would, so every file it writes is
// left whole and the terminal is restored.
void install_interrupt_flag();
bool interrupted();
// The signal that arrived (SIGINT, SIGTERM or SIGHUP), or 0.
int interrupting_signal();
// "SIGINT", "SIGTERM", "SIGHUP".
const char* signal_name(int signal);

// The window's size changed (SIGWINCH): after install_resize_flag, true once
// for every change since the last call (several changes count as one).
void install_resize_flag();
bool take_resize();

}  // namespace gas
