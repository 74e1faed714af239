// Re-checks, in every build, the .brdf fuzzer's seeds (tests/data/brdf/) and
// any input it once failed on (brdf_regressions/ in tests/fuzz/, once there
// is one) with its own property (tests/fuzz/brdf_fuzz_check.h).
#include "fuzz/brdf_fuzz_check.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace {

namespace fs = std::filesystem;

std::string check_file(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    return m3055::fuzz::check_brdf_input(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

TEST(BrdfFuzzRegressions, SeedsAndRegressionsPass) {
    int checked = 0;
    for (const char* folder : {"tests/data/brdf", "tests/fuzz/brdf_regressions"}) {
        const std::string path = m3055::test::source_path(folder);
        if (!fs::is_directory(path)) continue;
        for (const auto& entry : fs::directory_iterator(path)) {
            EXPECT_EQ(check_file(entry.path()), "") << entry.path();
            ++checked;
        }
    }
    EXPECT_GE(checked, 3);
}

}  // namespace
