// Numerical stress test (documented in docs/stress.md).
// Every model's GLSL runs on the GPU with ONE INPUT PER PIXEL
// (glsl/passes/stress.frag via tests/support/stress_harness.h) over more than a
// million random and extreme inputs, and the double reference runs on exactly
// the same float inputs. Checked: no NaN/Inf, the models' bounds, GPU within
// 1e-3 * max(1, |ref|) of the reference, and, along fine one-parameter sweeps,
// no jumps that the reference does not have.
#include "material_support.h"
#include "models/model_spec.h"
#include "stress_harness.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace m3055::test {
namespace {

constexpr double kTolerance = 1e-3;        // |gpu - ref| <= kTolerance * max(1, |ref|)
constexpr double kJumpSlack = 1e-4;        // sweeps: allowed jump beyond the reference's own step
constexpr double kJumpSlopeFactor = 2.0;   // sweeps: K in |dg| <= K * local |dr| + slack
constexpr double kBoundSlack = 1e-5;       // float rounding allowed past a bound (relative)
constexpr double kReferenceSlack = 1e-15;  // metal bound: rounding of double unit vectors
constexpr double kGpuSlack = 9.5367431640625e-07;  // 2^-20: rounding of float unit vectors
constexpr double kPi = 3.14159265358979323846;
constexpr int kWidth = 1024;

// The paper's models (the classic ones: classic_stress_test.cpp).
const char* const kModels[] = {"highlight", "translucent", "metal", "metal_blinn", "metal_phong"};
constexpr int kModelCount = int(std::size(kModels));

// The index of `material`'s model in kModels.
int model_index(const Material& material) {
    for (int i = 0; i < kModelCount; ++i)
        if (material.model_name() == kModels[i]) return i;
    throw std::logic_error("stress test: model " + material.model_name() + " is not one of the paper's");
}

bool is_metal(const Material& material) { return material.model().family == Family::metal; }

// The material's lobes, or none for a model without lobes.
LobeList lobes_of(const Material& material) { return material.has("lobes") ? material.lobes() : LobeList(); }

// ---- input generation ---------------------------------------------------------

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
double log_uniform(Rng& rng, double lo, double hi) { return std::exp(uniform(rng, std::log(lo), std::log(hi))); }
bool chance(Rng& rng, double p) { return uniform(rng, 0.0, 1.0) < p; }
template <class T>
T pick(Rng& rng, const std::vector<T>& values) {
    return values[std::uniform_int_distribution<std::size_t>(0, values.size() - 1)(rng)];
}

// Extreme values first, then a random value from the legal range.
double exponent_value(Rng& rng) {  // highlight m, lobe n: [0, 10000]
    if (chance(rng, 0.5)) return pick<double>(rng, {0.0, 1e-6, 0.5, 1.0, 10000.0});
    return chance(rng, 0.5) ? log_uniform(rng, 1e-6, 1e4) : uniform(rng, 0.0, 100.0);
}
double beckmann_m(Rng& rng) {  // [0.001, 2]
    if (chance(rng, 0.4)) return pick<double>(rng, {0.001, 0.002, 0.01, 0.2, 0.70710678, 1.0, 2.0});
    return log_uniform(rng, 0.001, 2.0);
}
double lobe_weight(Rng& rng) {  // [0, 100]
    if (chance(rng, 0.3)) return pick<double>(rng, {0.0, 1e-6, 1.0, 100.0});
    return log_uniform(rng, 1e-6, 100.0);
}
double unit_value(Rng& rng) {  // [0, 1]
    if (chance(rng, 0.3)) return pick<double>(rng, {0.0, 1e-6, 0.5, 1.0});
    return uniform(rng, 0.0, 1.0);
}
double t_p_value(Rng& rng) {  // [0, 10]
    if (chance(rng, 0.4)) return pick<double>(rng, {0.0, 1e-6, 0.5, 1.0, 2.0, 10.0});
    return uniform(rng, 0.0, 10.0);
}

// Every paper parameter is drawn for every model (so the random sequence does
// not depend on the model); the material takes those its model has.
Material random_material(Rng& rng, const char* model) {
    Material m = Material::of(model);
    m.set_vec3("color", dvec3{unit_value(rng), unit_value(rng), unit_value(rng)});
    const double d = unit_value(rng), w = unit_value(rng), exponent = exponent_value(rng);
    const double t_n = unit_value(rng), t_p = t_p_value(rng);
    m.set_number("d", d);
    if (m.has("w")) m.set_number("w", w), m.set_number("m", exponent);
    if (m.has("t_n")) m.set_number("t_n", t_n), m.set_number("t_p", t_p);
    if (is_metal(m)) {
        const int count = std::uniform_int_distribution<int>(1, 4)(rng);
        std::vector<Lobe> lobes;
        for (int j = 0; j < count; ++j)
            lobes.push_back({lobe_weight(rng), m.model_name() == "metal" ? beckmann_m(rng) : exponent_value(rng)});
        m.set_lobes(lobes);
    }
    return float_rounded(m);
}

dvec3 random_unit(Rng& rng) {
    std::normal_distribution<double> g;
    dvec3 v{g(rng), g(rng), g(rng)};
    while (glm::length(v) < 1e-6) v = dvec3{g(rng), g(rng), g(rng)};
    return glm::normalize(v);
}

// Rotation taking z to a random axis, applied to a whole configuration.
struct Frame {
    dvec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    dvec3 operator()(const dvec3& v) const { return v.x * x + v.y * y + v.z * z; }
};
Frame random_frame(Rng& rng) {
    Frame f;
    f.z = random_unit(rng);
    f.x = glm::normalize(glm::cross(f.z, std::abs(f.z.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0)));
    f.y = glm::cross(f.z, f.x);
    return f;
}

// Raw float direction: unit, a power-of-two length (direction kept exactly), or
// a random length in [1e-3, 1e3].
glm::vec3 raw(Rng& rng, const dvec3& unit) {
    double length = 1.0;
    const double u = uniform(rng, 0.0, 1.0);
    if (u < 0.3) length = std::ldexp(1.0, std::uniform_int_distribution<int>(-9, 9)(rng));
    else if (u < 0.7) length = log_uniform(rng, 1e-3, 1e3);
    return glm::vec3(unit * length);
}

// A unit vector at polar angle acos(c) from z, azimuth phi.
dvec3 at_cosine(double c, double phi) {
    const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
    return dvec3(s * std::cos(phi), s * std::sin(phi), c);
}

// Cosines from exactly 0 to exactly 1, with the floats just inside.
double special_cosine(Rng& rng) {
    static const std::vector<double> values = {
        0.0, double(std::nextafter(0.f, 1.f)), double(std::numeric_limits<float>::min()), 1e-7, 1e-3, 0.5,
        1.0 - 1e-3, double(std::nextafter(1.f, 0.f)), 1.0};
    return chance(rng, 0.6) ? pick(rng, values) : uniform(rng, 0.0, 1.0);
}

// Angles from 0 to pi/2 that matter for the lobes: 0, tiny, the angle of the
// float just below cos = 1, multiples of the Beckmann m, grazing.
double special_angle(Rng& rng, double lobe_m) {
    static const double just_inside = std::acos(double(std::nextafter(1.f, 0.f)));
    const std::vector<double> values = {0.0,         1e-7,         1e-5,         just_inside, 0.5 * lobe_m,
                                        lobe_m,      2 * lobe_m,   4 * lobe_m,   0.01,        kPi / 2 - 1e-6,
                                        kPi / 2};
    return chance(rng, 0.6) ? pick(rng, values) : uniform(rng, 0.0, kPi / 2);
}

// N, V, L (unit, double) for one input; the kinds of configuration the issue lists.
void random_geometry(Rng& rng, const Material& material, dvec3& N, dvec3& V, dvec3& L) {
    const LobeList lobes = lobes_of(material);
    const double lobe_m = lobes.empty() ? 0.1 : lobes[0].m;
    const int kind = std::uniform_int_distribution<int>(0, 9)(rng);
    if (kind <= 1) {  // anything, including N.V < 0 and N.L < 0
        N = random_unit(rng), V = random_unit(rng), L = random_unit(rng);
        return;
    }
    Frame frame;  // half of the constructed cases stay axis-aligned, so exact 0 and 1 stay exact
    if (chance(rng, 0.5)) frame = random_frame(rng);
    N = frame.z;
    if (kind <= 4) {  // given N.V and N.L; light along the view, mirrored, opposite, or anywhere
        const double phi = chance(rng, 0.6) ? pick<double>(rng, {0.0, kPi, kPi / 2}) : uniform(rng, 0.0, 2 * kPi);
        const double NoV = special_cosine(rng), NoL = chance(rng, 0.2) ? NoV : special_cosine(rng);
        V = frame(at_cosine(NoV, 0.0));
        L = frame(at_cosine(NoL, phi));
    } else if (kind <= 7) {  // given angle N-H and half-angle V-H (H = z before the tilt of N)
        const double alpha = special_angle(rng, lobe_m);
        const double half = chance(rng, 0.5) ? pick<double>(rng, {0.0, 1e-6, 0.3, kPi / 2 - 1e-6, kPi / 2})
                                             : uniform(rng, 0.0, kPi / 2);
        const double beta = uniform(rng, 0.0, 2 * kPi);  // where N tilts
        V = frame(at_cosine(std::cos(half), kPi / 2));
        L = frame(at_cosine(std::cos(half), -kPi / 2));
        N = frame(at_cosine(std::cos(alpha), beta));
    } else if (kind == 8) {  // R near V: V is the mirror of L turned by a small angle
        L = frame(at_cosine(special_cosine(rng), 0.0));
        const dvec3 R = 2.0 * glm::dot(N, L) * N - L;
        const double turn = pick<double>(rng, {0.0, 1e-7, 1e-5, 1e-3, 0.01, 0.1});
        V = glm::normalize(R + turn * glm::normalize(glm::cross(R, frame.y) + 1e-9 * frame.x));
    } else {  // colinear and opposite vectors
        const dvec3 a = random_unit(rng), b = random_unit(rng);
        switch (std::uniform_int_distribution<int>(0, 6)(rng)) {
            case 0: N = a, V = a, L = a; break;
            case 1: N = a, V = b, L = b; break;     // light along the view
            case 2: N = a, V = b, L = -b; break;    // light opposite the view
            case 3: N = a, V = a, L = b; break;
            case 4: N = a, V = b, L = a; break;
            case 5: N = a, V = -a, L = b; break;
            default: N = a, V = a, L = -a; break;
        }
    }
}

StressInput random_input(Rng& rng) {
    StressInput in;
    in.material = random_material(rng, pick(rng, std::vector<const char*>(std::begin(kModels), std::end(kModels))));
    dvec3 N, V, L;
    random_geometry(rng, in.material, N, V, L);
    in.N = raw(rng, N), in.V = raw(rng, V), in.L = raw(rng, L);
    if (chance(rng, 0.05)) {  // L an exact float copy of +-V: light exactly along / opposite the view
        const float scale = std::ldexp(1.f, std::uniform_int_distribution<int>(-3, 3)(rng));
        in.L = in.V * (chance(rng, 0.5) ? scale : -scale);
    }
    return in;
}

Light directional_light(dvec3 towards, double intensity, dvec3 color) {
    Light light;
    light.type = LightType::directional;
    light.direction = glm::normalize(dvec3(glm::vec3(glm::normalize(towards))));
    light.intensity = intensity;
    light.color = color;
    return light;
}

// Four light set-ups: one white light; a bright coloured one plus a second;
// per-light lobes of both kinds; a second light along z (the axis of the
// axis-aligned cases).
StressBatch light_setup(int which) {
    StressBatch batch;
    Light& l0 = batch.light0;
    switch (which % 4) {
        case 0: break;
        case 1:
            l0.intensity = 10.0, l0.color = dvec3(1.0, 0.5, 0.0);
            batch.more_lights.push_back(directional_light({0.3, 0.4, 0.866}, 2.0, {0.25, 1.0, 0.75}));
            break;
        case 2:
            l0.intensity = 0.375;
            l0.lobes = {{100.0, 0.001}, {0.5, 2.0}};
            l0.lobe_kind = LobeKind::beckmann;
            batch.more_lights.push_back(directional_light({-0.5, 0.1, 0.3}, 1.0, dvec3(1.0)));
            batch.more_lights.back().lobes = {{100.0, 10000.0}, {1.0, 0.0}};
            batch.more_lights.back().lobe_kind = LobeKind::exponent;
            break;
        default: batch.more_lights.push_back(directional_light({0.0, 0.0, 1.0}, 1.0, dvec3(1.0))); break;
    }
    return batch;
}

// ---- bounds -----------------------------------------------------------------

// Largest value of the Beckmann lobe over all angles: with u = tan^2,
// D = exp(-u/m^2) (1 + u)^2 / m^2 peaks at u = 0 (D = 1/m^2) when m^2 <= 1/2,
// else at 1 + u = 2 m^2 (D = 4 m^2 exp(1/m^2 - 2)).
double beckmann_max(double m) {
    const double m2 = m * m;
    return m2 <= 0.5 ? 1.0 / m2 : 4.0 * m2 * std::exp(1.0 / m2 - 2.0);
}

// Per-channel upper bound of a metal-family colour: lobes bounded by 1
// (eq. 15/16) or by max D * G/NoV with G/NoV <= min(1/NoV, 2/VoH) (G <= 1 and
// NoH <= 1); VoH = |L + V| / 2 for unit L, V.
// `slack` widens the bound to every input within that distance of unit
// directions: 1e-15 for the double reference, 2^-20 for the float GPU (N.V
// and V.H may then be that much smaller: a bound of infinity where they reach 0).
dvec3 metal_upper_bound(const StressInput& in, const std::vector<Light>& lights, double slack) {
    const dvec3 N = glm::normalize(dvec3(in.N)), V = glm::normalize(dvec3(in.V));
    const double NoV = glm::dot(N, V) - slack;
    // 0 * infinity is 0 here: a lobe of weight 0, or a black channel, adds nothing.
    auto times = [](double a, double b) { return a == 0.0 || b == 0.0 ? 0.0 : a * b; };
    dvec3 sum(0.0);
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const dvec3 L = l == 0 ? glm::normalize(dvec3(in.L)) : lights[l].direction;
        const double VoH = glm::length(L + V) / 2.0 - slack;
        const double G_over_NoV = std::min(NoV > 0 ? 1.0 / NoV : HUGE_VAL, VoH > 0 ? 2.0 / VoH : HUGE_VAL);
        double lobes = 0.0;  // none for a model without lobes (the bound is then d C0)
        for (const Lobe& lobe : is_metal(in.material) ? lobes_for(lights[l], in.material) : LobeList())
            lobes += in.material.model_name() == "metal" ? times(lobe.w * beckmann_max(lobe.m), G_over_NoV) : lobe.w;
        for (int c = 0; c < 3; ++c) sum[c] += times(lights[l].intensity * lights[l].color[c], lobes);
    }
    dvec3 bound;
    const double d = in.material.number("d");
    const dvec3 color = in.material.vec3("color");
    for (int c = 0; c < 3; ++c) bound[c] = times(d + sum[c], color[c]);
    return bound;
}

