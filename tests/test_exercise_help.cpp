// What a student meets in a terminal when stuck on an exercise
// (lessons/exercises/): the hints one a file, so that `cat` shows one at a
// time, and a failed check on an untouched stub's NaN that says what to
// write instead of "wanted 12.5 / got nan" alone (exercise_test.hpp reads
// the stub's TODO).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <regex>
#include <string>
#include <vector>

#include "exercise_test.hpp"
#include "support.hpp"

namespace {

namespace fs = std::filesystem;
using gas::testing::read_file;
using gas::testing::source_path;

// Every exercise's folder, NN-name, in order.
std::vector<fs::path> exercise_folders() {
  std::vector<fs::path> folders;
  for (const auto& entry : fs::directory_iterator(source_path("lessons/exercises"))) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && std::regex_match(name, std::regex("[0-9]{2}-.*")))
      folders.push_back(entry.path());
  }
  std::sort(folders.begin(), folders.end());
  return folders;
}

// The stub of an exercise's folder: NN-some-name/some_name.cpp.
fs::path stub_of(const fs::path& folder) {
  std::string name = folder.filename().string().substr(3);
  std::replace(name.begin(), name.end(), '-', '_');
  return folder / (name + ".cpp");
}

}  // namespace

TEST_SUITE("lessons") {
  TEST_CASE("exercises: hints one a file each saying which of how many and where next") {
    const std::vector<fs::path> folders = exercise_folders();
    REQUIRE(folders.size() >= 11);
    for (const fs::path& folder : folders) {
      CAPTURE(folder.string());
      const std::string index = read_file((folder / "hints.md").string());
      CHECK(index.find("<details>") == std::string::npos);  // nothing hidden in one file
      std::size_t count = 0;
      for (const auto& entry : fs::directory_iterator(folder / "hints")) {
        (void)entry;
        ++count;
      }
      REQUIRE(count >= 1);
      for (std::size_t k = 1; k <= count; ++k) {
        CAPTURE(k);
        const fs::path hint = folder / "hints" / fmt::format("{}.md", k);
        REQUIRE(fs::exists(hint));
        CHECK(index.find(fmt::format("[Hint {}](hints/{}.md)", k, k)) !=
              std::string::npos);
        const std::string text = read_file(hint.string());
        CHECK(text.rfind(fmt::format("# Exercise {}, hint {} of {}\n\n",
                                     folder.filename().string().substr(0, 2), k, count),
                         0) == 0);
        if (k < count) {
          CHECK(text.find(fmt::format("]({}.md)", k + 1)) != std::string::npos);
        } else {
          CHECK(text.find("the last hint") != std::string::npos);
        }
      }
      // The command that shows the first hint, as the index gives it.
      CHECK(index.find(fmt::format("`cat lessons/exercises/{}/hints/1.md`",
                                   folder.filename().string())) != std::string::npos);
    }
  }

  TEST_CASE("exercises: a NaN from an untouched stub says what to write from its TODO") {
    int stubs_of_nan = 0;
    for (const fs::path& folder : exercise_folders()) {
      const std::string stub = read_file(stub_of(folder).string());
      if (stub.find("quiet_NaN") == std::string::npos) continue;
      ++stubs_of_nan;
      CAPTURE(folder.string());
      // The TODO's first line, as the stub has it.
      const std::size_t todo = stub.find("// TODO: ");
      REQUIRE(todo != std::string::npos);
      const std::string first_line =
          stub.substr(todo + 9, stub.find('\n', todo) - (todo + 9));
      const std::string test_file =
          (folder / ("test_" + stub_of(folder).filename().string())).string();
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const std::string said = gas::exercises::compared("inputs", 12.5, nan, test_file);
      CHECK(said.find("  wanted 12.5\n  got    nan\n") != std::string::npos);
      CHECK(said.find("NaN is \"not a number\"") != std::string::npos);
      CHECK(said.find("What to write: " + first_line) != std::string::npos);
      // A wanted NaN came from the function itself, on other input.
      CHECK(gas::exercises::compared("inputs", nan, nan, test_file)
                .find("wanted nan (your function's own answer)") != std::string::npos);
      // A number is no NaN: nothing more said.
      CHECK(gas::exercises::compared("inputs", 12.5, 12, test_file).find("NaN") ==
            std::string::npos);
    }
    CHECK(stubs_of_nan == 4);  // 01, 04, 05, 11
  }
}
