// The benchmark (tests/benchmark/gas_benchmark.cpp) still runs and still
// writes every part of its report. Not a measurement: `gas-benchmark --smoke`
// runs each section at tiny sizes, in seconds, into a scratch folder; this
// test checks the report's sections, its description of the machine and the
// build, the CSV files beside it, the runs of the program itself (sections 5
// and 6, on a tiny scene) and the pictures: drawn if gnuplot is installed, else
// said to be missing. (The real report is made by hand, in minutes:
// README.md, "Speed against error".)
#include <doctest/doctest.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
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

TEST_SUITE("benchmark") {
  TEST_CASE(
      "gas-benchmark --smoke writes a report with every section and its CSV files") {
    const fs::path out = fs::temp_directory_path() /
                         fmt::format("gas-benchmark-test-{}-{}", getpid(), std::rand());
    const std::string command = fmt::format(
        "'{}' --smoke --out '{}' 2>'{}'", GAS_BENCHMARK, out.string(),
        (fs::temp_directory_path() / fmt::format("gas-benchmark-test-{}.err", getpid()))
            .string());
    const int status = std::system(command.c_str());
    REQUIRE_MESSAGE(status == 0, "gas-benchmark --smoke failed: " << command);

    const std::string report = read_file((out / "speed-against-error.md").string());
    for (const char* heading :
         {"# Speed against error\n", "\n## Targets\n", "\n## 1. Throughput\n",
          "\n## 2. Accuracy against cost for the number type\n",
          "\n## 3. Time reversal\n", "\n## 4. What an event-driven program buys\n",
          "\n## 5. The program as users run it\n",
          "\n## 6. Beside the best peer, and a million balls\n",
          "\n## 7. Checkpoints: a dump written and read back\n"}) {
      CHECK_MESSAGE(report.find(heading) != std::string::npos, "no heading " << heading);
    }
    // The machine and the build are described.
    for (const char* row : {"| CPU |", "| compiler |", "| build type |", "| flags |",
                            "| one read from memory, at random among"})
      CHECK_MESSAGE(report.find(row) != std::string::npos, "no row " << row);
    // Six targets are judged: two on the program (section 5), one on
    // --events (section 6); the peer's is not (no --peer: not run).
    std::size_t judged = 0;
    for (std::size_t at = report.find("met**"); at != std::string::npos;
         at = report.find("met**", at + 1))
      ++judged;
    CHECK(judged == 6);
    // Each section's numbers: the tables have rows for every way and type.
    for (const char* cell :
         {"| float |", "| double |", "| long double |", "| __float128 |",
          "| stages (double) |", "| time-stepped |", "| event-driven |",
          "| the engine: section 1's event loop |",
          "| the engine from the scene file to T |",
          "| (a) `build/gas smoke-200.scene --until 20 --mode none` |",
          "| (b) `build/gas smoke-200.scene --until 20 --mode stats --csv out.csv`",
          "| (c) `build/gas smoke-200.scene --until 2 --mode stats --csv out.csv "
          "--pictures collisions`"})
      CHECK_MESSAGE(report.find(cell) != std::string::npos, "no row with " << cell);
    // The program ran: every run of section 5 counted its collisions and none
    // failed (a failure is reported, not thrown).
    const std::string program = report.substr(report.find("\n## 5."));
    CHECK_MESSAGE(program.find("failed") == std::string::npos, program);
    CHECK_MESSAGE(program.find("not known") == std::string::npos, program);
    // Section 6 without --peer: build/gas timed, the peer said not run.
    const std::string peer = report.substr(report.find("\n## 6."));
    CHECK_MESSAGE(peer.find("**not run**: no checkout given") != std::string::npos, peer);
    CHECK_MESSAGE(peer.find("\n| 200 | ") != std::string::npos, peer);
    CHECK_MESSAGE(peer.find("failed") == std::string::npos, peer);
    // Section 7: the tiny scene dumped, read, and continued to the same bytes.
    const std::string dumps = report.substr(report.find("\n## 7."));
    CHECK_MESSAGE(dumps.find("\n| 200 | ") != std::string::npos, dumps);
    CHECK_MESSAGE(dumps.find("| identical |") != std::string::npos, dumps);
    CHECK_MESSAGE(dumps.find("failed") == std::string::npos, dumps);

    // The pictures: drawn and linked if gnuplot is installed, else the report
    // says why there are none.
    const bool gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
    for (const char* picture : {"throughput.svg", "number-types-distance.svg"}) {
      CAPTURE(picture);
      if (gnuplot) {
        CHECK(report.find(fmt::format("]({})", picture)) != std::string::npos);
        CHECK(read_file((out / picture).string()).find("<svg") != std::string::npos);
      } else {
        CHECK(report.find(fmt::format("*(No picture `{}`: gnuplot is not installed",
                                      picture)) != std::string::npos);
      }
    }

    // Every CSV file: its header and at least one row, every row as many
    // fields as the header.
    for (const char* name :
         {"throughput.csv", "default-scene.csv", "number-types.csv",
          "number-types-distance.csv", "time-reversal.csv", "time-stepping.csv",
          "program.csv", "peer.csv", "dumps.csv"}) {
      CAPTURE(name);
      const std::vector<std::string> lines = lines_of(read_file((out / name).string()));
      REQUIRE(lines.size() >= 2);
      const auto fields = [](const std::string& line) {
        return std::count(line.begin(), line.end(), ',');
      };
      for (const std::string& line : lines) CHECK(fields(line) == fields(lines[0]));
    }
    fs::remove_all(out);
  }
}
