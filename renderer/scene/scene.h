// Scene: plain structs describing what to render (SPEC section 7).
// Values here are already validated and normalized by the loader
// (directions are unit vectors, ranges are checked); renderers trust them.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace m3055 {

using glm::dvec3;

// SPEC section 2: the emulated display. The M3055 is 512 x 320, 5 bits a channel.
struct Display {
    int width = 512;
    int height = 320;
    int bits = 5;         // 1..8 bits per channel
    bool dither = false;  // ordered (4x4 Bayer) dithering before quantization
};

enum class Projection { perspective, orthographic };

// SPEC section 3.
struct Camera {
    Projection projection = Projection::perspective;
    dvec3 position{0.0, 0.0, 4.5};
    dvec3 target{0.0, 0.0, 0.0};
    dvec3 up{0.0, 1.0, 0.0};
    double fov_y_deg = 30.0;  // perspective only
    double height = 2.5;      // orthographic only: world-space height of the view
};

// One lobe of a metal model. For `metal` m is the Beckmann roughness m_j;
// for `metal_blinn` / `metal_phong` m holds the exponent n_j.
struct Lobe {
    double w = 0.0;
    double m = 0.0;
};

enum class LightType { directional, point, spot };

// Which models a light's own lobes are for: Beckmann lobes {"w", "m"} override
// the lobes of `metal`; exponent lobes {"w", "n"} those of `metal_blinn`/`metal_phong`.
enum class LobeKind { beckmann, exponent };

struct Light {
    LightType type = LightType::directional;
    dvec3 direction{0.0, 0.0, 1.0};  // directional: unit vector from the surface towards the light
    dvec3 position{0.0, 0.0, 0.0};   // point, spot
    double intensity = 1.0;          // a_l in [0, 10]
    dvec3 color{1.0, 1.0, 1.0};      // c_l in [0, 1]^3
    // Distance attenuation 1 / (S_c + S_l r + S_q r^2) for point and spot lights.
    double att_constant = 1.0;
    double att_linear = 0.0;
    double att_quadratic = 0.0;
    // Spot: C_spot = ((-L . spot_direction)+)^spot_exponent; spot_direction is unit,
    // the direction the spot shines along (from the light into the scene).
    dvec3 spot_direction{0.0, 0.0, -1.0};
    double spot_exponent = 1.0;
    // The lecture's per-light ambient L_amb,k (seed 003), per unit intensity: the
    // classic models (SPEC 5) add C_spot,k a_l ambient (x) K_amb, not attenuated.
    dvec3 ambient{0.0, 0.0, 0.0};
    // Per-light lobes replace the material's lobes for this light (metal models only).
    std::vector<Lobe> lobes;
    LobeKind lobe_kind = LobeKind::beckmann;
    bool enabled = true;
};

// The paper's models (SPEC 4), then the seeds' classic models (SPEC 5, docs/models.md).
enum class Model {
    highlight, translucent, metal, metal_blinn, metal_phong,
    // diffuse only
    lambert, half_lambert, half_lambert_clamped, half_lambert_normalized, oren_nayar,
    // Lambert diffuse plus a specular term
    phong, blinn_phong, microfacet, ward, heidrich_seidel,
};

// microfacet: the normal distribution D of its lobes, and its Fresnel term F.
enum class Distribution { blinn_phong, gaussian, beckmann, ggx };
enum class Fresnel { none, schlick, dielectric };

struct Material {
    Model model = Model::highlight;
    dvec3 color{0.8, 0.2, 0.2};  // C0
    double d = 0.5;              // environment / background share
    double w = 1.0;              // highlight brightness   (highlight, translucent)
    double m = 10.0;             // highlight exponent     (highlight, translucent)
    double t_n = 0.8;            // opacity                (translucent)
    double t_p = 1.0;            // Kay's falloff power    (translucent)
    std::vector<Lobe> lobes;     // 1..4 lobes             (metal, metal_blinn, metal_phong, microfacet)

    // The classic models (SPEC 5), in the lecture's form (seed 003):
    //   I = L_glob K_amb + L_emi + sum_k C_spot,k { I_amb,k + att_k (I_diff,k + I_spec,k) }.
    dvec3 ka{0.8, 0.2, 0.2};        // K_amb: ambient colour (defaults to kd in scene files)
    dvec3 kd{0.8, 0.2, 0.2};        // K_diff: diffuse colour
    dvec3 ks{1.0, 1.0, 1.0};        // K_spec: specular colour
    dvec3 emission{0.0, 0.0, 0.0};  // L_emi
    double shininess = 32.0;        // phong, blinn_phong, heidrich_seidel exponent
    double sigma = 0.3;             // oren_nayar roughness (radians)
    // microfacet: lobes are {w, m} (roughness m) or {w, n} (exponent, blinn_phong D).
    Distribution distribution = Distribution::beckmann;
    Fresnel fresnel = Fresnel::schlick;
    double ior = 1.5;               // index of refraction (schlick: F0 = ((n-1)/(n+1))^2)
    double alpha_x = 0.15;          // ward: roughness along the tangent T
    double alpha_y = 0.5;           // ward: roughness along the bitangent N x T
    dvec3 axis{0.0, 1.0, 0.0};      // ward, heidrich_seidel: T = normalize(axis x N) (unit)
};

// Spheres are exact (ray-cast); the other shapes are triangle meshes made by
// renderer/geometry/ (docs/shapes.md: fields, tessellation, normals, limits).
enum class Shape { sphere, plane, cube, cylinder, torus };

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
};

struct Scene {
    Display display;
    dvec3 background{0.0, 0.0, 0.0};
    Camera camera;
    std::vector<Light> lights;
    std::vector<Object> objects;
    dvec3 ambient{0.0, 0.0, 0.0};  // L_glob: the lecture's global ambient (classic models)
};

// Limits the loader enforces (documented in the README).
inline constexpr int kMaxLights = 16;
inline constexpr int kMaxLobes = 4;
inline constexpr int kMaxDisplaySize = 8192;

const char* to_string(Model model);
const char* to_string(LightType type);
const char* to_string(Projection projection);
const char* to_string(Distribution distribution);
const char* to_string(Fresnel fresnel);
const char* to_string(Shape shape);

// True for models whose output depends on what lies behind (needs the blended pass).
inline bool is_translucent(Model model) { return model == Model::translucent; }
// True for the seeds' classic models (SPEC 5): the lecture's shading equation.
inline bool is_classic(Model model) { return model >= Model::lambert; }
// True for the classic models with a specular term (ka, kd, ks).
inline bool has_specular(Model model) { return model >= Model::phong; }

// True for the metal family, which reads lobes (and per-light lobes).
inline bool uses_lobes(Model model) {
    return model == Model::metal || model == Model::metal_blinn || model == Model::metal_phong;
}

// The lobes light `light` uses on `material`: the light's own when it has lobes
// of the kind the model reads, else the material's (SPEC 4.3, Fig. 11).
inline const std::vector<Lobe>& lobes_for(const Light& light, const Material& material) {
    const LobeKind wanted = material.model == Model::metal ? LobeKind::beckmann : LobeKind::exponent;
    if (!light.lobes.empty() && light.lobe_kind == wanted) return light.lobes;
    return material.lobes;
}

}  // namespace m3055
