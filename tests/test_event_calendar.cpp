// The event calendar (stages/beyond/event_calendar.*): the cell grid's queue.
//
// The calendar must give exactly the ball with the smallest key (time, then
// place) — not nearly: the grid promises the scan's answer bit for bit, ties
// included. So each test here runs the calendar beside a plain reference (a
// list of keys searched in full) through long random sequences of
// schedulings, and requires the same ball at every question:
// - times drawn as an event-driven gas draws them (a little after the
//   present), rounded to a coarse grid so that exact ties are frequent;
// - keys set a hair in the past (round-off does that), taken off (never),
//   and set far in the future (beyond a year of pages);
// - a gas whose pace changes by a factor 10^4 halfway, so that the calendar
//   must lay itself out again;
// - huge times (beyond the last day the calendar counts) and an empty
//   calendar.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "beyond/event_calendar.hpp"
#include "stage4_first_collision.hpp"

namespace {

using gas::EventCalendar;
using gas::never;

// The reference: every ball's key, and the smallest found by looking at all.
struct Keys final : EventCalendar::Places {
  std::vector<double> time;
  std::vector<std::uint64_t> place_of;
  explicit Keys(std::size_t count) : time(count + 1, never), place_of(count + 1, 0) {}
  int earliest() const {
    int best = 0;
    for (std::size_t ball = 1; ball < time.size(); ++ball) {
      if (!(time[ball] < never)) continue;
      const auto b = static_cast<std::size_t>(best);
      if (best == 0 || time[ball] < time[b] ||
          (time[ball] == time[b] && place_of[ball] < place_of[b]))
        best = static_cast<int>(ball);
    }
    return best;
  }
  // What the calendar asks on a tie of times.
  std::uint64_t place(int ball) const override {
    return place_of[static_cast<std::size_t>(ball)];
  }
};

// A place for a ball's key: one of a few, so that ties of time are often
// decided by it, and never the same for two balls (in the grid two keys
// with the same time and place are the same event, held by both its balls,
// and either may come first).
std::uint64_t place_for(int ball, std::mt19937_64& random) {
  return (random() % 8) << 32 | static_cast<std::uint64_t>(ball);
}

// Both told the same.
struct Pair {
  EventCalendar calendar;
  Keys keys;
  explicit Pair(std::size_t count) : keys(count) { calendar.reset(count); }
  void schedule(int ball, double time, std::uint64_t place) {
    calendar.schedule(ball, time);
    keys.time[static_cast<std::size_t>(ball)] = time;
    keys.place_of[static_cast<std::size_t>(ball)] = place;
  }
};

// `questions` rounds of: ask for the earliest (both must agree), then move
// its key and a few others' to new times drawn by `next_time(now)`.
template <typename NextTime>
long long agree_for(std::size_t count, long long questions, std::uint64_t seed,
                    NextTime next_time, long long* layouts = nullptr) {
  std::mt19937_64 random(seed);
  Pair both(count);
  const auto ball_count = static_cast<int>(count);
  for (int ball = 1; ball <= ball_count; ++ball)
    both.schedule(ball, next_time(0.0, random), place_for(ball, random));
  long long agreed = 0;
  for (long long q = 0; q < questions; ++q) {
    const int expected = both.keys.earliest();
    const int found = both.calendar.earliest(both.keys);
    if (found != expected) {
      FAIL_CHECK("question " << q << ": the calendar gives ball " << found
                             << ", the reference " << expected);
      return agreed;
    }
    ++agreed;
    if (layouts != nullptr) *layouts = both.calendar.layouts();
    if (expected == 0) break;
    const double now = both.keys.time[static_cast<std::size_t>(expected)];
    // Like an event: its ball gets a new key, and so, now and then, do one
    // or two others (a collision's partner, a dropped prediction).
    both.schedule(expected, next_time(now, random), place_for(expected, random));
    for (auto others = random() % 3; others-- > 0;) {
      const int other = 1 + static_cast<int>(random() % count);
      both.schedule(other, next_time(now, random), place_for(other, random));
    }
  }
  return agreed;
}

// A wait like the gas's: exponential with the given mean, rounded to
// multiples of 1/64 of the mean (exact ties among many keys), and now and
// then a key a hair in the past, taken off, or a long way ahead.
auto gas_like(double mean) {
  return [mean](double now, std::mt19937_64& random) {
    const double unit = std::ldexp(static_cast<double>(random() >> 11), -53);
    const auto pick = random() % 64;
    if (pick == 0) return never;                               // taken off
    if (pick == 1) return now - 1e-15 * (1 + std::fabs(now));  // round-off: past
    if (pick == 2) return now + 1000 * mean * (1 + unit);      // years ahead
    const double wait = -mean * std::log1p(-unit);
    return now + std::round(wait * 64 / mean) * mean / 64;
  };
}

}  // namespace

