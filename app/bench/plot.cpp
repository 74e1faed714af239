// bench.png: run time (x, log) against error (y, log), one labelled dot per way.
#include "canvas.h"
#include "results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace m3055::bench {
namespace {

const Color kWhite{255, 255, 255}, kBlack{0, 0, 0}, kGrid{225, 225, 225}, kAxisText{60, 60, 60};

// Colour of a way's group (the legend lists them in this order).
struct GroupStyle {
    const char* group;
    Color color;
};
const GroupStyle kGroups[] = {
    {"exact ray-cast", {0, 140, 0}},     {"mesh per-pixel", {31, 100, 200}}, {"mesh Gouraud", {235, 120, 0}},
    {"cheap metal", {150, 70, 190}},     {"shaders", {0, 150, 160}},         {"CPU reference", {210, 30, 30}},
};

Color group_color(const std::string& group) {
    for (const auto& g : kGroups)
        if (group == g.group) return g.color;
    return kBlack;
}

Color darker(Color c) {
    return Color{static_cast<unsigned char>(c.r * 3 / 4), static_cast<unsigned char>(c.g * 3 / 4),
                 static_cast<unsigned char>(c.b * 3 / 4)};
}

struct Box {
    int x0, y0, x1, y1;
    int overlap(const Box& o) const {
        const int w = std::min(x1, o.x1) - std::max(x0, o.x0), h = std::min(y1, o.y1) - std::max(y0, o.y0);
        return (w > 0 && h > 0) ? w * h : 0;
    }
};

std::string decade_label(int k, bool time) {
    char text[32];
    if (time) {
        if (k >= 0) std::snprintf(text, sizeof text, "%.0f", std::pow(10.0, k));
        else std::snprintf(text, sizeof text, "%.*f", -k, std::pow(10.0, k));
    } else {
        std::snprintf(text, sizeof text, "1e%d", k);
    }
    return text;
}

}  // namespace

