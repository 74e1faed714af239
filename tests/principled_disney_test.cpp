// Burley's principled BRDF (docs/models.md#principled-burleys-principled-brdf)
// against its reference implementation, BRDF Explorer's src/brdfs/disney.brdf, read as a .brdf
// material: {"model": "brdf", "file": ".../disney.brdf", "params": {...}},
// shaded on the classic models' scale like `principled` (pi f (N.L)+ a c).
// disney.brdf is third-party and not in this repository: set
// M3055_BRDF_EXPLORER_BRDFS to a folder holding it (e.g. a checkout's
// src/brdfs); without it these tests are skipped, saying so.
//
// The file applies mon2lin (x^2.2) to its baseColor; `base_color` is linear,
// so the file is given baseColor = base_color^(1/2.2).
//
// Eleven parameter sets x four light set-ups x both cameras, the same scene
// each time, on the reference's interior pixels:
//   - principled (GPU) against disney.brdf (GPU): >= 99.5 % of pixels on the
//     same 5-bit display level, none more than one level off;
//   - disney.brdf (GPU) against principled's double reference: the same, and
//     |file - ref| <= 1e-3 max(1, |ref|) but for the glossy clear coat, where
//     the file's float 1 + (a^2 - 1) cos^2 loses its digits (a stated bound);
//   - principled (GPU) against its reference: |d| <= 1e-3 max(1, |ref|), as in
//     classic_gpu_test (here for the record beside the file's figures);
// and the BRDF itself, disney.brdf and principled on the GPU grid of m3055
// brdf-check against the reference's f for every pair of 177 directions (theta
// every 7.5 degrees to 82.5, 16 azimuths, the pole), with the same bounds.
#include "brdf_file/brdf_model.h"
#include "gpu_compare.h"
#include "analysis/brdf_check.h"
#include "frame/renderer.h"
#include "image/quantize.h"
#include "passes/brdf_grid.h"
#include "reference/classic.h"
#include "reference/reference.h"
#include "scene/load.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace m3055 {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kSameLevelShare = 0.995;
constexpr double kTolerance = 1e-3;
// disney.brdf's GTR1 at clearcoat_gloss 1 (alpha 0.001), in float: its
// 1 + (a^2 - 1) cos^2 theta_h must resolve a^2 = 1e-6 where cos theta_h, near 1,
// holds only ~6e-8; within a fraction of a degree of the coat's peak (display
// white) the file is off by up to some 10 %. Measured: 8.6e-2 in the renders,
// 0.12 on the grid, where principled's own GLSL measured 2.4e-4 and 4e-6; the
// file changed to take sin^2 theta_h from |N x H|^2 (as principled.glsl does)
// measured 2.4e-4 in the renders too: the difference is the file's rounding.
constexpr double kGlossyCoatTolerance = 0.25;

// The folder's disney.brdf, or "" when M3055_BRDF_EXPLORER_BRDFS names none.
std::string disney_file() {
    const char* folder = std::getenv("M3055_BRDF_EXPLORER_BRDFS");
    if (!folder) return "";
    const fs::path path = fs::path(folder) / "disney.brdf";
    return fs::is_regular_file(path) ? path.string() : "";
}

#define SKIP_WITHOUT_DISNEY_BRDF()                                                                             \
    if (disney_file().empty())                                                                                 \
    GTEST_SKIP() << "M3055_BRDF_EXPLORER_BRDFS does not hold disney.brdf: set it to BRDF Explorer's src/brdfs " \
                    "(github.com/wdas/brdf) to compare principled with Disney's own implementation"

// One parameter set: our keys; the file's names are the same in camelCase.
struct Setting {
    std::string name;
    json numbers;  // principled's number keys
    std::vector<double> base_color;  // empty: the defaults, disney.brdf's baseColor (.82, .67, .16)
    std::vector<double> axis = {0, 1, 0};
};

