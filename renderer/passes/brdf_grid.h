// Evaluates any opaque model's BRDF on the GPU over a grid of (L, V) pairs:
// one render pass of glsl/passes/brdf_grid.frag into an RGBA32F texture, the
// same model code as the renderer's, so built-in models and .brdf files go the
// same way (m3055 brdf-check, m3055 plot). N = +z; the tangent frame is the
// material's axis (default +y: X = +x, Y = +y... as docs/models.md says).
#pragma once

#include "gl/gl_api.h"
#include "gl/program.h"
#include "scene/scene.h"

#include <memory>
#include <string>
#include <vector>

namespace m3055 {

// The GLSL error of `material`'s model ("" if its code compiles), one line
// naming a .brdf file's own line: for a caller that keeps the last good
// material on screen while a file is edited (brdf_file/brdf_model.h:
// reload_brdf_material). Compiles the grid pass, which holds the same model code
// as the renderer's passes; the program stays in `programs` for the grid.
std::string brdf_compile_error(ProgramCache& programs, const Material& material);
// The same with a cache of its own, dropped after the check.
std::string brdf_compile_error(const GlApi& gl, const Material& material);

class BrdfGrid {
public:
    // The GL context must stay current. Programs come from `programs`, shared
    // with whatever else draws in this context, so each compiles once.
    BrdfGrid(const GlApi& gl, ProgramCache& programs);
    explicit BrdfGrid(const GlApi& gl);  // with a program cache of its own
    ~BrdfGrid();
    BrdfGrid(const BrdfGrid&) = delete;
    BrdfGrid& operator=(const BrdfGrid&) = delete;

    // f(L_i, V_j) for every i, j: RGB at [(j * Ls.size() + i) * 3]. L and V
    // unit (at most 16384 of each); f = 0 where L.z <= 0. Throws ShaderError
    // if the model's code does not compile.
    std::vector<float> evaluate(const Material& material, const std::vector<dvec3>& Ls,
                                const std::vector<dvec3>& Vs);
    // f(L_k, V_k) for pairs (Ls and Vs of one length, at most 16384): RGB at [k * 3].
    std::vector<float> evaluate_pairs(const Material& material, const std::vector<dvec3>& Ls,
                                      const std::vector<dvec3>& Vs);

private:
    std::vector<float> run(const Material& material, const std::vector<dvec3>& Ls, const std::vector<dvec3>& Vs,
                           bool paired);
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace m3055
