// The lines of --events, "T,K,N1,N2", written fast: one collision's line put
// straight into a buffer of characters, with no format string read and no
// check of the buffer's room at each character.
//
// Beyond the article: its program kept no record of the collisions. The
// line's text is exactly fmt's "{},{},{},{}" of (TC, K, N1, N2): T in the
// fewest digits that read back to the same double (shortest round-trip), laid
// out as fmt lays out "{}" (fixed from 1e-4 up to below 1e16, else with an
// exponent). A line costs about a third of what fmt's compiled format did,
// which made --events a fifth of a collision at N = 10^3 (issue 22).
// Lesson: lessons/7-model-control.md; the format: README.md ("The program").
#pragma once

#include <cstddef>

#include "stage4_first_collision.hpp"

namespace gas {

// The room one line needs: T takes at most 24 characters, the three
// integers at most 11 each, with three commas and the newline (62); the
// writing may put up to 24 characters of no meaning after a number's
// digits, which the next field or line writes over.
inline constexpr std::size_t longest_event_line = 96;

// Writes collision `c`'s line, newline included, at `out`, which has room
// for longest_event_line characters. Returns the end of the line (what
// follows it there may be overwritten).
char* write_event_line(char* out, const Collision& c);

}  // namespace gas