void write_plot(const std::string& path, const BenchResults& results) {
    const int W = 1200, H = 820, scale = 2;
    const int left = 120, right = W - 30, top = 70, bottom = H - 150;
    const int zero_band = bottom - 22;        // where error-free ways (the reference itself) sit
    const int log_bottom = bottom - 50;       // lowest decade line
    Canvas canvas(W, H, kWhite);

    // Ranges in whole decades around the data.
    double tmin = 1e300, tmax = 0, emin = 1e300, emax = 0;
    for (const WayResult& w : results.ways) {
        if (!w.small.valid()) continue;
        tmin = std::min(tmin, w.small.median_ms), tmax = std::max(tmax, w.small.median_ms);
        if (!w.exact_reference && w.error.valid() && w.error.mean_abs > 0)
            emin = std::min(emin, w.error.mean_abs), emax = std::max(emax, w.error.mean_abs);
    }
    if (tmax <= 0) tmin = 1, tmax = 10;
    if (emax <= 0) emin = 1e-6, emax = 1e-1;
    const int x_lo = int(std::floor(std::log10(tmin))), x_hi = std::max(x_lo + 1, int(std::ceil(std::log10(tmax))));
    const int y_lo = int(std::floor(std::log10(emin))), y_hi = std::max(y_lo + 1, int(std::ceil(std::log10(emax))));
    auto px = [&](double ms) { return left + int((std::log10(ms) - x_lo) / (x_hi - x_lo) * (right - left)); };
    auto py = [&](double e) { return log_bottom - int((std::log10(e) - y_lo) / (y_hi - y_lo) * (log_bottom - top)); };

    // Grid, ticks and tick labels.
    for (int k = x_lo; k <= x_hi; ++k) {
        const int x = px(std::pow(10.0, k));
        canvas.line(x, top, x, bottom, kGrid);
        for (int m = 2; m <= 9 && k < x_hi; ++m) {
            const int xm = px(m * std::pow(10.0, k));
            canvas.line(xm, bottom, xm, bottom + 4, kBlack);
        }
        canvas.line(x, bottom, x, bottom + 8, kBlack);
        const std::string label = decade_label(k, true);
        canvas.text(x - Canvas::text_width(label, scale) / 2, bottom + 14, label, kAxisText, scale);
    }
    for (int k = y_lo; k <= y_hi; ++k) {
        const int y = py(std::pow(10.0, k));
        canvas.line(left, y, right, y, kGrid);
        canvas.line(left - 8, y, left, y, kBlack);
        const std::string label = decade_label(k, false);
        canvas.text(left - 14 - Canvas::text_width(label, scale), y - 7, label, kAxisText, scale);
    }
    canvas.dashed_line(left, (log_bottom + zero_band) / 2, right, (log_bottom + zero_band) / 2, kAxisText, 4);
    canvas.line(left - 8, zero_band, left, zero_band, kBlack);
    canvas.text(left - 14 - Canvas::text_width("0", scale), zero_band - 7, "0", kAxisText, scale);
    canvas.rect(left, top, right, bottom, kBlack);

    // Titles.
    const std::string title = "Run time against error, per way of rendering (512 x 320)";
    canvas.text((W - Canvas::text_width(title, 3)) / 2, 18, title, kBlack, 3);
    const std::string x_title = "time per frame, ms (log scale; further left = faster)";
    canvas.text((left + right - Canvas::text_width(x_title, scale)) / 2, bottom + 40, x_title, kBlack, scale);
    const std::string y_title = "mean |error| vs double reference (log; lower = better)";
    canvas.text_up(16, (top + bottom + Canvas::text_width(y_title, scale)) / 2, y_title, kBlack, scale);

    // Dots first, so labels can avoid all of them.
    struct Point {
        int x, y;
        const WayResult* way;
    };
    std::vector<Point> points;
    std::vector<Box> taken;
    for (const WayResult& w : results.ways) {
        if (!w.small.valid() || (!w.exact_reference && !w.error.valid())) continue;
        const double e = w.exact_reference ? 0.0 : std::max(w.error.mean_abs, std::pow(10.0, y_lo));
        const Point p{px(w.small.median_ms), w.exact_reference || e <= 0 ? zero_band : py(e), &w};
        points.push_back(p);
        taken.push_back({p.x - 6, p.y - 6, p.x + 6, p.y + 6});
    }
    for (const Point& p : points) {
        canvas.disc(p.x, p.y, 6, group_color(p.way->group));
        canvas.ring(p.x, p.y, 6, kBlack);
    }
    // Labels: the nearest free spot among positions around the dot, with a
    // leader line when it had to move away.
    const Box area{left + 2, top + 2, right - 2, bottom - 2};
    for (const Point& p : points) {
        const std::string& label = p.way->label;
        const int tw = Canvas::text_width(label, scale), th = Canvas::text_height(scale);
        Box best{};
        int best_cost = 1 << 30;
        for (int ring = 1; ring <= 6 && best_cost > 0; ++ring) {
            const int d = 10 * ring;
            const int candidates[][2] = {{d, -th / 2},       {-d - tw, -th / 2}, {-tw / 2, -d - th}, {-tw / 2, d},
                                         {d, -d - th / 2},   {d, d - th / 2},    {-d - tw, -d - th / 2},
                                         {-d - tw, d - th / 2}};
            for (const auto& c : candidates) {
                const Box box{p.x + c[0], p.y + c[1], p.x + c[0] + tw, p.y + c[1] + th};
                int cost = 0;
                if (box.x0 < area.x0 || box.x1 > area.x1 || box.y0 < area.y0 || box.y1 > area.y1) cost += 1 << 20;
                const Box padded{box.x0 - 2, box.y0 - 2, box.x1 + 2, box.y1 + 2};
                for (const Box& t : taken) cost += padded.overlap(t);
                if (cost < best_cost) best_cost = cost, best = box;
                if (cost == 0) break;
            }
        }
        const Color color = group_color(p.way->group);
        const int cx = std::clamp(p.x, best.x0, best.x1), cy = std::clamp(p.y, best.y0, best.y1);
        if (std::abs(cx - p.x) + std::abs(cy - p.y) > 14) canvas.line(p.x, p.y, cx, cy, color);
        canvas.fill_rect(best.x0 - 1, best.y0 - 1, best.x1 + 1, best.y1 + 1, kWhite);
        canvas.text(best.x0, best.y0, label, darker(color), scale);
        taken.push_back(best);
    }

    // Legend: two rows of three under the x-axis title, in fixed columns.
    const int column = (right - left) / 3;
    for (std::size_t i = 0; i < std::size(kGroups); ++i) {
        const int x = left + int(i % 3) * column, y = bottom + 72 + int(i / 3) * 24;
        canvas.disc(x + 6, y + 7, 6, kGroups[i].color);
        canvas.ring(x + 6, y + 7, 6, kBlack);
        canvas.text(x + 18, y, kGroups[i].group, kBlack, scale);
    }
    const std::string note =
        "Mesh labels: slices x stacks of the UV sphere. Row \"0\": the reference itself.";
    canvas.text(left, bottom + 128, note, kAxisText, scale);
    write_png(path, canvas.image());
}

}  // namespace m3055::bench
