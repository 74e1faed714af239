#include "reference/emitters.h"

#include "numeric/angles.h"
#include "scene/area_light.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace m3055::ref {

namespace {

using numeric::kPi;

// Sutherland-Hodgman: the part of convex `polygon` where (q - P).N >= 0.
std::vector<dvec3> clip_to_horizon(const std::vector<dvec3>& polygon, const dvec3& P, const dvec3& N) {
    std::vector<dvec3> kept;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const dvec3& a = polygon[i];
        const dvec3& b = polygon[(i + 1) % polygon.size()];
        const double da = glm::dot(a - P, N), db = glm::dot(b - P, N);
        if (da >= 0.0) kept.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) kept.push_back(a + (da / (da - db)) * (b - a));
    }
    return kept;
}

// The rect's corners, in order around its normal.
std::vector<dvec3> rect_corners(const Light& light) {
    const RectFrame frame = rect_frame(light);
    const dvec3 s0 = 0.5 * light.size[0] * frame.side0, s1 = 0.5 * light.size[1] * frame.side1;
    const dvec3& c = light.position;
    return {c - s0 - s1, c + s0 - s1, c + s0 + s1, c - s0 + s1};
}

// The rect above the point's horizon, or nothing when the point does not face its front.
std::vector<dvec3> visible_rect(const Light& light, const SurfacePoint& point) {
    if (!(glm::dot(point.P - light.position, light.normal) > 0.0)) return {};
    std::vector<dvec3> polygon = clip_to_horizon(rect_corners(light), point.P, point.N);
    return polygon.size() >= 3 ? polygon : std::vector<dvec3>{};
}

// A node of a flat emitter at q, of area element dA per unit (u, v): seen from
// P at distance r along w, it subtends dA cos(theta_e) / r^2, cos(theta_e) = -w.n.
PatchSample flat_sample(const dvec3& q, double area_density, const dvec3& P, const dvec3& emitter_normal) {
    const dvec3 d = q - P;
    const double r = glm::length(d);
    const dvec3 w = d / r;
    return {w, area_density * std::max(-glm::dot(w, emitter_normal), 0.0) / (r * r), r};
}

// The triangle (g, a, b) by Duffy's map x = g + u (a - g) + u v (b - a), dA = u |(a - g) x (b - a)| du dv.
Patch triangle_patch(const dvec3& g, const dvec3& a, const dvec3& b, const dvec3& P, const dvec3& n) {
    const dvec3 ga = a - g, ab = b - a;
    const double twice_area = glm::length(glm::cross(ga, ab));
    return [=](double u, double v) { return flat_sample(g + u * ga + (u * v) * ab, u * twice_area, P, n); };
}

std::vector<Patch> rect_patches(const Light& light, const SurfacePoint& point) {
    const std::vector<dvec3> polygon = visible_rect(light, point);
    std::vector<Patch> patches;
    if (polygon.empty()) return patches;
    dvec3 g(0.0);
    for (const dvec3& corner : polygon) g += corner;
    g /= double(polygon.size());  // inside: the polygon is convex
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const dvec3& a = polygon[i];
        const dvec3& b = polygon[(i + 1) % polygon.size()];
        if (glm::length(glm::cross(a - g, b - a)) > 0.0) patches.push_back(triangle_patch(g, a, b, point.P, light.normal));
    }
    return patches;
}

// The disk {c + x ex + y ey : x^2 + y^2 <= R^2, x >= x0}, in strips parallel to
// the chord x = x0: x = R cos(theta), y = t R sin(theta), theta in [0, theta0],
// t in [-1, 1], dA = R^2 sin^2(theta) dtheta dt; each patch a quarter of it.
std::vector<Patch> disk_patches(const Light& light, const SurfacePoint& point) {
    const dvec3& c = light.position;
    const dvec3& n = light.normal;
    const double R = light.radius;
    std::vector<Patch> patches;
    if (!(glm::dot(point.P - c, n) > 0.0)) return patches;
    // The horizon's trace on the disk's plane: (c - P).N + x (ex.N) + y (ey.N) >= 0.
    const dvec3 along = point.N - glm::dot(point.N, n) * n;
    const double lean = glm::length(along);
    const double height = glm::dot(c - point.P, point.N);
    dvec3 ex = glm::length(glm::cross(n, dvec3(1, 0, 0))) > 0.5 ? glm::normalize(glm::cross(n, dvec3(1, 0, 0)))
                                                                 : glm::normalize(glm::cross(n, dvec3(0, 1, 0)));
    double theta0 = kPi;
    if (lean > 1e-12) {
        ex = along / lean;
        const double x0 = -height / lean;
        if (x0 >= R) return patches;
        theta0 = x0 <= -R ? kPi : std::acos(x0 / R);
    } else if (!(height >= 0.0)) {
        return patches;  // the disk's plane parallel to the horizon, below it
    }
    const dvec3 ey = glm::cross(n, ex);
    const dvec3 P = point.P;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            const double theta_lo = theta0 * 0.5 * i, t_lo = -1.0 + j;
            patches.push_back([=](double u, double v) {
                const double theta = theta_lo + 0.5 * theta0 * u, t = t_lo + v;
                const double s = std::sin(theta);
                const dvec3 q = c + (R * std::cos(theta)) * ex + (t * R * s) * ey;
                return flat_sample(q, R * R * s * s * 0.5 * theta0, P, n);
            });
        }
    return patches;
}

