// Text helpers shared by the CSV and table readers and the option parsers: one strict number
// grammar, trimming, quoting for messages, and the edit distance behind "did you mean".
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

namespace frictionid::text {

// Space or tab: what may surround a field or an option item.
inline bool is_space(char c) {
  return c == ' ' || c == '\t';
}

// s without leading and trailing spaces and tabs.
std::string_view trim(std::string_view s);

// The text in single quotes for a message, cut after max_bytes (then "..." before the closing
// quote); every byte that is not printable ASCII (a CR, a NUL, a byte of a UTF-8 sequence such
// as a zero-width space) except tab is shown as \xNN, so that a huge, binary or oddly encoded
// line still gives one readable line that shows what is there.
std::string shown(std::string_view text, std::size_t max_bytes = 60);

// One strict decimal number: optional leading '+' or '-', decimal digits with optional fraction
// and exponent (what std::from_chars accepts in chars_format::general); the whole text must be
// consumed. Rejects empty text, trailing characters, NaN/Inf spellings, hexadecimal floats and
// values outside the double range (overflow, or underflow to zero of a non-zero literal).
// Subnormal results are accepted. The conversion is correctly rounded, so a value written with
// %.17g reads back bit-identical. Returns nullptr on success, else a short reason for messages.
const char* parse_double_strict(std::string_view text, double& out);

// Case-insensitive optimal string alignment distance (edits + adjacent transpositions).
std::size_t edit_distance(std::string_view a, std::string_view b);

// s without the invisible characters a header may pick up (byte-order marks, zero-width and
// no-break spaces, in UTF-8).
std::string without_invisible(std::string_view s);

// Distance when `candidate` looks like a misspelling of `target` (a case-only difference, one
// edit for short names, two for names of 6+ characters; an invisible character is one more
// edit on top), else SIZE_MAX.
std::size_t misspelling_distance(std::string_view candidate, std::string_view target);

}  // namespace frictionid::text
