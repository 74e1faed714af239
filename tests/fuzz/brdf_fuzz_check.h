// The property the .brdf fuzzer checks (tests/fuzz/brdf_fuzz.cpp), kept in a
// header so that ctest re-checks the seeds and any committed regression input
// in every build (tests/brdf_fuzz_regressions_test.cpp): parse_brdf either
// returns a file whose GLSL wrapper can be generated, or throws one BrdfError
// line of valid UTF-8 naming the file; never another exception. The GLSL ES
// translation of the block (brdf_glsl_es.h) keeps its lines.
#pragma once

#include "brdf_file/brdf_file.h"
#include "brdf_file/brdf_glsl.h"
#include "scene_fuzz_check.h"

#include <algorithm>
#include <cstdint>
#include <string>

namespace m3055::fuzz {

inline std::string check_brdf_input(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const BrdfFile file = parse_brdf(text, "fuzz.brdf");
        std::vector<std::string> fields;
        for (std::size_t i = 0; i < file.params.size(); ++i) fields.push_back("b0_" + std::to_string(i));
        const auto sources = brdf_glsl_sources(file, 0, "generated/brdf_0.glsl", "m3055_b0_hook", fields);
        if (sources.size() != 2 || sources[1].second.size() < file.shader.size()) return "the GLSL sources are short";
        // The GLSL ES block (brdf_glsl_es.h) keeps the block's lines, whatever the input.
        const auto es = brdf_glsl_es_sources(file, 0, "generated/brdf_0.glsl", "m3055_b0_hook", fields);
        const auto lines = [](const std::string& t) { return std::count(t.begin(), t.end(), '\n'); };
        if (es.size() != 2 || lines(es[1].second) != lines(sources[1].second)) return "the GLSL ES block has other lines";
        for (const BrdfParam& p : file.params)
            for (double v : p.fallback)
                if (!std::isfinite(v)) return "a non-finite default for " + p.name;
    } catch (const BrdfError& e) {
        const std::string problem = check_error_message(e.what(), false);
        if (!problem.empty()) return problem;
        if (std::string(e.what()).rfind("fuzz.brdf", 0) != 0) return std::string("does not name the file: ") + e.what();
    } catch (const std::exception& e) {
        return std::string("not a BrdfError: ") + e.what();
    }
    return "";
}

}  // namespace m3055::fuzz
