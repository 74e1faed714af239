// The double-precision CPU twin of the GLSL pipeline (docs/spec.md#3-geometry and #4-paper-models).
// It mirrors glsl/ term by term, with the same names, and is what the tests
// hold the GPU path against. It is written for clarity, not speed.
#pragma once

#include "scene/scene.h"

#include <cstdint>
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
struct LightSample {
    dvec3 L;
    dvec3 scale;
    double spot = 1.0;  // C_spot alone (1 unless a spot light): the classic models' ambient
};
LightSample sample_light(const Light& light, const dvec3& P);

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
using OpaqueShadeFn = dvec3(const Material& material, const std::vector<Light>& lights, const SurfacePoint& point);
using TranslucentShadeFn = TranslucentShade(const Material& material, const std::vector<Light>& lights,
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
dvec3 shade_opaque(const Material& material, const std::vector<Light>& lights,
                   const SurfacePoint& point, const dvec3& global_ambient = dvec3(0.0));

// The paper's models (reference/models.cpp, mirroring glsl/models/highlight.glsl,
// translucent.glsl and metal.glsl): the highlight and translucent models'
// hooks, and the metal family's sum over the lights.
OpaqueShadeFn shade_highlight;
TranslucentShadeFn shade_translucent;
// The paper's metals' hooks: sum_j w_j lobe_j over Beckmann lobes (eq. 12),
// ((N.H)+)^n_j (eq. 15) and ((R.V)+)^n_j (eq. 16).
MetalLobeSumFn beckmann_lobe_sum, blinn_lobe_sum, phong_lobe_sum;
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
// it composited back to front (true per-pixel order), background elsewhere.
ReferenceImage render_reference(const Scene& scene);

// True when pixel (x, y) and its 8 neighbours (inside the image) share one coverage.
bool is_interior(const ReferenceImage& image, int x, int y);

}  // namespace m3055::ref
