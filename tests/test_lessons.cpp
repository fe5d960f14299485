// The lessons stay honest: what they quote is what the code says and does.
//
// A lesson quotes code only by anchor and console output only as checked
// output (lessons/README.md, "How the lessons quote"):
//
//   <!-- code: stages/FILE NAME -->      followed by a ```cpp block: the lines
//                                        strictly between "// [anchor: NAME]"
//                                        and "// [/anchor: NAME]" in FILE
//   <!-- output: ARGS -->                followed by a ```text block: the
//                                        standard output of `gas ARGS` (ARGS
//                                        split on spaces, run from the source
//                                        directory, standard input /dev/null)
//   <!-- unchecked: WHY -->              followed by a ```cpp or ```text block
//                                        that nothing can check (a sketch, an
//                                        example of a format), and WHY not
//   <!-- report: data/reports/FILE NAME --> followed by lines up to the next
//                                        blank one (a Markdown table, say): the
//                                        lines after '<!-- section: NAME -->'
//                                        in FILE up to its next blank line. A
//                                        report is written by the command it
//                                        names (figures that take minutes to
//                                        make), so a lesson's figures follow it
//
// A lesson is every .md file under lessons/, the exercises' instructions
// included. Every ```cpp and every ```text block of a lesson has one of these
// three lines just before it.
//
// This file checks that the anchors in stages/ are well formed, that every
// quoted block is what it claims to be, that no cpp or text block goes
// unchecked without a note saying why, and that the lessons named by
// lessons/README.md and by the stages' "Lesson:" lines exist. With
// GAS_UPDATE_GOLDEN=1 the quoted blocks are rewritten in place instead (a
// teacher's regeneration after a code change: then read the diff).
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "support.hpp"

namespace {

namespace fs = std::filesystem;
using gas::testing::read_file;
using gas::testing::run_program;
using gas::testing::source_path;

// ---------------------------------------------------------------- anchors

// One anchored region of a source file.
struct Anchor {
  std::string file;  // as named, e.g. "stages/stage4_first_collision.cpp"
  int open_line = 0;
  int close_line = 0;
  std::string body;  // the lines strictly between the markers, each with its '\n'
};

// The lines of a text, each without its '\n'; a final line without '\n'
// counts too.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// Reads the anchors of one file. Every problem is appended to `problems` as
// "FILE:LINE: what is wrong"; well-formed anchors are added to `anchors`
// (a name already there is a duplicate: anchor names are unique across all
// the files read into one map).
void read_anchors(const std::string& file, const std::string& text,
                  std::map<std::string, Anchor>& anchors,
                  std::vector<std::string>& problems) {
  static const std::regex open(R"(^\s*// \[anchor: ([A-Za-z0-9_.-]+)\]\s*$)");
  static const std::regex close(R"(^\s*// \[/anchor: ([A-Za-z0-9_.-]+)\]\s*$)");
  const std::vector<std::string> lines = lines_of(text);
  // Anchors open at this point of the file: name -> line of the open marker.
  std::map<std::string, int> open_at;
  std::vector<std::string> opened_in_order;
  // The body of each open anchor, collected line by line.
  std::map<std::string, std::string> bodies;

  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int number = static_cast<int>(i) + 1;
    const std::string& line = lines[i];
    std::smatch match;
    if (std::regex_match(line, match, open)) {
      const std::string name = match[1];
      if (open_at.count(name) != 0) {
        problems.push_back(
            fmt::format("{}:{}: anchor '{}' opened again inside itself (opened on "
                        "line {})",
                        file, number, name, open_at[name]));
        continue;
      }
      for (auto& [other, body] : bodies) body += line + "\n";
      open_at[name] = number;
      opened_in_order.push_back(name);
      bodies[name].clear();
      continue;
    }
    if (std::regex_match(line, match, close)) {
      const std::string name = match[1];
      if (open_at.count(name) == 0) {
        problems.push_back(
            fmt::format("{}:{}: '[/anchor: {}]' closes an anchor that is not open", file,
                        number, name));
        continue;
      }
      Anchor anchor{file, open_at[name], number, bodies[name]};
      open_at.erase(name);
      bodies.erase(name);
      opened_in_order.erase(
          std::find(opened_in_order.begin(), opened_in_order.end(), name));
      for (auto& [other, body] : bodies) body += line + "\n";
      if (const auto seen = anchors.find(name); seen != anchors.end()) {
        problems.push_back(fmt::format(
            "{}:{}: anchor name '{}' is used twice (also {}:{})", file, anchor.open_line,
            name, seen->second.file, seen->second.open_line));
        continue;
      }
      anchors.emplace(name, anchor);
      continue;
    }
    if (line.find("[anchor:") != std::string::npos ||
        line.find("[/anchor:") != std::string::npos) {
      problems.push_back(
          fmt::format("{}:{}: a malformed anchor marker (write '// [anchor: NAME]' "
                      "or '// [/anchor: NAME]' alone on its line, NAME of letters, "
                      "digits, '-', '_', '.'): {}",
                      file, number, line));
      continue;
    }
    for (auto& [name, body] : bodies) body += line + "\n";
  }
  for (const std::string& name : opened_in_order) {
    problems.push_back(
        fmt::format("{}:{}: anchor '{}' is never closed", file, open_at[name], name));
  }
}

