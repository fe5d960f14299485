// Memory in large pages (stages/beyond/large_pages.hpp): the grid's books.
//
// Whether the system backs a block by 2 MiB pages is its own decision (the
// allocator only asks), so a test cannot require it. What the allocator does
// decide is checked: a block of 2 MiB or more starts on a 2 MiB edge (a large
// page can only back a block that covers one whole), a smaller block is
// aligned as its type needs (a type may ask for 64 bytes, a cache line), and a
// vector in such memory keeps what is written to it through growing and
// copying.
#include <doctest/doctest.h>

#include <cstdint>

#include "beyond/large_pages.hpp"

namespace {

using gas::LargePageVector;

std::uintptr_t address(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p);
}

struct alignas(64) Line {
  std::int64_t value = 0;
};

}  // namespace

TEST_SUITE("stage4") {
  TEST_CASE("large pages: a block of 2 MiB or more starts on a 2 MiB edge") {
    constexpr std::size_t large_page = std::size_t{1} << 21;
    for (const std::size_t count : {large_page / 8, large_page / 8 + 1, 3 * large_page}) {
      LargePageVector<std::int64_t> numbers(count, 7);
      CHECK(address(numbers.data()) % large_page == 0);
      CHECK(numbers.front() == 7);
      CHECK(numbers.back() == 7);
    }
  }

  TEST_CASE("large pages: a small block is aligned as its type needs") {
    for (const std::size_t count : {1, 3, 1000}) {
      LargePageVector<Line> lines(count);
      CHECK(address(lines.data()) % alignof(Line) == 0);
    }
    LargePageVector<std::int32_t> few(5, 1);
    CHECK(address(few.data()) % alignof(std::int32_t) == 0);
  }

  TEST_CASE("large pages: a vector keeps its values through growing and copying") {
    LargePageVector<std::int32_t> numbers;
    for (std::int32_t i = 0; i < 600000; ++i) numbers.push_back(i);  // past 2 MiB
    const LargePageVector<std::int32_t> copy = numbers;
    bool same = copy.size() == 600000;
    for (std::int32_t i = 0; same && i < 600000; ++i)
      same = copy[static_cast<std::size_t>(i)] == i;
    CHECK(same);
  }
}
