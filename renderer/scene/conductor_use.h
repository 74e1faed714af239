// Whether a material is a measured metal, and how its Fresnel term depends on
// the angle (docs/spec.md#72-measured-metals): read from the model table's
// "conductor" and "fresnel" choices, for the GPU's tables (passes/spectral_tables.h)
// and the CPU reference (reference/conductor.h) alike.
#pragma once

#include "models/material.h"

#include <complex>
#include <optional>
#include <string>

namespace m3055 {

enum class ConductorFresnel {
    normal,   // F(lambda, theta) = R(lambda): the paper's assumption 3 (metals' "normal", microfacet's "none")
    schlick,  // R(lambda) + (1 - R(lambda)) (1 - cos)^5 per wavelength (microfacet's "schlick")
    full,     // eq. 19 with the complex index (metals' "full", microfacet's "dielectric")
};

struct ConductorUse {
    std::string metal;  // a data/conductors/ name
    ConductorFresnel fresnel = ConductorFresnel::normal;
};

// The material's conductor, or nothing (no "conductor" parameter, or "none").
std::optional<ConductorUse> conductor_use(const Material& material);

// The colour the metal shows under D65 at normal incidence (its C0 under the
// display's white): what its "color" field is given when the conductor is
// turned off in the explorer, so the material keeps its look.
dvec3 conductor_d65_colour(const std::string& metal);

// F of the metal's index `eta` at cos(theta) under `fresnel`.
double conductor_F(ConductorFresnel fresnel, std::complex<double> eta, double cos_theta);

}  // namespace m3055
