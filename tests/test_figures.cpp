// The pictures of lessons 12 and 13 (tests/figures/kinetic_figures.cpp) can
// still be made, each into its lesson's folder. Not a measurement:
// `gas-figures --smoke` runs every part a hundred times shorter, into a
// scratch folder, without pictures; this test checks that each part wrote its
// numbers where its lesson looks. (The real pictures are made by hand, in a
// few minutes: lessons/13-box-and-bulk.md, "Lesson 13 in pictures".)
#include <doctest/doctest.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "support.hpp"

namespace {

namespace fs = std::filesystem;
using gas::testing::lines_of;
using gas::testing::read_file;

}  // namespace

TEST_SUITE("figures") {
  TEST_CASE("gas-figures --smoke writes the numbers of every picture") {
    const gas::testing::Scratch scratch;
    const std::string command = fmt::format("'{}' --smoke --out '{}' 2>'{}'", GAS_FIGURES,
                                            scratch.path.string(), scratch.file("err"));
    REQUIRE_MESSAGE(std::system(command.c_str()) == 0, "gas-figures --smoke failed");
    // One line per area fraction, per speed bin, per bin of each curve.
    const std::vector<std::pair<std::string, std::size_t>> files = {
        {"lesson-13/eos.csv", 1 + 14},
        {"lesson-12/speeds.csv", 1 + 50},
        {"lesson-13/structure-contact.csv", 1 + 4},
        {"lesson-13/structure-0.5.csv", 1 + 60 + 200}};
    for (const auto& file : files) {
      const std::string& name = file.first;
      const std::size_t lines = file.second;
      CAPTURE(name);
      CHECK(lines_of(read_file(scratch.file(name))).size() == lines);
    }
    // H: the two runs, a line per display step (T0 = 0.25 to T = 20 and 60).
    CHECK(lines_of(read_file(scratch.file("lesson-12/h-theorem.csv"))).size() ==
          1 + 80 + 240);
  }

  TEST_CASE("gas-tail-figures --smoke writes the numbers of every picture and check") {
    // Lesson 16's pictures and checks (tests/figures/tail_figures.cpp), small
    // and short: three gases of 3000 balls, the chain of dumps over 1875.
    const gas::testing::Scratch scratch;
    const std::string command =
        fmt::format("'{}' --smoke --out '{}' 2>'{}'", GAS_TAIL_FIGURES,
                    scratch.path.string(), scratch.file("err"));
    REQUIRE_MESSAGE(std::system(command.c_str()) == 0, "gas-tail-figures --smoke failed");
    for (const char* name : {"tail-1970.csv", "tail.csv", "summary.csv",
                             "independent.csv", "independent-program.csv"}) {
      CAPTURE(name);
      CHECK(lines_of(read_file(scratch.file(name))).size() > 4);
    }
    // One line per lag of the plan in tail.csv, as in each gas's own file.
    CHECK(lines_of(read_file(scratch.file("tail.csv"))).size() ==
          lines_of(read_file(scratch.file("tail-1970.csv"))).size());
  }
}
