#include "analysis/plane_curve.h"
#include "reference/hooks.h"

#include "models/model_spec.h"
#include "numeric/angles.h"
#include "reference/reference.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace m3055 {

namespace {
using numeric::kDegree;
constexpr double kLogFloor = 1e-3;  // the log scale's centre
}  // namespace

double PlaneCurve::max_value() const {
    double top = 0.0;
    for (const dvec3& v : values) top = std::max({top, v.r, v.g, v.b});
    return top;
}

std::string PlaneCurve::quantity() const {
    if (translucent)
        return light_behind ? "light behind the surface: no lobe; the background seen through (t_n, t_p)"
                            : "displayed value: colour + transmittance x background (t_n, t_p)";
    return light_behind ? "light behind the surface: no lobe (0)" : "reflected value";
}

PlaneCurve plane_curve(const Material& material, const Light& light, double incidence_deg, const dvec3& background,
                       int steps) {
    PlaneCurve curve;
    curve.incidence_deg = incidence_deg;
    curve.light_behind = std::cos(incidence_deg * kDegree) <= 0.0;
    curve.translucent = material.model().family == Family::translucent;
    // The plane of incidence is x-y, N = +y, L on the left (-x): no clamp.
    const dvec3 N(0.0, 1.0, 0.0);
    Light plotted = light;  // keep intensity, colour and own lobes
    plotted.type = LightType::directional;
    plotted.enabled = true;
    plotted.direction = {-std::sin(incidence_deg * kDegree), std::cos(incidence_deg * kDegree), 0.0};
    const std::vector<Light> lights = {plotted};
    for (int i = 0; i <= steps; ++i) {
        const double view = -90.0 + 180.0 * i / steps;
        const ref::SurfacePoint point{dvec3(0.0), N, dvec3(std::sin(view * kDegree), std::cos(view * kDegree), 0.0)};
        dvec3 value(0.0);
        if (curve.translucent) {
            const ref::TranslucentShade shade = ref::shade_translucent_model(material, lights, point);
            value = shade.color + shade.transmittance * background;
        } else if (!curve.light_behind) {
            value = ref::shade_opaque(material, lights, point);
        }
        for (int c = 0; c < 3; ++c)
            if (!std::isfinite(value[c])) value[c] = 0.0;
        curve.view_deg.push_back(view);
        curve.values.push_back(value);
    }
    return curve;
}

double incidence_at_target(const Light& light, const Camera& camera) {
    const dvec3 N = glm::normalize(camera.position - camera.target);
    // The sky's stand-in direction is its zenith; a rect's or disk's, its centre.
    const dvec3 L = light.type == LightType::directional ? glm::normalize(light.direction)
                    : light.type == LightType::sky      ? glm::normalize(light.up)
                                                         : glm::normalize(light.position - camera.target);
    return std::acos(std::clamp(glm::dot(N, L), -1.0, 1.0)) / kDegree;
}

double radial_fraction(double value, RadialScale scale, double top) {
    if (!(value > 0.0) || !(top > 0.0)) return 0.0;
    if (scale != RadialScale::log) return value / top;
    if (top <= kLogFloor) return value >= top ? 1.0 : 0.0;
    return std::max(0.0, std::log10(value / kLogFloor) / std::log10(top / kLogFloor));
}

double nice_ceiling(double value) {
    if (!(value > 0.0) || !std::isfinite(value)) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (const double step : {1.0, 2.0, 5.0, 10.0})
        if (value <= step * decade * (1.0 + 1e-12)) return step * decade;
    return 10.0 * decade;
}

double lobe_top(const PlaneCurve& a, const PlaneCurve* b) {
    double top = a.max_value();
    if (b) top = std::max(top, b->max_value());
    return nice_ceiling(top);
}

double model_max(const Material& material, const Light& light, const dvec3& background) {
    double top = 0.0;
    for (int incidence = 0; incidence < 90; incidence += 5)
        top = std::max(top, plane_curve(material, light, incidence, background, 90).max_value());
    return top;
}

}  // namespace m3055
