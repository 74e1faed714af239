// libFuzzer target over the .brdf parser and the GLSL wrapper made from a
// parsed file; the property is tests/fuzz/brdf_fuzz_check.h. Built
// only with clang and -DM3055_FUZZ=ON; run by scripts/fuzz after the scene
// loader's target.
#include "brdf_fuzz_check.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string problem = m3055::fuzz::check_brdf_input(data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "brdf_fuzz: %s\n", problem.c_str());
        std::abort();  // libFuzzer saves the input as crash-*
    }
    return 0;
}
