#include "explore/material_fields.h"

#include "scene/conductor_use.h"

#include <glm/common.hpp>

namespace m3055::explore {

namespace {

// The parameter that stands in for `param` now: a choice whose first entry
// ("none") means "not given" (model_spec.h: replaces), set to another; nullptr if none.
const ParamSpec* replaced_by(const Material& material, const ParamSpec& param) {
    for (const ParamSpec& other : material.model().params)
        if (other.replaces == param.name && material.choice(other.name) != 0) return &other;
    return nullptr;
}

bool given_as_spectrum(const Material& material, const ParamSpec& param) {
    return !param.spectrum_key.empty() && material.colour_spectrum();
}

}  // namespace

std::string inert_reason(const Material& material, const ParamSpec& param) {
    if (const ParamSpec* other = replaced_by(material, param))
        return "no effect: the " + other->name + " " + material.choice_name(other->name) + " gives the colour per light";
    if (given_as_spectrum(material, param)) return "no effect: the " + param.spectrum_key + " gives the colour per light";
    return "";
}

std::string inert_detail(const Material& material, const ParamSpec& param) {
    if (const ParamSpec* other = replaced_by(material, param))
        return "C0 is worked out per light from the measured metal's n + i k (spec section 7.2). Choose " +
               other->name + " " + other->choices.front() + " to use this " + param.label + " again.";
    if (given_as_spectrum(material, param))
        return "C0 is worked out per light from the reflectance spectrum (spec section 7.3); the field shows "
               "the spectrum's colour under D65.";
    return "";
}

void carry_replaced_colour(const Material& before, Material& material, const ParamSpec& param) {
    if (param.replaces.empty() || param.name != "conductor" || material.choice(param.name) != 0) return;
    const std::optional<ConductorUse> was = conductor_use(before);
    if (!was) return;
    // Within the field's range, as every colour a scene gives: gold's D65 red is 1.04.
    const Range range = material.model().param(param.replaces).range;
    material.set_vec3(param.replaces, glm::clamp(conductor_d65_colour(was->metal), dvec3(range.lo), dvec3(range.hi)));
}

}  // namespace m3055::explore
