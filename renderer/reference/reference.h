// The double-precision CPU twin of the GLSL pipeline (SPEC sections 3 and 4).
// It mirrors glsl/ term by term, with the same names, and is what the tests
// hold the GPU path against. It is written for clarity, not speed.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace m3055::ref {

// ---- Terms (one function per term; see glsl/terms/) -------------------------

// x^e with x^0 = 1 for every x >= 0 (SPEC 4); x is clamped at 0 first.
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

// ---- Geometry ----------------------------------------------------------------

struct Ray {
    dvec3 origin;
    dvec3 dir;  // unit
};

// SPEC 3: the ray through pixel centre (x + 0.5, y + 0.5), y = 0 the top row.
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
    const std::vector<Lobe>* lobes;  // the light's own lobes if any, else nullptr
    double spot = 1.0;  // C_spot alone (1 unless a spot light): the classic models' ambient
};
LightSample sample_light(const Light& light, const dvec3& P);

// ---- Models ------------------------------------------------------------------

struct SurfacePoint {
    dvec3 P;  // position
    dvec3 N;  // unit normal
    dvec3 V;  // unit vector towards the viewer
};

// The colour of an opaque point: highlight, metal, metal_blinn, metal_phong,
// and the classic models of SPEC 5 (reference/classic.h), which also add the
// scene's global ambient L_glob K_amb (the paper's models have their own d).
// (Called with a translucent material it returns its colour as if t = 1.)
dvec3 shade_opaque(const Material& material, const std::vector<Light>& lights,
                   const SurfacePoint& point, const dvec3& global_ambient = dvec3(0.0));

// A translucent point as a premultiplied "over" (SPEC 4.2):
//   C = color + transmittance * C_B
struct TranslucentShade {
    dvec3 color;
    dvec3 transmittance;
};
TranslucentShade shade_translucent(const Material& material, const std::vector<Light>& lights,
                                   const SurfacePoint& point);

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
