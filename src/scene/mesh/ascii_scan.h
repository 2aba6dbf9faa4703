#pragma once
// Scanning words and numbers in ASCII mesh files (OBJ, MTL, ASCII PLY) without allocating:
// callers walk a [p, end) range. Inline because these run once per number; the digit and
// newline searches look at 8 bytes at a time (SWAR), which is what makes the OBJ loader fast.
#include "rtpro/core/printable_text.h"

#include <fast_float/fast_float.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rtpro::ascii {

// Blanks separate words within a line; a word ends at a blank, a newline or the end. Parsers
// that walk a whole buffer (OBJ) stop at '\n' themselves; line-at-a-time parsers never see one.
// One bit per character code below 64: a shift and a mask instead of a chain of comparisons.
inline bool in_set(char c, std::uint64_t set) { return static_cast<unsigned char>(c) < 64 && (set >> c & 1); }
inline constexpr std::uint64_t kBlanks = 1ull << ' ' | 1ull << '\t' | 1ull << '\r' | 1ull << '\v' | 1ull << '\f';
inline bool is_blank(char c) { return in_set(c, kBlanks); }
inline bool is_word_end(char c) { return in_set(c, kBlanks | 1ull << '\n'); }
inline bool is_digit(char c) { return static_cast<unsigned char>(c - '0') < 10u; }

inline const char* skip_blanks(const char* p, const char* end) {
  while (p != end && is_blank(*p)) ++p;
  return p;
}

inline const char* skip_word(const char* p, const char* end) {
  while (p != end && !is_word_end(*p)) ++p;
  return p;
}

// The blank-delimited word starting at p (for messages: what was found instead of a number).
inline std::string_view word_at(const char* p, const char* end) { return {p, std::size_t(skip_word(p, end) - p)}; }

// Words echoed in messages are cut to this many bytes: a 10 MB token must not become a 10 MB
// warning.
inline constexpr std::size_t kMaxQuotedBytes = 64;

// 'word', for messages: printable_text() within quotes, and a long word cut with its length given.
inline std::string quoted(std::string_view word) {
  std::string text = "'" + printable_text(word, kMaxQuotedBytes) + "'";
  if (word.size() > kMaxQuotedBytes) text += " (cut: " + std::to_string(word.size()) + " bytes)";
  return text;
}

namespace swar {

inline constexpr bool kAvailable = std::endian::native == std::endian::little;
inline constexpr std::uint64_t kOnes = 0x0101010101010101ull;
inline constexpr std::uint64_t kHighBits = 0x8080808080808080ull;

inline std::uint64_t load(const char* p) {
  std::uint64_t word;
  std::memcpy(&word, p, sizeof word);
  return word;
}

// One bit (the high bit of the byte) for every byte of `word` equal to `byte`, exactly: the
// sums stay inside each byte, so no carry can fake a match.
inline std::uint64_t bytes_equal(std::uint64_t word, char byte) {
  const std::uint64_t t = word ^ (kOnes * static_cast<unsigned char>(byte));
  return ~(((t & ~kHighBits) + ~kHighBits) | t) & kHighBits;
}

// Index of the first byte of `word` that is not an ASCII digit; 8 if all are.
inline int leading_digits(std::uint64_t word) {
  const std::uint64_t t = word ^ (kOnes * '0');  // digits become 0..9
  // Per byte, without carries between bytes: the high bit ends up set unless the byte is < 10.
  const std::uint64_t non_digit = (((t & ~kHighBits) + kOnes * (0x80 - 10)) | t) & kHighBits;
  return non_digit ? std::countr_zero(non_digit) / 8 : 8;
}

// The value of the first n (1..8) digits of `word`.
inline std::uint32_t digits_value(std::uint64_t word, int n) {
  std::uint64_t t = (word ^ (kOnes * '0')) << (8 * (8 - n));     // leading zeros replace later bytes
  t = (t * (10 * 256 + 1)) >> 8 & 0x00FF00FF00FF00FFull;         // pairs of digits
  t = (t * (100 * 65536 + 1)) >> 16 & 0x0000FFFF0000FFFFull;     // groups of four
  return std::uint32_t((t * (10000 * (1ull << 32) + 1)) >> 32);  // all eight
}

}  // namespace swar

// The end of the line starting at p: the next '\n', or end.
inline const char* find_line_end(const char* p, const char* end) {
#if defined(__SSE2__)
  const __m128i newline = _mm_set1_epi8('\n');
  for (; end - p >= 16; p += 16) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    if (const unsigned mask = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, newline))))
      return p + std::countr_zero(mask);
  }
#else
  if constexpr (swar::kAvailable) {
    for (; end - p >= 8; p += 8) {
      if (const std::uint64_t mask = swar::bytes_equal(swar::load(p), '\n')) return p + std::countr_zero(mask) / 8;
    }
  }
#endif
  while (p != end && *p != '\n') ++p;
  return p;
}

// Calls visit(newline) for every '\n' in [p, end), in order: 16 bytes per step with SSE2 (every
// x86-64 CPU has it), 8 with SWAR elsewhere.
template <typename Visit>
inline void for_each_newline(const char* p, const char* end, Visit&& visit) {
#if defined(__SSE2__)
  const __m128i newline = _mm_set1_epi8('\n');
  for (; end - p >= 16; p += 16) {
    const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p));
    for (unsigned mask = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, newline))); mask; mask &= mask - 1)
      visit(p + std::countr_zero(mask));
  }
