// Each model's C++ twin, found by name. A model's table entry names its GLSL
// hook (ModelSpec::glsl_hook, glsl_specular); the reference function with the
// same name in m3055::ref is its double-precision twin (the namesakes rule,
// tests/reference_namesakes_test.cpp). The binding lives here, above the model
// table, so that the table (models/) knows nothing of the reference and the
// reference depends on the table, not the other way round.
#pragma once

#include "reference/reference.h"

namespace m3055 {

struct ModelSpec;

namespace ref {

// The reference hook of each family (the signatures: reference/reference.h).
struct ReferenceHooks {
    OpaqueShadeFn* opaque = nullptr;
    TranslucentShadeFn* translucent = nullptr;
    MetalLobeSumFn* metal = nullptr;
    ClassicDiffuseFn* classic_diffuse = nullptr;
    ClassicSpecularFn* classic_specular = nullptr;  // nullptr: no specular term
};

// The hooks `model`'s entry names, for its family; all null for a model without
// a C++ twin (family brdf: a .brdf file's code runs on the GPU only). Resolved
// once per model (by its table id) and cached.
const ReferenceHooks& reference_hooks(const ModelSpec& model);

// Whether `model` has every hook its family needs: opaque, translucent or
// metal one, classic a diffuse one and a specular one exactly when the entry
// names a GLSL specular hook.
bool has_reference(const ModelSpec& model);

}  // namespace ref
}  // namespace m3055
