// libFuzzer target over the scene loader, the `--set` override parser and
// the batch manifest loader: an input starting with
// "#manifest" is a manifest (manifest_fuzz_check.h). Built only with clang and
// -DM3055_FUZZ=ON; run by scripts/fuzz. The properties live in the headers so
// that ctest re-checks every committed regression input
// (tests/fuzz/regressions/) in every build.
#include "manifest_fuzz_check.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string problem = m3055::fuzz::check_fuzz_input(data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "scene_loader_fuzz: %s\n", problem.c_str());
        std::abort();  // libFuzzer saves the input as crash-*
    }
    return 0;
}
