// libFuzzer target over the model-file loaders (OBJ through tinyobjloader,
// glTF and .glb through tinygltf, then triangulation and normals); the
// property is tests/fuzz/model_fuzz_check.h. Built only with clang and
// -DM3055_FUZZ=ON; run by scripts/fuzz beside the other targets.
#include "model_fuzz_check.h"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string problem = m3055::fuzz::check_model_input(data, size);
    if (!problem.empty()) {
        std::fprintf(stderr, "model_fuzz: %s\n", problem.c_str());
        std::abort();  // libFuzzer saves the input as crash-*
    }
    return 0;
}