TEST_SUITE("stage4") {
  TEST_CASE("event calendar: the earliest key every time, ties by place") {
    // Few balls (a page each) and many (several to a page, many years).
    CHECK(agree_for(5, 20000, 1, gas_like(1.0)) == 20000);
    CHECK(agree_for(200, 50000, 2, gas_like(0.25)) == 50000);
    CHECK(agree_for(3000, 50000, 3, gas_like(3.0)) == 50000);
  }

  TEST_CASE("event calendar: a change of pace makes it lay itself out again") {
    // The first half at one pace, the second 10^4 times faster: the days
    // chosen for the first are far too long for the second (a crowded
    // page), and the other way round (a year of empty pages).
    for (const double factor : {1e-4, 1e4}) {
      CAPTURE(factor);
      long long asked = 0;
      const auto changing = [&asked, first = gas_like(1.0), second = gas_like(factor)](
                                double now, std::mt19937_64& random) mutable {
        return ++asked < 30000 ? first(now, random) : second(now, random);
      };
      long long layouts = 0;
      CHECK(agree_for(500, 40000, 4, changing, &layouts) == 40000);
      CHECK(layouts >= 2);  // the first, and at least one after the change
    }
  }

  TEST_CASE("event calendar: huge times, equal times and an empty calendar") {
    Pair both(6);
    CHECK(both.calendar.earliest(both.keys) == 0);  // nothing on it
    // Beyond the last day the calendar counts (2^62 days of length ~1):
    // those keys share a day and are still compared exactly.
    both.schedule(1, 1e300, 5);
    both.schedule(2, 1e299, 9);
    both.schedule(3, 1e300, 4);
    both.schedule(4, 0.5, 7);
    both.schedule(5, 0.5, 3);  // a tie at 0.5: the smaller place first
    both.schedule(6, 2.0, 1);
    for (const int expected : {5, 4, 6, 2, 3, 1}) {
      REQUIRE(both.calendar.earliest(both.keys) == expected);
      CHECK(both.keys.earliest() == expected);
      both.schedule(expected, never, 0);
    }
    CHECK(both.calendar.earliest(both.keys) == 0);
    // A key set again before the calendar is asked: the last one counts.
    both.schedule(3, 7.0, 0);
    both.schedule(3, 6.0, 0);
    both.schedule(2, 6.5, 0);
    CHECK(both.calendar.earliest(both.keys) == 3);
    // Keys set before the present (before the calendar's day 0, even) count
    // as today's: they come first, in their order.
    for (int ball = 1; ball <= 6; ++ball) both.schedule(ball, 10.0 * ball, 0);
    for (int ball = 1; ball <= 4; ++ball) {
      REQUIRE(both.calendar.earliest(both.keys) == ball);
      both.schedule(ball, never, 0);
    }
    both.schedule(2, -100.0, 1);
    both.schedule(3, 49.0, 0);
    both.schedule(4, -100.0, 0);
    for (const int expected : {4, 2, 3, 5, 6}) {
      REQUIRE(both.calendar.earliest(both.keys) == expected);
      both.schedule(expected, never, 0);
    }
  }
}
