// Benchmark only: draws a scene's spheres as UV meshes (glsl/passes/mesh_sphere.*)
// through the same shading code and the Renderer's own frame sequence
// (frame/frame_sequence.h: lights, materials, camera, clear and quantize pass),
// so the only differences are geometry and interpolation.
// Opaque models only (the benchmark's tessellation scenes have no translucency).
#pragma once

#include "gl/gl_api.h"
#include "gl/indexed_vertex_array.h"
#include "gl/program.h"
#include "image/image.h"
#include "passes/frame_targets.h"
#include "passes/shader_plan.h"
#include "scene/scene.h"

namespace m3055::bench {

enum class Interpolation { per_pixel, gouraud };

class MeshRenderer {
public:
    explicit MeshRenderer(const GlApi& gl);  // not copyable: owns GL objects through its members

    // Uploads a UV sphere of slices x stacks used by every later render.
    void set_tessellation(int slices, int stacks);
    int triangles_per_sphere() const { return index_count_ / 3; }

    // Throws std::runtime_error for a translucent object (not supported here).
    void render(const Scene& scene, Interpolation interpolation, ShaderMode mode = ShaderMode::specialized);
    RgbFloatImage read_raw() const { return targets_.read_raw(); }  // unquantized, rows bottom to top

private:
    const GlApi& gl_;
    ProgramCache programs_;
    FrameTargets targets_;  // the Renderer's kind of targets, for its frame sequence
    IndexedVertexArray sphere_;  // the UV sphere every object is drawn with
    int index_count_ = 0;
};

}  // namespace m3055::bench
