#include "analysis/pixel_probe.h"

#include "scene/area_light.h"

#include "geometry/mesh.h"
#include "models/model_spec.h"
#include "reference/conductor.h"
#include "reference/reference.h"
#include "scene/conductor_use.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace m3055 {

ScenePicker::ScenePicker(const Scene& scene) : scene_(scene), meshes_(scene.objects.size()) {
    for (std::size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].shape != Shape::sphere)
            meshes_[i] = std::make_unique<ref::MeshIntersector>(geometry::make_mesh(scene.objects[i]));
}

PixelHit ScenePicker::pick(int x, int y) const {
    const ref::Ray ray = ref::camera_ray(scene_.camera, scene_.display.width, scene_.display.height, x, y);
    PixelHit best;
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < static_cast<int>(scene_.objects.size()); ++i) {
        const Object& object = scene_.objects[std::size_t(i)];
        double t = 0.0;
        dvec3 N(0.0);
        std::size_t group = 0;
        if (meshes_[std::size_t(i)]) {
            const auto hits = meshes_[std::size_t(i)]->intersect_all(ray);
            if (hits.empty()) continue;
            t = hits.front().t;
            N = hits.front().N;
            group = hits.front().group;
        } else if (!ref::intersect_sphere(ray, object.center, object.radius, &t)) {
            continue;
        }
        if (!(t < nearest)) continue;  // ties: the lower index, as the reference renderer
        nearest = t;
        best.object = i;
        best.group = group;
        best.P = ray.origin + t * ray.dir;
        best.N = meshes_[std::size_t(i)] ? N : glm::normalize((best.P - object.center) / object.radius);
        best.V = -ray.dir;
    }
    return best;
}

