// bench.gp: the gnuplot script of bench.png, data inline. gnuplot draws the
// axes, ticks, fonts and legend; this file only decides the ranges, the style
// of each group, and where each point's label goes (gnuplot has no label
// placement of its own, and the ways crowd: eq. 15 and eq. 16 coincide).
#include "plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <vector>

namespace m3055::bench {
namespace {

// Canvas and plot area, in pixels (gnuplot is told the same fractions).
constexpr double kWidth = 1200, kHeight = 720;
constexpr double kLeft = 100, kRight = 1170, kTop = 60, kBottom = 640;
// Label text: DejaVu Sans 11 pt on pngcairo; a generous average glyph width.
constexpr double kCharWidth = 7.6, kTextHeight = 16, kPointRadius = 7;

struct GroupStyle {
    const char* group;   // as bench.cpp names it
    const char* legend;  // legend text
    const char* color;
    int point_type;      // gnuplot pt: 7 circle, 5 square, 9 triangle, 13 diamond, 11 triangle down
    bool connect;        // a line through the group's points (a series of tessellations)
};
const GroupStyle kStyles[] = {
    {"exact ray-cast", "exact ray-cast spheres (the renderer)", "#008c00", 7, false},
    {"mesh per-pixel", "UV-sphere mesh, shaded per pixel (slices x stacks)", "#1f64c8", 5, true},
    {"mesh Gouraud", "UV-sphere mesh, shaded per vertex (Gouraud)", "#e07000", 9, true},
    {"cheap metal", "the paper's metals: eq. 12, 15, 16 (error against eq. 12)", "#9646be", 13, false},
    {"shaders", "specialized against general programs (the paper's figures)", "#00939a", 11, false},
    {"CPU reference", "double-precision CPU reference (error 0 by definition)", "#d21e1e", 7, false},
};
const GroupStyle kOtherStyle = {"", "", "#404040", 6, false};

const GroupStyle& style_of(const std::string& group) {
    for (const GroupStyle& s : kStyles)
        if (group == s.group) return s;
    return kOtherStyle;
}

struct Box {
    double x0, y0, x1, y1;
    double overlap(const Box& o) const {
        const double w = std::min(x1, o.x1) - std::max(x0, o.x0), h = std::min(y1, o.y1) - std::max(y0, o.y0);
        return (w > 0 && h > 0) ? w * h : 0;
    }
};

// Whole decades around the data; y gets one more decade below for the row of
// error-free ways ("0"), which a log axis cannot show.
struct Axes {
    int x_lo = 0, x_hi = 1, y_lo = -6, y_hi = -1;
    double zero_row() const { return std::pow(10.0, y_lo - 0.6); }
    double zero_break() const { return std::pow(10.0, y_lo - 0.3); }
    double y_min() const { return std::pow(10.0, y_lo - 1); }
    double px(double ms) const { return kLeft + (std::log10(ms) - x_lo) / (x_hi - x_lo) * (kRight - kLeft); }
    double py(double e) const {
        return kBottom - (std::log10(e) - (y_lo - 1)) / (y_hi - (y_lo - 1)) * (kBottom - kTop);
    }
    double ms_at(double x) const { return std::pow(10.0, x_lo + (x - kLeft) / (kRight - kLeft) * (x_hi - x_lo)); }
    double error_at(double y) const {
        return std::pow(10.0, (y_lo - 1) + (kBottom - y) / (kBottom - kTop) * (y_hi - (y_lo - 1)));
    }
};

Axes axes_for(const std::vector<PlotPoint>& points) {
    double tmin = 1e300, tmax = 0, emin = 1e300, emax = 0;
    for (const PlotPoint& p : points) {
        tmin = std::min(tmin, p.ms), tmax = std::max(tmax, p.ms);
        if (p.error > 0) emin = std::min(emin, p.error), emax = std::max(emax, p.error);
    }
    if (tmax <= 0) tmin = 1, tmax = 10;
    if (emax <= 0) emin = 1e-6, emax = 1e-1;
    Axes a;
    a.x_lo = int(std::floor(std::log10(tmin)));
    a.x_hi = std::max(a.x_lo + 1, int(std::ceil(std::log10(tmax))));
    a.y_lo = int(std::floor(std::log10(emin)));
    a.y_hi = std::max(a.y_lo + 1, int(std::ceil(std::log10(emax))));
    return a;
}

double y_of(const Axes& axes, const PlotPoint& p) { return p.error > 0 ? p.error : axes.zero_row(); }

// The free spot nearest to the point among rings of candidate positions
// around it (right first, as labels read best there): least overlap with
// points, labels already placed and the legend; inside the plot area.
Box place_label(double x, double y, const std::string& text, const std::vector<Box>& taken) {
    const double w = kCharWidth * double(text.size()), h = kTextHeight;
    const Box area{kLeft + 4, kTop + 4, kRight - 4, kBottom - 4};
    Box best{x + 10, y - h / 2, x + 10 + w, y + h / 2};
    double best_cost = 1e300;
    for (int ring = 1; ring <= 8 && best_cost > 0; ++ring) {
        const double d = 6 + 8 * ring;
        const double candidates[][2] = {{d, -h / 2},     {-d - w, -h / 2},     {-w / 2, -d - h}, {-w / 2, d},
                                        {d, -d - h / 2}, {d, d - h / 2},       {-d - w, -d - h / 2},
                                        {-d - w, d - h / 2}};
        for (const auto& c : candidates) {
            const Box box{x + c[0], y + c[1], x + c[0] + w, y + c[1] + h};
            double cost = 0;
            if (box.x0 < area.x0 || box.x1 > area.x1 || box.y0 < area.y0 || box.y1 > area.y1) cost += 1e9;
            for (const Box& t : taken) cost += box.overlap(t);
            if (cost < best_cost) best_cost = cost, best = box;
            if (cost == 0) break;
        }
    }
    return best;
}

std::string quoted(const std::string& text) {
    std::string q = "\"";
    for (char c : text) q += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    return q + "\"";
}

std::string num(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

// `set label` (and a leader line when the label had to move away) for every point.
std::string label_commands(const std::vector<PlotPoint>& points, const Axes& axes, const Box& legend) {
    std::vector<Box> taken = {legend};
    for (const PlotPoint& p : points) {
        const double x = axes.px(p.ms), y = axes.py(y_of(axes, p));
        taken.push_back({x - kPointRadius, y - kPointRadius, x + kPointRadius, y + kPointRadius});
    }
    std::ostringstream gp;
    for (const PlotPoint& p : points) {
        const double x = axes.px(p.ms), y = axes.py(y_of(axes, p));
        const Box box = place_label(x, y, p.label, taken);
        taken.push_back(box);
        const char* color = style_of(p.group).color;
        gp << "set label " << quoted(p.label) << " at first " << num(axes.ms_at(box.x0)) << ", first "
           << num(axes.error_at((box.y0 + box.y1) / 2)) << " left textcolor rgb \"" << color << "\" front\n";
        const double cx = std::clamp(x, box.x0, box.x1), cy = std::clamp(y, box.y0, box.y1);
        if (std::hypot(cx - x, cy - y) > 22)
            gp << "set arrow from first " << num(p.ms) << ", first " << num(y_of(axes, p)) << " to first "
               << num(axes.ms_at(cx)) << ", first " << num(axes.error_at(cy)) << " nohead lc rgb \"" << color
               << "\" lw 1 back\n";
    }
    return gp.str();
}

// A tick per decade of error, and "0" for the row of error-free ways.
std::string y_tics(const Axes& axes) {
    std::string tics = "set ytics nomirror (\"0\" " + num(axes.zero_row());
    for (int k = axes.y_lo; k <= axes.y_hi; ++k) tics += ", \"10^{" + std::to_string(k) + "}\" 1e" + std::to_string(k);
    return tics + ")\n";
}

std::string axis_commands(const Axes& axes) {
    std::ostringstream gp;
    gp << "set logscale xy\n"
       << "set xrange [" << num(std::pow(10.0, axes.x_lo)) << ":" << num(std::pow(10.0, axes.x_hi)) << "]\n"
       << "set yrange [" << num(axes.y_min()) << ":" << num(std::pow(10.0, axes.y_hi)) << "]\n"
       << "set format x \"%g\"\n" << y_tics(axes)
       << "set mxtics 10\nset xtics nomirror\n"
       << "set grid xtics ytics mxtics lc rgb \"#dddddd\" lw 1, lc rgb \"#eeeeee\" lw 1\n"
       << "set arrow from graph 0, first " << num(axes.zero_break()) << " to graph 1, first "
       << num(axes.zero_break()) << " nohead dt 2 lc rgb \"#808080\" back\n"
       << "set xlabel \"time per frame at 512 x 320, ms (median, log scale; left = faster)\"\n"
       << "set ylabel \"mean |error| against the double-precision reference (log scale; lower = better)\"\n";
    return gp.str();
}

}  // namespace

std::string gnuplot_script(const std::vector<PlotPoint>& points, const std::string& title) {
    const Axes axes = axes_for(points);
    // The legend, top right where slow and inaccurate ways would be (there are none).
    const Box legend{kRight - 560, kTop + 4, kRight - 4, kTop + 4 + 19.0 * std::size(kStyles) + 8};
    std::ostringstream gp;
    gp << "# bench.png: written by m3055 bench from bench.csv; run `gnuplot bench.gp` in this folder to\n"
       << "# redraw it (gnuplot -e \"out='other.png'\" bench.gp for another name).\n"
       << "if (!exists(\"out\")) out = \"bench.png\"\n"
       << "set terminal pngcairo size " << kWidth << "," << kHeight << " enhanced font \"DejaVu Sans,11\"\n"
       << "set output out\n"
       << "set lmargin at screen " << num(kLeft / kWidth) << "\nset rmargin at screen " << num(kRight / kWidth)
       << "\nset tmargin at screen " << num(1 - kTop / kHeight) << "\nset bmargin at screen "
       << num(1 - kBottom / kHeight) << "\n"
       << "set title " << quoted(title) << " font \",15\"\n"
       << "set key at graph 0.995, graph 0.99 right top box opaque reverse Left samplen 1.5 spacing 1.15 "
          "font \",10.5\"\nset border 3 lw 1.2\n"
       << axis_commands(axes) << label_commands(points, axes, legend);
    // One inline data block and one plot element per group, in the legend's
    // order; a group this file does not know comes last, in grey.
    std::vector<std::string> groups;
    for (const GroupStyle& s : kStyles) groups.push_back(s.group);
    for (const PlotPoint& p : points)
        if (std::find(groups.begin(), groups.end(), p.group) == groups.end()) groups.push_back(p.group);
    std::string plot = "plot ";
    int block = 0;
    for (const std::string& group : groups) {
        const GroupStyle& s = style_of(group);
        std::ostringstream data;
        for (const PlotPoint& p : points)
            if (p.group == group) data << num(p.ms) << " " << num(y_of(axes, p)) << "\n";
        if (data.str().empty()) continue;
        gp << "$group" << block << " << EOD\n" << data.str() << "EOD\n";
        plot += std::string(block ? ", \\\n     " : "") + "$group" + std::to_string(block) + " using 1:2 with " +
                (s.connect ? "linespoints lw 1.5" : "points") + " pt " + std::to_string(s.point_type) +
                " ps 1.6 lc rgb \"" + s.color + "\" title " + quoted(*s.legend ? s.legend : group);
        ++block;
    }
    gp << plot << "\n";
    return gp.str();
}

}  // namespace m3055::bench
