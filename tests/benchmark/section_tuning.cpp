// Section 7 of the report: what the tuning buys. See section_tuning.hpp.
#include "section_tuning.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "report_text.hpp"

namespace gas::benchmark {
namespace {

// A step of the tuned grid (stages/beyond/cell_grid.hpp numbers them), with
// what it bought as measured when it was added, and the commit.
struct Step {
  const char* name;
  const char* bought;
  const char* commit;
};

constexpr Step steps[] = {
    {"1. Books of 16 bytes",
     "with one event a ball: at 10^6 the process's memory 146.8 to 99.3 MB; in 16 "
     "bytes with 4-byte links: 93 bytes a ball (records of 24 holding the links were "
     "some 10 % slower at 10^5)",
     "c5f69f6, f4d6ffc"},
    {"2. Walls only along the edges",
     "one prediction fewer a ball, and no stale wall far ahead (the grid's from the "
     "first; not measured alone)",
     "493f332"},
    {"3. Coin tosses answered by arithmetic",
     "at 10^4: 565 to 467 ns a collision, wrong guesses 52 to 35 a collision (valgrind); "
     "the gathering's loops written out: 3192 to 3087 instructions a collision at 10^3",
     "9ed262f, 9603fb2"},
    {"4. The quick check of a meeting",
     "at 10^3: 2942 to 2873 instructions a collision (callgrind; two thirds of the "
     "checks answered so)",
     "6507d24"},
    {"5. Large pages",
     "the books: the growth of a collision's cost from 10^3 to 10^5 from 2.1x to below "
     "2x; the columns of R moved in at once (MADV_COLLAPSE): at 10^6 8.28 to 7.30 s "
     "(3 interleaved rounds; measured again since, 7 and 9 paired rounds: without it "
     "1.13x to 1.18x the time)",
     "9ed262f, b2320f3"},
    {"6. The calendar's look ahead",
     "a collision at 10^5 4.00 to 1.98 µs, at 10^6 6.00 to 4.01 µs; asking for the "
     "cells a crossing gathers, and the partner's: 10^5 some 10 %, 10^6 some 15 % "
     "faster; from 16384 balls only: 15 % at 10^4 not lost",
     "756b807, 21692fd, 80f46ee, a9c7dad"},
};

double median_ratio(const RatePairs& tuned, const RatePairs& plain) {
  std::vector<double> ratios;
  for (std::size_t i = 0; i < std::min(tuned.rates.size(), plain.rates.size()); ++i)
    if (plain.rates[i] > 0) ratios.push_back(tuned.rates[i] / plain.rates[i]);
  if (ratios.empty()) return 0;
  std::sort(ratios.begin(), ratios.end());
  const std::size_t n = ratios.size();
  return n % 2 == 1 ? ratios[n / 2] : (ratios[n / 2 - 1] + ratios[n / 2]) / 2;
}

std::string rate_or_failure(const RatePairs& pairs) {
  if (pairs.rates.empty()) return pairs.failure.empty() ? "not run" : "failed";
  return count_text(pairs.median());
}

}  // namespace

std::string tuning_section(const PeerSettings& settings, const PeerFigures& figures) {
  std::string text = fmt::format(
      "## 7. What the tuning buys\n\n"
      "The plain grid (`stages/beyond/plain_grid.*`: cells, one event a ball, the "
      "calendar, nothing else; `--strategy plain-grid`) beside the tuned grid the "
      "program runs (`stages/beyond/cell_grid.*`), both `build/gas --mode none` "
      "processes on the scenes of section 6, in its rounds: interleaved, ball "
      "collisions per second of processor time, the fixed costs removed by a run a "
      "tenth as long, the median of {} rounds; *tuned / plain* is the median of the "
      "rounds' ratios. The two find the same collisions, bit for bit (suite "
      "`strategies`).\n\n"
      "| N | plain grid | tuned grid | tuned / plain | plain: cost a collision against "
      "the smallest N | tuned: the same | plain: bytes a ball | tuned: bytes a ball "
      "|\n|---:|---:|---:|---:|---:|---:|---:|---:|\n",
      settings.rounds);
  const PeerRow& first = figures.rows.front();
  const auto growth = [](const RatePairs& at_first, const RatePairs& here) {
    return at_first.median() > 0 && here.median() > 0
               ? fmt::format("{:.2f}x", at_first.median() / here.median())
               : std::string("—");
  };
  const auto bytes = [](double b) {
    return b > 0 ? fmt::format("{:.0f}", b) : std::string("—");
  };
  for (const PeerRow& row : figures.rows) {
    const double ratio = median_ratio(row.plain, row.plain_grid);
    text += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", row.balls,
                        rate_or_failure(row.plain_grid), rate_or_failure(row.plain),
                        ratio > 0 ? fmt::format("{:.2f}x", ratio) : "—",
                        growth(first.plain_grid, row.plain_grid),
                        growth(first.plain, row.plain),
                        bytes(bytes_per_ball(figures, row, &PeerRow::plain_grid)),
                        bytes(bytes_per_ball(figures, row, &PeerRow::plain)));
  }
  text +=
      "\nThe steps, as `stages/beyond/cell_grid.hpp` numbers and describes them, each "
      "with what it bought when it was added (the commit's own measurement; "
      "`lessons/11-memory.md` has the whole history, what was tried and dropped "
      "included):\n\n"
      "| step | what it bought when added | commit |\n|---|---|---|\n";
  for (const Step& step : steps)
    text += fmt::format("| {} | {} | {} |\n", step.name, step.bought, step.commit);
  return text + "\n";
}

}  // namespace gas::benchmark