// Empty when `out` is inside the model's bounds, else what is violated.
std::string bound_violation(const StressInput& in, const dvec3& metal_bound, const StressOutput& out) {
    auto above = [](double value, double bound) { return value > bound + kBoundSlack * std::max(1.0, bound); };
    auto below = [](double value, double bound) { return value < bound - kBoundSlack * std::max(1.0, std::abs(bound)); };
    std::ostringstream why;
    for (int c = 0; c < 3; ++c) {
        const double C = out.color[c], T = out.transmittance[c];
        if (is_metal(in.material)) {
            const double hi = metal_bound[c], lo = in.material.number("d") * in.material.vec3("color")[c];
            if (below(C, lo) || above(C, hi)) why << "metal colour " << C << " outside [" << lo << ", " << hi << "] ";
        } else {
            if (below(C, 0.0) || above(C, 1.0)) why << "colour " << C << " outside [0, 1] ";
            if (is_translucent(in.material)) {
                if (below(T, 0.0) || above(T, 1.0)) why << "transmittance " << T << " outside [0, 1] ";
                if (above(C + T, 1.0)) why << "colour + transmittance " << C + T << " > 1 ";
            }
        }
    }
    return why.str();
}

bool all_finite(const StressOutput& out) {
    for (int c = 0; c < 3; ++c)
        if (!std::isfinite(out.color[c]) || !std::isfinite(out.transmittance[c])) return false;
    return true;
}