// The files of stages/ and its folders beyond/ and program/ that can hold
// anchors.
std::vector<std::string> stage_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(source_path("stages"))) {
    const std::string extension = entry.path().extension().string();
    if (entry.is_regular_file() && (extension == ".hpp" || extension == ".cpp")) {
      files.push_back(fs::relative(entry.path(), source_path("")).generic_string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::map<std::string, Anchor> stage_anchors(std::vector<std::string>& problems) {
  std::map<std::string, Anchor> anchors;
  for (const std::string& file : stage_files()) {
    read_anchors(file, read_file(source_path(file)), anchors, problems);
  }
  return anchors;
}

// ------------------------------------------------------------ the lessons

// The Markdown files of lessons/, as "lessons/..." paths, sorted.
std::vector<std::string> lesson_files() {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(source_path("lessons"))) {
    if (entry.is_regular_file() && entry.path().extension() == ".md") {
      files.push_back(fs::relative(entry.path(), source_path("")).generic_string());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

// A quoted block of a lesson: its marker, and where its content lies.
struct Quote {
  enum class Kind { code, output, report } kind = Kind::code;
  int marker_line = 0;    // 1-based line of the <!-- ... --> marker
  std::string file;       // code, report: the file named
  std::string anchor;     // code: the anchor named; report: the section named
  std::string arguments;  // output: ARGS as written
  std::size_t first = 0;  // index of the first content line
  std::size_t end = 0;    // index of the closing fence
  std::string content;    // the lines between the fences, each with '\n'
  std::string fault;      // why the block cannot be read, if it cannot
};

std::vector<std::string> split_on_spaces(const std::string& text) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && text[i] == ' ') ++i;
    std::size_t end = i;
    while (end < text.size() && text[end] != ' ') ++end;
    if (end > i) words.push_back(text.substr(i, end - i));
    i = end;
  }
  return words;
}

// The markers of a lesson, each alone on its line.
const std::regex code_marker(R"(^<!-- code: (\S+) (\S+) -->$)");
const std::regex output_marker(R"(^<!-- output:(.*)-->$)");
const std::regex unchecked_note(R"(^<!-- unchecked: \S.*\S -->$)");
const std::regex report_marker(R"(^<!-- report: (data/reports/\S+) (\S+) -->$)");

// Finds the quoted blocks of a lesson. Markers are looked for only outside
// fenced blocks, so a lesson can show the syntax inside a fence.
std::vector<Quote> find_quotes(const std::vector<std::string>& lines) {
  std::vector<Quote> quotes;
  bool in_fence = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    if (line.rfind("```", 0) == 0) {
      in_fence = !in_fence;
      continue;
    }
    if (in_fence) continue;
    std::smatch match;
    Quote quote;
    std::string fence;
    if (std::regex_match(line, match, code_marker)) {
      quote.kind = Quote::Kind::code;
      quote.file = match[1];
      quote.anchor = match[2];
      fence = "```cpp";
    } else if (std::regex_match(line, match, output_marker)) {
      quote.kind = Quote::Kind::output;
      quote.arguments = match[1];
      // "<!-- output: ARGS -->": one space after the colon and before "-->".
      if (!quote.arguments.empty() && quote.arguments.front() == ' ')
        quote.arguments.erase(0, 1);
      if (!quote.arguments.empty() && quote.arguments.back() == ' ')
        quote.arguments.pop_back();
      fence = "```text";
    } else if (std::regex_match(line, match, report_marker)) {
      // A report's lines: up to the next blank line, no fence.
      quote.kind = Quote::Kind::report;
      quote.file = match[1];
      quote.anchor = match[2];
      quote.marker_line = static_cast<int>(i) + 1;
      std::size_t end = i + 1;
      while (end < lines.size() && !lines[end].empty()) ++end;
      if (end == i + 1) {
        quote.fault = "a report marker must be followed at once by the quoted lines";
        quotes.push_back(quote);
        continue;
      }
      quote.first = i + 1;
      quote.end = end;
      for (std::size_t k = quote.first; k < end; ++k) quote.content += lines[k] + "\n";
      quotes.push_back(quote);
      i = end - 1;
      continue;
    } else if (line.rfind("<!-- code:", 0) == 0 || line.rfind("<!-- output:", 0) == 0 ||
               line.rfind("<!-- report:", 0) == 0) {
      quote.marker_line = static_cast<int>(i) + 1;
      quote.fault =
          "a malformed marker: write '<!-- code: stages/FILE NAME -->', "
          "'<!-- output: ARGS -->' or '<!-- report: data/reports/FILE NAME -->' alone "
          "on its line";
      quotes.push_back(quote);
      continue;
    } else {
      continue;
    }
    quote.marker_line = static_cast<int>(i) + 1;
    if (i + 1 >= lines.size() || lines[i + 1] != fence) {
      quote.fault =
          fmt::format("the marker must be followed at once by a line '{}'", fence);
      quotes.push_back(quote);
      continue;
    }
    std::size_t end = i + 2;
    while (end < lines.size() && lines[end].rfind("```", 0) != 0) ++end;
    if (end >= lines.size() || lines[end] != "```") {
      quote.fault = "the block has no closing line '```'";
      quotes.push_back(quote);
      continue;
    }
    quote.first = i + 2;
    quote.end = end;
    for (std::size_t k = quote.first; k < end; ++k) quote.content += lines[k] + "\n";
    quotes.push_back(quote);
    i = end;  // the closing fence: not a fence to toggle
  }
  return quotes;
}

// The language of a fence that opens a block, "cpp" for "```cpp": its first
// word.
std::string fence_language(const std::string& fence) {
  const std::vector<std::string> words = split_on_spaces(fence.substr(3));
  return words.empty() ? std::string() : words.front();
}

// Checks that every ```cpp and every ```text block of a lesson is either
// quoted (a code or output marker on the line before it; find_quotes checks
// the marker itself) or says on the line before it why it is not checked:
// "<!-- unchecked: WHY -->". Also finds such notes that are malformed or
// stand before no such block. Returns the problems, each "LINE: ...".
std::vector<std::string> unchecked_blocks(const std::vector<std::string>& lines) {
  std::vector<std::string> problems;
  const auto opens_checked_block = [&](std::size_t i) {
    if (i >= lines.size() || lines[i].rfind("```", 0) != 0) return false;
    const std::string language = fence_language(lines[i]);
    return language == "cpp" || language == "text";
  };
  bool in_fence = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const int number = static_cast<int>(i) + 1;
    if (line.rfind("```", 0) == 0) {
      in_fence = !in_fence;
      if (!in_fence || !opens_checked_block(i)) continue;
      const std::string before = i > 0 ? lines[i - 1] : std::string();
      if (before.rfind("<!-- code:", 0) == 0 || before.rfind("<!-- output:", 0) == 0 ||
          std::regex_match(before, unchecked_note))
        continue;
      problems.push_back(fmt::format(
          "{}: a ```{} block that nothing checks: put '<!-- code: stages/FILE NAME -->' "
          "or '<!-- output: ARGS -->' on the line before it, or, if it cannot be "
          "checked, '<!-- unchecked: WHY -->'",
          number, fence_language(line)));
      continue;
    }
    if (in_fence || line.rfind("<!-- unchecked:", 0) != 0) continue;
    if (!std::regex_match(line, unchecked_note)) {
      problems.push_back(
          fmt::format("{}: a malformed note: write '<!-- unchecked: WHY -->' alone on "
                      "its line",
                      number));
    } else if (!opens_checked_block(i + 1)) {
      problems.push_back(
          fmt::format("{}: '<!-- unchecked: ... -->' must stand just before a ```cpp or "
                      "```text block",
                      number));
    }
  }
  return problems;
}

