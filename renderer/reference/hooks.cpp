#include "reference/hooks.h"

#include "models/model_spec.h"
#include "reference/classic.h"
#include "reference/principled.h"

#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace m3055::ref {

namespace {

// Every reference hook, by the name its GLSL namesake has. A new model's hook
// is added here (docs/adding-a-model.md).
template <typename Fn>
using ByName = std::map<std::string_view, Fn*>;

const ByName<OpaqueShadeFn> kOpaque = {{"shade_highlight", shade_highlight}};
const ByName<TranslucentShadeFn> kTranslucent = {{"shade_translucent", shade_translucent}};
const ByName<MetalLobeSumFn> kMetal = {
    {"beckmann_lobe_sum", beckmann_lobe_sum}, {"blinn_lobe_sum", blinn_lobe_sum}, {"phong_lobe_sum", phong_lobe_sum}};
const ByName<ClassicDiffuseFn> kDiffuse = {{"diffuse_lambert", diffuse_lambert},
                                           {"diffuse_half_lambert", diffuse_half_lambert},
                                           {"diffuse_half_lambert_clamped", diffuse_half_lambert_clamped},
                                           {"diffuse_half_lambert_normalized", diffuse_half_lambert_normalized},
                                           {"diffuse_oren_nayar", diffuse_oren_nayar},
                                           {"diffuse_minnaert", diffuse_minnaert},
                                           {"diffuse_principled", diffuse_principled}};
const ByName<ClassicSpecularFn> kSpecular = {{"specular_phong", specular_phong},
                                             {"specular_blinn_phong", specular_blinn_phong},
                                             {"specular_microfacet", specular_microfacet},
                                             {"specular_ward", specular_ward},
                                             {"specular_heidrich_seidel", specular_heidrich_seidel},
                                             {"specular_principled", specular_principled}};

template <typename Fn>
Fn* find(const ByName<Fn>& hooks, const std::string& name) {
    const auto it = hooks.find(name);
    return it == hooks.end() ? nullptr : it->second;
}

ReferenceHooks resolve(const ModelSpec& model) {
    ReferenceHooks hooks;
    switch (model.family) {
        case Family::opaque: hooks.opaque = find(kOpaque, model.glsl_hook); break;
        case Family::translucent: hooks.translucent = find(kTranslucent, model.glsl_hook); break;
        case Family::metal: hooks.metal = find(kMetal, model.glsl_hook); break;
        case Family::classic:
            hooks.classic_diffuse = find(kDiffuse, model.glsl_hook);
            if (!model.glsl_specular.empty()) hooks.classic_specular = find(kSpecular, model.glsl_specular);
            break;
        case Family::brdf: break;  // no C++ twin
    }
    return hooks;
}

}  // namespace

const ReferenceHooks& reference_hooks(const ModelSpec& model) {
    // Table entries never move or change once added (models/model_table.h),
    // so an id's hooks are resolved once; the reference may run on threads.
    static std::mutex mutex;
    static std::vector<std::unique_ptr<ReferenceHooks>> by_id;
    const std::lock_guard<std::mutex> lock(mutex);
    if (model.id < 0) throw std::logic_error("model \"" + model.name + "\" is not in the model table");
    const auto id = static_cast<std::size_t>(model.id);
    if (by_id.size() <= id) by_id.resize(id + 1);
    if (!by_id[id]) by_id[id] = std::make_unique<ReferenceHooks>(resolve(model));
    return *by_id[id];
}

bool has_reference(const ModelSpec& model) {
    const ReferenceHooks& hooks = reference_hooks(model);
    switch (model.family) {
        case Family::opaque: return hooks.opaque != nullptr;
        case Family::translucent: return hooks.translucent != nullptr;
        case Family::metal: return hooks.metal != nullptr;
        case Family::classic:
            return hooks.classic_diffuse != nullptr && model.glsl_specular.empty() == (hooks.classic_specular == nullptr);
        case Family::brdf: return false;
    }
    return false;
}

}  // namespace m3055::ref
