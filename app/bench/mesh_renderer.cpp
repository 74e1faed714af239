#include "mesh_renderer.h"

#include "models/model_spec.h"

#include "frame/frame_sequence.h"
#include "uv_sphere.h"

#include <stdexcept>

namespace m3055::bench {

MeshRenderer::MeshRenderer(const GlApi& gl) : gl_(gl), programs_(gl), targets_(gl, programs_), sphere_(gl) {
    sphere_.bind();
    gl_.EnableVertexAttribArray(0);
    gl_.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    gl_.BindVertexArray(0);
}

void MeshRenderer::set_tessellation(int slices, int stacks) {
    const UvSphere mesh = make_uv_sphere(slices, stacks);
    sphere_.upload(mesh.positions.data(), mesh.positions.size() * sizeof(float), mesh.indices.data(),
                   mesh.indices.size() * sizeof(std::uint32_t), GL_STATIC_DRAW);
    gl_.BindVertexArray(0);
    index_count_ = int(mesh.indices.size());
}

void MeshRenderer::render(const Scene& scene, Interpolation interpolation, ShaderMode mode) {
    if (!index_count_) throw std::runtime_error("mesh renderer: call set_tessellation first");
    std::vector<const Object*> objects;
    for (const Object& object : scene.objects) {
        if (is_translucent(object.material))
            throw std::runtime_error("mesh renderer: translucent objects are not supported");
        objects.push_back(&object);
    }
    std::vector<std::string> defines = specialization_defines(mode, objects, scene.lights);
    if (interpolation == Interpolation::gouraud) defines.push_back("GOURAUD");
    const unsigned program = programs_.get({"passes/mesh_sphere.vert", "passes/mesh_sphere.frag", defines});

    FrameSequence sequence(gl_, targets_, scene);  // the Renderer's own steps around the draws
    sequence.begin();
    gl_.Enable(GL_CULL_FACE);  // default: back faces of counter-clockwise triangles
    sequence.use_program(program);
    auto loc = [&](const char* name) { return gl_.GetUniformLocation(program, name); };
    gl_.BindVertexArray(sphere_.vao());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        gl_.Uniform4f(loc("u_sphere"), float(object.center.x), float(object.center.y), float(object.center.z),
                      float(object.radius));
        gl_.Uniform1i(loc("u_material"), int(i));
        gl_.DrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
    }
    gl_.BindVertexArray(0);
    gl_.Disable(GL_CULL_FACE);
    sequence.finish();  // the same quantize pass as the Renderer, so the frame does the same work
}

}  // namespace m3055::bench
