#include "spectral/cie_data.h"

#include "spectral/cgats.h"

#include <cstdlib>
#include <map>
#include <mutex>

namespace m3055::spectral {

namespace {

std::mutex cache_mutex;

// Parsed files by path, kept for the process (a scene load after the first costs nothing).
template <typename T, typename Make>
const T& cached(std::map<std::string, T>& cache, const std::string& path, Make make) {
    std::lock_guard<std::mutex> lock(cache_mutex);
    auto found = cache.find(path);
    if (found == cache.end()) found = cache.emplace(path, make(path)).first;
    return found->second;
}

const char* const kPackageHint = " (Debian package colord-data; scripts/setup installs it)";

std::vector<Spectrum> read_with_hint(const std::string& path) {
    try {
        return read_cgats_spectra(path);
    } catch (const SpectralError& error) {
        throw SpectralError(std::string(error.what()) + kPackageHint);
    }
}

}  // namespace

std::string colord_dir() {
    const char* dir = std::getenv("M3055_COLORD_DIR");
    return dir && *dir ? std::string(dir) : std::string("/usr/share/colord");
}

const Observer& cie1931_observer() {
    static std::map<std::string, Observer> cache;
    return cached(cache, colord_dir() + "/cmf/CIE1931-2deg-XYZ.cmf", [](const std::string& path) {
        std::vector<Spectrum> sets = read_with_hint(path);
        if (sets.size() != 3)
            throw SpectralError(path + ": " + std::to_string(sets.size()) +
                                " data rows, expected 3 (x-bar, y-bar, z-bar)" + kPackageHint);
        return Observer{sets[0], sets[1], sets[2]};
    });
}

const std::vector<std::string>& illuminant_names() {
    static const std::vector<std::string> names = {"A",  "B",  "C",  "D50", "D55", "D65", "D93",
                                                   "E",  "F1", "F2", "F3",  "F4",  "F5",  "F6",
                                                   "F7", "F8", "F9", "F10", "F11", "F12"};
    return names;
}

const Spectrum& cie_illuminant(const std::string& name) {
    static std::map<std::string, Spectrum> cache;
    return cached(cache, colord_dir() + "/illuminant/CIE-" + name + ".sp", [](const std::string& path) {
        std::vector<Spectrum> sets = read_with_hint(path);
        if (sets.size() != 1)
            throw SpectralError(path + ": " + std::to_string(sets.size()) + " data rows, expected 1" + kPackageHint);
        return sets[0];
    });
}

}  // namespace m3055::spectral
