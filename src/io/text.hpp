// Text helpers shared by the CSV and table readers and the option parsers: one strict number
// grammar, trimming, quoting and escaping for messages, and the edit distance behind "did you
// mean".
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace frictionid::text {

// A missing value in a dataset column, a reading or a plot series.
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Space or tab: what may surround a field or an option item.
inline bool is_space(char c) {
  return c == ' ' || c == '\t';
}

// s without leading and trailing spaces and tabs.
std::string_view trim(std::string_view s);

// A message quotes at most this many bytes of the content it complains about: a 40 MB line
// gives a message of a few hundred bytes, not one of 40 MB.
inline constexpr std::size_t kMaxQuotedBytes = 200;
// A whole message (escaped) is cut to about this many bytes by for_terminal.
inline constexpr std::size_t kMaxMessageBytes = 1024;

// The text in single quotes for a message, cut after max_bytes, and never after more than
// kMaxQuotedBytes (then "..." before the closing quote); every byte that is not printable ASCII
// is escaped as in escaped(), so that a huge, binary or oddly encoded line still gives one
// readable line that shows what is there.
std::string shown(std::string_view text, std::size_t max_bytes = 60);

// The fewest significant digits that read back as x: "0.6", not 0.59999999999999998; nan and
// inf as printf spells them. For messages and labels.
std::string shortest_number(double x);

// s with every byte that is not printable ASCII or tab shown as \xNN: control characters (ESC,
// BEL, CR, LF, NUL), DEL, and every byte of a non-ASCII character, which covers bidirectional
// controls such as U+202E and bytes that are not UTF-8. Such bytes in a path or label would
// otherwise reach the user's terminal, which acts on them (retitles, clears, reorders text).
// The result is printable ASCII and tab only, so escaping it again changes nothing.
std::string escaped(std::string_view s);

// The command as a shell would take it back: the words joined by spaces, each word that holds
// anything but letters, digits and _@%+=:,./- in single quotes (a quote inside as '\''), an
// empty word as '', and then escaped(), so that a control character or a non-ASCII byte shows as
// \xNN. For the provenance of reports (io/provenance.hpp).
std::string command_line(const std::vector<std::string>& words);

// A message as it may be shown on a terminal or in an exception's text: escaped(), on one line,
// and when that is longer than max_bytes, its start and its end with the middle left out and
// the number of bytes left out said in between.
std::string for_terminal(std::string_view message, std::size_t max_bytes = kMaxMessageBytes);

// The length (2 to 4) of the well-formed UTF-8 sequence of one character that starts at
// s[i], a byte of 0x80 or more; 0 when the bytes there are not UTF-8 (a Latin-1 byte, a stray
// continuation byte, a cut, overlong or surrogate sequence, a value above U+10FFFF).
std::size_t utf8_sequence_length(std::string_view s, std::size_t i);

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
