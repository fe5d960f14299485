// Stage 6 — output to the screen.
//
// What this stage does: shows what we want to know of the gas (the article:
// it depends on 「われわれが何を知りたいか」) on the text screen of stage 3,
// in one of the article's three ways — the moving balls (erase each old
// image, draw the new one), their trajectories (a segment from each old
// centre to the new one, nothing erased), or a character screen of figures
// (no drawing at all) — and sends the screen to the terminal.
// Article: "Gas on the display", stage 6, "output to the screen".
// Lesson: lessons/6-output.md
//
// Assumptions: a terminal that understands ANSI escapes when frames are
// drawn in place (the program decides: stages/program/console.cpp); plain
// text frames otherwise.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

#include "stage1_data.hpp"
#include "stage3_screen.hpp"
#include "stage5_new_coordinates.hpp"

namespace gas {

// The three screens of the article.
enum class ScreenMode { balls, trails, stats };

const char* mode_name(ScreenMode mode);

// The base colour's tone: the B key changes it, so that the reversed run
// looks different from the forward one.
// [anchor: tone]
struct Tone {
  char ball_glyph;   // a ball's image
  char trail_glyph;  // a trajectory segment
  int ansi_colour;   // the ANSI foreground colour, when colour is on
};
inline constexpr Tone tones[2] = {{'O', '.', 36}, {'@', '+', 33}};
// [/anchor: tone]

// The cells of a ball's image centred at `centre`: every cell whose middle is
// within a of the centre, and always the centre's own cell (a ball smaller
// than a character is one glyph).
// [anchor: ball-image-declaration]
std::vector<Cell> ball_image(const TextScreen& screen, Point centre, double radius);
// [/anchor: ball-image-declaration]

// Balls screen: erase every old image (RS), then draw every new one.
void draw_balls(TextScreen& screen, const Picture& picture, double radius,
                const Tone& tone);

// Trajectories screen: a segment from each old centre to its new centre.
void draw_trails(TextScreen& screen, const Picture& picture, const Tone& tone);

// The figures the article's third screen can print, each a property of the
// gas now (and the heading above every frame).
struct Figures {
  double time = 0;                // T
  double display_step = 0;        // T0
  long long wall_collisions = 0;  // K = 1 and K = 2 so far
  long long ball_collisions = 0;  // K = 3 so far
  std::size_t balls = 0;          // N
  double mean_speed = 0;          // mean of |v|, "the mean speed for example"
  double energy = 0;              // kinetic energy, unit mass
  double energy_drift = 0;        // (E - E at start) / E at start; 0 if E at start is 0
  Point momentum;                 // total momentum, unit mass
};

Figures measure(const Gas& gas, double starting_energy, long long wall_collisions,
                long long ball_collisions);

// Writes `text` from column 2 of `row`, cut at the border.
void write_text(TextScreen& screen, int row, const std::string& text);

// Statistics screen: wipes the inside and writes the lines of figures at
// fixed places, one a row from the top, as far as the screen has room. What
// the lines say is the caller's (the program shows kinetic theory's figures,
// stages/beyond/kinetic_screen.hpp).
void draw_figures(TextScreen& screen, const std::vector<std::string>& lines);

// The one-line heading above every frame.
std::string status_line(const Figures& figures, ScreenMode mode, bool stopped);

// The words of a notice fitted to a window `columns` wide and `rows` high:
// as many words a line as fit, a word never split (a size "8 x 7" is one
// word) unless it alone is wider than the window; when the lines are more
// than `rows`, words are left out from the front, so that the last ones,
// which say the most (the size wanted), stay. 0 columns or rows: no limit.
std::vector<std::string> fit_words(const std::vector<std::string>& words, int columns,
                                   int rows);

// Sends frames to standard output. Drawn in place (a terminal that
// understands ANSI escapes): only the characters that changed are sent, the
// table's ball and trail glyphs in colour when `colour`, and nothing outside
// the window. Not in place (a file, a pipe, a terminal whose TERM is dumb):
// every frame in full, headed by its status line, with no escape at all.
class Display {
 public:
  Display(std::FILE* out, bool in_place, bool colour)
      : out_(out), in_place_(in_place), colour_(colour) {}
  // Sends `screen` under its `status` line. `tone`: the tone of a table,
  // whose ball and trail glyphs inside the border are coloured; none for a
  // screen of figures, where a '.' or a '+' is part of a number or a word.
  void show(const TextScreen& screen, const std::string& status, const Tone* tone);
  // A status line with no frame, for ticks in which the model stood
  // stopped and nothing moved: printed whole, the line alone; drawn in
  // place, nothing (the frame's own status line says "[stopped]").
  void status_only(const std::string& status);
  // A line under every frame from now on, saying the keys: the first of
  // `forms` that fits the window's width (else the last, cut). Drawn in
  // place, it takes the row under the frame (a frame taller than the window
  // is cut to leave it the window's last row); printed whole, it follows
  // each frame. No forms: no line.
  void keys_below(std::vector<std::string> forms);
  // Forget what the terminal shows, so that the next frame is drawn whole.
  void invalidate() {
    shown_.clear();
    notice_.clear();
  }
  // The terminal's window is `columns` x `rows` characters: from now on every
  // line is cut at its right edge, and lines below it are left out (the
  // frame's own size does not change). The frame is drawn whole next time.
  void fit_window(int columns, int rows);
  // Drawn in place: a clear screen with `words` alone at the top, fitted to
  // the window by fit_words (sent once, until a frame or invalidate());
  // printed whole: the words on one line.
  void notice(const std::vector<std::string>& words);
  void bell();
  // Drawn in place: the key line wiped, the cursor below the last frame (or
  // on the wiped line) and shown again.
  void finish();

 private:
  void cut_to_window(std::string& line) const;  // at the window's right edge
  std::string key_line() const;                 // the form that fits, cut
  // The escapes and characters that turn what the terminal shows into
  // `frame` (status line first), colouring the glyphs of `tone` in the
  // rows and columns of `table` (the frame's cells inside the border).
  std::string changes(const std::vector<std::string>& frame, const Tone* tone,
                      Cell table_end);

  std::FILE* out_;
  bool in_place_;
  bool colour_;
  int window_columns_ = 0;          // the window's width; 0: no limit
  int window_rows_ = 0;             // the window's height; 0: no limit
  std::vector<std::string> keys_;   // the key line's forms, widest first
  std::vector<std::string> shown_;  // what the terminal shows now, status line first
  std::string notice_;              // the notice the terminal shows now, if any
  std::size_t notice_rows_ = 0;     // its rows
  bool keys_shown_ = false;         // is the key line on the terminal?
};

}  // namespace gas
