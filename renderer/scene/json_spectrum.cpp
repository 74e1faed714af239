#include "scene/json_spectrum.h"

namespace m3055::scene_json {

ReflectanceSpectrum read_spectrum(const Node& node) {
    node.expect_object();
    node.check_keys({"nm", "values"});
    const Node nm = node.required("nm"), values = node.required("values");
    const std::size_t count = nm.array_size(2, kSpectrumMaxSamples, "2 to 1000 wavelengths");
    if (values.array_size(count, count, std::to_string(count) + " values, one per wavelength") != count)
        values.fail("must have one value per wavelength");
    ReflectanceSpectrum spectrum;
    for (std::size_t i = 0; i < count; ++i) {
        const double wavelength = nm.at(i).number_in(closed(kSpectrumMinNm, kSpectrumMaxNm));
        if (i > 0 && !(wavelength > spectrum.nm.back()))
            nm.at(i).fail("must be greater than the wavelength before it (" + format_number(spectrum.nm.back()) + ")");
        spectrum.nm.push_back(wavelength);
        spectrum.values.push_back(values.at(i).number_in(kUnit));
    }
    return spectrum;
}

json spectrum_json(const ReflectanceSpectrum& spectrum) { return {{"nm", spectrum.nm}, {"values", spectrum.values}}; }

}  // namespace m3055::scene_json
