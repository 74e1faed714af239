#include "io/message_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace m3055::text {
namespace {

constexpr std::size_t kEllipsisBytes = 3;

bool is_continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

// Length of the well-formed UTF-8 sequence at s[i] (1 to 4), its code point
// in `cp`; 0 when the bytes there are not well-formed UTF-8.
std::size_t decode(std::string_view s, std::size_t i, char32_t& cp) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
    const unsigned char c = byte(0);
    if (c < 0x80) {
        cp = c;
        return 1;
    }
    std::size_t length = 0;
    char32_t min = 0;
    if ((c & 0xE0) == 0xC0) length = 2, cp = c & 0x1F, min = 0x80;
    else if ((c & 0xF0) == 0xE0) length = 3, cp = c & 0x0F, min = 0x800;
    else if ((c & 0xF8) == 0xF0) length = 4, cp = c & 0x07, min = 0x10000;
    else return 0;
    if (i + length > s.size()) return 0;
    for (std::size_t k = 1; k < length; ++k) {
        if (!is_continuation(byte(k))) return 0;
        cp = (cp << 6) | (byte(k) & 0x3F);
    }
    // Overlong forms, UTF-16 surrogates and values past U+10FFFF are not UTF-8.
    if (cp < min || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF) return 0;
    return length;
}

// Code points shown as \uXXXX: controls, and those that move the cursor or
// reorder the text in a terminal (a name must not hide what follows it).
bool must_escape(char32_t cp) {
    return cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp <= 0x9F) || cp == 0x2028 || cp == 0x2029 ||
           cp == 0x200E || cp == 0x200F || (cp >= 0x202A && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069) ||
           cp == 0xFEFF;
}

// Appends the escaped form of the character (or invalid byte) at s[i] to
// `out` and moves `i` past it: one "unit", never split when text is cut.
void escape_unit(std::string_view s, std::size_t& i, bool quoted, std::string& out) {
    char32_t cp = 0;
    const std::size_t length = decode(s, i, cp);
    char buffer[16];
    if (length == 0) {
        std::snprintf(buffer, sizeof buffer, "\\x%02X", static_cast<unsigned char>(s[i]));
        out += buffer;
        ++i;
        return;
    }
    if (cp == '\n') out += "\\n";
    else if (cp == '\r') out += "\\r";
    else if (cp == '\t') out += "\\t";
    else if (quoted && (cp == '"' || cp == '\\')) out += '\\', out += char(cp);
    else if (must_escape(cp)) {
        std::snprintf(buffer, sizeof buffer, "\\u%04X", unsigned(cp));
        out += buffer;
    } else {
        out.append(s.substr(i, length));
    }
    i += length;
}

std::string escape_all(std::string_view s, bool quoted) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size();) escape_unit(s, i, quoted, out);
    return out;
}

// The escaped units of s[begin, end) that fit in `max` bytes from the start;
// `complete` tells whether every unit fitted.
std::string head_units(std::string_view s, bool quoted, std::size_t max, bool& complete) {
    std::string out, unit;
    std::size_t i = 0;
    while (i < s.size()) {
        unit.clear();
        escape_unit(s, i, quoted, unit);
        if (out.size() + unit.size() > max) {
            complete = false;
            return out;
        }
        out += unit;
    }
    complete = true;
    return out;
}

// The escaped units at the end of `s` that fit in `max` bytes. Each input byte
// gives at least one output byte, so they come from the last `max` bytes; the
// start is moved past continuation bytes to a character boundary.
std::string tail_units(std::string_view s, bool quoted, std::size_t max) {
    std::size_t start = s.size() > max ? s.size() - max : 0;
    for (int k = 0; k < 3 && start > 0 && start < s.size() && is_continuation(static_cast<unsigned char>(s[start])); ++k)
        ++start;
    std::vector<std::string> units;
    std::size_t total = 0;
    for (std::size_t i = start; i < s.size();) {
        units.emplace_back();
        escape_unit(s, i, quoted, units.back());
        total += units.back().size();
    }
    std::size_t first = 0;
    while (total > max) total -= units[first++].size();
    std::string out;
    for (std::size_t k = first; k < units.size(); ++k) out += units[k];
    return out;
}

std::string cut_end_impl(std::string_view s, bool quoted, std::size_t max) {
    bool complete = false;
    std::string head = head_units(s, quoted, max, complete);
    if (complete) return head;
    head = head_units(s, quoted, max > kEllipsisBytes ? max - kEllipsisBytes : 0, complete);
    return head + kEllipsis;
}

std::string cut_middle_impl(std::string_view s, bool quoted, std::size_t max) {
    bool complete = false;
    std::string whole = head_units(s, quoted, max, complete);
    if (complete) return whole;
    const std::size_t budget = max > kEllipsisBytes ? max - kEllipsisBytes : 0;
    const std::string head = head_units(s, quoted, budget / 2, complete);
    const std::string tail = tail_units(s, quoted, budget - head.size());
    return head + kEllipsis + tail;
}

bool is_plain_name(std::string_view s) {
    if (s.empty() || s.front() == ' ' || s.back() == ' ') return false;
    for (std::size_t i = 0; i < s.size();) {
        char32_t cp = 0;
        const std::size_t length = decode(s, i, cp);
        if (length == 0 || must_escape(cp) || cp == '"' || cp == '\\') return false;
        i += length;
    }
    return true;
}

}  // namespace

