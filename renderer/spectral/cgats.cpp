#include "spectral/cgats.h"

#include "io/input_file.h"
#include "io/message_text.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace m3055::spectral {

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& problem) {
    throw SpectralError(source + ": " + problem);
}

// A whole token as a finite double, or false.
bool parse_double(const std::string& token, double& out) {
    if (token.empty()) return false;
    errno = 0;
    char* end = nullptr;
    out = std::strtod(token.c_str(), &end);
    return end == token.c_str() + token.size() && errno == 0 && std::isfinite(out);
}

}  // namespace

std::vector<Spectrum> parse_cgats_spectra(const std::string& text, const std::string& source) {
    std::istringstream lines(text);
    std::string line;
    enum class Section { header, format, data } section = Section::header;
    std::vector<double> wavelengths;
    std::vector<Spectrum> sets;
    bool format_seen = false, data_seen = false;
    double start_nm = 0.0, end_nm = 0.0;
    bool has_start = false, has_end = false;
    std::size_t number = 0;
    while (std::getline(lines, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::vector<std::string> tokens;
        for (std::string word; words >> word;) tokens.push_back(word);
        if (tokens.empty() || tokens[0][0] == '#') continue;
        const std::string where = "line " + std::to_string(number) + ": ";
        if (section == Section::header) {
            if ((tokens[0] == "SPECTRAL_START_NM" || tokens[0] == "SPECTRAL_END_NM") && tokens.size() == 2) {
                double nm = 0.0;
                if (!parse_double(tokens[1], nm) || nm <= 0.0)
                    fail(source, where + tokens[0] + " " + text::quote(tokens[1]) + " is not a wavelength");
                (tokens[0] == "SPECTRAL_START_NM" ? start_nm : end_nm) = nm;
                (tokens[0] == "SPECTRAL_START_NM" ? has_start : has_end) = true;
                continue;
            }
            if (tokens[0] == "BEGIN_DATA_FORMAT") {
                if (format_seen) fail(source, where + "a second BEGIN_DATA_FORMAT");
                section = Section::format;
                format_seen = true;
            } else if (tokens[0] == "BEGIN_DATA") {
                if (!format_seen) fail(source, where + "BEGIN_DATA before BEGIN_DATA_FORMAT");
                section = Section::data;
                data_seen = true;
            }
            continue;
        }
        if (section == Section::format) {
            if (tokens[0] == "END_DATA_FORMAT") {
                if (wavelengths.size() < 2) fail(source, "BEGIN_DATA_FORMAT names fewer than 2 SPEC_<nm> fields");
                section = Section::header;
                continue;
            }
            for (const std::string& field : tokens) {
                double nm = 0.0;
                if (field.rfind("SPEC_", 0) != 0 || !parse_double(field.substr(5), nm) || nm <= 0.0)
                    fail(source, where + "field " + text::quote(field) + " is not SPEC_<nm>");
                wavelengths.push_back(nm);
            }
            continue;
        }
        // Data: one row a set.
        if (tokens[0] == "END_DATA") {
            section = Section::header;
            continue;
        }
        if (tokens.size() != wavelengths.size())
            fail(source, where + "a data row of " + std::to_string(tokens.size()) + " values, " +
                             std::to_string(wavelengths.size()) + " fields");
        Spectrum spectrum;
        for (const std::string& token : tokens) {
            double value = 0.0;
            if (!parse_double(token, value)) fail(source, where + text::quote(token) + " is not a finite number");
            spectrum.values.push_back(value);
        }
        sets.push_back(std::move(spectrum));
    }
    if (section != Section::header)
        fail(source, section == Section::format ? "BEGIN_DATA_FORMAT without END_DATA_FORMAT"
                                                : "BEGIN_DATA without END_DATA");
    if (!data_seen || sets.empty()) fail(source, "no data rows (BEGIN_DATA ... END_DATA)");
    // The grid: SPECTRAL_START_NM to SPECTRAL_END_NM over the fields when the file
    // gives them (colord-data's 1 nm files name their fields SPEC_300000 ...: nm
    // times 1000), else the fields' own wavelengths, which must be evenly spaced.
    double start = wavelengths.front(), step = wavelengths[1] - wavelengths[0];
    if (has_start != has_end) fail(source, "SPECTRAL_START_NM and SPECTRAL_END_NM come together");
    if (has_start) {
        if (!(end_nm > start_nm)) fail(source, "SPECTRAL_END_NM is not above SPECTRAL_START_NM");
        start = start_nm;
        step = (end_nm - start_nm) / double(wavelengths.size() - 1);
    } else {
        if (!(step > 0.0)) fail(source, "the SPEC_<nm> fields do not increase");
        for (std::size_t i = 1; i < wavelengths.size(); ++i)
            if (std::abs(wavelengths[i] - wavelengths[i - 1] - step) > 1e-9 * step)
                fail(source, "the SPEC_<nm> fields are not evenly spaced");
    }
    for (Spectrum& spectrum : sets) {
        spectrum.start_nm = start;
        spectrum.step_nm = step;
    }
    return sets;
}

std::vector<Spectrum> read_cgats_spectra(const std::string& path) {
    std::string content;
    try {
        content = io::read_input_file(path);
    } catch (const io::InputError& error) {
        throw SpectralError(error.what());
    }
    return parse_cgats_spectra(content, text::quote_name(path));
}

}  // namespace m3055::spectral