// The first line where two texts differ, for messages.
std::string first_difference(const std::string& quoted, const std::string& actual) {
  const std::vector<std::string> a = lines_of(quoted);
  const std::vector<std::string> b = lines_of(actual);
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  const auto show = [](const std::vector<std::string>& lines, std::size_t k) {
    return k < lines.size() ? fmt::format("'{}'", lines[k]) : std::string("(nothing)");
  };
  return fmt::format("block line {}: the lesson has {}, the {} {}", i + 1, show(a, i),
                     "real text has", show(b, i));
}

// What a lesson's quoted block should hold, or a reason it cannot be known.
struct Expected {
  std::optional<std::string> text;
  std::string why_not;
  std::string what;  // "anchor X in FILE" or "`gas ARGS`", for messages
};

using AnchorCache = std::map<std::string, std::map<std::string, Anchor>>;

Expected expected_code(const Quote& quote, AnchorCache& cache) {
  Expected expected;
  expected.what = fmt::format("anchor '{}' in {}", quote.anchor, quote.file);
  if (!fs::is_regular_file(source_path(quote.file))) {
    expected.why_not = fmt::format("{} does not exist", quote.file);
    return expected;
  }
  if (cache.count(quote.file) == 0) {
    std::vector<std::string> ignored;  // the anchor test reports these
    read_anchors(quote.file, read_file(source_path(quote.file)), cache[quote.file],
                 ignored);
  }
  const auto& anchors = cache[quote.file];
  const auto found = anchors.find(quote.anchor);
  if (found == anchors.end()) {
    expected.why_not =
        fmt::format("{} has no (well-formed) anchor '{}'", quote.file, quote.anchor);
    return expected;
  }
  expected.text = found->second.body;
  return expected;
}

Expected expected_output(const Quote& quote) {
  Expected expected;
  expected.what = fmt::format("`gas {}`", quote.arguments);
  const gas::testing::ProgramRun run = run_program(split_on_spaces(quote.arguments));
  if (run.status != 0) {
    expected.why_not = fmt::format("`gas {}` exits with status {}: {}", quote.arguments,
                                   run.status, run.err);
    return expected;
  }
  if (!run.out.empty() && run.out.back() != '\n') {
    expected.why_not = fmt::format(
        "`gas {}` prints a last line without a newline, which a "
        "fenced block cannot quote",
        quote.arguments);
    return expected;
  }
  expected.text = run.out;
  return expected;
}

// A report's section: the lines after "<!-- section: NAME -->" in the
// report up to its next blank line.
Expected expected_report(const Quote& quote) {
  Expected expected;
  expected.what = fmt::format("section '{}' of {}", quote.anchor, quote.file);
  if (!fs::is_regular_file(source_path(quote.file))) {
    expected.why_not = fmt::format("{} does not exist", quote.file);
    return expected;
  }
  const std::vector<std::string> lines = lines_of(read_file(source_path(quote.file)));
  const std::string opening = fmt::format("<!-- section: {} -->", quote.anchor);
  const auto found = std::find(lines.begin(), lines.end(), opening);
  if (found == lines.end()) {
    expected.why_not = fmt::format("{} has no line '{}'", quote.file, opening);
    return expected;
  }
  std::string text;
  for (auto it = found + 1; it != lines.end() && !it->empty(); ++it) text += *it + "\n";
  expected.text = text;
  return expected;
}