// |gpu - ref| / max(1, |ref|) over colour and transmittance.
double scaled_error(const StressOutput& gpu, const StressOutput& ref) {
    double worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        worst = std::max(worst, std::abs(gpu.color[c] - ref.color[c]) / std::max(1.0, std::abs(ref.color[c])));
        worst = std::max(worst, std::abs(gpu.transmittance[c] - ref.transmittance[c]) /
                                    std::max(1.0, std::abs(ref.transmittance[c])));
    }
    return std::isnan(worst) ? HUGE_VAL : worst;
}

std::string describe(const StressInput& in, const StressOutput& gpu, const StressOutput& ref) {
    char text[1400];
    const dvec3 N = glm::normalize(dvec3(in.N)), V = glm::normalize(dvec3(in.V)), L = glm::normalize(dvec3(in.L));
    char cosines[200];
    std::snprintf(cosines, sizeof cosines, " [N.V=%.3g N.L=%.3g |L+V|=%.3g R.V-1=%.3g]", glm::dot(N, V), glm::dot(N, L),
                  glm::length(L + V), glm::dot(2.0 * glm::dot(N, L) * N - L, V) - 1.0);
    std::snprintf(text, sizeof text,
                  " N=(%.9g,%.9g,%.9g) V=(%.9g,%.9g,%.9g) L=(%.9g,%.9g,%.9g) | gpu=(%.9g,%.9g,%.9g)/(%.9g,%.9g,%.9g) "
                  "ref=(%.9g,%.9g,%.9g)/(%.9g,%.9g,%.9g)",
                  in.N.x, in.N.y, in.N.z, in.V.x, in.V.y, in.V.z, in.L.x, in.L.y, in.L.z, gpu.color.r,
                  gpu.color.g, gpu.color.b, gpu.transmittance.r, gpu.transmittance.g, gpu.transmittance.b,
                  ref.color.r, ref.color.g, ref.color.b, ref.transmittance.r, ref.transmittance.g,
                  ref.transmittance.b);
    return test::describe(in.material) + text + std::string(cosines);
}

