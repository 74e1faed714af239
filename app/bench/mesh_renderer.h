// Benchmark only: draws a scene's spheres as UV meshes (glsl/passes/mesh_sphere.*)
// through the same shading code, lights, materials, camera and quantize pass as
// the Renderer, so the only differences are geometry and interpolation.
// Opaque models only (the benchmark's tessellation scenes have no translucency).
#pragma once

#include "gl/gl_api.h"
#include "gl/program.h"
#include "image/image.h"
#include "passes/shader_plan.h"
#include "scene/scene.h"

namespace m3055::bench {

enum class Interpolation { per_pixel, gouraud };

class MeshRenderer {
public:
    explicit MeshRenderer(const GlApi& gl);
    ~MeshRenderer();
    MeshRenderer(const MeshRenderer&) = delete;
    MeshRenderer& operator=(const MeshRenderer&) = delete;

    // Uploads a UV sphere of slices x stacks used by every later render.
    void set_tessellation(int slices, int stacks);
    int triangles_per_sphere() const { return index_count_ / 3; }

    // Throws std::runtime_error for a translucent object (not supported here).
    void render(const Scene& scene, Interpolation interpolation, ShaderMode mode = ShaderMode::specialized);
    RgbFloatImage read_raw() const;  // unquantized, rows bottom to top

private:
    void ensure_targets(int w, int h);
    void release_targets();
    const GlApi& gl_;
    ProgramCache programs_;
    unsigned vao_ = 0, vertex_buffer_ = 0, index_buffer_ = 0, empty_vao_ = 0;
    unsigned material_buffer_ = 0, material_texture_ = 0;
    unsigned scene_fbo_ = 0, colour_ = 0, depth_ = 0, display_fbo_ = 0, display_ = 0;
    int index_count_ = 0, width_ = 0, height_ = 0;
};

}  // namespace m3055::bench
