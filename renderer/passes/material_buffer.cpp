#include "passes/material_buffer.h"

#include "reference/classic.h"

namespace m3055 {

// The model ids glsl/common/material.glsl defines (MODEL_*).
static float model_id(Model model) {
    switch (model) {
        case Model::highlight: return 0;
        case Model::translucent: return 1;
        case Model::metal: return 2;
        case Model::metal_blinn: return 3;
        case Model::metal_phong: return 4;
        case Model::lambert: return 5;
        case Model::half_lambert: return 6;
        case Model::half_lambert_clamped: return 7;
        case Model::half_lambert_normalized: return 8;
        case Model::oren_nayar: return 9;
        case Model::phong: return 10;
        case Model::blinn_phong: return 11;
        case Model::microfacet: return 12;
        case Model::ward: return 13;
        case Model::heidrich_seidel: return 14;
    }
    return 0;
}

// DISTRIBUTION_* (glsl/terms/distributions.glsl) and FRESNEL_* (common/material.glsl).
static float distribution_id(Distribution distribution) {
    switch (distribution) {
        case Distribution::blinn_phong: return 0;
        case Distribution::gaussian: return 1;
        case Distribution::beckmann: return 2;
        case Distribution::ggx: return 3;
    }
    return 0;
}

static float fresnel_id(Fresnel fresnel) {
    switch (fresnel) {
        case Fresnel::none: return 0;
        case Fresnel::schlick: return 1;
        case Fresnel::dielectric: return 2;
    }
    return 0;
}

// The Gaussian distribution's normalization b(m) has no closed form: computed
// here in double, once per lobe, and read by glsl gaussian_D.
static float lobe_norm(const Material& material, std::size_t j) {
    if (material.model != Model::microfacet || material.distribution != Distribution::gaussian ||
        j >= material.lobes.size())
        return 1.0f;
    return float(ref::gaussian_norm(material.lobes[j].m));
}

void pack_material(const Material& material, std::vector<float>& out) {
    const float record[kMaterialTexels * 4] = {
        float(material.color.r), float(material.color.g), float(material.color.b), model_id(material.model),
        float(material.d), float(material.w), float(material.m), float(material.t_n),
        float(material.t_p), float(material.lobes.size()), distribution_id(material.distribution),
        fresnel_id(material.fresnel),
        0, 0, 0, 0,
        0, 0, 0, 0,
        float(material.kd.r), float(material.kd.g), float(material.kd.b), float(material.shininess),
        float(material.ka.r), float(material.ka.g), float(material.ka.b), float(material.sigma),
        float(material.ks.r), float(material.ks.g), float(material.ks.b), float(material.ior),
        float(material.emission.r), float(material.emission.g), float(material.emission.b), float(material.alpha_x),
        float(material.axis.x), float(material.axis.y), float(material.axis.z), float(material.alpha_y),
        lobe_norm(material, 0), lobe_norm(material, 1), lobe_norm(material, 2), lobe_norm(material, 3),
    };
    const std::size_t base = out.size();
    out.insert(out.end(), record, record + kMaterialTexels * 4);
    for (std::size_t j = 0; j < material.lobes.size() && j < std::size_t(kMaxLobes); ++j) {
        out[base + 12 + 2 * j] = float(material.lobes[j].w);
        out[base + 13 + 2 * j] = float(material.lobes[j].m);
    }
}

}  // namespace m3055
