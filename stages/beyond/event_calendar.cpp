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
      places.new_day();
    }
  }
}
// [/anchor: calendar-earliest]

}  // namespace gas
