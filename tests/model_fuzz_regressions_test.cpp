// Re-checks, in every build, the model-file fuzzer's seeds
// (tests/fuzz/model_seeds/) and any input it once failed on
// (model_regressions/ in tests/fuzz/, once there is one) with its own
// property (tests/fuzz/model_fuzz_check.h); and that the property can fail.
#include "fuzz/model_fuzz_check.h"

#include "fuzz_corpus.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace {

std::string check_bytes(const std::string& bytes) {
    return m3055::fuzz::check_model_input(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

TEST(ModelFuzzRegressions, SeedsAndRegressionsPass) {
    EXPECT_GE(m3055::test::expect_property_holds({"tests/fuzz/model_seeds", "tests/fuzz/model_regressions"}, check_bytes),
              3);
}

// Each seed loads (the fuzzer starts from real models, not refusals).
TEST(ModelFuzzRegressions, EachSeedIsAModel) {
    for (const auto& path : m3055::test::corpus_files(m3055::test::source_path("tests/fuzz/model_seeds"))) {
        const std::string bytes = m3055::test::file_bytes(path);
        std::string side;
        std::string body = bytes.substr(1);
        const std::size_t marker = body.find("\n#side\n");
        if (marker != std::string::npos) side = body.substr(marker + 7), body.resize(marker + 1);
        const auto format = static_cast<m3055::model_file::Format>(bytes[0] % 3);
        EXPECT_NO_THROW(m3055::model_file::parse_model(body, format, [&](const std::string&) { return side; }, 100))
            << path;
    }
}

// The property finds what it is for: a model whose normal is not unit, or whose index is past its positions.
TEST(ModelFuzzRegressions, ThePropertyNamesABrokenModel) {
    m3055::model_file::Model model;
    model.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    model.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    model.indices = {0, 1, 2};
    model.groups = {0};
    model.parts = {0};
    model.materials.resize(1);
    model.hi = {1, 1, 0};
    EXPECT_EQ(m3055::fuzz::check_model(model), "");
    model.normals[1] = {0, 0, 2};
    EXPECT_EQ(m3055::fuzz::check_model(model), "a normal that is not unit");
    model.normals[1] = {0, 0, 1};
    model.indices[2] = 3;
    EXPECT_EQ(m3055::fuzz::check_model(model), "an index past the positions");
    EXPECT_EQ(check_bytes(std::string("\x00", 1) + "v 0 0 0\nf 1 2 3\n"), "") << "a refusal in one line passes";
}

}  // namespace
