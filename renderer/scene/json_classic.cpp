// Scene-file form of the classic models (SPEC 5). Parameters and ranges are
// those of docs/models.md; every error is "SOURCE: json.path: problem".
#include "scene/json_classic.h"

#include <algorithm>

namespace m3055::scene_json {

namespace {

const Range kExponent = closed(0.0, 10000.0);     // shininess, blinn_phong D exponent n
const Range kRoughness = closed(0.001, 2.0);      // gaussian / beckmann / ggx m
const Range kLobeWeight = closed(0.0, 1.0);       // microfacet lobe weights
const Range kSigma = closed(0.0, 10.0);           // Oren-Nayar sigma (radians; A, B saturate)
const Range kIor = closed(1.0, 5.0);              // index of refraction
const Range kWardAlpha = closed(0.001, 1.0);      // Ward alpha_x, alpha_y

const std::vector<std::string> kDistributions = {"blinn_phong", "gaussian", "beckmann", "ggx"};
const std::vector<std::string> kFresnels = {"none", "schlick", "dielectric"};

// The keys each classic model reads, besides "model".
std::vector<std::string> keys_of(Model model) {
    std::vector<std::string> keys = {"kd", "ka", "emission"};
    if (has_specular(model)) keys.push_back("ks");
    switch (model) {
        case Model::oren_nayar: keys.push_back("sigma"); break;
        case Model::phong:
        case Model::blinn_phong: keys.push_back("shininess"); break;
        case Model::microfacet: keys.insert(keys.end(), {"distribution", "fresnel", "ior", "lobes"}); break;
        case Model::ward: keys.insert(keys.end(), {"alpha_x", "alpha_y", "axis"}); break;
        case Model::heidrich_seidel: keys.insert(keys.end(), {"shininess", "axis"}); break;
        default: break;
    }
    return keys;
}

// Microfacet lobes: {"w", "m"} (roughness) or {"w", "n"} (blinn_phong exponent).
std::vector<Lobe> read_lobes(const Node& node, Distribution distribution) {
    const bool exponent = distribution == Distribution::blinn_phong;
    return read_lobe_list(node, exponent ? "n" : "m", exponent ? "m" : "n", kLobeWeight,
                          exponent ? kExponent : kRoughness,
                          std::string("distribution ") + to_string(distribution));
}

}  // namespace

const std::vector<std::string>& classic_model_names() {
    static const std::vector<std::string> names = {
        "lambert", "half_lambert", "half_lambert_clamped", "half_lambert_normalized", "oren_nayar",
        "phong",   "blinn_phong",  "microfacet",           "ward",                    "heidrich_seidel"};
    return names;
}

bool is_classic_material_key(const std::string& key) {
    static const std::vector<std::string> all = {"kd",     "ka",          "ks",      "emission", "sigma",
                                                 "shininess", "distribution", "fresnel", "ior", "lobes",
                                                 "alpha_x", "alpha_y",     "axis"};
    return std::find(all.begin(), all.end(), key) != all.end();
}

Material read_classic_material(const Node& node, Model model) {
    std::vector<std::string> allowed = keys_of(model);
    allowed.push_back("model");
    const std::string problem = std::string("not a parameter of model ") + to_string(model);
    node.check_keys(allowed, [&](const std::string& key) {
        if (key == "color") return problem + " (its diffuse colour is \"kd\")";
        if (is_classic_material_key(key) || key == "d" || key == "w" || key == "m" || key == "t_n" || key == "t_p")
            return problem;
        return std::string();
    });

    Material material;
    material.model = model;
    material.kd = node.required("kd").vec3_in(kUnit);
    // seed 001: the ambient colour is the diffuse colour unless given.
    material.ka = node.has("ka") ? node.child("ka").vec3_in(kUnit) : material.kd;
    if (node.has("emission")) material.emission = node.child("emission").vec3_in(kUnit);
    if (node.has("ks")) material.ks = node.child("ks").vec3_in(kUnit);
    if (node.has("sigma")) material.sigma = node.child("sigma").number_in(kSigma);
    if (node.has("shininess")) material.shininess = node.child("shininess").number_in(kExponent);
    if (model == Model::microfacet) {
        if (node.has("distribution"))
            material.distribution = static_cast<Distribution>(node.child("distribution").one_of(kDistributions));
        if (node.has("fresnel")) material.fresnel = static_cast<Fresnel>(node.child("fresnel").one_of(kFresnels));
        if (node.has("ior")) material.ior = node.child("ior").number_in(kIor);
        material.lobes = node.has("lobes") ? read_lobes(node.child("lobes"), material.distribution)
                         : material.distribution == Distribution::blinn_phong ? std::vector<Lobe>{{1.0, 100.0}}
                                                                              : std::vector<Lobe>{{1.0, 0.3}};
    }
    if (node.has("alpha_x")) material.alpha_x = node.child("alpha_x").number_in(kWardAlpha);
    if (node.has("alpha_y")) material.alpha_y = node.child("alpha_y").number_in(kWardAlpha);
    if (node.has("axis")) material.axis = node.child("axis").direction();
    return material;
}

json classic_material_json(const Material& material) {
    auto vec = [](const dvec3& v) { return json::array({v.x, v.y, v.z}); };
    json out = {{"model", to_string(material.model)},
                {"kd", vec(material.kd)},
                {"ka", vec(material.ka)},
                {"emission", vec(material.emission)}};
    const Model model = material.model;
    if (has_specular(model)) out["ks"] = vec(material.ks);
    if (model == Model::oren_nayar) out["sigma"] = material.sigma;
    if (model == Model::phong || model == Model::blinn_phong || model == Model::heidrich_seidel)
        out["shininess"] = material.shininess;
    if (model == Model::microfacet) {
        out["distribution"] = to_string(material.distribution);
        out["fresnel"] = to_string(material.fresnel);
        out["ior"] = material.ior;
        const char* key = material.distribution == Distribution::blinn_phong ? "n" : "m";
        json lobes = json::array();
        for (const Lobe& lobe : material.lobes) lobes.push_back({{"w", lobe.w}, {key, lobe.m}});
        out["lobes"] = std::move(lobes);
    }
    if (model == Model::ward) {
        out["alpha_x"] = material.alpha_x;
        out["alpha_y"] = material.alpha_y;
    }
    if (model == Model::ward || model == Model::heidrich_seidel) out["axis"] = vec(material.axis);
    return out;
}

}  // namespace m3055::scene_json
