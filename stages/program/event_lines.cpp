// The lines of --events, written fast. See event_lines.hpp.
#include "program/event_lines.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>

namespace gas {
namespace {

// The eight decimal digits of `value` (below 10^8, leading zeros included)
// as eight characters, all at once in one 64-bit word ("SIMD within a
// register"): the value cut into two numbers below 10^4, each of those into
// two below 100, each of those into two digits, every cut done on all the
// parts at once by one multiplication (a division by 100 or 10 as a
// multiplication and a shift, exact below 10^4 and 100). The first digit
// lands in the lowest byte: the word written to memory on a little-endian
// machine reads left to right.
std::uint64_t eight_digits(std::uint32_t value) {
  const std::uint64_t merged = (value / 10000) | (std::uint64_t{value % 10000} << 32);
  const std::uint64_t top =  // each half / 100 (10486 / 2^20: exact below 10^4)
      ((merged * 10486) >> 20) & ((std::uint64_t{0x7F} << 32) | 0x7F);
  const std::uint64_t hundreds = ((merged - 100 * top) << 16) + top;  // 4 parts < 100
  std::uint64_t tens =
      (hundreds * 103) >> 10;  // each part / 10 (103 / 2^10: exact below 100)
  tens &= 0x000F000F000F000F;
  tens += (hundreds - 10 * tens) << 8;  // and each part's last digit beside it
  return tens + 0x3030303030303030;     // '0' added to each digit
}

// Puts the eight characters of `digits` (eight_digits) at `out`.
void put_eight(char* out, std::uint64_t digits) {
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(out, &digits, 8);
  } else {
    for (int i = 0; i < 8; ++i) out[i] = static_cast<char>(digits >> (8 * i));
  }
}

// How many decimal digits `value` has (1 for 0). Most moments need 16 or 17
// digits: those are asked first.
int digit_count(std::uint64_t value) {
  constexpr std::uint64_t e15 = 1000000000000000;
  if (value >= e15) {
    int count = 16;
    for (std::uint64_t bound = 10 * e15; count < 20 && value >= bound; bound *= 10)
      ++count;
    return count;
  }
  int count = 1;
  while (true) {
    if (value < 10) return count;
    if (value < 100) return count + 1;
    if (value < 1000) return count + 2;
    if (value < 10000) return count + 3;
    value /= 10000;
    count += 4;
  }
}

// Room after a number's digits that write_digits fills with characters
// that mean nothing (what comes next in the line writes over them; see
// longest_event_line).
constexpr int digits_spill = 24;

// Writes the `count` decimal digits of `value` (any 64-bit value: below
// 10^20) at `out`; returns their end. The digits are made eight at a time
// in a block, then copied to `out` in one copy of a fixed size (no loop, no
// call), which writes digits_spill characters, the digits first.
char* write_digits(char* out, std::uint64_t value, int count) {
  constexpr std::uint64_t eight = 100000000;
  char block[2 * digits_spill];  // the digits end at digits_spill
  put_eight(block + 16, eight_digits(static_cast<std::uint32_t>(value % eight)));
  if (count > 8)
    put_eight(block + 8, eight_digits(static_cast<std::uint32_t>(value / eight % eight)));
  if (count > 16)
    put_eight(block, eight_digits(static_cast<std::uint32_t>(value / eight / eight)));
  std::memcpy(out, block + digits_spill - count, digits_spill);
  return out + count;
}

// "00" to "99": a ball's number two digits at a time.
constexpr char digit_pairs[] =
    "0001020304050607080910111213141516171819"
    "2021222324252627282930313233343536373839"
    "4041424344454647484950515253545556575859"
    "6061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// An integer as "{}" writes it: below 10^4 (a ball's number in most scenes,
// K) a pair of digits at a time, else eight at a time.
char* write_integer(char* out, int value) {
  if (value >= 0 && value < 100) {
    if (value < 10) {
      *out = static_cast<char>('0' + value);
      return out + 1;
    }
    std::memcpy(out, digit_pairs + 2 * value, 2);
    return out + 2;
  }
  if (value >= 0 && value < 10000) {
    const int high = value / 100;
    if (high < 10) {
      *out++ = static_cast<char>('0' + high);
    } else {
      std::memcpy(out, digit_pairs + 2 * high, 2);
      out += 2;
    }
    std::memcpy(out, digit_pairs + 2 * (value % 100), 2);
    return out + 2;
  }
  std::uint64_t magnitude = static_cast<std::uint64_t>(value);
  if (value < 0) {
    *out++ = '-';
    magnitude = 0 - static_cast<std::uint64_t>(static_cast<std::int64_t>(value));
  }
  return write_digits(out, magnitude, digit_count(magnitude));
}

// fmt's own shortest digits (Dragonbox) for the versions of fmt tried; the
// public format_to for any other (the same text, some 300 instructions a
// line more).
#if FMT_VERSION >= 90100 && FMT_VERSION < 130000
#define GAS_EVENT_LINES_DRAGONBOX 1
#else
#define GAS_EVENT_LINES_DRAGONBOX 0
#endif

// A moment TC as "{}" writes it: the shortest digits that read back to the
// same double (fmt's own Dragonbox, so the very digits fmt picks), laid out
// as fmt lays them out for a decimal exponent from -4 up to 15 (every
// moment of a run from 1e-4 on, before 1e16). Anything else (0, the
// exponent form, a sign, not a number) is left to fmt itself.
char* write_time(char* out, double time) {
#if GAS_EVENT_LINES_DRAGONBOX
  if (!(time > 0 && time <= std::numeric_limits<double>::max()))
    return fmt::format_to(out, FMT_COMPILE("{}"), time);
  const auto decimal = fmt::detail::dragonbox::to_decimal(time);
  const int count = digit_count(decimal.significand);  // its digits
  const int exponent = decimal.exponent;               // TC = significand * 10^exponent
  const int leading = exponent + count;  // digits before the point (fmt: exp)
  if (leading - 1 < -4 || leading - 1 >= 16)
    return fmt::format_to(out, FMT_COMPILE("{}"), time);
  if (exponent >= 0) {  // 1234e2 -> 123400
    out = write_digits(out, decimal.significand, count);
    std::memset(out, '0', 15);  // (at most 15 are needed: leading is at most 16)
    return out + exponent;
  }
  if (leading > 0) {  // 1234e-2 -> 12.34: the digits one place on, the
                      // leading ones moved back before the point
    char* const end = write_digits(out + 1, decimal.significand, count);
    for (int i = 0; i < leading; ++i) out[i] = out[i + 1];
    out[leading] = '.';
    return end;
  }
  // 1234e-6 -> 0.001234
  *out++ = '0';
  *out++ = '.';
  std::memset(out, '0', 3);  // (at most 3 are needed: leading is at least -3)
  return write_digits(out - leading, decimal.significand, count);
#else
  return fmt::format_to(out, FMT_COMPILE("{}"), time);
#endif
}

}  // namespace

char* write_event_line(char* out, const Collision& c) {
  out = write_time(out, c.time);
  *out++ = ',';
  out = write_integer(out, static_cast<int>(c.kind));
  *out++ = ',';
  out = write_integer(out, c.first);
  *out++ = ',';
  out = write_integer(out, c.second);
  *out++ = '\n';
  return out;
}

}  // namespace gas
