// `m3055 plot spectrum`: the spectra of a (light, material) pair as a gnuplot
// script with its data inline (docs/spec.md#74-the-spectra-in-use): the
// light's S(lambda) at luminance 1 (E = 1) on the left axis, the material's
// R(lambda) in [0, 1] on the right; the numbers are scene/spectrum_view.h's,
// which the explorer's Spectra plot draws too.
#pragma once

#include "scene/spectrum_view.h"

#include <string>

namespace m3055::plot {

// pngcairo into the variable `out`; data inline: a block of "nm S" lines, then
// (with a reflectance) a block of "nm R" lines, each ended by "e".
std::string spectrum_script(const SpectrumView& view, const std::string& title);

}  // namespace m3055::plot
