#include "plot_spectrum.h"

#include <algorithm>
#include <sstream>

namespace m3055::plot {

namespace {

// gnuplot's double-quoted string: no quotes or backslashes inside; a line break as \n.
std::string gp_string(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '\n') out += "\\n";
        else out += c == '"' || c == '\\' ? '\'' : c;
    }
    return "\"" + out + "\"";
}

}  // namespace

std::string spectrum_script(const SpectrumView& view, const std::string& title) {
    const auto& c = view.curves;
    const bool has_r = !c.reflectance.empty();
    const double top = std::max(1.0, *std::max_element(c.light.begin(), c.light.end()));
    std::ostringstream s;
    s.precision(9);
    s << "if (!exists(\"out\")) out = 'spectrum.png'\n"
      << "set terminal pngcairo size 900,600 font 'DejaVu Sans,11' noenhanced\nset output out\n"
      << "set title " << gp_string(title) << "\n"
      << "set xlabel 'wavelength (nm)'\nset xrange [" << c.nm.front() << ":" << c.nm.back() << "]\nset grid\n"
      << "set ylabel 'light S(lambda), luminance 1 (E = 1)'\nset yrange [0:" << 1.05 * top << "]\n"
      << "set key below\n";
    if (has_r) s << "set y2label 'reflectance R(lambda)'\nset y2range [0:1.05]\nset y2tics 0.2\nset ytics nomirror\n";
    s << "plot '-' using 1:2 with lines lw 2 lc rgb '#d08000' title " << gp_string("light: " + view.light_label);
    if (has_r)
        s << ", '-' using 1:2 axes x1y2 with lines lw 2 lc rgb '#3050c0' title "
          << gp_string("material: " + view.reflectance_label);
    s << "\n";
    for (std::size_t i = 0; i < c.nm.size(); ++i) s << c.nm[i] << " " << c.light[i] << "\n";
    s << "e\n";
    if (has_r) {
        for (std::size_t i = 0; i < c.nm.size(); ++i) s << c.nm[i] << " " << c.reflectance[i] << "\n";
        s << "e\n";
    }
    return s.str();
}

}  // namespace m3055::plot
