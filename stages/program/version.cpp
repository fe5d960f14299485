// `gas --version`. See version.hpp.
#include "program/version.hpp"

#include <fmt/format.h>

#include <string_view>

namespace gas {

std::string version_text() {
  const bool known = std::string_view(program_commit) != "unknown";
  return fmt::format(
      "gas {} (Gas on the display: the billiard-ball gas of Bilenkin & Yutkin, "
      "1989)\n{}\n",
      program_version,
      known ? fmt::format("commit {}", program_commit)
            : std::string("commit unknown (not built from a git checkout)"));
}

}  // namespace gas
