// What the explorer's read-outs say about the display, ImGui-free so tests
// can hold them against headless renders:
//   - ScenePicker: the object under a display pixel (the pixel-centre ray of
//     docs/spec.md#3-geometry, the nearest front face, translucent or not),
//     and the object id of every pixel (the selection's outline);
//   - probe_pixel: one pixel's linear value, display level and PNG value, its
//     object and model, and N.L and R.V for one light;
//   - level_histogram: how many pixels show each level, per channel;
//   - row_profile: the display levels along one row (the scanline plot).
#pragma once

#include "image/image.h"
#include "reference/mesh_hits.h"
#include "scene/scene.h"

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace m3055 {

struct PixelHit {
    int object = -1;  // -1: the background
    dvec3 P{0.0}, N{0.0}, V{0.0};
};

class ScenePicker {
public:
    explicit ScenePicker(const Scene& scene);  // builds the meshes of non-sphere objects once
    // Pixel (x, y), y = 0 the top row, of the scene's display.
    PixelHit pick(int x, int y) const;
    // The object index of every pixel, rows top to bottom (-1: background).
    std::vector<int> object_ids() const;

private:
    Scene scene_;
    std::vector<std::unique_ptr<ref::MeshIntersector>> meshes_;
};

struct PixelProbe {
    int x = 0, y = 0;          // y = 0 the top row
    dvec3 linear{0.0};         // unquantized (the --raw PFM's value)
    std::array<int, 3> level{};  // the display level, 0 ... 2^bits - 1
    std::array<int, 3> png{};    // the PNG value, 0 ... 255
    int object = -1;           // -1: the background
    std::string model;
    bool lit = false;          // a light was given and the pixel shows an object
    double NoL = 0.0, RoV = 0.0;  // for that light; R the mirror of L about N
    // Every channel of `linear` a finite number (a .brdf material can make NaN or Inf).
    bool finite() const { return std::isfinite(linear.r) && std::isfinite(linear.g) && std::isfinite(linear.b); }
    std::string text() const;  // several lines, for the tooltip and --script's `probe`; "NOT FINITE: ..." last when not finite()
};

// `raw` rows bottom to top (Renderer::read_raw), `display` top to bottom
// (read_display), both of `scene`'s display; `light` < 0: no N.L / R.V.
PixelProbe probe_pixel(const Scene& scene, const ScenePicker& picker, const RgbFloatImage& raw,
                       const Rgb8Image& display, int x, int y, int light);

// The display level a PNG value stands for (docs/spec.md#2-display's png = round(level 255 / (2^bits - 1))).
int level_of_png(int png, int bits);

struct LevelHistogram {
    std::array<std::vector<long>, 3> counts;  // per channel, 2^bits bins
    std::array<int, 3> used{};                // bins with at least one pixel
};
LevelHistogram level_histogram(const Rgb8Image& display, int bits);

// The display levels (0 .. 2^bits - 1) of row `row` (0 = the top row) of a
// display image, per channel, left to right. Throws std::out_of_range for a
// row outside the image.
struct RowProfile {
    int row = 0, bits = 5;
    std::array<std::vector<int>, 3> levels;
};
RowProfile row_profile(const Rgb8Image& display, int bits, int row);

}  // namespace m3055
