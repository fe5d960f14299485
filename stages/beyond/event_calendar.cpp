// Stage 4 — first collision: an event calendar. See beyond/event_calendar.hpp.
#include "beyond/event_calendar.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "stage4_first_collision.hpp"

namespace gas {

namespace {

// Days beyond this are all one day (their keys are still compared exactly);
// the calendar is laid out afresh (today back to day 0) when today reaches
// half of it. An exact double, and a day that fits in 32 bits.
constexpr double last_day = 0x1p30;
constexpr std::int32_t lay_out_again_on = 1 << 29;

// The median wait is taken from at most this many keys, evenly spread over
// the balls: its use is to choose a day's length to within a few per cent,
// and a copy of every key would cost 8 bytes a ball.
constexpr std::size_t most_waits_sampled = 1 << 16;

// How much looking (balls compared on today's page, empty days turned) per
// question the calendar puts up with before it lays itself out again with
// days fitted to the keys it holds now. (Laid out well, it looks at about
// three.)
constexpr std::uint64_t looking_per_question = 16;

// The calendar looks ahead only for this many balls or more: with fewer, the
// books (some 100 bytes a ball) are read from the caches (second level: 512
// KiB a core on the machines measured; the third, a few MiB), waits are
// short, and the look ahead's work is a loss. Measured on build/gas, medians
// of 5 interleaved runs against the same build without the look ahead: 13 %
// slower at 3000 balls, even at 6000; 15 % slower at 10^4 and 8 % at 15000
// (since the look ahead asks for the cells a crossing gathers: when it asked
// for the 3 x 3 cells of every event, and the books were 146 bytes a ball,
// it was 15 % faster at 10^4); 14 % faster at 20000, 26 % at 30000.
constexpr std::size_t look_ahead_from = 1 << 14;

// The look ahead's stages (see the header), in days before a ball's day:
// the line of pages, the first ball's entry, the second ball's entry, the
// owner's steps 0 to 3. (Tried: a day further for every stage; not faster.
// The owner's fourth step, for a meeting's partner, was 6 % faster at 10^6
// balls, and no slower at 10^5.)
constexpr std::int32_t pages_ahead = 10;
constexpr std::int32_t first_entries_ahead = 6;
constexpr std::int32_t second_entries_ahead = 5;
constexpr std::int32_t owner_ahead[EventCalendar::Places::steps] = {4, 3, 2, 1};

}  // namespace

void EventCalendar::reset(std::size_t count) {
  entries_.assign(count + 1, Entry{});
  // About one page per ball: with days as long as below, most keys fall
  // within a year, and a page holds few balls.
  page_.assign(std::bit_ceil(std::max<std::size_t>(count, 16)), 0);
  page_mask_ = page_.size() - 1;
  on_calendar_ = 0;
  laid_out_ = false;
  layouts_ = 0;
  today_ = 0;
  questions_ = looked_ = 0;
  looking_ahead_ = count >= look_ahead_from;
}

// The day a key's time falls on: floor((time - start of day 0) x days per
// unit of time), never before today. Every step keeps the order of the times
// (a later time never gets an earlier day: rounded subtraction and
// multiplication by a positive number are monotonic), so days sort keys as
// their times do, and only keys of one day need comparing.
std::int32_t EventCalendar::day_of(double time) const {
  const double days = (time - first_day_starts_) * days_per_unit_;
  if (!(days >= 0)) return today_;  // in the past: today
  const auto day = static_cast<std::int32_t>(std::min(days, last_day));
  return std::max(day, today_);
}

void EventCalendar::put_on_page(int ball) {
  Entry& entry = entries_[static_cast<std::size_t>(ball)];
  std::int32_t& first = page(entry.day);
  entry.next = first;
  first = ball;
}

// (A page holds a ball or two: its list is walked to find the one before.)
void EventCalendar::take_off_page(int ball) {
  const Entry& entry = entries_[static_cast<std::size_t>(ball)];
  std::int32_t* link = &page(entry.day);
  while (*link != ball) link = &entries_[static_cast<std::size_t>(*link)].next;
  *link = entry.next;
}

void EventCalendar::schedule(int ball, double time) {
  Entry& entry = entries_[static_cast<std::size_t>(ball)];
  if (entry.day != off) {
    if (laid_out_) take_off_page(ball);
    entry.day = off;
    --on_calendar_;
  }
  entry.time = time;
  if (!(time < never)) return;
  ++on_calendar_;
  entry.day = laid_out_ ? day_of(time) : today_;
  if (laid_out_) put_on_page(ball);
}

// Choose the days for the keys held now: day 0 starts at the earliest key,
// and a day is three times the median wait beyond it divided by the number
// of keys, so that about two balls fall on each of the first days.
void EventCalendar::lay_out() {
  double earliest_time = never;
  for (const Entry& entry : entries_)
    if (entry.day != off) earliest_time = std::min(earliest_time, entry.time);
  // The median wait, not the mean: one ball whose next event is 10^70 time
  // units away (a ball all but at rest) must not make every day that long.
  // (From a sample: every stride-th ball.)
  waits_.clear();
  const std::size_t stride = entries_.size() / most_waits_sampled + 1;
  for (std::size_t ball = 1; ball < entries_.size(); ball += stride)
    if (entries_[ball].day != off) waits_.push_back(entries_[ball].time - earliest_time);
  if (waits_.empty()) waits_.push_back(0);  // (only unsampled balls have keys)
  const auto middle = waits_.begin() + static_cast<std::ptrdiff_t>(waits_.size() / 2);
  std::nth_element(waits_.begin(), middle, waits_.end());
  // (For waits spread as in a gas, roughly exponentially, the median is 0.7
  // of the mean, and near today N keys fall about N / mean to a unit of time.)
  double day_length = 3 * *middle / static_cast<double>(on_calendar_);
  if (!(day_length > 0 && day_length < never)) day_length = 1;  // all at one time
  days_per_unit_ = 1 / day_length;
  if (!(days_per_unit_ < never)) days_per_unit_ = 0x1p1000;  // days shorter than 1e-308
  first_day_starts_ = earliest_time;
  today_ = 0;
  std::fill(page_.begin(), page_.end(), 0);
  laid_out_ = true;
  ++layouts_;
  for (std::size_t ball = 1; ball < entries_.size(); ++ball) {
    Entry& entry = entries_[ball];
    if (entry.day == off) continue;
    entry.day = day_of(entry.time);
    put_on_page(static_cast<int>(ball));
  }
  questions_ = looked_ = 0;
}

// The smallest key among the balls whose day is today, or 0 if there is none
// (the balls of later years on the same page are passed over).
int EventCalendar::earliest_of_today(const Places& places) {
  int best = 0;
  for (std::int32_t ball = page(today_); ball != 0;) {
    const Entry& entry = entries_[static_cast<std::size_t>(ball)];
    ++looked_;
    if (entry.day == today_) {
      if (best == 0 || entry.time < entries_[static_cast<std::size_t>(best)].time ||
          (entry.time == entries_[static_cast<std::size_t>(best)].time &&
           places.place(ball) < places.place(best)))
        best = ball;
    }
    ball = entry.next;
  }
  return best;
}

// Today has moved on a day: the look ahead's stages, each on its day ahead
// (see the header). Reads only pages and entries asked for a day before (a
// page's third ball and later: rare, and read as they come). (Ball 0's
// entry, on an empty page, is read as any other: its `next` is 0.)
void EventCalendar::look_ahead(const Places& places) const {
  const auto first_on = [&](std::int32_t ahead) { return page(today_ + ahead); };
  const auto entry_of = [&](std::int32_t ball) -> const Entry& {
    return entries_[static_cast<std::size_t>(ball)];
  };
  __builtin_prefetch(&page(today_ + pages_ahead));
  __builtin_prefetch(&entry_of(first_on(first_entries_ahead)));
  __builtin_prefetch(&entry_of(entry_of(first_on(second_entries_ahead)).next));
  for (int step = 0; step < Places::steps; ++step) {
    const std::int32_t day = today_ + owner_ahead[step];
    for (std::int32_t ball = first_on(owner_ahead[step]); ball != 0;) {
      const Entry& entry = entry_of(ball);
      if (entry.day == day) places.prefetch(ball, step);
      ball = entry.next;
    }
  }
}

// (Step 1 reads the entry step 0 asked for.)
void EventCalendar::prefetch(int ball, int step) const {
  const Entry& entry = entries_[static_cast<std::size_t>(ball)];
  if (step == 0) {
    __builtin_prefetch(&entry);
  } else if (entry.day != off) {
    __builtin_prefetch(&page(entry.day));
  }
}

void EventCalendar::ask_day_early(double time) const {
  if (laid_out_) __builtin_prefetch(&page(day_of(time)));
}

// [anchor: calendar-earliest]
int EventCalendar::earliest(const Places& places) {
  if (on_calendar_ == 0) return 0;
  if (!laid_out_) lay_out();
  // Now and then: are the days still the right length for the keys? (Too
  // long, and today's page is crowded; too short, and most pages are empty.)
  if (++questions_ >= 4 * page_.size()) {
    if (looked_ > looking_per_question * questions_) lay_out();
    questions_ = looked_ = 0;
  }
  // Turn the pages from today until a day has a ball on it. (After a year
  // of empty days, or near the last day 32 bits count, lay the calendar out
  // afresh: then the earliest key falls on day 0.)
  for (std::size_t empty_days = 0;; ++empty_days) {
    const int ball = earliest_of_today(places);
    if (ball != 0) return ball;
    if (empty_days == page_.size() || today_ >= lay_out_again_on) {
      lay_out();
    } else {
      ++today_;
      ++looked_;
      if (looking_ahead_) look_ahead(places);
    }
  }
}
// [/anchor: calendar-earliest]

}  // namespace gas
