// The article's words: what the project says the article says stays exact.
//
// DEVELOPERS.md: a sentence that says what the article says, prints, orders
// or names must match the Japanese text; an inference says "our reading";
// a recurring fact is said once and pointed to. The recurring ones are said
// once in the glossary of lessons/README.md ("What the text says, and what
// is our reading"). This file keeps out, of every text file of the source
// tree, the phrases that once said more than the text does:
//
//   - "before TC" of the article's scan: the text says 「時刻 TC までに」 and
//     「TC までの時間に」, up to and including TC;
//   - "the article's program" or "code", "the article's BASIC", INKEY$: it gives
//     no program text and no language (「適当な言語で」);
//   - "the article's terminal": it names only an example graphics screen;
//   - "the article's 256 × 192": that screen is an example (「例えば」);
//   - "as in the article" of the keys' letter case, which the text never
//     mentions, and "as the article says" of a stopped model running again
//     after B, which is our reading;
//   - "Kvant" without "attribution" beside it: the text names no journal;
//   - "the article's nine columns": it names one figure, as an example.
//
// And each exercise's instructions say how many tests it has ("The nine
// tests: ..."): the number is checked against the TEST_CASEs of its file.
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <regex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "support.hpp"

namespace {

namespace fs = std::filesystem;
using gas::testing::read_file;
using gas::testing::source_path;

// ------------------------------------------------------------ the phrases

// A text flattened for searching: comment marks at the start of a line
// dropped, roff's escapes for a space, a hyphen and × written out, runs of
// white space (line ends included) made one space, letters in lower case;
// and for each character of it, the line of the file it came from.
struct FlatText {
  std::string text;
  std::vector<int> line;
};

FlatText flatten(const std::string& original) {
  FlatText flat;
  int number = 0;
  for (const std::string& raw : gas::testing::lines_of(original)) {
    ++number;
    std::string line = raw;
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"\\~", " "}, {"\\-", "-"}, {"\\(mu", "x"}, {"×", "x"}}) {
      for (std::size_t at = line.find(from); at != std::string::npos;
           at = line.find(from, at + to.size())) {
        line.replace(at, from.size(), to);
      }
    }
    std::size_t start = line.find_first_not_of(" \t");
    for (const char* mark : {"//", "#", ".\\\"", ">"}) {
      if (start != std::string::npos && line.compare(start, std::strlen(mark), mark) == 0)
        start = line.find_first_not_of(" \t", start + std::strlen(mark));
    }
    if (start == std::string::npos) continue;
    for (std::size_t i = start; i < line.size(); ++i) {
      const char c = line[i] == '\t' || line[i] == '\r' ? ' ' : line[i];
      if (c == ' ' && (flat.text.empty() || flat.text.back() == ' ')) continue;
      flat.text += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      flat.line.push_back(number);
    }
    if (!flat.text.empty() && flat.text.back() != ' ') {
      flat.text += ' ';
      flat.line.push_back(number);
    }
  }
  return flat;
}

// The sentence around position `at` of a flat text: from the last '.', '|'
// or '(' before it to the first '.', '|' or ')' after it, at most 200
// characters either way.
std::string sentence_around(const std::string& text, std::size_t at, std::size_t length) {
  std::size_t begin = at;
  while (begin > 0 && at - begin < 200 &&
         std::string_view(".|(").find(text[begin - 1]) == std::string_view::npos)
    --begin;
  std::size_t end = at + length;
  while (end < text.size() && end - at < 200 &&
         std::string_view(".|)").find(text[end]) == std::string_view::npos)
    ++end;
  return text.substr(begin, end - begin);
}

// One phrase kept out: where the flat text holds `anchor` (lower case), the
// sentence around it is a slip if it matches `slip` (none: always), unless
// `excused` finds something within 400 characters.
struct Rule {
  std::string anchor;
  std::string slip;     // an ECMAScript regular expression, or ""
  std::string excused;  // a plain lower-case string, or ""
  std::string why;      // what the text says, and where the glossary says it
};