std::size_t shown_multibyte_length(std::string_view bytes, std::size_t i) {
    char32_t cp = 0;
    const std::size_t length = decode(bytes, i, cp);
    return length >= 2 && !must_escape(cp) ? length : 0;
}

bool is_valid_utf8(std::string_view bytes) {
    for (std::size_t i = 0; i < bytes.size();) {
        char32_t cp = 0;
        const std::size_t length = decode(bytes, i, cp);
        if (length == 0) return false;
        i += length;
    }
    return true;
}

std::string escape(std::string_view bytes, bool quoted) { return escape_all(bytes, quoted); }

std::string quote_name(std::string_view path) {
    if (is_plain_name(path)) return cut_middle_impl(path, false, kMaxNameBytes);
    return "\"" + cut_middle_impl(path, true, kMaxNameBytes - 2) + "\"";
}

std::string cut_end(std::string_view text, std::size_t max) { return cut_end_impl(text, false, max); }

std::string quote(std::string_view text, std::size_t max) { return "\"" + cut_end_impl(text, true, max) + "\""; }

std::string one_line(std::string_view text, std::size_t max) { return cut_middle_impl(text, false, max); }

#ifdef __EMSCRIPTEN__
namespace {
// std::to_chars(double)'s output without <charconv>: the fewest significant
// digits that read back as the same double (printf's %.*e, 1 to 17 digits),
// written fixed or scientific ("1e+20", "1.5e-07"), whichever is shorter,
// fixed on a tie. Only the browser build uses it.
std::string shortest_round_trip(double value) {
    char buffer[64];
    int digits = 1;
    for (; digits < 17; ++digits) {
        std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    std::snprintf(buffer, sizeof buffer, "%.*e", digits - 1, value);
    const std::string sci_text = buffer;
    // Mantissa digits and exponent of that form.
    const std::size_t e = sci_text.find('e');
    std::string mantissa = sci_text.substr(0, e);
    const int exponent = std::atoi(sci_text.c_str() + e + 1);
    const bool negative = mantissa[0] == '-';
    std::string all_digits;
    for (char c : mantissa) {
        if (c >= '0' && c <= '9') all_digits += c;
    }
    while (all_digits.size() > 1 && all_digits.back() == '0') all_digits.pop_back();
    // Scientific: d[.ddd]e(+|-)XX, at least two exponent digits.
    std::string scientific = std::string(negative ? "-" : "") + all_digits.substr(0, 1);
    if (all_digits.size() > 1) scientific += "." + all_digits.substr(1);
    char exponent_text[16];
    std::snprintf(exponent_text, sizeof exponent_text, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
    scientific += exponent_text;
    // Fixed: the same digits with the point moved.
    std::string fixed;
    const int point = exponent + 1;  // digits before the point
    if (point <= 0) {
        fixed = "0." + std::string(std::size_t(-point), '0') + all_digits;
    } else if (std::size_t(point) >= all_digits.size()) {
        fixed = all_digits + std::string(std::size_t(point) - all_digits.size(), '0');
    } else {
        fixed = all_digits.substr(0, std::size_t(point)) + "." + all_digits.substr(std::size_t(point));
    }
    if (negative) fixed = "-" + fixed;
    return fixed.size() <= scientific.size() ? fixed : scientific;
}
}  // namespace
#endif

std::string format_number(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    if (value == 0.0) return "0";  // no "-0"
    char buffer[64];
    if (value == std::floor(value) && std::fabs(value) < 1e15) {
        std::snprintf(buffer, sizeof buffer, "%.0f", value);  // exact: every such integer is a double
        return buffer;
    }
    // Shortest round-trip form (C++17 <charconv>): fixed or scientific, whichever is shorter.
#ifdef __EMSCRIPTEN__
    return shortest_round_trip(value);  // Emscripten's libc++ has no std::to_chars(double)
#else
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
#endif
}

namespace {

// Edits (insert, delete, substitute, swap two neighbours) that turn a into b: the
// optimal string alignment distance, for "did you mean".
std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
    for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i)
        for (std::size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

}  // namespace

std::string closest_name(const std::string& typed, const std::vector<std::string>& names) {
    constexpr std::size_t kLongestCompared = 64;  // a long text is no typo, and costs length² to compare
    if (typed.size() > kLongestCompared) return "";
    const std::size_t most = typed.size() <= 4 ? 1 : 2;
    std::string best;
    std::size_t best_distance = most + 1, ties = 0;
    for (const std::string& candidate : names) {
        // At least the lengths' difference apart: a name far longer is skipped unread (a
        // scene's own key of a megabyte would cost its length times the typed one's).
        if (candidate.size() > typed.size() + most || typed.size() > candidate.size() + most) continue;
        const std::size_t distance = edit_distance(typed, candidate);
        if (distance < best_distance) {
            best = candidate, best_distance = distance, ties = 1;
        } else if (distance == best_distance) {
            ++ties;
        }
    }
    return best_distance <= most && ties == 1 ? best : "";
}

}  // namespace m3055::text