std::vector<Setting> settings() {
    return {
        {"defaults", json::object(), {}},
        {"metallic", {{"metallic", 1}, {"roughness", 0.3}}, {0.9, 0.6, 0.2}},
        {"anisotropic_axis", {{"anisotropic", 1}, {"roughness", 0.45}}, {0.3, 0.3, 0.8}, {0, 1, 1}},
        {"clearcoat_gloss05", {{"clearcoat", 1}, {"clearcoat_gloss", 0.5}}, {0.1, 0.2, 0.6}},
        {"clearcoat_gloss1", {{"clearcoat", 1}, {"clearcoat_gloss", 1}}, {0.1, 0.2, 0.6}},
        {"sheen", {{"sheen", 1}, {"sheen_tint", 1}, {"roughness", 0.9}}, {0.5, 0.1, 0.1}},
        {"subsurface", {{"subsurface", 1}, {"roughness", 0.8}}, {0.7, 0.3, 0.2}},
        {"rough", {{"roughness", 1}}, {0.2, 0.6, 0.3}},
        {"smooth", {{"roughness", 0.05}, {"specular", 1}}, {0.2, 0.6, 0.3}},
        {"specular_tint", {{"specular", 1}, {"specular_tint", 1}, {"roughness", 0.25}}, {0.2, 0.5, 0.8}},
        {"all", {{"subsurface", 0.4}, {"metallic", 0.3}, {"specular", 0.7}, {"specular_tint", 0.5},
                 {"roughness", 0.35}, {"anisotropic", 0.6}, {"sheen", 0.8}, {"sheen_tint", 0.3},
                 {"clearcoat", 0.6}, {"clearcoat_gloss", 0.7}},
         {0.8, 0.5, 0.3}, {1, 1, 0}},
    };
}

// "clearcoat_gloss" -> "clearcoatGloss": disney.brdf's names.
std::string camel(const std::string& key) {
    std::string out;
    for (std::size_t i = 0; i < key.size(); ++i)
        out += key[i] == '_' && i + 1 < key.size() ? char(std::toupper(static_cast<unsigned char>(key[++i]))) : key[i];
    return out;
}

json principled_material(const Setting& s) {
    json m = s.numbers;
    m["model"] = "principled";
    if (!s.base_color.empty()) m["base_color"] = s.base_color;
    m["axis"] = s.axis;
    return m;
}

json disney_material(const Setting& s) {
    json params = json::object();
    for (const auto& [key, value] : s.numbers.items()) params[camel(key)] = value;
    // mon2lin(baseColor) = baseColor^2.2 is our linear base_color.
    if (!s.base_color.empty())
        params["baseColor"] = {std::pow(s.base_color[0], 1 / 2.2), std::pow(s.base_color[1], 1 / 2.2),
                               std::pow(s.base_color[2], 1 / 2.2)};
    return {{"model", "brdf"}, {"file", disney_file()}, {"params", params}, {"axis", s.axis}};
}

Light light(LightType type, dvec3 at, double intensity, dvec3 colour) {
    Light l;
    l.type = type;
    if (type == LightType::directional) l.direction = glm::normalize(at);
    else l.position = at;
    l.intensity = intensity;
    l.color = colour;
    return l;
}

// As brdf_model_test's: a key; key, coloured fill, attenuated point and spot; behind; grazing.
std::vector<std::pair<std::string, std::vector<Light>>> light_setups() {
    Light point = light(LightType::point, {-2, 1.5, 3}, 1.0, {0.9, 0.8, 0.6});
    point.att_constant = 0.5, point.att_linear = 0.1, point.att_quadratic = 0.02;
    Light spot = light(LightType::spot, {0.5, 3, 3}, 1.0, {1, 1, 1});
    spot.spot_direction = glm::normalize(dvec3(-0.5, -3, -3));
    spot.spot_exponent = 8;
    return {{"key", {light(LightType::directional, {1, 1, 1}, 1.0, {1, 1, 1})}},
            {"four", {light(LightType::directional, {1, 1, 1}, 1.0, {1, 1, 1}),
                      light(LightType::directional, {-1, 0.2, 0.5}, 0.4, {0.3, 0.5, 1.0}), point, spot}},
            {"behind", {light(LightType::directional, {0, 0, -1}, 1.0, {1, 1, 1})}},
            {"grazing", {light(LightType::directional, {1, 0, 0.02}, 2.0, {1, 1, 1})}}};
}

// `material` (JSON, as a scene gives it) on test::single_sphere_scene's sphere.
Scene scene_with(const json& material, const std::vector<Light>& lights, bool ortho) {
    Scene scene = test::single_sphere_scene(Material::of("lambert"), lights, ortho);
    json doc = scene_to_json(scene, PathWriting::absolute());
    doc["objects"][0]["material"] = material;
    return scene_from_json(doc, "principled_disney.json", LoadContext::trusted());
}

RgbFloatImage render(const Scene& scene) {
    Renderer& renderer = test::shared_renderer();
    renderer.set_shader_mode(ShaderMode::specialized);
    renderer.render(scene);
    return renderer.read_raw();
}

