// io/message_text.h: whatever bytes an untrusted file or name holds, what a
// message shows of them is one line of valid UTF-8, bounded, and true.
#include "io/message_text.h"
#include "scene/json_node.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>

namespace m3055::text {
namespace {

bool one_clean_line(const std::string& s) {
    if (!is_valid_utf8(s)) return false;
    for (const unsigned char c : s)
        if (c < 0x20 || c == 0x7F) return false;
    return s.find("\xE2\x80\xA8") == std::string::npos && s.find("\xE2\x80\xA9") == std::string::npos;
}

TEST(MessageText, Utf8Validation) {
    EXPECT_TRUE(is_valid_utf8("plain"));
    EXPECT_TRUE(is_valid_utf8("caf\xC3\xA9 \xE2\x80\xA6 \xF0\x9F\x98\x80"));
    EXPECT_FALSE(is_valid_utf8("caf\xE9"));          // Latin-1
    EXPECT_FALSE(is_valid_utf8("\xC0\xAF"));         // overlong '/'
    EXPECT_FALSE(is_valid_utf8("\xED\xA0\x80"));     // a UTF-16 surrogate
    EXPECT_FALSE(is_valid_utf8("\xF4\x90\x80\x80"));  // past U+10FFFF
    EXPECT_FALSE(is_valid_utf8("\xE2\x80"));         // cut short
}

TEST(MessageText, EscapeShowsControlsInvalidBytesAndLineBreakers) {
    EXPECT_EQ(escape("a\nb\tc\rd"), "a\\nb\\tc\\rd");
    EXPECT_EQ(escape(std::string("a\0b", 3)), "a\\u0000b");
    EXPECT_EQ(escape("caf\xE9"), "caf\\xE9");
    EXPECT_EQ(escape("\x1B[31mred"), "\\u001B[31mred");
    EXPECT_EQ(escape("x\xE2\x80\xA8y"), "x\\u2028y");            // line separator
    EXPECT_EQ(escape("\xE2\x80\xAEtxt.exe"), "\\u202Etxt.exe");  // right-to-left override
    EXPECT_EQ(escape("caf\xC3\xA9"), "caf\xC3\xA9");             // printable UTF-8 is kept
    EXPECT_EQ(escape("say \"hi\" \\", true), "say \\\"hi\\\" \\\\");
    EXPECT_EQ(escape("say \"hi\"", false), "say \"hi\"");
}

TEST(MessageText, FileNamesPlainOrQuotedAndCutInTheMiddle) {
    EXPECT_EQ(quote_name("scenes/a b.json"), "scenes/a b.json");
    EXPECT_EQ(quote_name("a\nb.json"), "\"a\\nb.json\"");
    EXPECT_EQ(quote_name("caf\xE9.json"), "\"caf\\xE9.json\"");
    EXPECT_EQ(quote_name(" lead.json"), "\" lead.json\"");
    EXPECT_EQ(quote_name(""), "\"\"");
    const std::string deep = "/home/" + std::string(500, 'd') + "/scene.json";
    const std::string shown = quote_name(deep);
    EXPECT_LE(shown.size(), kMaxNameBytes);
    EXPECT_EQ(shown.rfind("/home/", 0), 0u) << shown;
    EXPECT_EQ(shown.substr(shown.size() - 11), "/scene.json") << shown;
    EXPECT_NE(shown.find(kEllipsis), std::string::npos);
    // A long name of newlines: still one line, quoted, bounded.
    const std::string breaks = quote_name(std::string(1000, '\n'));
    EXPECT_LE(breaks.size(), kMaxNameBytes);
    EXPECT_TRUE(one_clean_line(breaks)) << breaks;
}

TEST(MessageText, CutNeverSplitsACharacterOrAnEscape) {
    std::mt19937 random(7);
    for (int round = 0; round < 2000; ++round) {
        std::string bytes(std::size_t(random() % 200), '\0');
        for (char& c : bytes) c = char(random() % 256);
        for (const std::size_t max : {std::size_t(1), std::size_t(10), std::size_t(40), std::size_t(120)}) {
            const std::string end = cut_end(bytes, max);
            EXPECT_LE(end.size(), std::max<std::size_t>(max, 3));
            EXPECT_TRUE(one_clean_line(end));
            const std::string middle = one_line(bytes, max);
            EXPECT_LE(middle.size(), std::max<std::size_t>(max, 3));
            EXPECT_TRUE(one_clean_line(middle));
            const std::string quoted = quote(bytes, max);
            EXPECT_TRUE(one_clean_line(quoted));
            const std::string name = quote_name(bytes);
            EXPECT_LE(name.size(), kMaxNameBytes);
            EXPECT_TRUE(one_clean_line(name));
        }
    }
    // Multi-byte characters at the cut: whole or gone.
    EXPECT_EQ(cut_end("\xC3\xA9\xC3\xA9\xC3\xA9\xC3\xA9", 6), "\xC3\xA9\xE2\x80\xA6");
    EXPECT_EQ(cut_end("ab\\ncd", 6), "ab\\ncd");
    EXPECT_EQ(cut_end("ab\ncdef", 6), "ab\xE2\x80\xA6");  // "\n" would be 2 bytes too many with the ellipsis
}

TEST(MessageText, OneLineBoundsAMegabyteOfAnything) {
    const std::string huge(1 << 20, '\n');
    const std::string line = one_line("m3055: " + huge + ": problem at the end");
    EXPECT_LE(line.size(), kMaxLineBytes);
    EXPECT_TRUE(one_clean_line(line));
    EXPECT_EQ(line.rfind("m3055: ", 0), 0u);
    EXPECT_EQ(line.substr(line.size() - 18), "problem at the end") << line;
}

// Class 11: a number in a message reads back as exactly the value compared.
TEST(MessageText, NumbersAreShortestRoundTrip) {
    EXPECT_EQ(format_number(-1000000.0000001), "-1000000.0000001");
    EXPECT_EQ(format_number(-1000000.0000000001), "-1000000.0000000001");
    EXPECT_EQ(format_number(std::nextafter(1e6, 2e6)), "1000000.0000000001");
    EXPECT_EQ(format_number(-3), "-3");
    EXPECT_EQ(format_number(12.5), "12.5");
    EXPECT_EQ(format_number(0.001), "0.001");
    EXPECT_EQ(format_number(1e6), "1000000");
    EXPECT_EQ(format_number(1e20), "1e+20");
    EXPECT_EQ(format_number(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(format_number(-0.0), "0");
    EXPECT_EQ(format_number(std::numeric_limits<double>::denorm_min()), "5e-324");
    EXPECT_EQ(format_number(std::numeric_limits<double>::quiet_NaN()), "nan");
    EXPECT_EQ(format_number(-std::numeric_limits<double>::infinity()), "-inf");
    std::mt19937_64 random(11);
    for (int i = 0; i < 100000; ++i) {
        std::uint64_t bits = random();
        double value = 0;
        std::memcpy(&value, &bits, sizeof value);
        if (!std::isfinite(value)) continue;
        const std::string shown = format_number(value);
        EXPECT_EQ(std::strtod(shown.c_str(), nullptr), value == 0 ? 0.0 : value) << shown;
    }
}

TEST(MessageText, JsonValuesAreDescribedExactlyAndShortly) {
    using scene_json::describe;
    using scene_json::json;
    EXPECT_EQ(describe(json::parse("9007199254740993")), "9007199254740993");  // not ...992
    EXPECT_EQ(describe(json::parse("-9223372036854775808")), "-9223372036854775808");
    EXPECT_EQ(describe(json::parse("18446744073709551615")), "18446744073709551615");
    EXPECT_EQ(describe(json::parse("-1000000.0000001")), "-1000000.0000001");
    const std::string long_string = describe(json(std::string(10 << 20, 'x')));
    EXPECT_LE(long_string.size(), kMaxEchoBytes);
    EXPECT_EQ(long_string.rfind("\"xxx", 0), 0u);
    const std::string latin = describe(json(std::string("caf\xE9")));
    EXPECT_TRUE(is_valid_utf8(latin)) << latin;
    EXPECT_EQ(describe(json(std::string("a\xE2\x80\xA8z"))), "\"a\\u2028z\"");
}

TEST(MessageText, KeysInPathsAreQuotedAndCut) {
    using scene_json::join_key;
    EXPECT_EQ(join_key("objects[0]", "material"), "objects[0].material");
    EXPECT_EQ(join_key("a", "two\nlines"), "a[\"two\\nlines\"]");
    const std::string long_key = join_key("a", std::string(1 << 20, 'k'));
    EXPECT_LE(long_key.size(), 2 + kMaxEchoBytes + 4);
    EXPECT_TRUE(one_clean_line(long_key));
}

// "Did you mean": the one name a typo away (one edit up to 4 characters, two beyond; a swap of
// neighbours is one), none when two are as near; a name far longer is not compared at all.
TEST(MessageText, ClosestNameIsTheOneNameATypoAway) {
    const std::vector<std::string> keys = {"intensity", "position", "color", "type", "size", "side"};
    EXPECT_EQ(text::closest_name("intensty", keys), "intensity");
    EXPECT_EQ(text::closest_name("psoition", keys), "position");
    EXPECT_EQ(text::closest_name("typ", keys), "type");
    EXPECT_EQ(text::closest_name("colour", keys), "color");
    EXPECT_EQ(text::closest_name("sixe", keys), "");  // size and side: as near
    EXPECT_EQ(text::closest_name("lamps", keys), "");
    EXPECT_EQ(text::closest_name("x", {"a", "b"}), "");
    const std::string huge(std::size_t(1) << 24, 'k');  // a scene's own key: skipped by its length
    EXPECT_EQ(text::closest_name("kk", {huge, "kkk"}), "kkk");
}

}  // namespace
}  // namespace m3055::text
