// The double-precision CPU twin of the GLSL pipeline (docs/spec.md#3-geometry and #4-paper-models).
// It mirrors glsl/ term by term, with the same names, and is what the tests
// hold the GPU path against. It is written for clarity, not speed.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace m3055::ref {

// ---- Terms (one function per term; see glsl/terms/) -------------------------

// x^e with x^0 = 1 for every x >= 0 (docs/spec.md#4-paper-models); x is clamped at 0 first.
double pow_safe(double x, double e);

// eq. 13/17: Beckmann distribution delta(m, alpha) = exp(-tan^2 a / m^2) / (m^2 cos^4 a),
// cos a = NoH. Returns 0 for NoH <= 0.
double beckmann_D(double m, double NoH);

// eq. 12: Cook-Torrance masking/shadowing G = min{1, 2 NoH NoV / VoH, 2 NoH NoL / VoH}.
double ct_G(double NoH, double NoV, double NoL, double VoH);

// G / NoV computed without the 0/0 at grazing view: min(2 NoH / VoH, min(1, 2 NoH NoL / VoH) / NoV).
double ct_G_over_NoV(double NoH, double NoV, double NoL, double VoH);

// eq. 6: Kay's opacity t = t_n ((1 - cos b)+)^t_p, cos b = (N.V)+.
double kay_opacity(double t_n, double t_p, double NoV);

// eq. 4, one light's share of white per channel: s_l = clamp(w a_l c_l ((R.V)+)^m, 0, 1),
// scale = a_l c_l (att, spot).
dvec3 highlight_strength(double w, const dvec3& scale, double RoV, double m);

// eq. 4 once per light: C = 1 - (1 - C1) keep, keep = prod_l (1 - s_l).
dvec3 highlight_to_white(const dvec3& C1, const dvec3& keep);

// ---- Geometry ----------------------------------------------------------------

struct Ray {
    dvec3 origin;
    dvec3 dir;  // unit
};

// docs/spec.md#3-geometry: the ray through pixel centre (x + 0.5, y + 0.5), y = 0 the top row.
Ray camera_ray(const Camera& camera, int width, int height, int x, int y);

// Nearest intersection with t > 0 of a ray with a sphere's front face. Returns
// false on a miss (or when the origin is inside the sphere: only front faces).
bool intersect_sphere(const Ray& ray, const dvec3& center, double radius, double* t);

// ---- Lights ------------------------------------------------------------------

// What light l delivers at point P: unit direction towards the light, and the
// scale a_l * c_l * attenuation * spot factor (zero for a disabled light).
// Directional, point and spot lights only: an area or sky light has no one
// direction at a point (lit_lights below integrates it); it throws std::logic_error.
struct LightSample {
    dvec3 L;
    dvec3 scale;
    double spot = 1.0;  // C_spot alone (1 unless a spot light): the classic models' ambient
};
LightSample sample_light(const Light& light, const dvec3& P);

// One light as the families' composers sum it at a shaded point: a
// directional, point or spot light (its sample; scale 0 where a shadow blocks
// it), or one node of an area or sky light's quadrature, a directional light
// from sample.L with scale L c dw (docs/spec.md#75-area-lights-the-sky-and-shadows).
// Nodes stand for many small lights: the highlight models take them in that
// limit (keep *= exp(-s) in place of 1 - s), every other model as any light.
struct LitLight {
    const Light* light;  // its lobes and spectrum; for a node, the area light's
    LightSample sample;
    bool node = false;
};
using LitLights = std::vector<LitLight>;

class SceneBvh;  // reference/scene_bvh.h

// How area and sky lights are integrated (reference/area_quadrature.h): each
// light at each point until the estimated error is below tolerance max(1,
// |shaded colour|) (shadow_tolerance for a light with a shadow: the edge of a
// shadow converges as the cells' size, not their sixth power), or max_cells
// cells; Lambert surfaces under a rect or the sky (unshadowed) by their closed
// forms, exactly, unless closed_forms is off.
struct AreaQuadrature {
    double tolerance = 1e-5;
    double shadow_tolerance = 1e-4;
    int max_cells = 4096;
    bool closed_forms = true;
};

// What the quadrature did, summed over the points and lights integrated.
struct AreaStats {
    long long integrals = 0;    // (point, light) pairs integrated by quadrature
    long long closed = 0;       // ... and by a closed form
    long long cells = 0;        // cells they ended with
    long long nodes = 0;        // model evaluations of one direction
    long long rays = 0;         // visibility tests of one direction (shadows)
    long long unconverged = 0;  // integrals that reached max_cells above the tolerance
    double worst_error = 0.0;   // the largest final estimate, relative to max(1, |shaded colour|)
};

// What lights a point beyond its lights: the objects that block lights with
// "shadow" (nullptr: nothing blocks, as for a point shaded alone), and how
// area and sky lights are integrated.
struct LightingOptions {
    const SceneBvh* occluders = nullptr;
    AreaQuadrature quadrature;
    AreaStats* stats = nullptr;  // optional
};

// The lights at `point` as the composers take them, with no area light and no
// shadow (each light sampled in order; reference/lit_point.h does the rest).
LitLights sampled_lights(const std::vector<Light>& lights, const dvec3& P);

