// Stage 4 — first collision: memory in large pages for the grid's books
// (beyond the article).
//
// What this file does: gives the cell grid and its event calendar a
// std::vector whose memory, once it is 2 MiB or more, is asked of the system
// in 2 MiB pages instead of the usual 4 KiB ones; and asks for memory
// already in use (the gas's columns of R) to be moved into such pages.
//
// Why: every address a program reads is translated to a place in the
// machine's memory, page by page, and the processor keeps only the last two
// thousand or so translations at hand. With 4 KiB pages that covers 8 MiB;
// the grid's books and the columns of R are some 80 bytes a ball, read at
// random, so past 10^5 balls most reads would first wait for a translation
// fetched from the page tables. In 2 MiB pages, a few translations cover
// them. (Measured when the books first went into large pages, at N = 10^5:
// 8 to 12 % less time per collision. Below 2 MiB nothing changes.)
// Beyond the article: a memory of 1989 had no pages to speak of.
// Lesson: lessons/11-memory.md (step 5 of beyond/cell_grid.hpp)
//
// Assumptions: Linux's "transparent huge pages" in the mode `madvise` or
// `always` (Debian's default is `madvise`); where they are off, or where
// <sys/mman.h> has no MADV_HUGEPAGE, the memory is ordinary and only the
// speed differs. The memory is released with std::free.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

#if __has_include(<sys/mman.h>)
#include <sys/mman.h>
#endif

namespace gas {

template <typename T>
struct LargePageAllocator {
  using value_type = T;
  static constexpr std::size_t large_page = std::size_t{1} << 21;  // 2 MiB

  LargePageAllocator() = default;
  template <typename U>
  LargePageAllocator(const LargePageAllocator<U>&) {}  // (for rebinding)

  T* allocate(std::size_t count) {
    const std::size_t bytes = count * sizeof(T);
    // A block of 2 MiB or more starts on a large page's edge; a smaller one
    // is aligned as its type needs. (aligned_alloc wants a size that is a
    // multiple of the alignment.)
    const std::size_t alignment = bytes >= large_page
                                      ? large_page
                                      : std::max(alignof(T), alignof(std::max_align_t));
    const std::size_t size = (bytes + alignment - 1) / alignment * alignment;
    void* block = std::aligned_alloc(alignment, std::max(size, alignment));
    if (block == nullptr) throw std::bad_alloc();
#ifdef MADV_HUGEPAGE
    if (alignment == large_page) madvise(block, size, MADV_HUGEPAGE);  // a wish
#endif
    return static_cast<T*>(block);
  }
  void deallocate(T* block, std::size_t) {
    std::free(block);
  }

  template <typename U>
  bool operator==(const LargePageAllocator<U>&) const {
    return true;
  }
};

// A std::vector in large pages, for arrays read at random places.
template <typename T>
using LargePageVector = std::vector<T, LargePageAllocator<T>>;

// Asks the system to move memory already in use into large pages now: the
// 2 MiB pages that lie wholly within [data, data + bytes). For an array the
// grid reads at random places but does not own: the columns of R, in the gas
// (40 MB at 10^6 balls: ten thousand small pages, far more translations
// than the processor keeps at hand). MADV_HUGEPAGE alone only marks memory
// already in use for the system's sweeper, which moves it minutes later, if
// at all; MADV_COLLAPSE moves it at once (Linux 6.1 and later; an older
// kernel refuses it). Measured on build/gas at 10^6 balls to T = 5 (paired
// rounds of processor time): without MADV_COLLAPSE 1.13x to 1.18x the time,
// without either some 1.8x; at 10^5 (4 MB of columns) no difference. Only
// the speed depends on it.
inline void ask_large_pages(const void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
#ifdef MADV_COLLAPSE
  constexpr int collapse = MADV_COLLAPSE;
#else
  constexpr int collapse = 25;  // Linux's number (glibc 2.36's <sys/mman.h> lacks it)
#endif
  constexpr std::size_t large_page = std::size_t{1} << 21;
  const auto from = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t start = (from + large_page - 1) / large_page * large_page;
  const std::uintptr_t end = (from + bytes) / large_page * large_page;
  if (end <= start) return;
  void* block = reinterpret_cast<void*>(start);
  madvise(block, end - start, MADV_HUGEPAGE);
  madvise(block, end - start, collapse);
#else
  (void)data;
  (void)bytes;
#endif
}

}  // namespace gas
