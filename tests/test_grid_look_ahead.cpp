// The tuned grid's look ahead (stages/beyond/grid_look_ahead.cpp) is in the
// program that users run.
//
// A prefetch changes no result: were the compiler to drop one, every other
// test would still pass, and the grid would only be slower (GCC 12 once
// judged a function that only prefetched to have no effect and dropped the
// calls to it: 10^5 balls ran 25 % slower, every test green). So this test
// reads the machine code of build/gas itself (objdump) and counts the
// prefetch instructions where the look ahead is written out: the calendar's
// one call into the grid each new day, CellGrid::KeyPlaces::new_day (and
// none in the grid's update). No loop of the look ahead is unrolled, so each prefetch of
// its source is one instruction for each place it is written out.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

// The prefetch instructions in each function of `program` whose name (as
// objdump -C writes it) starts with one of `names`; -1 for a function not
// found.
std::map<std::string, int> prefetches_in(const std::string& program,
                                         const std::vector<std::string>& names) {
  std::map<std::string, int> counts;
  for (const std::string& name : names) counts[name] = -1;
  const std::string command =
      fmt::format("objdump -d -C --no-show-raw-insn '{}' 2>/dev/null", program);
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  REQUIRE_MESSAGE(pipe != nullptr, "cannot run objdump");
  std::string function;  // the name of the function being read, if counted
  char line[4096];
  while (std::fgets(line, sizeof line, pipe.get()) != nullptr) {
    const std::string text = line;
    // A function starts with "ADDRESS <NAME>:".
    const std::size_t open = text.find(" <");
    if (open != std::string::npos && text.find(">:") != std::string::npos &&
        text.find_first_not_of("0123456789abcdef") == open) {
      function.clear();
      for (const std::string& name : names) {
        if (text.compare(open + 2, name.size(), name) == 0) {
          function = name;
          counts[name] = 0;
        }
      }
      continue;
    }
    if (!function.empty() && text.find("\tprefetch") != std::string::npos)
      ++counts[function];
  }
  return counts;
}

}  // namespace

TEST_SUITE("stage4") {
  TEST_CASE("the tuned grid's look ahead: every prefetch is in build/gas") {
    const std::string new_day = "gas::CellGrid::KeyPlaces::new_day() const";
    const std::string update = "gas::CellGrid::update(";
    const auto counts = prefetches_in(GAS_PROGRAM, {new_day, update});
    REQUIRE_MESSAGE(counts.at(new_day) >= 0, "no function "
                                                 << new_day << " in " << GAS_PROGRAM
                                                 << " (is objdump installed?)");
    // The look ahead's own 3 (a line of pages, the entries of a page's first
    // two balls); 4 days ahead, a ball's record and column of R (2: it may
    // span two cache lines): 3; 3 days ahead, a block's heads (2 a cell
    // row), the ball's own head, the partner's record, column of R and
    // calendar entry: 7; 2 days ahead, a block's first balls (a link, a
    // column of R: 3), the partner's page, its heads (2): 6; 1 day ahead, the
    // partner's first balls: 3.
    CHECK(counts.at(new_day) == 3 + 3 + 7 + 6 + 3);
    // And none elsewhere in the grid: a prediction waits for what it reads.
    CHECK(counts.at(update) == 0);
  }
}