struct Measured {
    double max_abs = 0, max_scaled = 0, same_share = 1;
    int max_levels = 0;
    long nonfinite = 0;
    void fold(const Measured& m) {
        max_abs = std::max(max_abs, m.max_abs), max_scaled = std::max(max_scaled, m.max_scaled);
        same_share = std::min(same_share, m.same_share), max_levels = std::max(max_levels, m.max_levels);
        nonfinite += m.nonfinite;
    }
};

// Channel c of pixel (x, y), y from the top: of a raw image (stored bottom to
// top) and of the reference.
double raw_at(const RgbFloatImage& image, int x, int y, int c) {
    return image.pixels[(std::size_t(image.height - 1 - y) * image.width + std::size_t(x)) * 3 + std::size_t(c)];
}
double ref_at(const ref::ReferenceImage& image, int x, int y, int c) {
    return image.rgb[(std::size_t(y) * image.width + std::size_t(x)) * 3 + std::size_t(c)];
}

// `a` against `b` (b(x, y, c): a raw image or the reference) on the
// reference's interior pixels.
template <typename At>
Measured measure(const RgbFloatImage& a, At b, const ref::ReferenceImage& reference, int bits, long* interior) {
    Measured m;
    long same = 0, count = 0;
    for (float v : a.pixels)
        if (!std::isfinite(v)) ++m.nonfinite;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            if (!ref::is_interior(reference, x, y)) continue;
            ++count;
            bool on_level = true;
            for (int c = 0; c < 3; ++c) {
                const double got = raw_at(a, x, y, c);
                const double expected = b(x, y, c);
                const double diff = std::abs(got - expected);
                m.max_abs = std::max(m.max_abs, diff);
                m.max_scaled = std::max(m.max_scaled, diff / std::max(1.0, std::abs(expected)));
                const int levels = std::abs(quantize_level(got, bits) - quantize_level(expected, bits));
                m.max_levels = std::max(m.max_levels, levels);
                if (levels) on_level = false;
            }
            if (on_level) ++same;
        }
    m.same_share = count ? double(same) / count : 1.0;
    *interior = count;
    return m;
}

TEST(PrincipledVsDisneyBrdf, RendersOnTheSameDisplayLevels) {
    SKIP_WITHOUT_DISNEY_BRDF();
    Measured all_gpu, all_file_ref, all_ours_ref;
    for (const Setting& s : settings()) {
        Measured gpu, file_ref, ours_ref;
        for (const auto& [lights_name, lights] : light_setups())
            for (bool ortho : {false, true}) {
                SCOPED_TRACE(s.name + " " + lights_name + (ortho ? " ortho" : " persp"));
                const Scene ours = scene_with(principled_material(s), lights, ortho);
                const Scene theirs = scene_with(disney_material(s), lights, ortho);
                const ref::ReferenceImage reference = ref::render_reference(ours);
                const RgbFloatImage ours_raw = render(ours), theirs_raw = render(theirs);
                const int bits = ours.display.bits;
                long interior = 0;
                auto theirs_at = [&](int x, int y, int c) { return raw_at(theirs_raw, x, y, c); };
                auto reference_at = [&](int x, int y, int c) { return ref_at(reference, x, y, c); };
                const Measured g = measure(ours_raw, theirs_at, reference, bits, &interior);
                const Measured f = measure(theirs_raw, reference_at, reference, bits, &interior);
                const Measured o = measure(ours_raw, reference_at, reference, bits, &interior);
                EXPECT_GT(interior, 1000);
                EXPECT_EQ(g.nonfinite + f.nonfinite, 0);
                EXPECT_GE(g.same_share, kSameLevelShare);
                EXPECT_LE(g.max_levels, 1);
                EXPECT_GE(f.same_share, kSameLevelShare);
                EXPECT_LE(f.max_levels, 1);
                EXPECT_LE(f.max_scaled, s.name == "clearcoat_gloss1" ? kGlossyCoatTolerance : kTolerance);
                EXPECT_LE(o.max_scaled, kTolerance);
                gpu.fold(g), file_ref.fold(f), ours_ref.fold(o);
            }
        std::printf("[ result   ] %-18s principled vs disney.brdf: max |d| %.2g, same level %.4f %%, max %d level(s); "
                    "disney.brdf vs reference: max scaled %.2g; principled vs reference: max scaled %.2g\n",
                    s.name.c_str(), gpu.max_abs, 100 * gpu.same_share, gpu.max_levels, file_ref.max_scaled,
                    ours_ref.max_scaled);
        all_gpu.fold(gpu), all_file_ref.fold(file_ref), all_ours_ref.fold(ours_ref);
    }
    std::printf("[ result   ] all: principled vs disney.brdf: max |d| %.2g, fewest on the same level %.4f %%, "
                "max %d level(s); disney.brdf vs reference %.2g, principled vs reference %.2g (max scaled)\n",
                all_gpu.max_abs, 100 * all_gpu.same_share, all_gpu.max_levels, all_file_ref.max_scaled,
                all_ours_ref.max_scaled);
}

