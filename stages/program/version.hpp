// `gas --version`: the program's name, its version and the commit it is
// built from.
//
// Not one of the article's stages: the conventions of a command-line
// program. The version is CMake's project(... VERSION ...); the commit
// is asked of git at every build (version_info.cmake).
// Lesson: lessons/7-model-control.md (the command line); the reference:
// README.md ("Installing") and `man gas`.
#pragma once

#include <string>

namespace gas {

// The project's version, "MAJOR.MINOR.PATCH" (CMakeLists.txt's project()).
extern const char* const program_version;
// `git describe --always --dirty` of the checkout built, e.g. "f0385bc0e1a2"
// or "f0385bc0e1a2-dirty"; "unknown" when built without git or outside a
// checkout (from a tarball, say).
extern const char* const program_commit;

// The text of --version: "gas VERSION (...)" and a line with the commit.
std::string version_text();

}  // namespace gas
