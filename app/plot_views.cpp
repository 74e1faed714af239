#include "plot_views.h"

#include "analysis/brdf_check.h"
#include "analysis/brdf_views.h"
#include "numeric/angles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace m3055::plot {

namespace {

using numeric::kPi;
double rad(double deg) { return deg * kPi / 180.0; }

std::string header(int width, int height, const std::string& title) {
    return "if (!exists(\"out\")) out = 'plot.png'\nset terminal pngcairo size " + std::to_string(width) + "," +
           std::to_string(height) + " font 'DejaVu Sans,11' noenhanced\nset output out\nset title \"" + title + "\"\n";
}

// A target as the plots name it: a .brdf file by its file name.
std::string shown(const BrdfTarget& t) {
    const auto slash = t.name.find_last_of('/');
    return slash == std::string::npos ? t.name : t.name.substr(slash + 1);
}

std::string quoted(const std::string& text) {
    std::string out;
    for (char c : text) out += c == '"' ? '\'' : c;
    return "\"" + out + "\"";
}

std::string short_number(double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", x);
    return buffer;
}

// L in the plane y = 0, on the -x side; V = (sin t, 0, cos t) for t in [-90, 90].
dvec3 in_plane(double theta_deg) { return {std::sin(rad(theta_deg)), 0.0, std::cos(rad(theta_deg))}; }

}  // namespace

std::string polar_script(BrdfGrid& grid, const std::vector<BrdfTarget>& targets, const ViewOptions& o) {
    const dvec3 L = in_plane(-o.theta_in_deg);
    std::vector<dvec3> Vs;
    for (int k = 0; k <= 360; ++k) Vs.push_back(in_plane(-90.0 + 0.5 * k));
    std::vector<std::vector<double>> values;
    double top = 0;
    for (const BrdfTarget& t : targets) {
        const std::vector<float> f = grid.evaluate(t.material, {L}, Vs);
        values.emplace_back();
        for (std::size_t k = 0; k < Vs.size(); ++k) values.back().push_back(std::max(0.0, channel_max(f, k)));
        top = std::max(top, *std::max_element(values.back().begin(), values.back().end()));
    }
    if (!(top > 0)) top = 1;
    // Log: 4 decades below the largest value, radius 0 to 1.
    const auto radius = [&](double v) { return o.log ? std::max(0.0, std::log10(std::max(v, 1e-30) / top) + 4.0) / 4.0 : v; };
    const double rmax = o.log ? 1.0 : top;
    std::ostringstream s;
    s << header(900, 620, "f in the plane of incidence, theta_in = " + std::to_string(int(o.theta_in_deg)) +
                              " deg" + (o.log ? " (log10 f, 4 decades)" : " (f, linear, max " + short_number(top) + ")"));
    s << "set size ratio -1\nunset border\nunset xtics\nunset ytics\nset key below\n"
      << "set xrange [" << -1.05 * rmax << ":" << 1.05 * rmax << "]\nset yrange [" << -0.05 * rmax << ":" << 1.05 * rmax << "]\n";
    for (int ring = 1; ring <= 4; ++ring)
        s << "set object circle at 0,0 size " << rmax * ring / 4.0 << " arc [0:180] fs empty border lc rgb '#cccccc'\n";
    s << "set arrow from " << L.x * rmax << "," << L.z * rmax << " to 0,0 lw 2 lc rgb 'orange'\n"
      << "set label 'L' at " << L.x * rmax * 1.03 << "," << L.z * rmax * 1.03 << " tc rgb 'orange'\n";
    s << "plot ";
    for (std::size_t t = 0; t < targets.size(); ++t)
        s << (t ? ", " : "") << "'-' using 1:2 with lines lw 2 title " << quoted(shown(targets[t]));
    s << "\n";
    for (const auto& curve : values) {
        for (std::size_t k = 0; k < Vs.size(); ++k) s << radius(curve[k]) * Vs[k].x << " " << radius(curve[k]) * Vs[k].z << "\n";
        s << "e\n";
    }
    return s.str();
}

