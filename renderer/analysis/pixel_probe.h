// What the explorer's read-outs say about the display, ImGui-free so tests
// can hold them against headless renders:
//   - ScenePicker: the object under a display pixel (the pixel-centre ray of
//     docs/spec.md#3-geometry, the nearest front face, translucent or not),
//     and the object id of every pixel (the selection's outline);
//   - probe_pixel: one pixel's linear value, display level and PNG value, its
//     object and model, and N.L and R.V for one light; for a spectral material
//     (a conductor or a color_spectrum) each light's colour for the pair (pair_colours);
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
    std::size_t group = 0;  // a mesh from a file: the group hit (its material: material_of)
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

// The colour one light gives a spectral material (docs/spec.md#72-measured-metals,
// #73-spectral-colours): C0_l, eq. 2 summed per wavelength for the (material,
// light) pair, the value the shader's table holds for that light (passes/spectral_tables.h;
// the table's interpolation over cos(theta) aside), and a_l c_l C0_l, what the
// light adds as colour before the geometry and the lobes.
struct PairColour {
    int light = 0;          // index into the scene's lights
    std::string name;       // the light's name ("" : none)
    dvec3 c0{0.0};          // C0_l at cos_theta
    dvec3 lit{0.0};         // a_l c_l C0_l
    double cos_theta = 1.0;  // V.H at the pixel (the metals' Fresnel angle)
    bool by_angle = false;  // C0_l depends on the angle ("fresnel" full or schlick): cos_theta matters
    // The colour's name in the read-out: "C0" (the paper's models, a conductor),
    // "kd" (a classic model's kd_spectrum: K_diff per light; on a microfacet
    // conductor with a kd_spectrum the read-out shows kd's, not the metal's).
    std::string symbol = "C0";
};
// One per light that reaches the shader (enabled, intensity > 0), for the
// material at `hit`; none for a material whose colour is RGB (every light
// then sees the same C0) or for the background.
std::vector<PairColour> pair_colours(const Scene& scene, const PixelHit& hit);

struct PixelProbe {
    int x = 0, y = 0;          // y = 0 the top row
    dvec3 linear{0.0};         // unquantized (the --raw PFM's value)
    std::array<int, 3> level{};  // the display level, 0 ... 2^bits - 1
    std::array<int, 3> png{};    // the PNG value, 0 ... 255
    int object = -1;           // -1: the background
    std::string model;
    bool lit = false;          // a light was given and the pixel shows an object
    double NoL = 0.0, RoV = 0.0;  // for that light; R the mirror of L about N
    std::vector<PairColour> pairs;  // pair_colours at this pixel (spectral materials only)
    // Every channel of `linear` a finite number (a .brdf material can make NaN or Inf).
    bool finite() const { return std::isfinite(linear.r) && std::isfinite(linear.g) && std::isfinite(linear.b); }
    // Several lines, for the tooltip and --script's `probe`: then a line per pair,
    // "light 0 "key": C0_l 0.951 0.602 0.199  a_l c_l C0_l 1.598 0.521 0.065" (" at V.H 0.83" when
    // by angle); "NOT FINITE: ..." last when not finite().
    std::string text() const;
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