bool updating() {
  const char* update = std::getenv("GAS_UPDATE_GOLDEN");
  return update != nullptr && std::string(update) == "1";
}

// Checks (or, when updating, rewrites) every quoted block of one lesson.
// Returns the problems, each "LESSON:LINE: ...".
std::vector<std::string> check_lesson(const std::string& lesson, AnchorCache& cache,
                                      bool update) {
  const std::string path = source_path(lesson);
  const std::string text = read_file(path);
  std::vector<std::string> lines = lines_of(text);
  std::vector<std::string> problems;
  const std::vector<Quote> quotes = find_quotes(lines);
  // Rewrites go from the last block up, so that earlier indices stay valid.
  std::vector<std::pair<const Quote*, std::string>> rewrites;
  for (const Quote& quote : quotes) {
    const std::string where = fmt::format("{}:{}", lesson, quote.marker_line);
    if (!quote.fault.empty()) {
      problems.push_back(fmt::format("{}: {}", where, quote.fault));
      continue;
    }
    const Expected expected =
        quote.kind == Quote::Kind::code     ? expected_code(quote, cache)
        : quote.kind == Quote::Kind::report ? expected_report(quote)
                                            : expected_output(quote);
    if (!expected.text) {
      problems.push_back(fmt::format("{}: {}", where, expected.why_not));
      continue;
    }
    if (*expected.text == quote.content) continue;
    if (update) {
      rewrites.emplace_back(&quote, *expected.text);
      continue;
    }
    problems.push_back(fmt::format(
        "{}: the block quoting {} differs from it ({}); GAS_UPDATE_GOLDEN=1 rewrites it",
        where, expected.what, first_difference(quote.content, *expected.text)));
  }
  if (!rewrites.empty()) {
    std::reverse(rewrites.begin(), rewrites.end());
    for (const auto& [quote, replacement] : rewrites) {
      const std::vector<std::string> fresh = lines_of(replacement);
      lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(quote->first),
                  lines.begin() + static_cast<std::ptrdiff_t>(quote->end));
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(quote->first),
                   fresh.begin(), fresh.end());
    }
    std::string rewritten;
    for (const std::string& line : lines) rewritten += line + "\n";
    if (!text.empty() && text.back() != '\n') rewritten.pop_back();
    std::ofstream(path, std::ios::binary) << rewritten;
    MESSAGE(fmt::format("rewrote {} quoted block(s) of {}", rewrites.size(), lesson));
  }
  return problems;
}

// ------------------------------------------------------- links and names

// The Markdown files a text links to or names: targets of "](...)" links
// ending in .md (resolved against `directory`), and "lessons/....md" named in
// the text (resolved against the source directory). Paths are relative to
// the source directory.
std::set<std::string> named_lessons(const std::string& text,
                                    const std::string& directory) {
  std::set<std::string> named;
  static const std::regex link(R"(\]\(([^)#\s]+\.md)(#[^)]*)?\))");
  static const std::regex path(R"((^|[^A-Za-z0-9_./-])(lessons/[A-Za-z0-9_./-]+\.md))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), link);
       it != std::sregex_iterator(); ++it) {
    const std::string target = (*it)[1];
    if (target.find("://") != std::string::npos) continue;
    named.insert((fs::path(directory) / target).lexically_normal().generic_string());
  }
  for (auto it = std::sregex_iterator(text.begin(), text.end(), path);
       it != std::sregex_iterator(); ++it) {
    named.insert(fs::path((*it)[2].str()).lexically_normal().generic_string());
  }
  return named;
}

// Every relative link of a Markdown file (not only to .md files): "](...)"
// targets without a scheme, resolved against `directory`.
std::set<std::string> relative_links(const std::string& text,
                                     const std::string& directory) {
  std::set<std::string> links;
  static const std::regex link(R"(\]\(([^)#\s]+)(#[^)]*)?\))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), link);
       it != std::sregex_iterator(); ++it) {
    const std::string target = (*it)[1];
    if (target.find("://") != std::string::npos || target.rfind("mailto:", 0) == 0)
      continue;
    links.insert((fs::path(directory) / target).lexically_normal().generic_string());
  }
  return links;
}

// ------------------------------------------------ words, asides, lengths

// The most lines a numbered lesson may have: one lesson, one sitting of
// about 45 minutes (lessons/README.md, "How to use them").
constexpr std::size_t most_lesson_lines = 500;

// Is `lesson` ("lessons/....md") a numbered lesson, such as
// lessons/4-first-collision.md (not the README, not an exercise)?
bool numbered_lesson(const std::string& lesson) {
  static const std::regex numbered(R"(^lessons/[0-9]+-[^/]+\.md$)");
  return std::regex_match(lesson, numbered);
}

// A phrase no lesson may use, and what to write instead.
struct RetiredPhrase {
  std::regex pattern;
  const char* instead;
};

