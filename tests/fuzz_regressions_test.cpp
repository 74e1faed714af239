// Re-checks, in every build (Release and the sanitizer build), each input the
// scene-loader fuzzer ever failed on (tests/fuzz/regressions/) and its seed
// corpus, with the fuzzer's own properties (tests/fuzz/scene_fuzz_check.h):
// a finite, in-range scene or a one-line SceneError, never another exception,
// a NaN or a scene that does not reload. Crashes and sanitizer reports fail
// the test process itself.
#include "fuzz/manifest_fuzz_check.h"

#include "fuzz_corpus.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

namespace {

namespace fs = std::filesystem;
using m3055::test::source_path;

std::string check_file(const fs::path& path) {
    const std::string bytes = m3055::test::file_bytes(path);
    return m3055::fuzz::check_fuzz_input(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

TEST(FuzzRegressions, EveryInputThatOnceFailedNowPasses) {
    const auto files = m3055::test::corpus_files(source_path("tests/fuzz/regressions"));
    ASSERT_FALSE(files.empty()) << "tests/fuzz/regressions/ is empty";
    for (const fs::path& path : files) EXPECT_EQ(check_file(path), "") << path;
}

TEST(FuzzRegressions, SeedCorpusPasses) {
    std::vector<fs::path> files = m3055::test::corpus_files(source_path("scenes"), ".json");
    // tests/data/ holds the reference images' scenes (tests/data/reference-images/) too.
    for (const auto& more : {m3055::test::corpus_files(source_path("tests/data"), ".json"),
                             m3055::test::corpus_files(source_path("tests/fuzz/seeds"))})
        files.insert(files.end(), more.begin(), more.end());
    ASSERT_GE(files.size(), 10u);
    for (const fs::path& path : files) EXPECT_EQ(check_file(path), "") << path;
}

std::string check_text(const std::string& text) {
    return m3055::fuzz::check_scene_input(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

std::string nested_arrays(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// Found by the fuzzer: 200 000 nested arrays (400 KB) took gigabytes in the
// duplicate-key pass (a path copy per level) and then overflowed the stack in
// the error message's dump(). Too big to commit as a file, so built here.
TEST(FuzzRegressions, DeeplyNestedFileIsAnErrorNotACrash) {
    const std::string text = R"({"camera": {"projection": )" + nested_arrays(200000) + R"(}, "objects": []})";
    EXPECT_EQ(check_text(text), "");
    try {
        m3055::scene_json::parse_document(text, "deep.json");
        FAIL() << "no error";
    } catch (const m3055::SceneError& error) {
        EXPECT_NE(std::string(error.what()).find("nested deeper than 64 levels"), std::string::npos) << error.what();
    }
}

TEST(FuzzRegressions, DeeplyNestedSetValueIsAnErrorNotACrash) {
    // 65 536 levels: about the longest argument Linux passes (MAX_ARG_STRLEN, 128 KiB).
    const std::string scene =
        R"({"camera": {"projection": "perspective", "position": [0, 0, 1], "target": [0, 0, 0], "fov_y_deg": 30}, "objects": []})";
    EXPECT_EQ(check_text(scene + "\n#set camera.projection=" + nested_arrays(65536)), "");
    nlohmann::json doc = nlohmann::json::parse(scene);
    try {
        m3055::apply_overrides(doc, {{"camera.projection", nested_arrays(65)}}, "s.json");
        FAIL() << "no error";
    } catch (const m3055::SceneError& error) {
        EXPECT_STREQ(error.what(), "s.json: --set camera.projection: value nested deeper than 64 levels");
    }
    // 64 levels are still a value (and then a validation error, not a nesting one).
    EXPECT_NO_THROW(m3055::apply_overrides(doc, {{"camera.projection", nested_arrays(64)}}, "s.json"));
}

// Found by the fuzzer: a --set text with a newline split the one-line message.
TEST(FuzzRegressions, SetTextsWithControlCharactersStayOnOneLine) {
    try {
        m3055::parse_override("a\nb");
        FAIL() << "no error";
    } catch (const m3055::SceneError& error) {
        EXPECT_STREQ(error.what(), "--set \"a\\nb\": expected path=value");
    }
    nlohmann::json doc = nlohmann::json::parse(R"({"camera": {}})");
    try {
        m3055::apply_overrides(doc, {{"camera.x\n.y", "1"}}, "s.json");
        FAIL() << "no error";
    } catch (const m3055::SceneError& error) {
        EXPECT_STREQ(error.what(), "s.json: --set \"camera.x\\n.y\": no such key \"x\\n\"");
    }
}

// The checker itself must catch what it is there to catch.
TEST(FuzzRegressions, CheckerRejectsNonFiniteScenesAndMultiLineErrors) {
    m3055::Scene scene;
    scene.objects.push_back(m3055::Object{});
    EXPECT_EQ(m3055::fuzz::check_loaded_scene(scene), "");
    scene.objects[0].material.set_number("m", std::nan(""));
    EXPECT_EQ(m3055::fuzz::check_loaded_scene(scene), "objects[0].material.m is not finite");
    EXPECT_NE(m3055::fuzz::check_error_message("fuzz.json: a\nb", true), "");
    EXPECT_NE(m3055::fuzz::check_error_message("other.json: a", true), "");
    EXPECT_EQ(m3055::fuzz::check_error_message("fuzz.json: camera: is required", true), "");
}

TEST(FuzzRegressions, InputsSplitIntoSceneAndSetTexts) {
    const std::string text = "{}\n#set a=1\n#set b.c=[1, 2]";
    const auto input = m3055::fuzz::split_input(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
    EXPECT_EQ(input.scene, "{}");
    EXPECT_EQ(input.sets, (std::vector<std::string>{"a=1", "b.c=[1, 2]"}));
}

}  // namespace
