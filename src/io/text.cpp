#include "io/text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <system_error>
#include <vector>

#include <frictionid/model/shortest_number.hpp>

namespace frictionid::text {

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

namespace {

constexpr char kHex[] = "0123456789abcdef";

bool printable(unsigned char u) {
  return (u >= 0x20 && u < 0x7f) || u == '\t';
}

void append_escaped(std::string& out, unsigned char u) {
  if (printable(u))
    out += static_cast<char>(u);
  else
    out += {'\\', 'x', kHex[u >> 4], kHex[u & 15]};
}

std::size_t escaped_size(unsigned char u) {
  return printable(u) ? 1 : 4;
}

}  // namespace

std::string shortest_number(double x) {
  return model::shortest_number(x);
}

std::string shown(std::string_view text, std::size_t max_bytes) {
  max_bytes = std::min(max_bytes, kMaxQuotedBytes);
  std::string out = "'";
  for (const char c : text.substr(0, max_bytes)) append_escaped(out, static_cast<unsigned char>(c));
  return out + (text.size() > max_bytes ? "...'" : "'");
}

std::string escaped(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) append_escaped(out, static_cast<unsigned char>(c));
  return out;
}

std::string command_line(const std::vector<std::string>& words) {
  static constexpr std::string_view kPlain =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_@%+=:,./-";
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& w = words[i];
    if (i > 0) out += ' ';
    if (!w.empty() && w.find_first_not_of(kPlain) == std::string::npos) {
      out += w;
      continue;
    }
    out += '\'';
    for (char ch : w) {
      if (ch == '\'')
        out += "'\\''";
      else
        out += ch;
    }
    out += '\'';
  }
  return escaped(out);
}

std::string for_terminal(std::string_view message, std::size_t max_bytes) {
  std::size_t total = 0;
  for (const char c : message) total += escaped_size(static_cast<unsigned char>(c));
  if (total <= max_bytes) return escaped(message);
  // The start says what is wrong, the end often how to fix it: keep both, whole escapes only.
  const std::size_t tail_budget = max_bytes / 4, head_budget = max_bytes - tail_budget;
  std::size_t head = 0, used = 0;
  while (used + escaped_size(static_cast<unsigned char>(message[head])) <= head_budget)
    used += escaped_size(static_cast<unsigned char>(message[head++]));
  std::size_t tail = message.size();
  used = 0;
  while (tail > head &&
         used + escaped_size(static_cast<unsigned char>(message[tail - 1])) <= tail_budget)
    used += escaped_size(static_cast<unsigned char>(message[--tail]));
  return escaped(message.substr(0, head)) + " ... [" + std::to_string(tail - head) +
         " bytes left out] ... " + escaped(message.substr(tail));
}

std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) {
    return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u;
  };
  const unsigned lead = byte(0);
  // The ranges of the second byte follow the table of well-formed sequences in the Unicode
  // standard (3.9, table 3-7): they exclude overlong forms, surrogates and values > U+10FFFF.
  std::size_t length = 0;
  unsigned lo = 0x80, hi = 0xbf;
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    if (lead == 0xe0) lo = 0xa0;
    if (lead == 0xed) hi = 0x9f;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    if (lead == 0xf0) lo = 0x90;
    if (lead == 0xf4) hi = 0x8f;
  } else {
    return 0;
  }
  if (byte(1) < lo || byte(1) > hi) return 0;
  for (std::size_t k = 2; k < length; ++k)
    if (byte(k) < 0x80 || byte(k) > 0xbf) return 0;
  return length;
}