// ---- conditioning: what float rounding of the input alone can change ---------------

// What the GPU may have seen instead of `in` after float rounding:
//  - kind 0: components below 2^-100 of their vector's length, or denormal,
//    set to 0 (llvmpipe flushes denormals, also in products);
//  - kind 1: nearly (anti)parallel directions (within 2^-19) made exactly so
//    (normalize can round two such vectors to the same one);
//  - kinds 2 and 3: L and V moved along N by +-2^-22 of their length, so that
//    the side of the surface a grazing light or view is on flips whichever
//    way the random moves below happen to go (the jump of a light at
//    N.L = 0: a highlight at R.V ~ 1 switches on at once);
//  - otherwise every direction moved by |v| 2^-k u, u in [-1, 1]^3, k = 21..24:
//    a few ulps of a unit vector, what the GPU's normalize, L / |L|, L + V and
//    dot products may be off by. (Relative changes of each component would
//    leave exact zeros, and directions with one dominant component, almost
//    unmoved.)
StressInput perturbed(const StressInput& in, Rng& rng, int kind) {
    StressInput out = in;
    if (kind == 0) {
        for (glm::vec3* v : {&out.N, &out.V, &out.L}) {
            const float length = glm::length(*v);
            for (int c = 0; c < 3; ++c)
                if (std::abs((*v)[c]) < std::max(std::numeric_limits<float>::min(), std::ldexp(length, -100)))
                    (*v)[c] = 0.f;
        }
    } else if (kind == 1) {
        auto snap_pair = [](glm::vec3& a, const glm::vec3& b) {
            const dvec3 ua = glm::normalize(dvec3(a)), ub = glm::normalize(dvec3(b));
            if (glm::length(ua - ub) < std::ldexp(1.0, -19)) a = b;
            else if (glm::length(ua + ub) < std::ldexp(1.0, -19)) a = -b;
        };
        snap_pair(out.L, out.V);
        snap_pair(out.N, out.V);
        snap_pair(out.N, out.L);
    } else if (kind == 2 || kind == 3) {
        const dvec3 N = glm::normalize(dvec3(in.N));
        const double step = std::ldexp(kind == 2 ? 1.0 : -1.0, -22);
        for (glm::vec3* v : {&out.L, &out.V}) *v = glm::vec3(dvec3(*v) + glm::length(dvec3(*v)) * step * N);
    } else if (kind % 2 == 0) {
        // H = normalize(L + V) from float unit vectors is off in direction by
        // about 2^-23 / |L + V| (their lengths are off by an ulp, and L + V
        // cancels): the lobes see that as N turned by as much.
        const dvec3 L = glm::normalize(dvec3(in.L)), V = glm::normalize(dvec3(in.V));
        const double turn = std::min(1.0, std::ldexp(1.0, -22) / std::max(glm::length(L + V), 1e-300));
        const dvec3 u{uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0)};
        out.N = glm::vec3(glm::normalize(dvec3(in.N)) + turn * u);
    } else {
        const double size = std::ldexp(1.0, -std::uniform_int_distribution<int>(21, 24)(rng));
        for (glm::vec3* v : {&out.N, &out.V, &out.L}) {
            const dvec3 u{uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0), uniform(rng, -1.0, 1.0)};
            *v = glm::vec3(dvec3(*v) + glm::length(dvec3(*v)) * size * u);
        }
    }
    return out;
}