// The lune of directions above both the sky's horizon (w.up >= 0) and the
// point's (w.N >= 0): w = cos(b) (cos(a) N + sin(a) e2) + sin(b) k, k the unit
// vector along up x N where the two horizons meet, e2 = k x N; its longitudes a
// lie in [-pi/2, pi/2] and within pi/2 of up's; dw = cos(b) da db.
struct Lune {
    dvec3 N, e2, k;
    double a_lo = 0.0, a_hi = 0.0;  // empty when equal
};

Lune sky_lune(const dvec3& up, const dvec3& N) {
    Lune lune{N, dvec3(0.0), dvec3(0.0)};
    dvec3 k = glm::cross(up, N);
    const double sin_angle = glm::length(k);
    if (sin_angle < 1e-12) {
        if (glm::dot(up, N) < 0.0) return lune;  // the sky is wholly below the horizon
        const dvec3 e = std::fabs(N.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
        k = glm::normalize(glm::cross(N, e));
    } else {
        k /= sin_angle;
    }
    lune.k = k;
    lune.e2 = glm::cross(k, N);
    const double a_up = std::atan2(glm::dot(up, lune.e2), glm::dot(up, N));
    lune.a_lo = std::max(-0.5 * kPi, a_up - 0.5 * kPi);
    lune.a_hi = std::min(0.5 * kPi, a_up + 0.5 * kPi);
    return lune;
}

std::vector<Patch> sky_patches(const Light& light, const SurfacePoint& point) {
    const Lune lune = sky_lune(light.up, point.N);
    std::vector<Patch> patches;
    if (!(lune.a_hi > lune.a_lo)) return patches;
    const double a_half = 0.5 * (lune.a_hi - lune.a_lo);
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            const double a0 = lune.a_lo + a_half * i, b0 = -0.5 * kPi + 0.5 * kPi * j;
            patches.push_back([=](double u, double v) {
                const double a = a0 + a_half * u, b = b0 + 0.5 * kPi * v;
                const double cb = std::cos(b);
                const dvec3 w = cb * (std::cos(a) * lune.N + std::sin(a) * lune.e2) + std::sin(b) * lune.k;
                return PatchSample{w, cb * a_half * 0.5 * kPi, std::numeric_limits<double>::infinity()};
            });
        }
    return patches;
}

}  // namespace

std::vector<Patch> emitter_patches(const Light& light, const SurfacePoint& point) {
    switch (light.type) {
        case LightType::rect: return rect_patches(light, point);
        case LightType::disk: return disk_patches(light, point);
        case LightType::sky: return sky_patches(light, point);
        default: return {};
    }
}

double polygon_projected_solid_angle(const std::vector<dvec3>& corners, const dvec3& P, const dvec3& N) {
    double sum = 0.0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const dvec3 a = glm::normalize(corners[i] - P), b = glm::normalize(corners[(i + 1) % corners.size()] - P);
        const dvec3 axb = glm::cross(a, b);
        const double sine = glm::length(axb);
        if (!(sine > 0.0)) continue;  // an edge seen end-on subtends nothing
        sum += std::atan2(sine, glm::dot(a, b)) * glm::dot(axb, N) / sine;
    }
    return 0.5 * std::fabs(sum);
}

std::optional<double> projected_solid_angle(const Light& light, const SurfacePoint& point) {
    if (light.type == LightType::rect) {
        const std::vector<dvec3> polygon = visible_rect(light, point);
        return polygon.empty() ? 0.0 : polygon_projected_solid_angle(polygon, point.P, point.N);
    }
    if (light.type == LightType::sky) return 0.5 * kPi * (1.0 + std::clamp(glm::dot(light.up, point.N), -1.0, 1.0));
    return std::nullopt;
}

}  // namespace m3055::ref
