// Every object of a scene as a shadow ray meets it (glsl/common/shadows.glsl):
// spheres and the meshes' triangles (geometry/mesh.h, the same triangles the
// mesh pass draws) under a bounding-volume hierarchy (geometry/box_tree.h),
// packed into one RGBA32F texture on texture unit kOccluderUnit. Uploaded only
// for scenes with a shadow, and rebuilt only when the objects' geometry
// changes (a material edit keeps the tree).
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace m3055 {

inline constexpr int kOccluderUnit = 3;
inline constexpr int kOccluderTextureWidth = 4096;  // texels a row
inline constexpr int kOccluderLeafSize = 4;   // at most 4: glsl/common/shadows.glsl's leaf code
inline constexpr int kOccluderMaxDepth = 64;  // never reached: every split halves

// The objects as a shadowed sky's samples are drawn about them
// (glsl/common/sky_occluders.glsl): each one's bounding sphere and box, and a
// plane's normal; and the shapes whose silhouettes have closed forms (a sphere:
// its bounding sphere is the sphere; a cube or a plane: a box, its unit axes
// and half sizes, a plane's 0 along its normal; a capped cylinder: the prism of
// its mesh, its axis, radial axes, half height, radius and segments). At most
// kMaxSkyOccluders objects (the GLSL's MAX_SKY_OCCLUDERS).
inline constexpr std::size_t kMaxSkyOccluders = 8;
// The GLSL's kOccluderSphere, kOccluderBox, kOccluderPrism.
enum class SkyOccluderShape { other = 0, sphere = 1, box = 2, prism = 3 };
struct SkyOccluder {
    dvec3 sphere_centre;
    double radius = 0.0;
    dvec3 box_centre, box_half;
    bool plane = false;
    dvec3 normal;  // a plane's
    SkyOccluderShape shape = SkyOccluderShape::other;
    dvec3 centre;           // a box's centre,
    dvec3 axes[3];          // its unit axes (the mesh's own: geometry/shapes.cpp)
    dvec3 half_sizes{0.0};  // and its half size along each
    // A cylinder's prism: centre, axes[0] its axis, axes[1] and axes[2] the radial axes its
    // corners are drawn from (corner k at angle 2 pi k / segments from axes[1] towards axes[2]);
    // half_sizes (half height, radius, radius): what the GPU is given (frame_texel_w).
    int segments = 0;
};

// The w of frame texel a (0-2) that the GLSL reads: a box's half size along axis a; a
// prism's half height, radius, and segments.
float frame_texel_w(const SkyOccluder& o, int a);

// The texels of glsl/common/shadows.glsl's layout: the nodes (two texels
// each), then the primitives from texel `primitives_at` (three each).
struct OccluderTexels {
    std::vector<float> texels;  // RGBA
    int primitives_at = 0;      // 0: no objects
    int depth = 0;              // of the tree
    std::vector<SkyOccluder> sky;  // one an object, or none where the scene has more than kMaxSkyOccluders
};
OccluderTexels pack_occluders(const Scene& scene);

class OccluderTexture {
public:
    explicit OccluderTexture(const GlApi& gl);

    // Makes `scene`'s occluders current: packed and uploaded when its objects'
    // geometry differs from the last upload's. Throws std::runtime_error when
    // they need more rows than GL_MAX_TEXTURE_SIZE.
    void upload(const Scene& scene);
    // A program's occluder uniforms (binds the texture to kOccluderUnit).
    void set_uniforms(unsigned program) const;

private:
    const GlApi& gl_;
    GlTexture texture_;
    std::string key_;            // the geometry of the last upload
    bool uploaded_ = false;
    int primitives_at_ = 0;
    std::vector<SkyOccluder> sky_;
};

}  // namespace m3055