// ---- Models ------------------------------------------------------------------

struct SurfacePoint {
    dvec3 P;  // position
    dvec3 N;  // unit normal
    dvec3 V;  // unit vector towards the viewer
};

// A translucent point as a premultiplied "over" (docs/spec.md#42-translucent):
//   C = color + transmittance * C_B
struct TranslucentShade {
    dvec3 color;
    dvec3 transmittance;
};

// Each model family's hook: what a model of that family supplies (its table
// entry points at it; models/model_spec.h). The GLSL hooks have the same names
// and the same shapes (glsl/models/).
//   opaque:      the colour at a point, every light included (highlight)
//   translucent: the premultiplied colour and transmittance (translucent)
//   metal:       sum_j w_j lobe_j for one light that faces the point (N.L > 0),
//                over the light's own lobes or the material's (lobes_for)
//   classic:     two hooks, the lecture's I_diff + I_spec per unit light scale:
//                the diffuse factor (of K_diff), and the specular colour
//                (K_spec included, 0 where N.L <= 0); a model may have no specular
using OpaqueShadeFn = dvec3(const Material& material, const LitLights& lights, const SurfacePoint& point);
using TranslucentShadeFn = TranslucentShade(const Material& material, const LitLights& lights,
                                            const SurfacePoint& point);
using MetalLobeSumFn = double(const Material& material, const Light& light, const SurfacePoint& point,
                              const dvec3& L, double NoL, double NoV);
using ClassicDiffuseFn = double(const Material& material, double NoL, double NoV, double LoV);
using ClassicSpecularFn = dvec3(const Material& material, const dvec3& N, const dvec3& L, const dvec3& V,
                                double NoL, double NoV);

// The colour of an opaque point, by the model's family: the paper's highlight
// and metals, and the classic models of docs/spec.md#5-classic-models (reference/classic.h), which
// also add the scene's global ambient L_glob K_amb (the paper's models have
// their own d). Called with a translucent material it returns the colour the
// point would have if it were opaque (t = 1): the highlight model's.
// Every light type; shadows and the quadrature as `options` say.
dvec3 shade_opaque(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point,
                   const dvec3& global_ambient = dvec3(0.0), const LightingOptions& options = {});
// The same for lights already at the point (the families' composers).
dvec3 shade_opaque_lit(const Material& material, const LitLights& lights, const SurfacePoint& point,
                       const dvec3& global_ambient);

// A translucent material's premultiplied colour and transmittance, by its
// model's hook; every light type, as shade_opaque.
TranslucentShade shade_translucent_model(const Material& material, const std::vector<Light>& lights,
                                         const SurfacePoint& point, const LightingOptions& options = {});

// The paper's models (reference/models.cpp, mirroring glsl/models/highlight.glsl,
// translucent.glsl and metal.glsl): the highlight and translucent models'
// hooks, and the metal family's sum over the lights; each also for a plain
// list of lights (every type, no shadows).
OpaqueShadeFn shade_highlight;
TranslucentShadeFn shade_translucent;
dvec3 shade_highlight(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point);
TranslucentShade shade_translucent(const Material& material, const std::vector<Light>& lights,
                                   const SurfacePoint& point);
// The paper's metals' hooks: sum_j w_j lobe_j over Beckmann lobes (eq. 12),
// ((N.H)+)^n_j (eq. 15) and ((R.V)+)^n_j (eq. 16).
MetalLobeSumFn beckmann_lobe_sum, blinn_lobe_sum, phong_lobe_sum;
dvec3 shade_metal(const Material& material, const LitLights& lights, const SurfacePoint& point);
dvec3 shade_metal(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point);

// ---- Whole image -------------------------------------------------------------

struct ReferenceImage {
    int width = 0;
    int height = 0;
    std::vector<double> rgb;  // unquantized linear colour, rows TOP to bottom, 3 per pixel
    // For each pixel, a signature of the set of objects its ray hits (0 = none).
    // A pixel is "interior" when its 8 neighbours share its signature: tests
    // compare only those, away from silhouettes.
    std::vector<std::uint64_t> coverage;
};

// Per pixel: the nearest opaque hit, then translucent front faces in front of
// it composited back to front (true per-pixel order), background elsewhere;
// every light type and shadow (docs/spec.md#75-area-lights-the-sky-and-shadows),
// area and sky lights integrated as AreaQuadrature{} says (its error and run
// time: docs/reference.md). Rows are shared among the hardware's threads; the
// image does not depend on their number.
ReferenceImage render_reference(const Scene& scene);
// The same with the quadrature's tolerances chosen, and what it did (`stats`: optional).
ReferenceImage render_reference(const Scene& scene, const AreaQuadrature& quadrature, AreaStats* stats = nullptr);
// The same, calling `row_done` after each row is drawn (from the thread that drew
// it, one call at a time): a long render's progress (`m3055 render --reference`).
ReferenceImage render_reference(const Scene& scene, const AreaQuadrature& quadrature, AreaStats* stats,
                                const std::function<void()>& row_done);

// True when pixel (x, y) and its 8 neighbours (inside the image) share one coverage.
bool is_interior(const ReferenceImage& image, int x, int y);

}  // namespace m3055::ref
