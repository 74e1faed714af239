// The spheres on the GPU: one screen-space quad each (passes/sphere_bounds.h),
// ray-cast by glsl/passes/sphere.{vert,frag}; drawn by the Renderer in its
// opaque pass (one instanced draw) and its translucent pass (runs of spheres
// far to near, between the meshes: passes/mesh_pass.h).
#pragma once

#include "gl/gl_api.h"
#include "gl/gl_object.h"
#include "passes/camera_frame.h"
#include "passes/draw_chunks.h"
#include "passes/translucent_blend.h"
#include "scene/scene.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace m3055 {

// Per-instance data of the sphere quads (glsl/passes/sphere.vert).
struct SphereInstance {
    float sphere[4];  // centre, radius
    float rect[4];    // NDC rectangle
    int material;     // material record index = object index
};

// The spheres on screen by pass: opaque ones, and translucent ones sorted far to near.
struct SphereSets {
    std::vector<SphereInstance> opaque;
    std::vector<const Object*> opaque_objects, translucent_objects;
    std::vector<std::pair<double, SphereInstance>> translucent;  // (far_to_near_sphere_key, instance), sorted
};
SphereSets sort_spheres(const Scene& scene, const CameraFrame& frame);

// Back-to-front key of a sphere (larger = farther); far_to_near_mesh_key is comparable.
double far_to_near_sphere_key(const CameraFrame& frame, const Object& object);

class SpherePass {
public:
    explicit SpherePass(const GlApi& gl);

    // Draws `instances` with the program in use (camera, lights and materials
    // already set), in buffer order: back to front. `chunks`: the render's
    // deadline, checked between chunks of bounded work (nullptr: none, one
    // draw). `two_pass`: a translucent run drawn by `blender` as a multiply
    // and an add draw with `program` (passes/translucent_blend.h), nullptr
    // otherwise. `width` and `height`: the targets' pixels.
    void draw(const std::vector<SphereInstance>& instances, ChunkedDraws* chunks, std::size_t lights,
              TranslucentBlender* two_pass, unsigned program, int width, int height);

private:
    void point_instances(std::size_t first);
    void draw_instances(const std::vector<SphereInstance>& instances, std::size_t first, std::size_t count,
                        TranslucentBlender* two_pass, unsigned program, int width, int height);
    struct Rewind;

    const GlApi& gl_;
    GlBuffer instance_buffer_;
    GlVertexArray vao_;
};

}  // namespace m3055
