// The program installed like any Unix program (issue 25): scenes by name,
// --version, and the manual page in step with --help.
//
// - Scenes by name: `gas crowd`, `gas crowd.scene`, `gas hard/corner` from a
//   folder that holds no scene run the source tree's scenes (the program is
//   run from its build folder), the same frames as the file named; a name
//   found nowhere: exit 2, nothing on stdout, and a message that lists every
//   place looked at.
// - scene_folders: a program inside its build folder looks in the source
//   tree's data/, an installed one in share/gas-on-the-display beside its
//   bin/ (a folder whose name only begins like the build folder's is not
//   inside it); find_scene: a file first, then NAME.scene, never a folder.
// - --version: "gas VERSION (...)" with CMake's project version, then the
//   commit, which is known when the source tree is a git checkout.
// - The manual page (stages/program/gas.1.in) names every option of --help
//   and no other, every key of --help's key list and no other, and every
//   exit status --help gives; its SYNOPSIS every option of --help's usage.
// - --help fits a terminal of 80 columns.
// - What a Debian package must carry: the copyright in Debian's
//   machine-readable form, a changelog whose newest entry names the
//   project's version, the manual page and the changelog gzipped as
//   `gzip -9n` does (no name, no time: the same bytes from every build), and
//   `cmake --install` puts them where lintian looks.
// Not one of the article's stages; the reference: README.md ("Installing").
#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "program/options.hpp"
#include "program/scene_lookup.hpp"
#include "program/version.hpp"
#include "stage2_input.hpp"
#include "support.hpp"

using gas::testing::read_file;
using gas::testing::run_program;
using gas::testing::run_program_in;
using gas::testing::Scratch;
using gas::testing::source_path;

