// scene/json_parse.h: what is checked before a document is built, so that no
// file of at most 16 MiB costs much memory to reject: encodings, nesting, keys per object, and the estimated size of the
// document, which is held here against what nlohmann::json really allocates.
#include "scene/json_parse.h"
#include "scene/load.h"

#include <gtest/gtest.h>
#include <malloc.h>

#include <string>

namespace m3055::scene_json {
namespace {

using nlohmann::json;

std::string error_of(const std::string& text) {
    try {
        parse_document(text, "f.json");
    } catch (const SceneError& error) {
        return error.what();
    }
    return "no error";
}

std::string repeated(const std::string& item, std::size_t count) {
    std::string text = "[";
    for (std::size_t i = 0; i < count; ++i) text += (i ? "," : "") + item;
    return text + "]";
}

// Bytes nlohmann::json::parse(text) keeps allocated (glibc's in-use count).
std::size_t measured_document_bytes(const std::string& text) {
    const std::size_t before = mallinfo2().uordblks;
    const json doc = json::parse(text);
    return mallinfo2().uordblks - before;
}

TEST(JsonParse, EstimateCoversWhatTheDocumentTakes) {
    std::string keys = "{";
    for (int i = 0; i < 200; ++i) keys += (i ? ",\"key_number_" : "\"key_number_") + std::to_string(i) + "\":" + std::to_string(i);
    keys += "}";
    const std::string sphere =
        R"({"shape":"sphere","center":[0.5,-1,2],"radius":0.25,)"
        R"("material":{"model":"metal","color":[1,0.5,0.25],"lobes":[{"w":0.1,"m":0.2},{"w":0.3,"m":0.4}]}})";
    for (const std::string& text :
         {repeated("0", 200000), repeated("{}", 100000), repeated("[]", 100000), repeated("\"short\"", 50000),
          repeated("\"a string longer than fifteen bytes\"", 50000), repeated("[[[[1]]]]", 20000), keys,
          repeated(keys, 500), repeated(sphere, 20000)}) {
        const DocumentScan scan = scan_document(text);
        ASSERT_EQ(scan.problem, "");
        const std::size_t measured = measured_document_bytes(text);
        // Under AddressSanitizer malloc is ASan's, which mallinfo2 does not see.
        if (measured < 1024) GTEST_SKIP() << "the allocator is not glibc's (a sanitizer build): nothing to compare";
        EXPECT_GE(scan.document_bytes, measured) << text.substr(0, 60);
        // Not wildly pessimistic either: a legal scene must not be refused for nothing.
        EXPECT_LE(scan.document_bytes, measured * 16 / 10 + 4096) << text.substr(0, 60);
    }
}

TEST(JsonParse, DocumentsTooLargeOnceParsedAreRefusedBeforeBuilding) {
    // 16 MiB of "{}," would be 600 MB as a document.
    const std::string text = repeated("{}", (std::size_t(16) << 20) / 3);
    EXPECT_EQ(error_of(text), "f.json: too large: parsed, it would take more than 192 MiB of memory "
                              "(too many objects, keys or values)");
    // A syntax error further on still wins, as when the document was parsed first.
    EXPECT_EQ(error_of(text.substr(0, text.size() - 1) + ",]").rfind("f.json: invalid JSON: ", 0), 0u);
}

// The limit crossed while a key is read (two keys per object): the scanner
// dropped its frames there and then read the top one (a crash, found by a
// 90 000-sphere scene of four-lobe metals).
TEST(JsonParse, LimitCrossedOnAKeyIsAnErrorNotACrash) {
    for (const char* item : {R"({"k":1,"l":2})", R"({"k":[1],"l":{"m":2}})"})
        EXPECT_EQ(error_of(repeated(item, 1500000)).rfind("f.json: too large: ", 0), 0u) << item;
}

TEST(JsonParse, EncodingsThatAreNotUtf8) {
    EXPECT_EQ(error_of(std::string("\xFF\xFE{\0}\0", 6)),
              "f.json: is UTF-16 text (it starts with a byte order mark); save it as UTF-8");
    EXPECT_EQ(error_of(std::string("\xFE\xFF\0{\0}", 6)),
              "f.json: is UTF-16 text (it starts with a byte order mark); save it as UTF-8");
    EXPECT_EQ(error_of(std::string("\xFF\xFE\0\0{\0\0\0", 8)),
              "f.json: is UTF-32 text (it starts with a byte order mark); save it as UTF-8");
    EXPECT_EQ(error_of(std::string("{\0\"\0", 4)),
              "f.json: holds a NUL byte at byte 1: not UTF-8 text (UTF-16, UTF-32 or a binary file?)");
    // A UTF-8 byte order mark is fine.
    EXPECT_NO_THROW(parse_document("\xEF\xBB\xBF{}", "f.json"));
    // Latin-1 inside a string: nlohmann's message, its raw byte escaped.
    EXPECT_EQ(error_of("{\"a\": \"caf\xE9\"}"),
              "f.json: invalid JSON: parse error at line 1, column 12: syntax error while parsing value - "
              "invalid string: ill-formed UTF-8 byte; last read: '\"caf\\xE9\"'");
}

TEST(JsonParse, EchoedTokensAreCut) {
    const std::string digits = error_of("{\"a\": 1" + std::string(1000000, '0') + "}");
    EXPECT_LT(digits.size(), 200u) << digits.substr(0, 300);
    EXPECT_NE(digits.find("number overflow parsing '10000"), std::string::npos) << digits;
    const std::string unterminated = error_of("{\"a\": \"" + std::string(1000000, 'x'));
    EXPECT_LT(unterminated.size(), 300u) << unterminated.substr(0, 400);
}

TEST(JsonParse, NestingKeysAndDuplicates) {
    EXPECT_EQ(error_of(std::string(100000, '[') + std::string(100000, ']')).rfind("f.json: [0]", 0), 0u);
    EXPECT_NE(error_of(std::string(100000, '[') + std::string(100000, ']')).find(": nested deeper than 64 levels"),
              std::string::npos);
    std::string many = "{\"a\": {";
    for (int i = 0; i < 300; ++i) many += (i ? ",\"k" : "\"k") + std::to_string(i) + "\":0";
    EXPECT_EQ(error_of(many + "}}"), "f.json: a: has more than 256 keys");
    EXPECT_EQ(error_of(R"({"objects": [{"m": 1, "m": 2}]})"), "f.json: objects[0].m: duplicate key");
    EXPECT_EQ(error_of("{\"a\\nb\": 1, \"a\\nb\": 2}"), "f.json: [\"a\\nb\"]: duplicate key");
}

}  // namespace
}  // namespace m3055::scene_json