// Per channel (colour 0-2, transmittance 3-5): how far the reference moves
// under kPerturbations such perturbations, and the metal bound's largest value.
constexpr int kPerturbations = 18;
struct Conditioning {
    double spread[6] = {0, 0, 0, 0, 0, 0};
    dvec3 metal_bound{0.0};
};
Conditioning conditioning(const StressInput& in, const std::vector<Light>& lights, const StressOutput& ref,
                          std::uint64_t seed) {
    Rng rng(seed);
    Conditioning result;
    result.metal_bound = metal_upper_bound(in, lights, kGpuSlack);
    for (int k = 0; k < kPerturbations; ++k) {
        const StressInput p = perturbed(in, rng, k);
        const StressOutput r = evaluate_reference(p, lights);
        for (int c = 0; c < 3; ++c) {
            result.spread[c] = std::max(result.spread[c], std::abs(r.color[c] - ref.color[c]));
            result.spread[3 + c] = std::max(result.spread[3 + c], std::abs(r.transmittance[c] - ref.transmittance[c]));
        }
    }
    return result;
}

// Tolerance of one channel: kTolerance * max(1, |ref|).
double tolerance(double ref) { return kTolerance * std::max(1.0, std::abs(ref)); }

// After the conditioning: a channel whose reference moves by more than its
// tolerance under float-rounding-sized changes of the input is not
// determined at float precision (e.g. H = normalize(L + V) at L ~ -V, the
// jump of a light at N.L = 0, x^1e-6 at x ~ 0): it is only checked finite and
// bounded. Every other channel must be within tolerance + that spread.
struct Verdict {
    bool undetermined = false;
    double worst_scaled = 0.0;  // over determined channels
    bool beyond = false;
};
// Where the formula itself is not defined to float precision, whatever the
// implementation: H = normalize(L + V) when |L + V| < 2^-12 (light nearly
// opposite the view, seen only where N.V <= ~1e-4; the metal family reads H):
// float unit vectors put H off by 2^-23 / |L + V| > 2^-11 rad, wider than the
// sharpest lobe (m = 0.001); and x^e with e < 1 at
// x within 2^-20 of 0 (infinite slope; for e = 1e-6 a jump from 0 to ~1
// between x = 0 and x = 1e-16, which float cannot tell apart):
// x = 1 - N.V for Kay's t_p, x = R.V for the highlight m and metal_phong n,
// x = N.H for metal_blinn n. Checked in double on the unit input directions.
bool singular(const StressInput& in, const std::vector<Light>& lights) {
    const Material& m = in.material;
    const dvec3 N = glm::normalize(dvec3(in.N)), V = glm::normalize(dvec3(in.V));
    const double near = std::ldexp(1.0, -20);
    auto edge = [&](double x, double e) { return e > 0.0 && e < 1.0 && std::abs(x) < near; };
    if (is_translucent(m) && edge(1.0 - glm::dot(N, V), m.number("t_p"))) return true;
    for (std::size_t l = 0; l < lights.size(); ++l) {
        const dvec3 L = l == 0 ? glm::normalize(dvec3(in.L)) : lights[l].direction;
        const double lv = glm::length(L + V);
        if (is_metal(m) && lv < std::ldexp(1.0, -12)) return true;
        const dvec3 H = lv > 0 ? (L + V) / lv : N;
        const double RoV = glm::dot(2.0 * glm::dot(N, L) * N - L, V);
        if ((m.model_name() == "highlight" || m.model_name() == "translucent") && edge(RoV, m.number("m")))
            return true;
        if (!is_metal(m)) continue;  // only the metals have lobes
        for (const Lobe& lobe : lobes_for(lights[l], m)) {
            if (m.model_name() == "metal_phong" && edge(RoV, lobe.m)) return true;
            if (m.model_name() == "metal_blinn" && edge(glm::dot(N, H), lobe.m)) return true;
        }
    }
    return false;
}

