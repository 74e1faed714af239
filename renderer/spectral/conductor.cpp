#include "spectral/conductor.h"

#include "spectral/conductor_files.h"
#include "spectral/spectrum.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <sstream>

namespace m3055::spectral {

std::complex<double> ComplexIndex::at(double wavelength_nm) const {
    if (wavelength_nm <= nm.front()) return {n.front(), k.front()};
    if (wavelength_nm >= nm.back()) return {n.back(), k.back()};
    const std::size_t i = std::size_t(std::upper_bound(nm.begin(), nm.end(), wavelength_nm) - nm.begin()) - 1;
    const double f = (wavelength_nm - nm[i]) / (nm[i + 1] - nm[i]);
    return {n[i] + f * (n[i + 1] - n[i]), k[i] + f * (k[i + 1] - k[i])};
}

ComplexIndex parse_conductor(const std::string& text, const std::string& source) {
    ComplexIndex table;
    std::istringstream lines(text);
    std::string line;
    int number = 0;
    auto fail = [&](const std::string& problem) {
        throw SpectralError(source + ": line " + std::to_string(number) + ": " + problem);
    };
    while (std::getline(lines, line)) {
        ++number;
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::istringstream row(line);
        double um = 0.0, n = 0.0, k = 0.0;
        std::string extra;
        if (!(row >> um >> n >> k) || (row >> extra)) fail("expected \"wavelength_um n k\"");
        if (!std::isfinite(um) || !std::isfinite(n) || !std::isfinite(k) || !(n > 0.0) || k < 0.0)
            fail("needs finite numbers, n > 0 and k >= 0");
        if (!table.nm.empty() && !(um * 1000.0 > table.nm.back())) fail("wavelengths must increase");
        table.nm.push_back(um * 1000.0), table.n.push_back(n), table.k.push_back(k);
    }
    if (table.nm.size() < 2 || table.nm.front() > 360.0 || table.nm.back() < 830.0)
        throw SpectralError(source + ": needs rows covering 360-830 nm");
    return table;
}

const std::vector<std::string>& conductor_names() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> out;
        for (const ConductorFile& file : conductor_files()) out.push_back(file.name);
        return out;
    }();
    return names;
}

const ComplexIndex& conductor(const std::string& name) {
    static std::mutex mutex;
    static std::map<std::string, ComplexIndex> cache;
    std::lock_guard<std::mutex> lock(mutex);
    auto found = cache.find(name);
    if (found != cache.end()) return found->second;
    for (const ConductorFile& file : conductor_files())
        if (name == file.name)
            return cache.emplace(name, parse_conductor(file.text, "data/conductors/" + name + ".nk")).first->second;
    throw SpectralError("unknown conductor \"" + name + "\"");
}

double normal_reflectance(std::complex<double> eta) {
    const double n = eta.real(), k = eta.imag();
    return ((n - 1.0) * (n - 1.0) + k * k) / ((n + 1.0) * (n + 1.0) + k * k);
}

double conductor_fresnel(std::complex<double> eta, double cos_theta) {
    const double c = std::clamp(cos_theta, 0.0, 1.0);
    if (c <= 0.0) return 1.0;  // grazing: total reflection (the limit of the formula)
    // The principal root (real part >= 0): the transmitted wave decays into the metal.
    const std::complex<double> g = std::sqrt(eta * eta + c * c - 1.0);
    const double a = std::norm(g - c) / std::norm(g + c);
    const double b = std::norm(c * (g + c) - 1.0) / std::norm(c * (g - c) + 1.0);
    return 0.5 * a * (1.0 + b);
}

}  // namespace m3055::spectral