// f itself: the file on the GPU grid (m3055 brdf-check's) against the
// reference's f over the upper hemisphere, every pair (L, V) of brdf-check's
// directions above the horizon.
TEST(PrincipledVsDisneyBrdf, TheFilesBrdfIsTheReferences) {
    SKIP_WITHOUT_DISNEY_BRDF();
    BrdfGrid grid(test::shared_gl());
    const std::vector<dvec3> dirs = check_directions(12, 16);  // brdf-check's: theta 7.5 ... 90 deg x 16, the pole
    // The largest |f - ref| / max(1, |ref|) of `model`'s f on the grid.
    auto worst_of = [&](const Material& model, const Material& principled, long* compared) {
        const std::vector<float> f = grid.evaluate(model, dirs, dirs);
        double worst = 0;
        *compared = 0;
        for (std::size_t j = 0; j < dirs.size(); ++j)
            for (std::size_t i = 0; i < dirs.size(); ++i) {
                if (!(dirs[i].z > 0.0 && dirs[j].z > 0.0)) continue;  // exactly grazing: N.L = 0
                const dvec3 expected = ref::classic_brdf(principled, dvec3(0, 0, 1), dirs[i], dirs[j]);
                ++*compared;
                for (int c = 0; c < 3; ++c) {
                    const double got = f[(j * dirs.size() + i) * 3 + std::size_t(c)];
                    worst = std::max(worst, std::abs(got - expected[c]) / std::max(1.0, std::abs(expected[c])));
                }
            }
        return worst;
    };
    double worst_file = 0, worst_ours = 0;
    for (const Setting& s : settings()) {
        const Material principled = scene_with(principled_material(s), {}, false).objects[0].material;
        const Material file = scene_with(disney_material(s), {}, false).objects[0].material;
        long compared = 0;
        const double theirs = worst_of(file, principled, &compared);
        const double ours = worst_of(principled, principled, &compared);
        EXPECT_EQ(compared, 177 * 177);
        EXPECT_LE(theirs, s.name == "clearcoat_gloss1" ? kGlossyCoatTolerance : kTolerance) << s.name;
        EXPECT_LE(ours, kTolerance) << s.name;
        std::printf("[ result   ] %-18s f on the grid vs the reference (%ld pairs): disney.brdf %.2g, "
                    "principled %.2g\n",
                    s.name.c_str(), compared, theirs, ours);
        worst_file = std::max(worst_file, theirs), worst_ours = std::max(worst_ours, ours);
    }
    std::printf("[ result   ] all: f on the grid vs the reference: disney.brdf %.2g, principled %.2g (max scaled)\n",
                worst_file, worst_ours);
}

// A base colour given to the file as it is (baseColor = base_color, so the
// file's mon2lin darkens it): the comparison sees the gamma convention.
TEST(PrincipledVsDisneyBrdf, TheComparisonSeesTheGammaOfTheBaseColour) {
    SKIP_WITHOUT_DISNEY_BRDF();
    const Setting s = settings()[7];  // rough, base colour (0.2, 0.6, 0.3)
    json wrong = disney_material(s);
    wrong["params"]["baseColor"] = s.base_color;
    const auto lights = light_setups()[0].second;
    const Scene ours = scene_with(principled_material(s), lights, false);
    const ref::ReferenceImage reference = ref::render_reference(ours);
    long interior = 0;
    const RgbFloatImage theirs = render(scene_with(wrong, lights, false));
    auto reference_at = [&](int x, int y, int c) { return ref_at(reference, x, y, c); };
    const Measured m = measure(theirs, reference_at, reference, ours.display.bits, &interior);
    EXPECT_LT(m.same_share, 0.8);  // measured 0.70: the lit pixels differ
    EXPECT_GE(m.max_levels, 8);    // measured 12
}

}  // namespace
}  // namespace m3055