Verdict judge(const StressOutput& gpu, const StressOutput& ref, const Conditioning& cond, bool is_singular) {
    Verdict v;
    v.undetermined = is_singular;
    for (int k = 0; k < 6 && !is_singular; ++k) {
        const double g = k < 3 ? gpu.color[k] : gpu.transmittance[k - 3];
        const double r = k < 3 ? ref.color[k] : ref.transmittance[k - 3];
        if (cond.spread[k] > tolerance(r)) {
            v.undetermined = true;
            continue;
        }
        const double diff = std::abs(g - r);
        v.worst_scaled = std::max(v.worst_scaled, std::isnan(diff) ? HUGE_VAL : diff / std::max(1.0, std::abs(r)));
        if (!(diff <= tolerance(r) + cond.spread[k])) v.beyond = true;
    }
    return v;
}

StressHarness& harness() {
    static StressHarness instance;
    return instance;
}

// ---- the million-input run --------------------------------------------------------

TEST(StressTest, MillionRandomAndExtremeInputsAreFiniteBoundedAndMatchTheReference) {
    constexpr int kBatches = 4, kRows = 256;  // 4 x 1024 x 256 = 1,048,576 evaluations
    Rng rng(20240604);
    long evaluations = 0, nonfinite_gpu = 0, nonfinite_ref = 0, out_of_bounds = 0, beyond_tolerance = 0;
    double worst[5] = {0, 0, 0, 0, 0}, worst_plain[5] = {0, 0, 0, 0, 0};
    long above_1e5[5] = {0, 0, 0, 0, 0};
    long per_model[5] = {0, 0, 0, 0, 0}, ill_conditioned[5] = {0, 0, 0, 0, 0}, undetermined[5] = {0, 0, 0, 0, 0};
    std::vector<std::string> examples;
    auto note = [&](const std::string& what) {
        if (examples.size() < 12) examples.push_back(what);
    };
    double gpu_seconds = 0, ref_seconds = 0;
    for (int b = 0; b < kBatches; ++b) {
        StressBatch batch = light_setup(b);
        batch.inputs.reserve(std::size_t(kWidth) * kRows);
        for (int i = 0; i < kWidth * kRows; ++i) batch.inputs.push_back(random_input(rng));
        const std::vector<Light> lights = stress_lights(batch);

        auto t0 = std::chrono::steady_clock::now();
        const std::vector<StressOutput> gpu = harness().evaluate_gpu(batch, kWidth);
        auto t1 = std::chrono::steady_clock::now();
        std::vector<StressOutput> ref(batch.inputs.size());
        for (std::size_t i = 0; i < batch.inputs.size(); ++i) ref[i] = evaluate_reference(batch.inputs[i], lights);
        auto t2 = std::chrono::steady_clock::now();
        gpu_seconds += std::chrono::duration<double>(t1 - t0).count();
        ref_seconds += std::chrono::duration<double>(t2 - t1).count();

        for (std::size_t i = 0; i < batch.inputs.size(); ++i) {
            const StressInput& in = batch.inputs[i];
            const int model = model_index(in.material);
            ++evaluations, ++per_model[model];
            if (!all_finite(gpu[i])) ++nonfinite_gpu, note("GPU non-finite: " + describe(in, gpu[i], ref[i]));
            if (!all_finite(ref[i])) ++nonfinite_ref, note("reference non-finite: " + describe(in, gpu[i], ref[i]));
            const double error = scaled_error(gpu[i], ref[i]);
            const dvec3 plain_bound =
                is_metal(in.material) ? metal_upper_bound(in, lights, kReferenceSlack) : dvec3(0.0);
            const bool plain_ok = error <= kTolerance && bound_violation(in, plain_bound, gpu[i]).empty();
            if (!bound_violation(in, plain_bound, ref[i]).empty())
                ++out_of_bounds, note("reference out of bounds: " + bound_violation(in, plain_bound, ref[i]) +
                                      describe(in, gpu[i], ref[i]));
            if (plain_ok) {
                worst[model] = std::max(worst[model], error);
                worst_plain[model] = std::max(worst_plain[model], error);
                if (error > 1e-5) ++above_1e5[model];
                continue;
            }
            // The GPU only ever sees the input to float precision: where the
            // reference itself moves that much under a few ulps, allow it.
            ++ill_conditioned[model];
            const Conditioning cond = conditioning(in, lights, ref[i], (std::uint64_t(b) << 32) + i);
            const std::string why = bound_violation(in, cond.metal_bound, gpu[i]);
            if (!why.empty()) ++out_of_bounds, note("GPU out of bounds: " + why + describe(in, gpu[i], ref[i]));
            const Verdict verdict = judge(gpu[i], ref[i], cond, singular(in, lights));
            worst[model] = std::max(worst[model], verdict.worst_scaled);
            if (verdict.undetermined) ++undetermined[model];
            if (verdict.beyond)
                ++beyond_tolerance, note("beyond tolerance (scaled error " + std::to_string(verdict.worst_scaled) +
                                         ", reference spread " + std::to_string(cond.spread[0]) + " " +
                                         std::to_string(cond.spread[1]) + "): " + describe(in, gpu[i], ref[i]));
        }
    }
    std::printf("stress: %ld evaluations on %s (GPU %.2f s, reference %.2f s)\n", evaluations,
                harness().renderer_string().c_str(), gpu_seconds, ref_seconds);
    for (int model = 0; model < kModelCount; ++model)
        std::printf("stress: %-12s %7ld inputs, worst |gpu - ref| / max(1, |ref|) = %.3g (%.3g where the plain "
                    "check passes, %ld of them above 1e-5); %ld past the plain check, %ld of them not determined at float "
                    "precision\n",
                    kModels[model], per_model[model], worst[model], worst_plain[model],
                    above_1e5[model],
                    ill_conditioned[model], undetermined[model]);
    for (const std::string& example : examples) ADD_FAILURE() << example;
    EXPECT_GE(evaluations, 1000000);
    EXPECT_EQ(nonfinite_gpu, 0);
    EXPECT_EQ(nonfinite_ref, 0);
    EXPECT_EQ(out_of_bounds, 0);
    EXPECT_EQ(beyond_tolerance, 0);
}