#else
  if constexpr (swar::kAvailable) {
    for (; end - p >= 8; p += 8) {
      for (std::uint64_t mask = swar::bytes_equal(swar::load(p), '\n'); mask; mask &= mask - 1)
        visit(p + std::countr_zero(mask) / 8);
    }
  }
#endif
  for (; p != end; ++p)
    if (*p == '\n') visit(p);
}

inline constexpr std::uint64_t kPowersOf10[] = {1,       10,       100,       1000,       10000,         100000,
                                                1000000, 10000000, 100000000, 1000000000, 10000000000ull};

// Up to 18 decimal digits at p into `value` (so it cannot overflow); returns the number read,
// or -1 past 18.
inline int scan_digits(const char*& p, const char* end, std::uint64_t& value) {
  const char* const first = p;
  if constexpr (swar::kAvailable) {
    while (end - p >= 8) {
      const std::uint64_t word = swar::load(p);
      const int n = swar::leading_digits(word);
      if (n == 0) break;
      if (p - first + n > 18) return -1;
      value = value * kPowersOf10[n] + swar::digits_value(word, n);
      p += n;
      if (n < 8) return int(p - first);
    }
  }
  for (; p != end && is_digit(*p); ++p) {
    if (p - first == 18) return -1;
    value = value * 10 + std::uint64_t(*p - '0');
  }
  return int(p - first);
}

// The common case of an OBJ index in one 8-byte load: 1 to 7 digits, then a blank or a newline.
// Returns the number of digits, or 0 when the case does not apply (the caller then takes the
// general path).
inline int scan_short_unsigned(const char* p, const char* end, std::uint32_t& value) {
  if (!swar::kAvailable || end - p < 8) return 0;
  const std::uint64_t word = swar::load(p);
  const int n = swar::leading_digits(word);
  if (n == 0 || n == 8 || !is_word_end(static_cast<char>(word >> (8 * n)))) return 0;
  value = swar::digits_value(word, n);
  return n;
}

enum class NumberStatus { kOk, kMalformed, kNotFinite };

struct FloatScan {
  NumberStatus status;
  const char* next;  // just past the number when kOk
};

// Plain decimals like "-0.0503644" (the bulk of scanned meshes), read with 8-byte loads: at most
// 7 digits before the point and 10 after it, and a mantissa below 2^24. That is the exact path
// fast_float also takes for them: the mantissa and a power of ten up to 10^10 are exact floats, so
// the one rounding of the division gives the correctly rounded result. Anything else returns false
// and goes to fast_float.
inline bool scan_short_decimal(const char* p, const char* end, float& value, const char*& next) {
  const bool negative = p != end && *p == '-';
  if (negative) ++p;
  if (!swar::kAvailable || end - p < 16) return false;
  const std::uint64_t head = swar::load(p);
  const int whole = swar::leading_digits(head);
  if (whole == 8) return false;
  std::uint64_t mantissa = whole ? swar::digits_value(head, whole) : 0;
  int fraction = 0;
  p += whole;
  if (*p == '.') {
    const std::uint64_t tail = swar::load(++p);
    fraction = swar::leading_digits(tail);
    if (fraction) mantissa = mantissa * kPowersOf10[fraction] + swar::digits_value(tail, fraction);
    p += fraction;
    if (fraction == 8) {  // "0.00531858": leading zeros make long fractions common
      if (end - p < 8) return false;
      const std::uint64_t more = swar::load(p);
      const int extra = swar::leading_digits(more);
      if (fraction + extra > 10) return false;
      if (extra) mantissa = mantissa * kPowersOf10[extra] + swar::digits_value(more, extra);
      fraction += extra;
      p += extra;
    }
  }
  if (whole + fraction == 0 || mantissa > (1u << 24) || !is_word_end(*p)) return false;
  const float magnitude = float(mantissa) / float(kPowersOf10[fraction]);
  value = negative ? -magnitude : magnitude;
  next = p;
  return true;
}

// A finite number (optionally signed with '+') that ends where a word ends.
// nan, inf and values beyond the type's range (1e999) are kNotFinite; "1,5" and "abc" are
// kMalformed.
template <typename Real>
inline FloatScan scan_real(const char* p, const char* end, Real& value) {
  if (p != end && *p == '+' && (p + 1 == end || p[1] != '-')) ++p;
  if constexpr (std::is_same_v<Real, float>) {
    const char* next = nullptr;
    if (scan_short_decimal(p, end, value, next)) return {NumberStatus::kOk, next};
  }
  const fast_float::from_chars_result result = fast_float::from_chars(p, end, value);
  if (result.ec == std::errc::result_out_of_range) return {NumberStatus::kNotFinite, result.ptr};
  if (result.ec != std::errc() || (result.ptr != end && !is_word_end(*result.ptr)))
    return {NumberStatus::kMalformed, p};
  if (!std::isfinite(value)) return {NumberStatus::kNotFinite, result.ptr};
  return {NumberStatus::kOk, result.ptr};
}

struct IntegerScan {
  bool ok;
  const char* next;  // just past the digits when ok
};

// A decimal integer with an optional sign and at most 18 digits, so it always fits int64. The
// caller checks what follows (a blank, '/', ...).
inline IntegerScan scan_integer(const char* p, const char* end, std::int64_t& value) {
  bool negative = false;
  if (p != end && (*p == '-' || *p == '+')) {
    negative = *p == '-';
    ++p;
  }
  std::uint64_t magnitude = 0;
  const int digits = scan_digits(p, end, magnitude);
  if (digits <= 0) return {false, p};
  value = negative ? -std::int64_t(magnitude) : std::int64_t(magnitude);
  return {true, p};
}

}  // namespace rtpro::ascii
