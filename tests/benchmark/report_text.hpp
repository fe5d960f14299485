// What every section of the benchmark's report writes with: its progress
// lines on standard error, counts in words a reader takes in at a glance,
// and the verdict on a target.
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <string>
#include <utility>

namespace gas::benchmark {

template <class... Args>
void progress(fmt::format_string<Args...> format, Args&&... args) {
  fmt::print(stderr, "gas-benchmark: {}\n",
             fmt::format(format, std::forward<Args>(args)...));
  std::fflush(stderr);
}

// 2140000 -> "2.14 M", 25900 -> "25.9 k", 198 -> "198".
inline std::string count_text(double x) {
  if (x >= 1e6) return fmt::format("{:.2f} M", x / 1e6);
  if (x >= 1e3) return fmt::format("{:.1f} k", x / 1e3);
  return fmt::format("{:.0f}", x);
}

inline std::string yes_no(bool met) {
  return met ? "**met**" : "**not met**";
}

}  // namespace gas::benchmark