// ---- sweeps: no jumps the formula does not have -------------------------------------

struct Sweep {
    std::string name;
    Material material;
    // Unit N, V, L for the sample at parameter s in [0, 1].
    std::function<void(double s, dvec3& N, dvec3& V, dvec3& L)> geometry;
};

Material lobed(const char* model, std::vector<Lobe> lobes, double d = 0.05) {
    Material m = Material::of(model);
    m.set_vec3("color", dvec3(1.0, 0.75, 0.5));
    m.set_number("d", d);
    m.set_lobes(lobes);
    return float_rounded(m);
}

// highlight or translucent (t_n and t_p: translucent only).
Material shiny(const char* model, double exponent, double t_p = 1.0) {
    Material m = Material::of(model);
    m.set_vec3("color", dvec3(0.8, 0.25, 0.125));
    m.set_number("d", 0.5), m.set_number("w", 1.0), m.set_number("m", exponent);
    if (m.has("t_n")) m.set_number("t_n", 0.75), m.set_number("t_p", t_p);
    return float_rounded(m);
}

// N at angle alpha from H = z; V and L at +-half from H (so H is exact).
void around_half_vector(double alpha, double half, dvec3& N, dvec3& V, dvec3& L) {
    N = at_cosine(std::cos(alpha), 0.0);
    V = at_cosine(std::cos(half), kPi / 2);
    L = at_cosine(std::cos(half), -kPi / 2);
}

// N = z, L fixed in the xz-plane, V the mirror of L turned by `angle`.
void around_mirror(double angle, dvec3& N, dvec3& V, dvec3& L) {
    N = dvec3(0, 0, 1);
    L = at_cosine(0.6, kPi);
    V = at_cosine(std::cos(std::acos(0.6) + angle), 0.0);
}

// N = L = z, so R = z exactly, and R.V = sin(eps) for V in the xz-plane: the
// GPU gets R.V to float precision even where it is 1e-8 (nothing cancels).
void nearly_perpendicular_to_mirror(double RoV, dvec3& N, dvec3& V, dvec3& L) {
    N = L = dvec3(0, 0, 1);
    V = dvec3(-std::sqrt(1.0 - RoV * RoV), 0.0, RoV);
}

void view_at(double NoV, dvec3 L, dvec3& N, dvec3& V, dvec3& Lout) {
    N = dvec3(0, 0, 1);
    V = at_cosine(NoV, 0.0);
    Lout = glm::normalize(L);
}