const std::vector<Rule>& rules() {
  static const std::string glossary = "lessons/README.md, glossary";
  static const std::vector<Rule> all = {
      {"before the best tc", "", "",
       "the article's scan asks up to and including TC, 「時刻 TC までに」 (" + glossary +
           ")"},
      // Excused beside "the rendering": lesson 8 quotes the English rendering's
      // "before TC" to set it against the Japanese.
      {"before tc", R"((collide|reach|get past|gets past|do not|does not)\b.*before tc)",
       "the rendering",
       "the article's scan asks up to and including TC, 「時刻 TC までに」 (" + glossary +
           ")"},
      {"the article's program", "", "",
       "the article gives no program text, 「適当な言語で」: say 'the article's plan', "
       "'the article's loop' (" +
           glossary + ")"},
      {"the article's code", "", "",
       "the article gives no program text, 「適当な言語で」 (" + glossary + ")"},
      {"the article's basic", "", "", "the article names no language (" + glossary + ")"},
      {"inkey", "", "",
       "the article names no command for reading a key (" + glossary + ")"},
      {"the article's terminal", "", "",
       "the article names no terminal, only an example screen (" + glossary + ")"},
      {"article's 256", "", "",
       "the article's screen of 256 x 192 points is an example, 「例えば」, not a rule "
       "(" +
           glossary + ")"},
      {"case",
       R"(\b(lower|upper|letter) case\b.*\bas (in )?the article|\bas (in )?the article\b.*\b(lower|upper|letter) case\b)",
       "",
       "the article gives the keys as capitals and never mentions letter case (" +
           glossary + ")"},
      {"stopped", R"(stopped.*as (in )?the article (says|has it|wants))", "",
       "a stopped model running again after B is our reading of 「計算過程を実行する」 "
       "(" +
           glossary + ")"},
      {"kvant", "", "attribution",
       "the text names no journal: 'Kvant' is our attribution, and says so (" + glossary +
           ")"},
      {"article's nine", "", "",
       "the article's stage 6 names one figure, as an example: "
       "「系のいくつかの特性量(例えば平均速度)」"},
  };
  return all;
}

// The slips of one file's text, as "FILE:LINE: what was found — why".
std::vector<std::string> slips_in(const std::string& name, const std::string& original) {
  std::vector<std::string> found;
  const FlatText flat = flatten(original);
  for (const Rule& rule : rules()) {
    const std::regex slip(rule.slip.empty() ? "." : rule.slip);
    for (std::size_t at = flat.text.find(rule.anchor); at != std::string::npos;
         at = flat.text.find(rule.anchor, at + 1)) {
      const std::string sentence = sentence_around(flat.text, at, rule.anchor.size());
      if (!rule.slip.empty() && !std::regex_search(sentence, slip)) continue;
      if (!rule.excused.empty()) {
        const std::size_t from = at > 400 ? at - 400 : 0;
        if (flat.text.substr(from, 800 + rule.anchor.size()).find(rule.excused) !=
            std::string::npos)
          continue;
      }
      found.push_back(
          fmt::format("{}:{}: \"{}\" — {}", name, flat.line[at], sentence, rule.why));
    }
  }
  return found;
}