namespace {

// Clinger's fast path. A decimal without exponent whose digits, read as one whole number w, make
// at most 2^53 is w / 10^k (k digits after the point), both exact in a double, so one correctly
// rounded division gives the correctly rounded value: the one from_chars returns. Such numbers
// (0, 2000, 0.05, -1.25) fill many columns of data files, and this costs a fraction of
// from_chars. False for any other text, which from_chars then reads.
bool parse_short_decimal(const char* p, const char* last, bool negative, double& out) {
  // 2^53 has 16 digits: a longer text (such as the 17 significant digits %.17g writes) is
  // left to from_chars before any digit is read.
  if (last - p > 17) return false;
  static constexpr double kPowersOf10[] = {1e0, 1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7, 1e8,
                                           1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16};
  std::uint64_t whole = 0;  // at most 17 digits: no overflow
  bool digits = false;
  int after_point = -1;  // digits after the point; -1 without a point
  for (; p != last; ++p) {
    const unsigned digit = static_cast<unsigned char>(*p) - unsigned{'0'};
    if (digit <= 9) {
      whole = whole * 10 + digit;
      digits = true;
      if (after_point >= 0) ++after_point;
    } else if (*p == '.' && after_point < 0 && digits) {
      after_point = 0;
    } else {
      return false;
    }
  }
  if (!digits || after_point == 0 || whole > (std::uint64_t{1} << 53)) return false;
  double value = static_cast<double>(whole);
  if (after_point > 0) value /= kPowersOf10[after_point];
  out = negative ? -value : value;
  return true;
}

}  // namespace

const char* parse_double_strict(std::string_view text, double& out) {
  if (text.empty()) return "empty";
  const char* first = text.data();
  const char* const last = first + text.size();
  // from_chars accepts '-' but not '+'; allow one '+' that is followed by a digit or '.'.
  if (*first == '+') {
    if (last - first < 2 || !((first[1] >= '0' && first[1] <= '9') || first[1] == '.'))
      return "not a number";
    ++first;
  }
  const char* digits = first + (*first == '-' ? 1 : 0);
  if (parse_short_decimal(digits, last, digits != first, out)) return nullptr;
  if (last - digits >= 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X'))
    return "hexadecimal floats are not accepted";
  const auto [ptr, ec] = std::from_chars(first, last, out);
  if (ec == std::errc::result_out_of_range) return "out of the double range";
  if (ec != std::errc()) return "not a number";
  if (std::isnan(out)) return "NaN is not allowed";
  if (std::isinf(out)) return "Inf is not allowed";
  if (ptr != last) return "unexpected characters after the number";
  return nullptr;
}

namespace {
char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}
}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::size_t> prev2(m + 1), prev(m + 1), cur(m + 1);
  for (std::size_t j = 0; j <= m; ++j) prev[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1]))
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
    }
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return prev[m];
}

std::string without_invisible(std::string_view s) {
  static constexpr std::string_view kInvisible[] = {
      "\xEF\xBB\xBF",  // byte-order mark / zero-width no-break space
      "\xE2\x80\x8B",  // zero-width space
      "\xE2\x80\x8C",  // zero-width non-joiner
      "\xE2\x80\x8D",  // zero-width joiner
      "\xE2\x81\xA0",  // word joiner
      "\xC2\xA0",      // no-break space
  };
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    bool skipped = false;
    for (const auto inv : kInvisible)
      if (s.substr(i, inv.size()) == inv) {
        i += inv.size();
        skipped = true;
        break;
      }
    if (!skipped) out += s[i++];
  }
  return out;
}

std::size_t misspelling_distance(std::string_view candidate, std::string_view target) {
  // An invisible character counts as one edit, however many bytes it takes.
  const std::string visible = without_invisible(candidate);
  if (visible.size() != candidate.size()) {
    const std::size_t d = edit_distance(visible, target) + 1;
    return d <= (target.size() >= 6 ? 3 : 2) ? d : std::numeric_limits<std::size_t>::max();
  }
  const std::size_t d = edit_distance(candidate, target);
  const std::size_t limit = target.size() >= 6 ? 2 : 1;
  return d <= limit ? d : std::numeric_limits<std::size_t>::max();
}

}  // namespace frictionid::text
