#include "passes/mesh_pass.h"

#include "models/model_spec.h"

#include "geometry/mesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace m3055 {

namespace {

// One vertex as glsl/passes/mesh.vert reads it.
struct Vertex {
    float position[3];
    float normal[3];
    int material;  // material record index = object index
};

// Appends `mesh` to the buffers; its triangles sorted far to near when `sort_from` is given.
void append(const geometry::Mesh& mesh, int material, const CameraFrame* sort_from, std::vector<Vertex>& vertices,
            std::vector<std::uint32_t>& indices) {
    const std::uint32_t base = std::uint32_t(vertices.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const dvec3& p = mesh.positions[i];
        const dvec3& n = mesh.normals[i];
        vertices.push_back({{float(p.x), float(p.y), float(p.z)}, {float(n.x), float(n.y), float(n.z)}, material});
    }
    std::vector<std::size_t> order(mesh.triangles());
    std::iota(order.begin(), order.end(), std::size_t(0));
    if (sort_from) {
        // Far to near by the centroid: the eye's distance (perspective) or the depth along f.
        std::vector<double> key(order.size());
        for (std::size_t t = 0; t < order.size(); ++t) {
            const dvec3 c = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                             mesh.positions[mesh.indices[3 * t + 2]]) / 3.0;
            const dvec3 d = c - sort_from->position;
            key[t] = sort_from->projection == Projection::perspective ? glm::dot(d, d) : glm::dot(d, sort_from->forward);
        }
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key[a] > key[b]; });
    }
    for (std::size_t t : order)
        for (int k = 0; k < 3; ++k) indices.push_back(base + mesh.indices[3 * t + k]);
}

}  // namespace

double far_to_near_mesh_key(const CameraFrame& frame, const Object& object) {
    const dvec3 d = object.center - frame.position;
    if (frame.projection == Projection::orthographic) return glm::dot(d, frame.forward);
    return glm::dot(d, d);
}

MeshPass::MeshPass(const GlApi& gl) : gl_(gl), buffers_(gl) {
    buffers_.bind();
    const GLsizei stride = sizeof(Vertex);
    gl_.EnableVertexAttribArray(0);
    gl_.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, (void*)offsetof(Vertex, position));
    gl_.EnableVertexAttribArray(1);
    gl_.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, (void*)offsetof(Vertex, normal));
    gl_.EnableVertexAttribArray(2);
    gl_.VertexAttribIPointer(2, 1, GL_INT, stride, (void*)offsetof(Vertex, material));
    gl_.BindVertexArray(0);
}

void MeshPass::prepare(const Scene& scene, const CameraFrame& frame) {
    opaque_objects_.clear();
    translucent_objects_.clear();
    translucent_.clear();
    opaque_ranges_.clear();
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    // Opaque meshes first, as one batch; then one range per translucent mesh.
    for (int pass = 0; pass < 2; ++pass) {
        for (std::size_t i = 0; i < scene.objects.size(); ++i) {
            const Object& object = scene.objects[i];
            if (object.shape == Shape::sphere || is_translucent(object.material) != (pass == 1)) continue;
            const std::size_t first = indices.size();
            append(geometry::make_mesh(object), int(i), pass == 1 ? &frame : nullptr, vertices, indices);
            if (pass == 0) {
                opaque_objects_.push_back(&object);
                opaque_ranges_.push_back({first, indices.size() - first, &object});
            } else {
                translucent_objects_.push_back(&object);
                translucent_.push_back({far_to_near_mesh_key(frame, object), first, indices.size() - first, &object});
            }
        }
        if (pass == 0) opaque_count_ = indices.size();
    }
    if (indices.empty()) return;
    buffers_.upload(vertices.data(), vertices.size() * sizeof(Vertex), indices.data(),
                    indices.size() * sizeof(std::uint32_t), GL_STREAM_DRAW);
    gl_.BindVertexArray(0);
}

void MeshPass::draw(std::size_t first, std::size_t count) const {
    if (!count) return;
    gl_.Enable(GL_CULL_FACE);  // GL's default: cull clockwise (back) faces
    gl_.BindVertexArray(buffers_.vao());
    gl_.DrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT, (void*)(first * sizeof(std::uint32_t)));
    gl_.BindVertexArray(0);
    gl_.Disable(GL_CULL_FACE);
}

void MeshPass::draw_opaque() const { draw(0, opaque_count_); }
void MeshPass::draw_translucent(const Translucent& mesh) const { draw(mesh.first, mesh.count); }

}  // namespace m3055
