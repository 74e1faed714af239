#include "spectral/colorimetry.h"

#include "spectral/blackbody.h"
#include "spectral/cie_data.h"

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>

namespace m3055::spectral {

namespace {

// XYZ of chromaticity (x, y) at Y = 1.
glm::dvec3 xyz_at_unit_y(double x, double y) { return {x / y, 1.0, (1.0 - x - y) / y}; }

// RGB -> XYZ: the primaries' XYZ columns, each scaled so that RGB (1, 1, 1) is
// the white (SMPTE RP 177 derivation). glm matrices are column-major.
glm::dmat3 rgb_to_xyz() {
    const glm::dmat3 primaries(xyz_at_unit_y(0.64, 0.33), xyz_at_unit_y(0.30, 0.60), xyz_at_unit_y(0.15, 0.06));
    const glm::dvec3 scale = glm::inverse(primaries) * xyz_at_unit_y(0.3127, 0.3290);
    return glm::dmat3(primaries[0] * scale.x, primaries[1] * scale.y, primaries[2] * scale.z);
}

const glm::dmat3& to_xyz() {
    static const glm::dmat3 m = rgb_to_xyz();
    return m;
}

const glm::dmat3& from_xyz() {
    static const glm::dmat3 m = glm::inverse(to_xyz());
    return m;
}

}  // namespace

glm::dvec3 xyz_of(const std::function<double(double)>& power) {
    const Observer& cmf = cie1931_observer();
    glm::dvec3 xyz(0.0);
    for (std::size_t i = 0; i < cmf.y.values.size(); ++i) {
        const double nm = cmf.y.start_nm + cmf.y.step_nm * double(i);
        const double p = power(nm);
        xyz += p * glm::dvec3(cmf.x.values[i], cmf.y.values[i], cmf.z.values[i]);
    }
    return xyz * cmf.y.step_nm;
}

glm::dvec3 xyz_of(const Spectrum& power) {
    return xyz_of([&power](double nm) { return power.at(nm); });
}

glm::dvec2 chromaticity(const glm::dvec3& xyz) {
    const double sum = xyz.x + xyz.y + xyz.z;
    return {xyz.x / sum, xyz.y / sum};
}

glm::dvec3 linear_srgb(const glm::dvec3& xyz) { return from_xyz() * xyz; }

double luminance(const glm::dvec3& rgb) {
    const glm::dmat3& m = to_xyz();
    return m[0].y * rgb.r + m[1].y * rgb.g + m[2].y * rgb.b;
}

glm::dvec3 light_rgb(const glm::dvec3& xyz) {
    if (!(xyz.y > 0.0)) throw SpectralError("the spectrum has no luminance in 360-830 nm");
    glm::dvec3 rgb = linear_srgb(xyz / xyz.y);
    if (rgb.r >= 0.0 && rgb.g >= 0.0 && rgb.b >= 0.0) return rgb;
    rgb = glm::max(rgb, glm::dvec3(0.0));
    return rgb / luminance(rgb);
}

glm::dvec3 temperature_rgb(double kelvin) {
    return light_rgb(xyz_of([kelvin](double nm) { return planck(nm, kelvin); }));
}

glm::dvec3 illuminant_rgb(const std::string& name) {
    const Spectrum& spectrum = cie_illuminant(name);
    try {
        return light_rgb(xyz_of(spectrum));
    } catch (const SpectralError& error) {
        throw SpectralError(colord_dir() + "/illuminant/CIE-" + name + ".sp: " + error.what());
    }
}

}  // namespace m3055::spectral