namespace {

namespace fs = std::filesystem;

// Every match of the regex's first group in `text`, as a set.
std::set<std::string> matches_of(const std::string& text, const std::string& pattern) {
  std::set<std::string> found;
  const std::regex regex(pattern);
  for (auto match = std::sregex_iterator(text.begin(), text.end(), regex);
       match != std::sregex_iterator(); ++match) {
    found.insert((*match)[1].str());
  }
  return found;
}

// The part of `text` from the line starting with `from` to the next line
// starting with `to` (to the end if there is none).
std::string section_of(const std::string& text, const std::string& from,
                       const std::string& to) {
  const std::size_t start = text.find("\n" + from);
  REQUIRE_MESSAGE(start != std::string::npos, "no section " << from);
  const std::size_t end = text.find("\n" + to, start + 1);
  return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The manual page's source.
std::string manual_page() {
  return read_file(source_path("stages/program/gas.1.in"));
}

// The options a text names: words that start with - or --.
std::set<std::string> options_in(const std::string& text) {
  return matches_of(text, "(?:^|[\\s\\[(|])(--?[a-z][a-z0-9-]*)");
}

// The options a part of the manual page names (its hyphens written \-).
std::set<std::string> options_in_page(const std::string& text) {
  std::set<std::string> options;
  for (const std::string& option :
       matches_of(text, "(?:^|[\\s\\[(|\"])((?:\\\\-){1,2}[a-z][a-z0-9-]*)"))
    options.insert(std::regex_replace(option, std::regex("\\\\-"), "-"));
  return options;
}

// What `gzip -dc` makes of a file.
std::string gunzipped(const std::string& path) {
  const gas::testing::Scratch scratch;
  const std::string out = scratch.file("out");
  REQUIRE(std::system(fmt::format("gzip -dc '{}' >'{}'", path, out).c_str()) == 0);
  return read_file(out);
}

// Is `path` a gzip file as `gzip -9n` writes it: no file name and no time
// in its header (byte 3, the flags: no FNAME; bytes 4-7, the time: 0), and
// the most compression (byte 8: 2)?
bool gzipped_for_a_package(const std::string& path) {
  const std::string bytes = read_file(path);
  return bytes.size() > 10 && bytes[0] == '\x1f' && bytes[1] == '\x8b' &&
         (bytes[3] & 0x08) == 0 && bytes.substr(4, 4) == std::string(4, '\0') &&
         bytes[8] == 2;
}

}  // namespace

TEST_SUITE("install") {
  TEST_CASE("scenes by name: crowd and crowd.scene and hard/corner run from any folder") {
    const Scratch elsewhere;  // a folder with no scene in it
    const auto by_file = run_program({"data/crowd.scene", "--frames", "2"});
    REQUIRE(by_file.status == 0);
    for (const char* name : {"crowd", "crowd.scene"}) {
      CAPTURE(name);
      const auto by_name =
          run_program_in(elsewhere.path.string(), {name, "--frames", "2"});
      CHECK(by_name.status == 0);
      CHECK(by_name.err.empty());
      CHECK(by_name.out == by_file.out);
    }
    // --trace says which file stage 2 read: the source tree's, found by name.
    const auto traced = run_program_in(elsewhere.path.string(),
                                       {"hard/corner", "--trace", "--frames", "1"});
    CHECK(traced.status == 0);
    CHECK(traced.out.find(fmt::format("stage 2  input: 1 ball from {}\n",
                                      source_path("data/hard/corner.scene"))) !=
          std::string::npos);
  }

  TEST_CASE("scenes by name: a name found nowhere says where it looked and exits 2") {
    const Scratch elsewhere;
    const auto run = run_program_in(elsewhere.path.string(), {"crowdd", "--frames", "1"});
    CHECK(run.status == 2);
    CHECK(run.out.empty());
    CHECK(run.err ==
          fmt::format(
              "crowdd: no such scene file (looked in the current folder and at {})\n",
              source_path("data/crowdd.scene")));
    // A folder of the scenes is no scene: not taken for one.
    const auto folder =
        run_program_in(elsewhere.path.string(), {"hard", "--frames", "1"});
    CHECK(folder.status == 2);
    CHECK(folder.out.empty());
    CHECK(folder.err.find(source_path("data/hard.scene")) != std::string::npos);
  }

  TEST_CASE(
      "scene_folders: the build's source data/ or share/ beside an installed bin/") {
    const fs::path build = "/work/project/build";
    const fs::path source = "/work/project/data";
    const fs::path share = "../share/gas-on-the-display";
    using Folders = std::vector<fs::path>;
    CHECK(gas::scene_folders(build / "gas", build, source, share) == Folders{source});
    CHECK(gas::scene_folders(build / "tests" / "gas_tests", build, source, share) ==
          Folders{source});
    CHECK(gas::scene_folders("/usr/bin/gas", build, source, share) ==
          Folders{"/usr/share/gas-on-the-display"});
    CHECK(gas::scene_folders("/tmp/p/bin/gas", build, source, share) ==
          Folders{"/tmp/p/share/gas-on-the-display"});
    // Its name begins like the build folder's, but it is another folder.
    CHECK(gas::scene_folders("/work/project/build-deb/gas", build, source, share) ==
          Folders{"/work/project/share/gas-on-the-display"});
  }

  TEST_CASE(
      "find_scene: a file as it is or else NAME.scene in a folder but never a folder") {
    const Scratch scratch;
    const fs::path scenes = scratch.path / "scenes";
    fs::create_directories(scenes / "hard");
    for (const char* name : {"crowd.scene", "hard/corner.scene"})
      std::ofstream(scenes / name) << "a 1\n";
    const std::vector<fs::path> folders{scenes};
    const std::string here = source_path("data/default.scene");  // an existing file
    CHECK(gas::find_scene(here, folders) == here);
    CHECK(gas::find_scene("crowd", folders) == (scenes / "crowd.scene").string());
    CHECK(gas::find_scene("crowd.scene", folders) == (scenes / "crowd.scene").string());
    CHECK(gas::find_scene("hard/corner", folders) ==
          (scenes / "hard/corner.scene").string());
    // An absolute path is not looked up: stage 2 says it is missing.
    CHECK(gas::find_scene("/no/such.scene", folders) == "/no/such.scene");
    CHECK_THROWS_WITH_AS(
        gas::find_scene("hard", folders),
        fmt::format("hard: no such scene file (looked in the current folder and at {})",
                    (scenes / "hard.scene").string())
            .c_str(),
        gas::SceneError);
    CHECK_THROWS_WITH_AS(
        gas::find_scene("x", {scenes, scratch.path}),
        fmt::format(
            "x: no such scene file (looked in the current folder and at {} and {})",
            (scenes / "x.scene").string(), (scratch.path / "x.scene").string())
            .c_str(),
        gas::SceneError);
  }

  TEST_CASE("--version: the name and CMake's project version and the commit") {
    const auto run = run_program({"--version"});
    CHECK(run.status == 0);
    CHECK(run.err.empty());
    CHECK(run.out == gas::version_text());
    std::smatch match;
    REQUIRE_MESSAGE(
        std::regex_match(run.out, match,
                         std::regex("gas ([0-9]+\\.[0-9]+\\.[0-9]+) \\(Gas on "
                                    "the display[^\n]*\\)\ncommit ([^\n]+)\n")),
        run.out);
    CHECK(match[1] == GAS_VERSION);
    // Built from a checkout: git's description of it, e.g. f0385bc0e1a2 or
    // f0385bc0e1a2-dirty (v1.0.0-3-gf0385bc0e1a2 once tagged).
    if (fs::exists(source_path(".git"))) {
      CHECK(std::regex_match(match[2].str(),
                             std::regex("([^ ]+-g)?[0-9a-f]{12,40}(-dirty)?")));
    } else {
      CHECK(match[2] == "unknown (not built from a git checkout)");
    }
  }

  TEST_CASE("--help fits 80 columns and the manual page's SYNOPSIS names its usage") {
    const std::string help = gas::help_text();
    for (const std::string& line : gas::testing::lines_of(help)) {
      CAPTURE(line);
      CHECK(line.size() <= 80);
    }
    // --help's usage (to the first blank line) against the page's SYNOPSIS.
    const std::size_t usage = help.find("usage:");
    REQUIRE(usage != std::string::npos);
    const auto in_usage =
        options_in(help.substr(usage, help.find("\n\n", usage) - usage));
    const auto in_synopsis =
        options_in_page(section_of(manual_page(), ".SH SYNOPSIS", ".SH "));
    REQUIRE(in_usage.count("--structure") == 1);  // the pattern reads the usage
    for (const std::string& option : in_usage) {
      CAPTURE(option);
      CHECK_MESSAGE(in_synopsis.count(option) == 1,
                    "add " << option << " to the SYNOPSIS of stages/program/gas.1.in");
    }
    for (const std::string& option : in_synopsis) {
      CAPTURE(option);
      CHECK(in_usage.count(option) == 1);
    }
  }

  TEST_CASE(
      "the package's copyright and changelog: machine-readable and the project's "
      "version") {
    // Debian's machine-readable format: its Format line, a Files paragraph
    // with a Copyright and a License; the license's name followed by its text.
    const std::vector<std::string> copyright =
        gas::testing::lines_of(read_file(source_path("stages/program/copyright")));
    REQUIRE(!copyright.empty());
    CHECK(copyright[0] ==
          "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/");
    const auto files = std::find(copyright.begin(), copyright.end(), "Files: *");
    REQUIRE(files != copyright.end());
    REQUIRE(files + 3 < copyright.end());
    CHECK(files[1].rfind("Copyright: ", 0) == 0);
    CHECK(files[2].rfind("License: ", 0) == 0);
    CHECK(files[3].rfind(" ", 0) == 0);  // the license's text
    // The changelog, newest entry first: the version CMake gives the package.
    const std::vector<std::string> changelog =
        gas::testing::lines_of(read_file(source_path("stages/program/changelog")));
    REQUIRE(!changelog.empty());
    CHECK(changelog[0] ==
          fmt::format("gas-on-the-display ({}) unstable; urgency=medium", GAS_VERSION));
    CHECK(std::regex_match(
        changelog.back(), std::regex(" -- .+ <.+>  [A-Z][a-z]{2}, [0-9]{2} [A-Z][a-z]{2} "
                                     "[0-9]{4} [0-9:]{8} [+-][0-9]{4}")));
  }

  TEST_CASE(
      "cmake --install puts the gzipped page and the copyright and the changelog in "
      "place") {
    const gas::testing::Scratch prefix;
    const std::string command =
        fmt::format("'{}' --install '{}' --prefix '{}' >'{}' 2>&1", GAS_CMAKE,
                    GAS_BUILD_FOLDER, prefix.path.string(), prefix.file("log"));
    REQUIRE_MESSAGE(std::system(command.c_str()) == 0, read_file(prefix.file("log")));
    const fs::path doc = prefix.path / "share/doc/gas-on-the-display";
    const std::string page = (prefix.path / "share/man/man1/gas.1.gz").string();
    const std::string changelog = (doc / "changelog.gz").string();
    REQUIRE(fs::exists(page));
    REQUIRE(fs::exists(changelog));
    CHECK(!fs::exists(prefix.path / "share/man/man1/gas.1"));  // only gzipped
    CHECK(gzipped_for_a_package(page));
    CHECK(gzipped_for_a_package(changelog));
    CHECK(gunzipped(page) == read_file(fmt::format("{}/gas.1", GAS_BUILD_FOLDER)));
    CHECK(gunzipped(changelog) == read_file(source_path("stages/program/changelog")));
    CHECK(read_file((doc / "copyright").string()) ==
          read_file(source_path("stages/program/copyright")));
  }

  TEST_CASE("the manual page names every option of --help and no other") {
    const std::string help = gas::help_text();
    const std::string page = manual_page();
    // An option starts a word: the hyphen of billiard-ball is none. In the
    // page an option's hyphens are \- (hyphens that copy as such).
    const auto in_help = options_in(help);
    const auto in_page = options_in_page(page);
    REQUIRE(in_help.count("--frames") == 1);  // the pattern reads --help
    for (const std::string& option : in_help) {
      CAPTURE(option);
      CHECK_MESSAGE(in_page.count(option) == 1,
                    "add " << option << " to stages/program/gas.1.in (see its top)");
    }
    for (const std::string& option : in_page) {
      CAPTURE(option);
      CHECK_MESSAGE(in_help.count(option) == 1,
                    option << " is in the manual page but not in --help");
    }
  }

  TEST_CASE("the manual page names every key and exit status of --help") {
    const std::string help = gas::help_text();
    const std::string page = manual_page();
    // --help's keys: "S stop, R run, ..., E end; beyond the article, A restarts".
    const std::string key_list = section_of(help, "keys", "In a terminal");
    const auto help_keys = matches_of(key_list, "(?:[:,;]|\n) +(\\S) [a-z]");
    const auto page_keys =
        matches_of(section_of(page, ".SH KEYS", ".SH "), "\n\\.B (\\S)\n");
    CHECK(help_keys == std::set<std::string>{"S", "R", "B", ">", "<", "0", "E", "A"});
    CHECK(page_keys == help_keys);
    const std::string help_statuses = help.substr(help.find("Exit status:"));
    const std::string page_statuses = section_of(page, ".SH EXIT STATUS", ".SH ");
    const auto statuses = matches_of(help_statuses, "\\b([0-9]{1,3})\\b");
    CHECK(statuses == std::set<std::string>{"0", "1", "2", "128", "129", "130", "143"});
    const auto in_page = matches_of(page_statuses, "\\b([0-9]{1,3})\\b");
    for (const std::string& status : statuses) {
      CAPTURE(status);
      CHECK(in_page.count(status) == 1);
    }
  }
}
