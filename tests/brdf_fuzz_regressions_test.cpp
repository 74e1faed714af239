// Re-checks, in every build, the .brdf fuzzer's seeds (tests/data/brdf/) and
// any input it once failed on (brdf_regressions/ in tests/fuzz/, once there
// is one) with its own property (tests/fuzz/brdf_fuzz_check.h).
#include "fuzz/brdf_fuzz_check.h"

#include "fuzz_corpus.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace {

std::string check_bytes(const std::string& bytes) {
    return m3055::fuzz::check_brdf_input(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

TEST(BrdfFuzzRegressions, SeedsAndRegressionsPass) {
    EXPECT_GE(m3055::test::expect_property_holds({"tests/data/brdf", "tests/fuzz/brdf_regressions"}, check_bytes), 3);
}

}  // namespace
