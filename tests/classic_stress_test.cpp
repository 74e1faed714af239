// Numerical stress of the classic models (docs/spec.md#5-classic-models) through the stress harness:
// one input per pixel, the real GLSL (glsl/passes/stress.frag, general
// program) against the double reference on the same float inputs.
//   - Hostile inputs (grazing and exactly opposite L and V, N at the tangent
//     axis's pole, exponents 0 and 10000, roughness 0.001 and 2, IOR 1 and 5,
//     principled's numbers at 0 and 1):
//     never NaN or Inf, on the GPU or in the reference.
//   - Inputs away from the edges (N.L, N.V >= 0.02, lobe widths >= 0.02,
//     exponents <= 1000): |gpu - ref| <= 1e-3 max(1, |ref|), the GPU test's bound.
#include "material_support.h"
#include "reference/classic.h"
#include "stress_harness.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <map>
#include <random>

namespace m3055 {
namespace {

using test::StressInput;

// The classic models, in the model table's order: the random model is an
// index into this list, so a classic model added to the table is drawn too.
const std::vector<std::string>& classic_models() {
    static const std::vector<std::string> names = test::builtin_models_of(Family::classic);
    return names;
}

struct Generated {
    Material material;
    bool well_conditioned;  // lobe widths >= 0.01 rad, exponents <= 1000
    dvec3 axis;             // the drawn tangent axis (the material's, where its model has one), as a float
};

// Every parameter is drawn for every model (so the random sequence does not
// depend on the model); the material takes those its model has.
Generated random_material(std::mt19937& rng, bool hostile) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto pick = [&](std::initializer_list<double> edges, double lo, double hi) {
        if (hostile && u(rng) < 0.5) return *(edges.begin() + int(u(rng) * edges.size()) % edges.size());
        return lo + (hi - lo) * u(rng);
    };
    const int models = int(classic_models().size());
    Material m = Material::of(classic_models()[std::size_t(int(u(rng) * models) % models)]);
    const dvec3 kd{u(rng), u(rng), u(rng)};
    const dvec3 ka{u(rng), u(rng), u(rng)};
    const dvec3 ks{u(rng), u(rng), u(rng)};
    const dvec3 emission{0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)};
    const double shininess = pick({0.0, 1e-3, 10000.0}, 0.0, 1000.0);
    const double sigma = pick({0.0, 10.0}, 0.0, 1.5);
    const double ior = pick({1.0, 5.0}, 1.0, 3.0);
    const double alpha_x = pick({0.001, 1.0}, 0.02, 1.0);
    const double alpha_y = pick({0.001, 1.0}, 0.02, 1.0);
    const dvec3 axis = glm::normalize(dvec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5) + dvec3(0, 1e-3, 0));
    const auto distribution = static_cast<ref::Distribution>(int(u(rng) * 4) % 4);
    const auto fresnel = static_cast<ref::Fresnel>(int(u(rng) * 3) % 3);
    const int count = 1 + int(u(rng) * 4) % 4;
    const bool exponent = distribution == ref::Distribution::blinn_phong;
    std::vector<Lobe> lobes;
    for (int j = 0; j < count; ++j)
        lobes.push_back({u(rng), exponent ? pick({0.0, 10000.0}, 0.0, 1000.0) : pick({0.001, 2.0}, 0.02, 2.0)});
    // principled: every number in [0, 1], hostile at its ends.
    const char* principled_numbers[] = {"subsurface", "metallic", "specular", "specular_tint", "roughness",
                                        "anisotropic", "sheen", "sheen_tint", "clearcoat", "clearcoat_gloss"};
    double principled[10];
    for (double& value : principled) value = pick({0.0, 1.0}, 0.0, 1.0);
    bool ok = shininess <= 1000.0 && alpha_x >= 0.02 && alpha_y >= 0.02;
    for (const Lobe& lobe : lobes) ok = ok && (exponent ? lobe.m <= 1000.0 : lobe.m >= 0.02);

    // The diffuse colour: kd, or principled's base_color (what ka defaults to).
    m.set_vec3(m.model().param("ka").default_from, kd);
    m.set_vec3("ka", ka);
    m.set_vec3("emission", emission);
    if (m.has("ks")) m.set_vec3("ks", ks);
    if (m.has("shininess")) m.set_number("shininess", shininess);
    if (m.has("sigma")) m.set_number("sigma", sigma);
    if (m.has("ior")) m.set_number("ior", ior);
    if (m.has("alpha_x")) m.set_number("alpha_x", alpha_x), m.set_number("alpha_y", alpha_y);
    if (m.has("axis")) m.set_vec3("axis", axis);
    if (m.has("roughness")) {
        for (int k = 0; k < 10; ++k) m.set_number(principled_numbers[k], principled[k]);
        // Lobe widths >= 0.02 as above: the specular's alpha_y = r^2 sqrt(1 - 0.9 anisotropic),
        // and the clear coat's alpha = mix(0.1, 0.001, gloss) where it shows.
        const double r2 = principled[4] * principled[4];
        const double coat_alpha = 0.1 + (0.001 - 0.1) * principled[9];
        ok = r2 * std::sqrt(1.0 - 0.9 * principled[5]) >= 0.02 && (principled[8] == 0.0 || coat_alpha >= 0.02);
    }
    if (m.has("distribution")) {
        m.set_choice("distribution", int(distribution));
        m.set_choice("fresnel", int(fresnel));
        m.set_lobes(lobes);
    }
    // Every number as the GPU reads it (float), so both sides see the same input.
    return {test::float_rounded(m), ok, dvec3(glm::vec3(axis))};
}