// Every text file of the source tree, as paths relative to it: build
// folders (any folder holding a CMakeCache.txt, and the top's build*), .git
// and files with a NUL byte (binary) left out, and this file, which names
// the phrases it keeps out.
std::vector<std::string> text_files() {
  std::vector<std::string> files;
  const fs::path top = source_path("");
  for (auto it = fs::recursive_directory_iterator(top);
       it != fs::recursive_directory_iterator(); ++it) {
    const fs::path relative = fs::relative(it->path(), top);
    const std::string name = it->path().filename().string();
    if (it->is_directory()) {
      const bool build = (it.depth() == 0 && name.starts_with("build")) ||
                         fs::exists(it->path() / "CMakeCache.txt");
      if (name == ".git" || build) it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file() || name == ".git") continue;
    if (relative.generic_string() == "tests/test_article_words.cpp") continue;
    files.push_back(relative.generic_string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string joined(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += "\n  " + line;
  return text;
}

// ------------------------------------------------- the exercises' counts

// "one" ... "twenty" as a number; 0 for anything else.
int number_word(const std::string& word) {
  static const std::vector<std::string> words = {
      "zero",     "one",     "two",     "three",     "four",     "five",     "six",
      "seven",    "eight",   "nine",    "ten",       "eleven",   "twelve",   "thirteen",
      "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen", "twenty"};
  const auto found = std::find(words.begin(), words.end(), word);
  return found == words.end() ? 0 : static_cast<int>(found - words.begin());
}

// The TEST_CASEs of a test file: the lines that start one.
int test_cases(const std::string& text) {
  static const std::regex opening(R"(^\s*TEST_CASE\()");
  int count = 0;
  for (const std::string& line : gas::testing::lines_of(text))
    count += std::regex_search(line, opening);
  return count;
}

}  // namespace

TEST_SUITE("lessons") {
  TEST_CASE("article words: the checker finds each slip and passes the exact wording") {
    // Each phrase the rules keep out, as it was once written, is found; the
    // wording that replaced it is not.
    const std::vector<std::string> slips = {
        "check that N3 and N4 do not collide\n// before TC, for which",
        "does the ball get past the limit before the best TC so far?",
        "the article's program asks the keyboard",
        "the article's BASIC had a screen of fixed size",
        "the article's loop asks the keyboard (INKEY$)",
        "80 x 24, the article's terminal, keeps the histogram",
        "seven balls on the article's 256 x 192 screen",
        ".\\\" Lengths are pixels of the article's 256\\~\\(mu\\~192 screen.",
        "Keys, in a terminal, without Enter, upper or lower case — as in the article:",
        "one key, in upper or lower case, as the article lists them",
        "and go on computing: a stopped model runs again, as the article has it |",
        "(`stopped` becomes false, as the article says)",
        "the billiard-ball gas of \"Gas on the display\" (Kvant 1989)",
        "the article's nine columns, then kinetic theory's",
        "Beyond the article's code: its stage 6 suggests"};
    for (const std::string& slip : slips) {
      CAPTURE(slip);
      CHECK(slips_in("t", slip).size() == 1);
    }
    const std::vector<std::string> exact = {
        "check that N3 and N4 do not collide up to and including TC",
        "The structure's snapshots due before TC, while the flights still reach them.",
        "the program the article describes reads the keyboard",
        "seven balls on a 256 x 192 table, the numbers of the article's example screen",
        "Keys, in a terminal, without Enter, in upper or lower case (the article gives "
        "capitals):",
        "and go on computing: a stopped model runs again (our reading)",
        "(1989, No. 6; the journal, Kvant, is our attribution)",
        "stage 6's nine figures, then kinetic theory's"};
    for (const std::string& text : exact) {
      CAPTURE(text);
      CHECK(slips_in("t", text).empty());
    }
    // The line named is the line of the file where the phrase starts.
    const std::vector<std::string> found =
        slips_in("f", "one\ntwo\n// the article's\n// 256");
    REQUIRE(found.size() == 1);
    CHECK(found[0].starts_with("f:3: "));
  }

  TEST_CASE("article words: no text file of the tree says more than the article") {
    std::vector<std::string> problems;
    const std::vector<std::string> files = text_files();
    for (const std::string& file : files) {
      const std::string text = read_file(source_path(file));
      if (text.find('\0') != std::string::npos) continue;  // binary
      for (std::string& slip : slips_in(file, text)) problems.push_back(std::move(slip));
    }
    MESSAGE(fmt::format("{} files read", files.size()));
    CHECK(files.size() > 100);  // the tree itself, not an empty folder
    CHECK_MESSAGE(problems.empty(), "says more than the article:" << joined(problems));
  }

  TEST_CASE("article words: each exercise says how many tests it has, truly") {
    std::vector<std::string> problems;
    int exercises = 0;
    static const std::regex says(R"(The ([a-z]+) tests)");
    for (const auto& entry : fs::directory_iterator(source_path("lessons/exercises"))) {
      if (!entry.is_directory()) continue;
      const std::string folder = entry.path().filename().string();
      if (folder.size() < 3 || !std::isdigit(static_cast<unsigned char>(folder[0])))
        continue;
      ++exercises;
      int cases = 0;
      for (const auto& file : fs::directory_iterator(entry.path())) {
        const std::string name = file.path().filename().string();
        if (name.starts_with("test_") && name.ends_with(".cpp"))
          cases += test_cases(read_file(file.path().string()));
      }
      const std::string instructions =
          read_file((entry.path() / "instructions.md").string());
      std::smatch match;
      if (!std::regex_search(instructions, match, says)) {
        problems.push_back(fmt::format(
            "lessons/exercises/{}/instructions.md: no sentence 'The N tests: ...'",
            folder));
      } else if (number_word(match[1]) != cases) {
        problems.push_back(
            fmt::format("lessons/exercises/{}/instructions.md says '{}', its test file "
                        "has {} TEST_CASEs",
                        folder, match.str(), cases));
      }
    }
    CHECK(exercises >= 11);
    CHECK_MESSAGE(problems.empty(), "exercise counts:" << joined(problems));
  }
}