std::string slice_script(BrdfGrid& grid, const BrdfTarget& target, const ViewOptions& o) {
    const ThetaSlice slice = theta_slice(grid, target.material);
    const int n = slice.n;
    std::ostringstream s;
    s << header(760, 640, "theta_h / theta_d slice (phi_d = 90 deg) of " + shown(target) +
                              (o.log ? ", log10 f" : ", f"));
    s << "set xlabel 'theta_h (deg)'\nset ylabel 'theta_d (deg)'\nset xrange [0:90]\nset yrange [0:90]\n"
      << "set size ratio 1\nset palette rgb 21,22,23\nset cblabel '" << (o.log ? "log10 f" : "f") << "'\n"
      << "plot '-' using 1:2:3 with image notitle\n";
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double v = slice.at(i, j);
            const bool below = slice.below[std::size_t(j * n + i)];
            const double shown = below || !std::isfinite(v) ? 0.0 : (o.log ? std::log10(std::max(v, 1e-4)) : v);
            s << i + 0.5 << " " << j + 0.5 << " " << shown << "\n";
        }
        s << "\n";
    }
    s << "e\n";
    return s.str();
}

std::string albedo_script(BrdfGrid& grid, const std::vector<BrdfTarget>& targets, const ViewOptions& o) {
    const std::size_t samples = std::size_t(o.albedo_mu) * std::size_t(o.albedo_phi);
    std::ostringstream s;
    s << header(900, 560, "directional albedo, " + std::to_string(samples) +
                              " incident samples per view (cosine midpoint)");
    s << "set xlabel 'view angle theta_v (deg)'\nset ylabel 'albedo (largest channel)'\nset xrange [0:90]\n"
      << "set grid\nset key right center box opaque\nset arrow from 0,1 to 90,1 nohead dt 2 lc rgb 'gray'\nplot ";
    for (std::size_t t = 0; t < targets.size(); ++t)
        s << (t ? ", " : "") << "'-' using 1:2 with lines lw 2 title " << quoted(shown(targets[t]));
    s << "\n";
    for (const BrdfTarget& t : targets) {
        const AlbedoCurve curve = albedo_curve(grid, t.material, o.albedo_mu, o.albedo_phi);
        for (std::size_t k = 0; k < curve.view_deg.size(); ++k)
            s << curve.view_deg[k] << " " << (std::isfinite(curve.albedo[k]) ? curve.albedo[k] : 0.0) << "\n";
        s << "e\n";
    }
    return s.str();
}

std::string lobe_script(BrdfGrid& grid, const BrdfTarget& target, const ViewOptions& o) {
    const Lobe3d lobe = lobe_3d(grid, target.material, o.theta_in_deg);
    const dvec3 L = lobe.L;
    std::ostringstream s;
    s << header(800, 700, "3D lobe of f (N.L), theta_in = " + std::to_string(int(o.theta_in_deg)) + " deg: " +
                              shown(target) + " (max " + short_number(lobe.top) + " scaled to 1)");
    s << "set view 60,30\nset view equal xyz\nunset key\nset xyplane at 0\nset pm3d depthorder\nset style fill solid\n"
      << "set palette rgb 33,13,10\nunset colorbox\nset xrange [-1:1]\nset yrange [-1:1]\nset zrange [0:1]\n"
      << "set arrow from " << L.x << ",0," << L.z << " to 0,0,0 lw 3 lc rgb 'orange' front\n"
      << "splot '-' using 1:2:3:4 with pm3d\n";
    for (int t = 0; t < lobe.nt; ++t) {
        for (int p = 0; p < lobe.np; ++p) {
            const std::size_t k = std::size_t(t * lobe.np + p);
            const double r = lobe.value[k] / lobe.top;
            s << r * lobe.V[k].x << " " << r * lobe.V[k].y << " " << r * lobe.V[k].z << " " << r << "\n";
        }
        s << "\n";
    }
    s << "e\n";
    return s.str();
}

}  // namespace m3055::plot
