// Which of a material's parameters have no effect as it stands, and why, so
// the Material section can show them disabled with the reason (one line):
//   - a colour that another parameter replaces (ParamSpec::replaces) while
//     that parameter is set: "color" (the paper's metals) or "ks" (microfacet)
//     under a "conductor" other than none (docs/spec.md#72-measured-metals);
//   - a colour the material gives as a reflectance spectrum (its
//     color_spectrum, #73-spectral-colours): the field shows its D65 colour.
// Read from the model table, so a model added there needs nothing here.
#pragma once

#include "models/material.h"
#include "models/model_spec.h"

#include <string>

namespace m3055::explore {

// "" when `param` has an effect on `material`; else the reason, one short line.
std::string inert_reason(const Material& material, const ParamSpec& param);
// What to do about it, for the reason's tooltip ("" when it has an effect).
std::string inert_detail(const Material& material, const ParamSpec& param);

// After the choice `param` changed from `before` to `material`: when it was a
// conductor standing in for a colour and is now "none", that colour takes the
// metal's colour under D65 (scene/conductor_use.h; within the field's range),
// so turning the conductor off keeps the material's look instead of showing
// the colour hidden under it.
void carry_replaced_colour(const Material& before, Material& material, const ParamSpec& param);

}  // namespace m3055::explore
