// Scene: plain structs describing what to render (docs/spec.md#7-scene-files).
// Values here are already validated and normalized by the loader
// (directions are unit vectors, ranges are checked); renderers trust them.
#pragma once

#include "models/material.h"  // Material, Lobe, LobeKind
#include "model_file/model.h"

#include <memory>

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace m3055 {

using glm::dvec3;

// docs/spec.md#2-display: what a display does to a linear value before its
// levels: nothing (the M3055 showed levels of the linear value, as the paper's
// figures do), or sRGB's encoding (IEC 61966-2-1), as other tools show colour.
enum class ViewTransform { none, srgb };

// docs/spec.md#2-display: the emulated display. The M3055 is 512 x 320, 5 bits a channel.
struct Display {
    int width = 512;
    int height = 320;
    int bits = 5;         // 1..8 bits per channel
    bool dither = false;  // ordered (4x4 Bayer) dithering before quantization
    ViewTransform view_transform = ViewTransform::none;
};

enum class Projection { perspective, orthographic };

// docs/spec.md#3-geometry.
struct Camera {
    Projection projection = Projection::perspective;
    dvec3 position{0.0, 0.0, 4.5};
    dvec3 target{0.0, 0.0, 0.0};
    dvec3 up{0.0, 1.0, 0.0};
    double fov_y_deg = 30.0;  // perspective only
    double height = 2.5;      // orthographic only: world-space height of the view
};

// directional, point and spot lights shine from one direction at a point; rect,
// disk and sky lights from every direction in which a point sees them
// (docs/spec.md#75-area-lights-the-sky-and-shadows; scene/area_light.h).
enum class LightType { directional, point, spot, rect, disk, sky };

struct Light {
    // Optional, shown in the explorer and kept on save: "key", "fill", "back"
    // when a three-point preset made the light, any text otherwise (1 to 64
    // bytes of UTF-8, no control characters). Grading rules refer to lights by it.
    std::string name;
    LightType type = LightType::directional;
    dvec3 direction{0.0, 0.0, 1.0};  // directional: unit vector from the surface towards the light
    dvec3 position{0.0, 0.0, 0.0};   // point, spot; rect, disk: the centre
    double intensity = 1.0;          // a_l in [0, 10]
    dvec3 color{1.0, 1.0, 1.0};      // c_l: in [0, 1]^3 as given, or made from the spectrum below
    // A spectral light (docs/spec.md#71-spectral-lights): a black body at
    // temperature_k kelvin (0: none), or a CIE illuminant by name ("" : none).
    // The loader sets `color` from it (linear sRGB at luminance 1, components may
    // exceed 1); the renderers use `color` alone. Kept so a save writes it back.
    double temperature_k = 0.0;
    std::string illuminant;
    // Distance attenuation 1 / (S_c + S_l r + S_q r^2) for point and spot lights.
    double att_constant = 1.0;
    double att_linear = 0.0;
    double att_quadratic = 0.0;
    // Spot: C_spot = ((-L . spot_direction)+)^spot_exponent; spot_direction is unit,
    // the direction the spot shines along (from the light into the scene).
    dvec3 spot_direction{0.0, 0.0, -1.0};
    double spot_exponent = 1.0;
    // The lecture's per-light ambient L_amb,k (seed 003), per unit intensity: the
    // classic models (docs/spec.md#5-classic-models) add C_spot,k a_l ambient (x) K_amb, not attenuated.
    dvec3 ambient{0.0, 0.0, 0.0};
    // Per-light lobes replace the material's lobes for this light (metal models only).
    std::vector<Lobe> lobes;
    LobeKind lobe_kind = LobeKind::beckmann;
    bool enabled = true;
    // Area lights (docs/spec.md#75-area-lights-the-sky-and-shadows): a rect or
    // disk emits from `position` towards the side `normal` points to; a rect's
    // size[1] side runs along `up` made perpendicular to `normal`, its size[0]
    // side along normal x up (scene/area_light.h: rect_frame); the sky is the
    // hemisphere about `up`. Unit vectors; `up` as given (a rect's default is
    // resolved by the loader), not yet made perpendicular.
    dvec3 normal{0.0, 0.0, 1.0};         // rect, disk
    dvec3 up{0.0, 1.0, 0.0};             // rect, sky
    double size[2] = {1.0, 1.0};         // rect: its sides, [1e-6, 1e6] each
    double radius = 1.0;                 // disk: [1e-6, 1e6]
    // Objects block this light (every type; the sky: occlusion by the objects).
    bool shadow = false;
};

// Spheres are exact (ray-cast); the other shapes are triangle meshes made by
// renderer/geometry/ (docs/shapes.md: fields, tessellation, normals, limits);
// a mesh's triangles come from a model file (docs/shapes.md#meshes-from-files).
enum class Shape { sphere, plane, cube, cylinder, torus, mesh };

// The material of one group of a model file's triangles (the file's
// material of that name): the file's own, made a model of the table, or the
// scene's "materials" entry of that name.
struct GroupMaterial {
    std::string name;
    Material material;
    bool overridden = false;  // from the scene's "materials" (written back), not the file's own
};

struct Object {
    Shape shape = Shape::sphere;
    dvec3 center{0.0, 0.0, 0.0};
    double radius = 1.0;          // sphere, cylinder
    Material material;
    // The other shapes' own fields (after `material`, so {shape, center, radius,
    // material} still initializes a sphere).
    dvec3 axis{0.0, 1.0, 0.0};    // unit: plane's normal ("normal"), cylinder's and torus's axis
    double size = 1.0;            // plane: side of the square; cube: edge length
    dvec3 rotation_deg{0.0, 0.0, 0.0};  // cube: about x, then y, then z (degrees, world axes)
    double height = 1.0;          // cylinder: length along the axis, centred on center
    bool capped = true;           // cylinder: closed by two flat discs
    double major_radius = 1.0;    // torus: centre of the tube to the axis
    double minor_radius = 0.25;   // torus: radius of the tube
    int segments = 0;             // cylinder, torus: segments a full circle (0 = the default)
    // mesh: the model file as opened (relative to the load's folder, or
    // absolute), its triangles in the file's coordinates (placed by `center`,
    // `size` and `rotation_deg`), and, when the object gives no "material",
    // one material a group of the file; `material` is then the first group's.
    std::string file{};
    std::shared_ptr<const model_file::Model> model{};
    std::vector<GroupMaterial> groups{};
};

// The material of group `group` of a mesh from a file (the object's own
// material for every other shape, and for a mesh given one "material").
const Material& material_of(const Object& object, std::size_t group);
// Every material the object wears: its groups' in order, else its `material`.
std::vector<const Material*> materials_of(const Object& object);

struct Scene {
    Display display;
    dvec3 background{0.0, 0.0, 0.0};
    Camera camera;
    std::vector<Light> lights;
    std::vector<Object> objects;
    dvec3 ambient{0.0, 0.0, 0.0};  // L_glob: the lecture's global ambient (classic models)
};

// Limits the loader enforces (documented in the README). kMaxLobes: models/material.h.
inline constexpr int kMaxLights = 16;
inline constexpr int kMaxDisplaySize = 8192;

const char* to_string(LightType type);
const char* to_string(ViewTransform transform);
const char* to_string(Projection projection);
const char* to_string(Shape shape);

// The lobes light `light` uses on `material`: the light's own when it has lobes
// of the kind the model reads (docs/spec.md#43-metal, Fig. 11; ModelSpec::light_lobes), else
// the material's "lobes".
LobeList lobes_for(const Light& light, const Material& material);

}  // namespace m3055