std::vector<int> ScenePicker::object_ids() const {
    const int w = scene_.display.width, h = scene_.display.height;
    std::vector<int> ids(std::size_t(w) * h, -1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ids[std::size_t(y) * w + x] = pick(x, y).object;
    return ids;
}

int level_of_png(int png, int bits) {
    const int top = (1 << bits) - 1;
    return static_cast<int>(std::lround(png * double(top) / 255.0));
}

// The direction the read-outs take N.L, R.V and V.H against: a directional,
// point or spot light's own. A rect, disk or sky light has no one direction
// (its light is an integral over the emitter): the way to the emitter's
// centre, or the sky's up, stand for it.
dvec3 probe_direction(const Light& light, const dvec3& P) {
    if (light.type == LightType::sky) return glm::normalize(light.up);
    if (is_area_light(light.type)) {
        const dvec3 to_centre = light.position - P;
        const double distance = glm::length(to_centre);
        return distance > 0.0 ? to_centre / distance : -light.normal;
    }
    return ref::sample_light(light, P).L;
}

std::vector<PairColour> pair_colours(const Scene& scene, const PixelHit& hit) {
    std::vector<PairColour> pairs;
    if (hit.object < 0) return pairs;
    const Material& material = material_of(scene.objects[std::size_t(hit.object)], hit.group);
    if (!ref::is_spectral(material)) return pairs;
    const std::optional<ConductorUse> use = conductor_use(material);
    const bool by_angle = !material.colour_spectrum() && use && use->fresnel != ConductorFresnel::normal;
    for (std::size_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (!light.enabled || !(light.intensity > 0.0)) continue;  // passes/light_uniforms.h: reaches_shader
        PairColour pair;
        pair.light = int(i);
        pair.name = light.name;
        pair.by_angle = by_angle;
        if (material.colour_spectrum() && material.model().family == Family::classic) pair.symbol = "kd";
        const dvec3 L = probe_direction(light, hit.P);
        const dvec3 H = L + hit.V;
        // V.H: the angle of the metals' Fresnel term (docs/spec.md#72-measured-metals), as the reference takes it.
        pair.cos_theta = glm::length(H) > 0.0 ? std::clamp(glm::dot(hit.V, glm::normalize(H)), 0.0, 1.0) : 0.0;
        pair.c0 = ref::spectral_c0(material, &light, pair.cos_theta);
        pair.lit = light.intensity * light.color * pair.c0;
        pairs.push_back(pair);
    }
    return pairs;
}

PixelProbe probe_pixel(const Scene& scene, const ScenePicker& picker, const RgbFloatImage& raw,
                       const Rgb8Image& display, int x, int y, int light) {
    PixelProbe p;
    p.x = x;
    p.y = y;
    const std::size_t raw_at = (std::size_t(raw.height - 1 - y) * raw.width + x) * 3;
    const std::size_t png_at = (std::size_t(y) * display.width + x) * 3;
    for (int c = 0; c < 3; ++c) {
        p.linear[c] = raw.pixels[raw_at + c];
        p.png[std::size_t(c)] = display.pixels[png_at + c];
        p.level[std::size_t(c)] = level_of_png(p.png[std::size_t(c)], scene.display.bits);
    }
    const PixelHit hit = picker.pick(x, y);
    p.object = hit.object;
    if (hit.object < 0) return p;
    p.model = material_of(scene.objects[std::size_t(hit.object)], hit.group).shown_name();
    p.pairs = pair_colours(scene, hit);
    if (light < 0 || light >= static_cast<int>(scene.lights.size())) return p;
    const dvec3 L = probe_direction(scene.lights[std::size_t(light)], hit.P);
    p.lit = true;
    p.NoL = glm::dot(hit.N, L);
    p.RoV = glm::dot(2.0 * p.NoL * hit.N - L, hit.V);
    return p;
}

std::string PixelProbe::text() const {
    char buffer[512];
    int n = std::snprintf(buffer, sizeof buffer,
                          "pixel (%d, %d)\nlinear %.6g %.6g %.6g\nlevel %d %d %d\npng %d %d %d\n", x, y, linear.r,
                          linear.g, linear.b, level[0], level[1], level[2], png[0], png[1], png[2]);
    if (object < 0) n += std::snprintf(buffer + n, sizeof buffer - n, "background");
    else n += std::snprintf(buffer + n, sizeof buffer - n, "object %d (%s)", object, model.c_str());
    if (lit) std::snprintf(buffer + n, sizeof buffer - n, "\nN.L %.4f  R.V %.4f", NoL, RoV);
    std::string out = buffer;
    for (const PairColour& pair : pairs) {
        char line[256];
        const char* symbol = pair.symbol.c_str();
        std::snprintf(line, sizeof line, "\nlight %d%s%s%s: %s_l %.3f %.3f %.3f  a_l c_l %s_l %.3f %.3f %.3f", pair.light,
                      pair.name.empty() ? "" : " \"", pair.name.c_str(), pair.name.empty() ? "" : "\"", symbol,
                      pair.c0.r, pair.c0.g, pair.c0.b, symbol, pair.lit.r, pair.lit.g, pair.lit.b);
        out += line;
        if (pair.by_angle) {
            std::snprintf(line, sizeof line, " at V.H %.3f", pair.cos_theta);
            out += line;
        }
    }
    // A NaN or infinite value (a .brdf material can make one) is quantized
    // to some level: the level and PNG lines above would pass for a colour.
    if (!finite()) out += "\nNOT FINITE: " + std::string(std::isnan(linear.r) || std::isnan(linear.g) || std::isnan(linear.b) ? "NaN" : "infinite") +
                          " (the display's level here means nothing)";
    return out;
}

LevelHistogram level_histogram(const Rgb8Image& display, int bits) {
    LevelHistogram h;
    for (auto& c : h.counts) c.assign(std::size_t(1) << bits, 0);
    for (std::size_t i = 0; i + 2 < display.pixels.size(); i += 3)
        for (int c = 0; c < 3; ++c) ++h.counts[std::size_t(c)][std::size_t(level_of_png(display.pixels[i + c], bits))];
    for (int c = 0; c < 3; ++c)
        for (long count : h.counts[std::size_t(c)]) h.used[std::size_t(c)] += count > 0;
    return h;
}

RowProfile row_profile(const Rgb8Image& display, int bits, int row) {
    if (row < 0 || row >= display.height)
        throw std::out_of_range("row " + std::to_string(row) + " is outside the " + std::to_string(display.height) +
                                "-row display");
    RowProfile profile;
    profile.row = row;
    profile.bits = bits;
    for (auto& channel : profile.levels) channel.resize(std::size_t(display.width));
    const std::uint8_t* p = display.pixels.data() + std::size_t(row) * display.width * 3;
    for (int x = 0; x < display.width; ++x)
        for (std::size_t c = 0; c < 3; ++c) profile.levels[c][std::size_t(x)] = level_of_png(p[3 * x + c], bits);
    return profile;
}

}  // namespace m3055