const std::vector<RetiredPhrase>& retired_phrases() {
  using flags = std::regex_constants::syntax_option_type;
  const flags any_case = std::regex::ECMAScript | std::regex::icase;
  static const std::vector<RetiredPhrase> phrases = {
      {std::regex(R"(earlier versions?)", any_case),
       "the lessons say nothing of their own past versions: history goes in commit "
       "messages"},
      {std::regex(R"(before issue)", any_case),
       "the lessons say nothing of their own past versions: history goes in commit "
       "messages"},
      {std::regex(R"(\bissues?\s+(#\s*)?[0-9]+)", any_case),
       "no issue numbers in the lessons: history goes in commit messages"},
      {std::regex(R"(collisions? of two balls a ball)", any_case),
       "write 'pair collisions per ball' (2 x ball-ball collisions / N: each collision "
       "counts for both its balls)"},
      {std::regex(R"(\bcollisions? a ball\b)", any_case),
       "write 'pair collisions per ball' or 'wall collisions per ball' (or 'collisions "
       "per ball, walls and pairs')"},
      // Case matters: R is the article's array.
      {std::regex(R"(\brows? of R\b)"),
       "ball i is column i of R(4, N): write 'column of R'"},
      {std::regex(R"(ball's row\b)"),
       "ball i is column i of R(4, N): write 'column of R'"},
  };
  return phrases;
}

// The problems of one lesson's words, asides and length, each "LINE: ..."
// (a length problem has no line). Checks, outside fenced blocks for the
// asides and everywhere for the phrases: no retired phrase; every block
// quote is an aside, opening with '> **Aside: TITLE.**' (lessons/README.md);
// no fenced block inside a block quote (nothing there could be checked); a
// numbered lesson at most most_lesson_lines long.
std::vector<std::string> lesson_form_problems(const std::string& lesson,
                                              const std::vector<std::string>& lines) {
  std::vector<std::string> problems;
  static const std::regex aside_opening(R"(^> \*\*Aside: [^*]+\.\*\* \S.*$)");
  bool in_fence = false;
  bool in_quote = false;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const int number = static_cast<int>(i) + 1;
    for (const RetiredPhrase& phrase : retired_phrases()) {
      std::smatch match;
      if (std::regex_search(line, match, phrase.pattern)) {
        problems.push_back(
            fmt::format("{}: '{}': {}", number, match.str(0), phrase.instead));
      }
    }
    if (line.rfind("```", 0) == 0) {
      in_fence = !in_fence;
      in_quote = false;
      continue;
    }
    if (in_fence) continue;
    const bool quoted = line.rfind(">", 0) == 0;
    if (quoted && !in_quote && !std::regex_match(line, aside_opening)) {
      problems.push_back(fmt::format(
          "{}: a block quote that is not an aside: open it with '> **Aside: TITLE.** "
          "text' (lessons/README.md)",
          number));
    }
    if (quoted && line.find("```") != std::string::npos) {
      problems.push_back(fmt::format(
          "{}: a fenced block inside a block quote: nothing checks it there; put "
          "code and output outside the aside",
          number));
    }
    in_quote = quoted;
  }
  if (numbered_lesson(lesson) && lines.size() > most_lesson_lines) {
    problems.push_back(fmt::format("{} lines, more than {}: one lesson, one sitting",
                                   lines.size(), most_lesson_lines));
  }
  return problems;
}

std::string joined(const std::vector<std::string>& problems) {
  std::string out;
  for (const std::string& problem : problems) out += "\n  " + problem;
  return out;
}

}  // namespace

