// Text that goes into an error message: one line, valid UTF-8, bounded.
// Scene files, manifests and file names are untrusted: a name may
// hold a newline, a scene may be UTF-16 or Latin-1, a value may be 10 MB
// long. Every message is built from these pieces, so whatever the input, a
// terminal or a log gets one readable line of at most kMaxLineBytes.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace m3055::text {

// A whole error line, "m3055: " included, the newline not.
inline constexpr std::size_t kMaxLineBytes = 300;
// A file name as a message shows it (quotes and "…" included).
inline constexpr std::size_t kMaxNameBytes = 120;
// A JSON path ("objects[3].material.m") as a message shows it.
inline constexpr std::size_t kMaxPathBytes = 120;
// A value or token echoed from the input, and one key of a JSON path.
inline constexpr std::size_t kMaxEchoBytes = 40;
// Marks where text was cut (U+2026, 3 bytes).
inline constexpr const char* kEllipsis = "\xE2\x80\xA6";

// True when `bytes` is well-formed UTF-8 (no overlong forms, no surrogates).
bool is_valid_utf8(std::string_view bytes);

// Length (2 to 4) of the well-formed UTF-8 sequence at bytes[i] when `escape`
// shows that character as it is; 0 for ASCII, invalid bytes and the code
// points it escapes.
std::size_t shown_multibyte_length(std::string_view bytes, std::size_t i);

// `bytes` with everything a terminal or a log could misread escaped: invalid
// UTF-8 bytes as \xHH; \n \r \t; other C0 and C1 controls, DEL, the line and
// paragraph separators, the bidirectional controls and U+FEFF as \uXXXX.
// With `quoted`, also " and \ (so the result can sit between quotes).
std::string escape(std::string_view bytes, bool quoted = false);

// A file name as a message shows it: as typed when it is plain printable
// UTF-8 (no quote, backslash, control or leading/trailing space), otherwise in
// double quotes with escape(); longer than kMaxNameBytes, its middle is cut
// ("/home/…/scene.json"), so both the folder and the name stay visible.
std::string quote_name(std::string_view path);

// `text` made safe with escape(), cut to at most `max` bytes with its end
// replaced by "…" when longer; never splits a character or an escape.
std::string cut_end(std::string_view text, std::size_t max = kMaxEchoBytes);
// `text` in double quotes, escaped, cut like cut_end (quotes not counted).
std::string quote(std::string_view text, std::size_t max = kMaxEchoBytes);

// escape() without quoting, then cut in the middle (start and end kept) to
// `max` bytes: the last guard before a line is printed, and the form of a
// long JSON path. The result is one line of valid UTF-8.
std::string one_line(std::string_view text, std::size_t max = kMaxLineBytes);

// Shortest text that reads back as exactly `value` ("-3", "12.5", "0.001",
// "1e+20", "-1000000.0000001"): a message never shows a rounded value, which
// could lie inside the range it is said to violate. Integers below 1e15 are
// written in full ("1000000", not "1e+06"); "nan", "inf", "-inf"; no "-0".
std::string format_number(double value);

// The one name of `names` a typo away from `typed` (one edit up to 4 characters, two beyond:
// "intensty" -> "intensity"), or "" when none is or two are equally near: "did you mean".
std::string closest_name(const std::string& typed, const std::vector<std::string>& names);

}  // namespace m3055::text