std::vector<Sweep> sweeps() {
    const Material paper_metal = lobed("metal", {{0.013, 0.2}, {0.1, 0.4}});
    return {
        {"metal N.V 0..1", paper_metal, [](double s, dvec3& N, dvec3& V, dvec3& L) { view_at(s, {-0.6, 0.2, 0.77}, N, V, L); }},
        {"metal N.V 0..0.01 (G/N.V)", lobed("metal", {{1.0, 0.5}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { view_at(0.01 * s, {-0.6, 0.0, 0.8}, N, V, L); }},
        {"metal m=0.001 N.H angle 0..5m", lobed("metal", {{1e-6, 0.001}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_half_vector(0.005 * s, 0.4, N, V, L); }},
        {"metal m=0.001 N.H angle 2m..2.2m (fine)", lobed("metal", {{1e-6, 0.001}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_half_vector(0.002 + 0.0002 * s, 0.4, N, V, L); }},
        {"metal m=2 grazing N.H", lobed("metal", {{1.0, 2.0}, {0.5, 0.7}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_half_vector(kPi / 2 - 0.3 * (1 - s), 0.3, N, V, L); }},
        {"metal m=0.3 grazing N.H", lobed("metal", {{1.0, 0.3}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_half_vector(kPi / 2 - 0.3 * (1 - s), 0.3, N, V, L); }},
        {"metal_blinn n=10000 N.H angle 0..0.05", lobed("metal_blinn", {{1.0, 10000.0}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_half_vector(0.05 * s, 0.4, N, V, L); }},
        {"metal_blinn n=10000 N.H angle 0.009..0.0095 (fine)", lobed("metal_blinn", {{1.0, 10000.0}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_half_vector(0.009 + 0.0005 * s, 0.4, N, V, L); }},
        {"metal_phong n=10000 R.V angle 0..0.03", lobed("metal_phong", {{1.0, 10000.0}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_mirror(0.03 * s, N, V, L); }},
        {"highlight m=10000 R.V angle 0..0.03", shiny("highlight", 10000.0),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_mirror(0.03 * s, N, V, L); }},
        {"highlight m=10000 R.V angle 0.009..0.0095 (fine)", shiny("highlight", 10000.0),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_mirror(0.009 + 0.0005 * s, N, V, L); }},
        {"highlight m=0.5 R.V angle 0..pi/2", shiny("highlight", 0.5),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { around_mirror(0.3 + 0.9 * s, N, V, L); }},
        {"highlight m=1e-6 R.V 1e-8..1e-6", shiny("highlight", 1e-6),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { nearly_perpendicular_to_mirror(1e-8 * std::pow(100.0, s), N, V, L); }},
        {"metal_phong n=0.3 R.V 1e-8..1e-6", lobed("metal_phong", {{100.0, 0.3}}),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { nearly_perpendicular_to_mirror(1e-8 * std::pow(100.0, s), N, V, L); }},
        {"translucent t_p=10 N.V 0..1", shiny("translucent", 20.0, 10.0),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { view_at(s, {-0.6, 0.2, 0.77}, N, V, L); }},
        {"translucent t_p=1e-6 N.V 0..1", shiny("translucent", 20.0, 1e-6),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { view_at(s, {-0.6, 0.2, 0.77}, N, V, L); }},
        {"translucent t_p=0.5 N.V 0.99..1 (fine)", shiny("translucent", 20.0, 0.5),
         [](double s, dvec3& N, dvec3& V, dvec3& L) { view_at(0.99 + 0.01 * s, {-0.6, 0.2, 0.77}, N, V, L); }},
    };
}

TEST(StressTest, FineSweepsHaveNoJumpsTheReferenceDoesNotHave) {
    const std::vector<Sweep> all = sweeps();
    StressBatch batch;  // one white light
    for (const Sweep& sweep : all) {
        for (int i = 0; i < kWidth; ++i) {
            dvec3 N, V, L;
            sweep.geometry(double(i) / (kWidth - 1), N, V, L);
            StressInput in;
            in.material = sweep.material;
            in.N = glm::vec3(N), in.V = glm::vec3(V), in.L = glm::vec3(L);
            batch.inputs.push_back(in);
        }
    }
    const std::vector<Light> lights = stress_lights(batch);
    const std::vector<StressOutput> gpu = harness().evaluate_gpu(batch, kWidth);
    for (std::size_t row = 0; row < all.size(); ++row) {
        const std::size_t base = row * kWidth;
        std::vector<StressOutput> ref(kWidth);
        for (int i = 0; i < kWidth; ++i) ref[i] = evaluate_reference(batch.inputs[base + i], lights);
        auto value = [](const StressOutput& o, int k) { return k < 3 ? o.color[k] : o.transmittance[k - 3]; };
        int jumps = 0;
        double worst_excess = 0.0, worst_error = 0.0;
        std::string first;
        for (int i = 0; i < kWidth; ++i) worst_error = std::max(worst_error, scaled_error(gpu[base + i], ref[i]));
        for (int i = 0; i + 1 < kWidth; ++i) {
            for (int k = 0; k < 6; ++k) {
                double local = 0.0;  // the reference's largest step around i -> i + 1
                for (int j = std::max(0, i - 1); j <= std::min(kWidth - 2, i + 1); ++j)
                    local = std::max(local, std::abs(value(ref[j + 1], k) - value(ref[j], k)));
                const double step = std::abs(value(gpu[base + i + 1], k) - value(gpu[base + i], k));
                const double scale = std::max({1.0, std::abs(value(ref[i], k)), std::abs(value(ref[i + 1], k))});
                const double allowed = kJumpSlopeFactor * local + kJumpSlack * scale;
                if (!(step <= allowed)) {
                    ++jumps;
                    worst_excess = std::max(worst_excess, step - allowed);
                    if (first.empty())
                        first = "at sample " + std::to_string(i) + " channel " + std::to_string(k) + ": gpu step " +
                                std::to_string(step) + ", reference step " + std::to_string(local) + "; " +
                                describe(batch.inputs[base + i], gpu[base + i], ref[i]);
                }
            }
        }
        std::printf("sweep %-50s worst scaled error %.3g, jumps %d\n", all[row].name.c_str(), worst_error, jumps);
        EXPECT_EQ(jumps, 0) << all[row].name << ": " << jumps << " jumps, worst excess " << worst_excess << ", first "
                            << first;
        EXPECT_LE(worst_error, kTolerance) << all[row].name;
    }
}

}  // namespace
}  // namespace m3055::test
