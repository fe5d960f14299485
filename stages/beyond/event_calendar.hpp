// Stage 4 — first collision: an event calendar, the cell grids' queue
// (beyond the article).
//
// What this file does: holds one key per ball — the time of the ball's
// earliest predicted event and its place in the article's scan — and gives
// the ball with the smallest key. It is a calendar (R. Brown, "Calendar
// queues", Comm. ACM 31, 1988): model time is cut into days of equal length,
// and a page per day-of-the-year keeps the balls whose key falls on that day,
// in this year or a later one. The next event is on the page of today: only
// the few balls there are compared. Moving a key costs a few steps whatever
// N is; a binary heap takes log2 N steps, each at a scattered place in
// memory.
// Beyond the article: the article scans every event anew. Ties are broken
// exactly as the scan breaks them (beyond/event_order.hpp): a day is only a
// coarse first sorting, the same for equal times, and the balls of a day are
// compared by (time, place). The place is asked of the calendar's owner
// (`Places`), and only when two times are equal: the calendar keeps no copy
// of it, 8 bytes a ball fewer to write at every change of a key.
// Lesson: lessons/10-scaling.md
//
// Assumptions: a key is never set earlier than the earliest key of the
// calendar was when it was last asked (model time runs forward); a key set
// earlier all the same (round-off can place an event a hair in the past)
// counts as today's. At most 2^31 - 1 balls.
#pragma once

#include <cstdint>
#include <vector>

#include "beyond/large_pages.hpp"

namespace gas {

class EventCalendar {
 public:
  // What the calendar asks its owner: when two keys have the same time, the
  // second part of a ball's key, its place in the scan's order. And it tells
  // the owner each time today moves on a day (the tuned grid looks ahead
  // from there: beyond/cell_grid.hpp, step 6).
  class Places {
   public:
    virtual std::uint64_t place(int ball) const = 0;
    virtual void new_day() const {}

   protected:
    ~Places() = default;
  };

  // Balls 1..count, none with an event yet.
  void reset(std::size_t count);

  // The key of `ball` becomes (time, its place as `Places` gives it then); a
  // time of `never` (infinity) takes the ball off the calendar.
  void schedule(int ball, double time);

  // The ball with the smallest key (time, then place), or 0 if no ball has
  // an event.
  int earliest(const Places& places);

  // What an owner that looks ahead reads: today; the first ball on the page
  // of a day, and the next on its page after a ball (0: no more); the day a
  // ball's key falls on (a page also holds the balls of later years). And,
  // to ask memory for them early, where a page and an entry are.
  std::int32_t today() const { return today_; }
  int first_on_page(std::int32_t day) const { return page(day); }
  int next_on_page(int ball) const { return entry(ball).next; }
  std::int32_t key_day(int ball) const { return entry(ball).day; }
  const void* page_address(std::int32_t day) const { return &page(day); }
  const void* entry_address(int ball) const { return &entry(ball); }

  // How many times it was laid out since `reset` (for tests).
  long long layouts() const { return layouts_; }

 private:
  // A ball's key and its place in the calendar: on the page `day % pages`,
  // in a list of balls linked one way (0 ends it). (The key's second part,
  // the place in the scan, is asked of `Places` on a tie of times.)
  // (16 bytes: days are counted in 32 bits, the calendar laid out afresh
  // before today reaches the last of them.)
  struct Entry {
    double time = 0;         // its earliest event (model time)
    std::int32_t day = off;  // the day it falls on (today if in the past)
    std::int32_t next = 0;   // the next ball on its page
  };
  static constexpr std::int32_t off = -1;  // a `day` for: not on the calendar

  std::int32_t day_of(double time) const;
  // The page of a day: its first ball, or 0 (pages reused year after year).
  std::int32_t& page(std::int32_t day) {
    return page_[static_cast<std::uint64_t>(day) & page_mask_];
  }
  const std::int32_t& page(std::int32_t day) const {
    return page_[static_cast<std::uint64_t>(day) & page_mask_];
  }
  const Entry& entry(int ball) const { return entries_[static_cast<std::size_t>(ball)]; }
  void put_on_page(int ball);
  void take_off_page(int ball);
  void lay_out();
  int earliest_of_today(const Places& places);

  LargePageVector<Entry> entries_;      // by ball number 1..N (entry 0 unused)
  std::vector<double> waits_;           // lay_out's scratch (a sample of the keys)
  LargePageVector<std::int32_t> page_;  // first ball on each page, or 0
  std::uint64_t page_mask_ = 0;         // pages - 1 (pages is a power of two)
  std::size_t on_calendar_ = 0;         // how many balls have an event
  bool laid_out_ = false;               // are the days' length and start chosen?
  double first_day_starts_ = 0;         // model time at which day 0 starts
  double days_per_unit_ = 0;            // 1 / the length of a day in model time
  long long layouts_ = 0;               // lay_out calls since reset
  std::int32_t today_ = 0;              // the day of the earliest key
  std::uint64_t questions_ = 0;         // calls of `earliest` since the last check
  std::uint64_t looked_ = 0;            // balls compared and empty days turned since
};

}  // namespace gas