TEST_SUITE("lessons") {
  TEST_CASE("lessons: every anchor in stages/ is balanced and anchor names are unique") {
    std::vector<std::string> problems;
    const std::map<std::string, Anchor> anchors = stage_anchors(problems);
    CHECK_MESSAGE(problems.empty(), "anchors in stages/:" << joined(problems));
    CHECK_MESSAGE(!anchors.empty(), "no anchors found in stages/");
    MESSAGE(fmt::format("{} anchors in {} files of stages/", anchors.size(),
                        stage_files().size()));
  }

  TEST_CASE("lessons: the anchor reader finds every kind of broken anchor") {
    // This test proves that the one above can fail.
    const auto problems_in = [](const std::string& text) {
      std::map<std::string, Anchor> anchors;
      std::vector<std::string> problems;
      read_anchors("copy.cpp", text, anchors, problems);
      return problems;
    };
    const auto says = [](const std::vector<std::string>& problems,
                         const std::string& what) {
      return std::any_of(problems.begin(), problems.end(), [&](const std::string& p) {
        return p.find(what) != std::string::npos;
      });
    };

    // Well formed, nested under another name, indented: no problem.
    const std::string good =
        "int a;\n// [anchor: outer]\nint b;\n  // [anchor: inner]\n  int c;\n  // "
        "[/anchor: "
        "inner]\n// [/anchor: outer]\n";
    CHECK(problems_in(good).empty());
    std::map<std::string, Anchor> anchors;
    std::vector<std::string> none;
    read_anchors("copy.cpp", good, anchors, none);
    REQUIRE(anchors.count("outer") == 1);
    REQUIRE(anchors.count("inner") == 1);
    CHECK(anchors["inner"].body == "  int c;\n");
    CHECK(anchors["outer"].body ==
          "int b;\n  // [anchor: inner]\n  int c;\n  // [/anchor: inner]\n");
    CHECK(anchors["outer"].open_line == 2);
    CHECK(anchors["outer"].close_line == 7);

    // A renamed close marker (the copy of a stage with one anchor renamed).
    const auto renamed = problems_in("// [anchor: ball]\nint x;\n// [/anchor: bal]\n");
    CHECK(
        says(renamed, "copy.cpp:3: '[/anchor: bal]' closes an anchor that is not open"));
    CHECK(says(renamed, "copy.cpp:1: anchor 'ball' is never closed"));
    // Closed before it is opened.
    CHECK(says(problems_in("// [/anchor: a]\n// [anchor: a]\n"),
               "closes an anchor that is not open"));
    // Opened inside itself.
    CHECK(says(problems_in("// [anchor: a]\n// [anchor: a]\n// [/anchor: a]\n"),
               "opened again inside itself"));
    // Closed twice.
    CHECK(says(problems_in("// [anchor: a]\n// [/anchor: a]\n// [/anchor: a]\n"),
               "copy.cpp:3: '[/anchor: a]' closes an anchor that is not open"));
    // The same name twice, in one file...
    CHECK(says(
        problems_in("// [anchor: a]\n// [/anchor: a]\n// [anchor: a]\n// [/anchor: a]\n"),
        "anchor name 'a' is used twice"));
    // ...or in two files read into one map.
    std::map<std::string, Anchor> across;
    std::vector<std::string> problems;
    read_anchors("one.hpp", "// [anchor: a]\n// [/anchor: a]\n", across, problems);
    read_anchors("two.cpp", "// [anchor: a]\n// [/anchor: a]\n", across, problems);
    CHECK(says(problems, "two.cpp:1: anchor name 'a' is used twice (also one.hpp:1)"));
    // A malformed marker.
    CHECK(says(problems_in("//[anchor:a]\n"), "copy.cpp:1: a malformed anchor marker"));
  }

  TEST_CASE("lessons: the block reader finds a changed quote and says where") {
    // This test proves that the next one can fail: a lesson quoting an
    // anchor of a (made-up) file, with one line of the quote changed.
    const std::string lesson =
        "Some prose.\n\n<!-- code: stages/none.cpp x -->\n```cpp\nint x = 1;\n```\n\n"
        "<!-- output: --frames 1 -->\n```text\nT=1\n```\n<!-- code: stages/none.cpp y "
        "-->\nint y;\n"
        "```cpp\n<!-- code: stages/none.cpp z -->\n```\n";
    const std::vector<Quote> quotes = find_quotes(lines_of(lesson));
    REQUIRE(quotes.size() == 3);  // the marker inside the fence is not one
    CHECK(quotes[0].kind == Quote::Kind::code);
    CHECK(quotes[0].marker_line == 3);
    CHECK(quotes[0].file == "stages/none.cpp");
    CHECK(quotes[0].anchor == "x");
    CHECK(quotes[0].content == "int x = 1;\n");
    CHECK(quotes[1].kind == Quote::Kind::output);
    CHECK(quotes[1].arguments == "--frames 1");
    CHECK(quotes[1].content == "T=1\n");
    CHECK(quotes[2].marker_line == 12);
    CHECK(quotes[2].fault.find("followed at once by a line '```cpp'") !=
          std::string::npos);
    CHECK(first_difference("int x = 1;\n", "int x = 2;\n") ==
          "block line 1: the lesson has 'int x = 1;', the real text has 'int x = 2;'");
    CHECK(split_on_spaces(" --keys  S>>R.B --until 80 ") ==
          std::vector<std::string>{"--keys", "S>>R.B", "--until", "80"});
  }

  TEST_CASE("lessons: a report's figures are read up to the blank line, and checked") {
    // This test proves that the quoted reports can fail: a made-up lesson
    // quoting a section of data/reports/kinetic-seeds.md, its table's last
    // line changed, and a report marker with nothing after it.
    const std::string lesson =
        "Prose.\n<!-- report: data/reports/kinetic-seeds.md closed -->\n| a | b |\n"
        "|---|---|\n| 1 | 2 |\n\nMore prose.\n<!-- report: data/reports/none.md x -->\n\n"
        "<!-- report: reports/kinetic-seeds.md closed -->\n";
    const std::vector<Quote> quotes = find_quotes(lines_of(lesson));
    REQUIRE(quotes.size() == 3);
    CHECK(quotes[0].kind == Quote::Kind::report);
    CHECK(quotes[0].file == "data/reports/kinetic-seeds.md");
    CHECK(quotes[0].anchor == "closed");
    CHECK(quotes[0].content == "| a | b |\n|---|---|\n| 1 | 2 |\n");
    CHECK(quotes[1].fault.find("followed at once by the quoted lines") !=
          std::string::npos);
    CHECK(quotes[2].fault.find("a malformed marker") != std::string::npos);
    // The real section is a table that the made-up one is not.
    const Expected expected = expected_report(quotes[0]);
    REQUIRE(expected.text);
    CHECK(expected.text->rfind("| η |", 0) == 0);
    // Up to the section's blank line, not beyond: table lines only.
    for (const std::string& line : lines_of(*expected.text))
      CHECK(line.rfind("|", 0) == 0);
    CHECK(*expected.text != quotes[0].content);
    Quote missing = quotes[0];
    missing.anchor = "no-such-section";
    CHECK(expected_report(missing).why_not.find("has no line") != std::string::npos);
  }

  TEST_CASE("lessons: the block rule finds a cpp or text block that nothing checks") {
    // This test proves that the next one can fail: a made-up lesson with
    // a quoted block of each kind, a block that says why it is not checked,
    // and blocks the rule does not ask about (sh, a bare fence).
    const std::vector<std::string> good = {
        "# A lesson",                                             // 1
        "<!-- code: stages/none.cpp x -->",                       // 2
        "```cpp",                                                 // 3
        "int x;",                                                 // 4
        "```",                                                    // 5
        "<!-- output: --frames 1 -->",                            // 6
        "```text",                                                // 7
        "T=1",                                                    // 8
        "```",                                                    // 9
        "<!-- unchecked: a sketch, not code of the project -->",  // 10
        "```cpp",                                                 // 11
        "sketch();",                                              // 12
        "```",                                                    // 13
        "```sh",                                                  // 14
        "build/gas",                                              // 15
        "```",                                                    // 16
        "```",                                                    // 17
        "VI = (d·w) / 4a²",                                       // 18
        "```",                                                    // 19
    };
    CHECK(unchecked_blocks(good).empty());

    // The same lesson with its note, then one of its markers, taken away.
    std::vector<std::string> no_note = good;
    no_note.erase(no_note.begin() + 9);  // line 10
    REQUIRE(unchecked_blocks(no_note).size() == 1);
    CHECK(unchecked_blocks(no_note)[0].rfind("10: a ```cpp block that nothing checks",
                                             0) == 0);
    std::vector<std::string> no_marker = good;
    no_marker.erase(no_marker.begin() + 5);  // line 6
    REQUIRE(unchecked_blocks(no_marker).size() == 1);
    CHECK(unchecked_blocks(no_marker)[0].rfind("6: a ```text block that nothing checks",
                                               0) == 0);

    // A blank line between the note and its block, a note without a reason,
    // a note before a block the rule does not ask about.
    const std::vector<std::string> bad = {
        "<!-- unchecked: a sketch -->",   // 1
        "",                               // 2
        "```cpp",                         // 3
        "```",                            // 4
        "<!-- unchecked: -->",            // 5
        "```text",                        // 6
        "```",                            // 7
        "<!-- unchecked: a command -->",  // 8
        "```sh",                          // 9
        "```",                            // 10
    };
    const std::vector<std::string> problems = unchecked_blocks(bad);
    REQUIRE(problems.size() == 5);
    CHECK(problems[0].rfind("1: '<!-- unchecked: ... -->' must stand just before", 0) ==
          0);
    CHECK(problems[1].rfind("3: a ```cpp block that nothing checks", 0) == 0);
    CHECK(problems[2].rfind("5: a malformed note", 0) == 0);
    CHECK(problems[3].rfind("6: a ```text block that nothing checks", 0) == 0);
    CHECK(problems[4].rfind("8: '<!-- unchecked: ... -->' must stand just before", 0) ==
          0);
  }

  TEST_CASE("lessons: every cpp and text block of a lesson is checked or says why not") {
    std::vector<std::string> problems;
    for (const std::string& lesson : lesson_files()) {
      for (const std::string& problem :
           unchecked_blocks(lines_of(read_file(source_path(lesson))))) {
        problems.push_back(fmt::format("{}:{}", lesson, problem));
      }
    }
    CHECK_MESSAGE(problems.empty(), "unchecked blocks:" << joined(problems));
  }

  TEST_CASE(
      "lessons: every quoted code block equals its anchor and every quoted run its "
      "output") {
    const std::vector<std::string> lessons = lesson_files();
    REQUIRE_MESSAGE(!lessons.empty(), "no lessons in lessons/");
    AnchorCache cache;
    std::vector<std::string> problems;
    int quotes = 0;
    for (const std::string& lesson : lessons) {
      quotes +=
          static_cast<int>(find_quotes(lines_of(read_file(source_path(lesson)))).size());
      for (const std::string& problem : check_lesson(lesson, cache, updating())) {
        problems.push_back(problem);
      }
    }
    MESSAGE(fmt::format("{} quoted blocks in {} lessons", quotes, lessons.size()));
    CHECK_MESSAGE(problems.empty(), "quoted blocks:" << joined(problems));
  }

  TEST_CASE("lessons: the form rule finds retired words, stray quotes and long lessons") {
    // This test proves that the next one can fail: a made-up lesson that
    // breaks each rule once, and one that keeps them all.
    const std::vector<std::string> good = {
        "# 4. A lesson",                                           // 1
        "Pair collisions per ball, and a ball's column of R.",     // 2
        "",                                                        // 3
        "> **Aside: the last-bit trap.** A pair that approaches",  // 4
        "> at 1e-16 of its speed.",                                // 5
        "",                                                        // 6
        "```text",                                                 // 7
        "> a quote inside a fence is not a block quote",           // 8
        "```",                                                     // 9
    };
    CHECK(lesson_form_problems("lessons/4-a-lesson.md", good).empty());

    const std::vector<std::string> bad = {
        "Earlier versions of this lesson said so.",             // 1
        "The table, before issue 21, was slower (issue #12).",  // 2
        "after 10 collisions of two balls a ball",              // 3
        "12 collision a ball per unit time",                    // 4
        "a row of R is a Ball; the ball's row is written",      // 5
        "> A note that is no aside.",                           // 6
        "",                                                     // 7
        "> **Aside: code.** Here:",                             // 8
        "> ```cpp",                                             // 9
    };
    const std::vector<std::string> problems = lesson_form_problems("lessons/4-x.md", bad);
    const auto says = [&](const std::string& what) {
      return std::any_of(problems.begin(), problems.end(),
                         [&](const std::string& p) { return p.rfind(what, 0) == 0; });
    };
    CHECK(says("1: 'Earlier versions'"));
    CHECK(says("2: 'before issue'"));
    CHECK(says("2: 'issue 21'"));
    CHECK(says("3: 'collisions of two balls a ball'"));
    CHECK(says("4: 'collision a ball'"));
    CHECK(says("5: 'row of R'"));
    CHECK(says("5: 'ball's row'"));
    CHECK(says("6: a block quote that is not an aside"));
    CHECK(says("9: a fenced block inside a block quote"));
    CHECK_FALSE(says("8:"));  // a well-formed aside

    // Length: a numbered lesson of 501 lines is too long, 500 is not; the
    // README and the exercises are not numbered lessons.
    const std::vector<std::string> long_lesson(most_lesson_lines + 1, "text");
    const std::vector<std::string> full_lesson(most_lesson_lines, "text");
    CHECK(lesson_form_problems("lessons/11-memory.md", long_lesson).size() == 1);
    CHECK(lesson_form_problems("lessons/11-memory.md", full_lesson).empty());
    CHECK(lesson_form_problems("lessons/README.md", long_lesson).empty());
    CHECK(lesson_form_problems("lessons/exercises/01-x/instructions.md", long_lesson)
              .empty());
  }

  TEST_CASE(
      "lessons: no lesson uses a retired phrase, every block quote is an aside, and no "
      "lesson is over 500 lines") {
    // Applies to every lesson, those still being split included: a lesson
    // listed here is one to shorten or reword, not an exception.
    std::vector<std::string> problems;
    for (const std::string& lesson : lesson_files()) {
      for (const std::string& problem :
           lesson_form_problems(lesson, lines_of(read_file(source_path(lesson))))) {
        problems.push_back(fmt::format("{}:{}", lesson, problem));
      }
    }
    CHECK_MESSAGE(problems.empty(), "the lessons' form:" << joined(problems));
  }

  TEST_CASE("lessons: the lessons named by lessons/README.md and by the stages exist") {
    std::vector<std::string> problems;
    const auto exists = [](const std::string& relative) {
      return fs::is_regular_file(source_path(relative));
    };

    // Every lesson file lessons/README.md names.
    const std::string readme = read_file(source_path("lessons/README.md"));
    const std::set<std::string> named = named_lessons(readme, "lessons");
    for (const std::string& lesson : named) {
      if (!exists(lesson))
        problems.push_back(
            fmt::format("lessons/README.md names {}, which does not exist", lesson));
    }
    // The README names each lesson of the seven stages and the rest.
    for (const char* lesson :
         {"lessons/1-variables-and-data.md", "lessons/2-input.md",
          "lessons/3-screen-preparation.md", "lessons/4-first-collision.md",
          "lessons/5-new-coordinates.md", "lessons/6-output.md",
          "lessons/7-model-control.md", "lessons/8-errata.md",
          "lessons/9-time-reversal.md", "lessons/10-scaling.md", "lessons/11-memory.md",
          "lessons/12-statistics-screen.md", "lessons/13-box-and-bulk.md",
          "lessons/14-error-bars.md", "lessons/15-chaos.md",
          "lessons/16-long-time-tail.md"}) {
      if (named.count(lesson) == 0)
        problems.push_back(fmt::format("lessons/README.md does not name {}", lesson));
    }

    // Every relative link of every lesson leads to a file or a folder.
    for (const std::string& lesson : lesson_files()) {
      const std::string directory = fs::path(lesson).parent_path().generic_string();
      for (const std::string& target :
           relative_links(read_file(source_path(lesson)), directory)) {
        if (!fs::exists(source_path(target))) {
          problems.push_back(
              fmt::format("{} links to {}, which does not exist", lesson, target));
        }
      }
    }

    // Every "Lesson:" line of a stage file points to a lesson that exists,
    // and every stage of the article has one.
    static const std::regex lesson_line(R"(^// Lesson: (.*)$)");
    static const std::regex lesson_path(R"(lessons/[A-Za-z0-9_./-]+\.md)");
    for (const std::string& file : stage_files()) {
      bool has_lesson_line = false;
      int number = 0;
      for (const std::string& line : lines_of(read_file(source_path(file)))) {
        ++number;
        std::smatch match;
        if (!std::regex_match(line, match, lesson_line)) continue;
        has_lesson_line = true;
        const std::string rest = match[1];
        bool points = false;
        for (auto it = std::sregex_iterator(rest.begin(), rest.end(), lesson_path);
             it != std::sregex_iterator(); ++it) {
          points = true;
          if (!exists(it->str())) {
            problems.push_back(
                fmt::format("{}:{}: 'Lesson: {}' names a lesson that does not exist",
                            file, number, it->str()));
          }
        }
        if (!points)
          problems.push_back(fmt::format(
              "{}:{}: a 'Lesson:' line that names no lessons/....md", file, number));
      }
      // Every header, of a stage, of beyond/ or of program/, names its lesson.
      if (!has_lesson_line && fs::path(file).extension() == ".hpp") {
        problems.push_back(
            fmt::format("{}: no '// Lesson: lessons/...' line in its header", file));
      }
    }
    CHECK_MESSAGE(problems.empty(), "lesson names and links:" << joined(problems));
  }
}