dvec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> g(0.0, 1.0);
    return glm::normalize(dvec3{g(rng), g(rng), g(rng)});
}

TEST(ClassicStress, FiniteEverywhereAndAccurateAwayFromTheEdges) {
    test::StressHarness harness;
    std::mt19937 rng(2024);
    test::StressBatch batch;
    batch.light0.intensity = 1.0;
    batch.light0.ambient = {0.1, 0.1, 0.1};
    Light fill;
    fill.direction = glm::normalize(dvec3(-1, 0.3, 0.5));
    fill.intensity = 0.5;
    fill.ambient = {0.05, 0.0, 0.05};
    batch.more_lights = {fill};
    std::vector<bool> checked;
    const int count = 200000;
    for (int i = 0; i < count; ++i) {
        const bool hostile = i % 2 == 1;
        Generated g = random_material(rng, hostile);
        dvec3 N = random_unit(rng), V = random_unit(rng), L = random_unit(rng);
        if (glm::dot(N, V) < 0) V = -V;
        if (hostile) {
            switch (i / 2 % 6) {
                case 0: L = -V; break;                                             // opposite
                case 1: L = glm::normalize(L - glm::dot(L, N) * N + 1e-7 * N); break;  // grazing light
                case 2: V = glm::normalize(V - glm::dot(V, N) * N + 1e-7 * N); break;  // grazing view
                case 3: N = g.axis; break;                                         // tangent-frame pole
                case 4: L = V = N; break;                                          // head on
                default: break;
            }
        }
        StressInput input;
        input.N = glm::vec3(N);
        input.V = glm::vec3(V);
        input.L = glm::vec3(L);
        input.material = g.material;
        batch.inputs.push_back(input);
        const dvec3 n = glm::normalize(dvec3(input.N)), v = glm::normalize(dvec3(input.V)),
                    l = glm::normalize(dvec3(input.L));
        checked.push_back(!hostile && g.well_conditioned && glm::dot(n, l) >= 0.02 && glm::dot(n, v) >= 0.02);
    }
    const std::vector<test::StressOutput> gpu = harness.evaluate_gpu(batch);
    const std::vector<Light> lights = test::stress_lights(batch);
    long nonfinite_gpu = 0, nonfinite_ref = 0, compared = 0, beyond = 0;
    double worst = 0.0;
    std::map<std::string, std::pair<long, double>> by_model;  // compared, worst
    for (int i = 0; i < count; ++i) {
        const dvec3 ref = test::evaluate_reference(batch.inputs[i], lights).color;
        const dvec3 got = gpu[i].color;
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(got[c])) ++nonfinite_gpu;
            if (!std::isfinite(ref[c])) ++nonfinite_ref;
        }
        if (!checked[i]) continue;
        ++compared;
        double scaled = 0.0;
        for (int c = 0; c < 3; ++c) scaled = std::max(scaled, std::abs(got[c] - ref[c]) / std::max(1.0, std::abs(ref[c])));
        worst = std::max(worst, scaled);
        auto& [model_compared, model_worst] = by_model[batch.inputs[i].material.model_name()];
        ++model_compared;
        model_worst = std::max(model_worst, scaled);
        if (scaled > 1e-3) {
            ++beyond;
            if (beyond <= 5)
                ADD_FAILURE() << test::describe(batch.inputs[i].material) << " input " << i << ": gpu " << got.x << " "
                              << got.y << " " << got.z << " ref " << ref.x << " " << ref.y << " " << ref.z;
        }
    }
    std::printf("[ result   ] %ld inputs compared, worst scaled difference %.3g; non-finite gpu %ld ref %ld\n",
                compared, worst, nonfinite_gpu, nonfinite_ref);
    for (const auto& [model, measured] : by_model)
        std::printf("[ result   ]   %s: %ld compared, worst %.3g\n", model.c_str(), measured.first, measured.second);
    EXPECT_EQ(nonfinite_gpu, 0);
    EXPECT_EQ(nonfinite_ref, 0);
    EXPECT_GT(compared, 5000);
    EXPECT_EQ(beyond, 0) << "worst scaled difference " << worst;
}

}  // namespace
}  // namespace m3055
