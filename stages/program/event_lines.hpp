// The lines of --events, "T,K,N1,N2", written fast: one collision's line put
// straight into a buffer of characters, with no format string read and no
// check of the buffer's room at each character.
//
// Beyond the article: its program kept no record of the collisions. The
// line's text is exactly fmt's "{},{},{},{}" of (TC, K, N1, N2): T in the
// fewest digits that read back to the same double (shortest round-trip), laid
// out as fmt lays out "{}" (fixed from 1e-4 up to below 1e16, else with an
// exponent). A line costs some 470 instructions where fmt's compiled
// format of the whole line takes some 600, and fmt's "{}" for T with this
// file's integers some 590 (callgrind, data/large-1000.scene to T = 200,
// fmt 9.1): at N = 10^3, where a collision is some 2830 instructions,
// --events adds a sixth of a collision instead of a fifth.
// Lesson: lessons/11-memory.md ("The line of --events"); the format:
// README.md ("The program").
//
// Assumptions: fmt's shortest digits are taken from fmt's own Dragonbox
// (fmt::detail, not fmt's public API) only for the versions of fmt this was
// built and checked with, 9.1 to 12.1 (CMakeLists.txt); with any other,
// fmt's public format_to writes the same text, more slowly.
#pragma once

#include <cstddef>

#include "stage4_first_collision.hpp"

namespace gas {

// The room one line needs. The line itself is at most 61 characters: T at
// most 24, the three integers at most 11 each, three commas and the
// newline. But a number's digits are placed by a copy of a fixed size (24
// characters, however many digits it has: no loop), whose characters past
// the digits mean nothing and are written over by what follows. N2, the
// last number, starts at most 49 characters in (after its sign), so the
// writing reaches at most 74; the room asked for is 96.
inline constexpr std::size_t longest_event_line = 96;

// Writes collision `c`'s line, newline included, at `out`, which has room
// for longest_event_line characters. Returns the end of the line (what
// follows it there may be overwritten).
char* write_event_line(char* out, const Collision& c);

}  // namespace gas
