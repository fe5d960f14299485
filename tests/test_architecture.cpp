// The house: stages/ holds the article's seven stages, one .hpp/.cpp pair
// each, and two folders, beyond/ (what goes past the article) and program/
// (the console around the stages). Dependencies run one way:
//
//   stage N     includes only stage1 ... stageN (the model and earlier stages),
//               never beyond/ or program/;
//   beyond/     includes stages and beyond/, never program/;
//   program/    includes anything.
//
// This file reads the #include lines of every file under stages/ and fails,
// naming the file and line, when one breaks the rule. (The checker is also
// run on made-up files that break each rule, so that a checker that never
// complains fails too.)
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "support.hpp"

namespace {

namespace fs = std::filesystem;
using gas::testing::read_file;
using gas::testing::source_path;

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += "\n  " + line;
  return text;
}

// The number of a core stage file, "stage4_first_collision.hpp" -> 4.
std::optional<int> stage_number(const std::string& name) {
  static const std::regex stage(R"(^stage([1-7])_[a-z0-9_]+\.(hpp|cpp)$)");
  std::smatch match;
  if (!std::regex_match(name, match, stage)) return std::nullopt;
  return std::stoi(match[1]);
}

// The problems with the project's own includes of one file, as
// "FILE:LINE: what is wrong". `file` is its path from the top, e.g.
// "stages/stage7_control.hpp" or "stages/beyond/cell_grid.cpp".
std::vector<std::string> include_problems(const std::string& file,
                                          const std::string& text) {
  static const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
  const fs::path path(file);
  const std::string folder = path.parent_path().generic_string();
  const std::optional<int> own_stage = stage_number(path.filename().string());
  std::vector<std::string> problems;
  int number = 0;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    std::smatch match;
    if (!std::regex_search(line, match, include)) continue;
    const std::string target = match[1];
    const bool to_beyond = target.rfind("beyond/", 0) == 0;
    const bool to_program = target.rfind("program/", 0) == 0;
    if (folder == "stages") {
      // A core stage: only the model and earlier stages.
      const std::optional<int> their_stage = stage_number(target);
      if (to_beyond || to_program) {
        problems.push_back(
            fmt::format("{}:{}: a core stage includes \"{}\": the stages never use {}",
                        file, number, target, to_beyond ? "beyond/" : "program/"));
      } else if (!their_stage) {
        problems.push_back(
            fmt::format("{}:{}: includes \"{}\", which is not one of the seven stages",
                        file, number, target));
      } else if (own_stage && *their_stage > *own_stage) {
        problems.push_back(fmt::format(
            "{}:{}: stage {} includes stage {} (\"{}\"): a stage uses only earlier ones",
            file, number, *own_stage, *their_stage, target));
      }
    } else if (folder == "stages/beyond" && to_program) {
      problems.push_back(fmt::format(
          "{}:{}: beyond/ includes \"{}\": what goes past the article never needs "
          "the program",
          file, number, target));
    }
  }
  return problems;
}

// Every .hpp and .cpp under stages/, as paths from the top.
std::vector<std::string> source_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(source_path("stages"))) {
    const std::string extension = entry.path().extension().string();
    if (entry.is_regular_file() && (extension == ".hpp" || extension == ".cpp"))
      files.push_back(fs::relative(entry.path(), source_path("")).generic_string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

TEST_SUITE("architecture") {
  TEST_CASE("architecture: stages/ shows the seven stages, beyond/ and program/") {
    std::set<std::string> found;
    for (const auto& entry : fs::directory_iterator(source_path("stages")))
      found.insert(entry.path().filename().string() + (entry.is_directory() ? "/" : ""));
    const std::set<std::string> expected = {"stage1_data.hpp",
                                            "stage1_data.cpp",
                                            "stage2_input.hpp",
                                            "stage2_input.cpp",
                                            "stage3_screen.hpp",
                                            "stage3_screen.cpp",
                                            "stage4_first_collision.hpp",
                                            "stage4_first_collision.cpp",
                                            "stage5_new_coordinates.hpp",
                                            "stage5_new_coordinates.cpp",
                                            "stage6_output.hpp",
                                            "stage6_output.cpp",
                                            "stage7_control.hpp",
                                            "stage7_control.cpp",
                                            "beyond/",
                                            "program/"};
    std::vector<std::string> extra, missing;
    std::set_difference(found.begin(), found.end(), expected.begin(), expected.end(),
                        std::back_inserter(extra));
    std::set_difference(expected.begin(), expected.end(), found.begin(), found.end(),
                        std::back_inserter(missing));
    CHECK_MESSAGE(extra.empty(),
                  "in stages/ but not one of the seven stages or the two "
                  "folders:"
                      << joined(extra));
    CHECK_MESSAGE(missing.empty(), "missing from stages/:" << joined(missing));
  }

  TEST_CASE("architecture: dependencies run one way (core <- beyond <- program)") {
    std::vector<std::string> problems;
    const std::vector<std::string> files = source_files();
    for (const std::string& file : files) {
      for (const std::string& problem :
           include_problems(file, read_file(source_path(file))))
        problems.push_back(problem);
    }
    CHECK_MESSAGE(problems.empty(),
                  "includes against the house's rule:" << joined(problems));
    MESSAGE(fmt::format("{} files under stages/ checked", files.size()));
    CHECK(files.size() > 14);  // the seven pairs, and more
  }

  TEST_CASE("architecture: the checker complains about each kind of wrong include") {
    // A core stage that uses beyond/ or program/.
    CHECK(include_problems("stages/stage7_control.hpp",
                           "#include \"beyond/strategy.hpp\"\n")
              .size() == 1);
    CHECK(include_problems("stages/stage6_output.cpp",
                           "#include <vector>\n\n#include \"program/terminal.hpp\"\n")
              .at(0)
              .rfind("stages/stage6_output.cpp:3: ", 0) == 0);
    // A stage that uses a later one.
    CHECK(include_problems("stages/stage4_first_collision.hpp",
                           "#include \"stage7_control.hpp\"\n")
              .size() == 1);
    // beyond/ that uses the program.
    CHECK(include_problems("stages/beyond/cell_grid.cpp",
                           "#include \"program/console.hpp\"\n")
              .size() == 1);
    // And what is allowed passes: earlier stages in a stage, anything in
    // beyond/ but the program, anything in program/.
    CHECK(include_problems("stages/stage7_control.hpp",
                           "#include <memory>\n#include \"stage1_data.hpp\"\n"
                           "#include \"stage7_control.hpp\"\n")
              .empty());
    CHECK(include_problems("stages/beyond/cell_grid.hpp",
                           "#include \"beyond/large_pages.hpp\"\n"
                           "#include \"stage4_first_collision.hpp\"\n")
              .empty());
    CHECK(include_problems("stages/program/console.cpp",
                           "#include \"beyond/strategy.hpp\"\n"
                           "#include \"program/terminal.hpp\"\n")
              .empty());
  }
}  // TEST_SUITE
