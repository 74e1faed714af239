#include "passes/mesh_pass.h"

#include "models/model_spec.h"
#include "passes/material_slots.h"

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
    int material;  // material record index (passes/material_slots.h)
};

// Appends the triangles of `mesh` whose groups `take` says (all of a generated
// shape's), their vertices with their groups' records; sorted far to near
// when `sort_from` is given.
void append(const geometry::Mesh& mesh, const std::vector<bool>& take, const std::vector<int>& records,
            const CameraFrame* sort_from, std::vector<Vertex>& vertices, std::vector<std::uint32_t>& indices) {
    // A model dressed whole by its "material" has one record for all its file's groups.
    auto group_of = [&](std::size_t t) {
        return mesh.groups.empty() || records.size() == 1 ? std::size_t(0) : std::size_t(mesh.groups[t]);
    };
    // A vertex's record: its triangles' group (a model file's vertex belongs to one group).
    std::vector<int> vertex_record(mesh.positions.size(), records[0]);
    if (!mesh.groups.empty())
        for (std::size_t t = 0; t < mesh.triangles(); ++t)
            for (int k = 0; k < 3; ++k) vertex_record[mesh.indices[3 * t + k]] = records[group_of(t)];
    const std::uint32_t base = std::uint32_t(vertices.size());
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const dvec3& p = mesh.positions[i];
        const dvec3& n = mesh.normals[i];
        vertices.push_back({{float(p.x), float(p.y), float(p.z)}, {float(n.x), float(n.y), float(n.z)}, vertex_record[i]});
    }
    std::vector<std::size_t> order;
    order.reserve(mesh.triangles());
    for (std::size_t t = 0; t < mesh.triangles(); ++t)
        if (take[group_of(t)]) order.push_back(t);
    if (sort_from) {
        // Far to near by the centroid: the eye's distance (perspective) or the depth along f.
        std::vector<double> key(mesh.triangles());
        for (std::size_t t : order) {
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

// Per group of `object`: whether it is drawn in the translucent pass (`translucent`) or the opaque one.
std::vector<bool> groups_in_pass(const Object& object, bool translucent) {
    std::vector<bool> out;
    for (const Material* material : materials_of(object)) out.push_back(is_translucent(*material) == translucent);
    return out;
}

bool any(const std::vector<bool>& flags) { return std::find(flags.begin(), flags.end(), true) != flags.end(); }

void set_attributes(const GlApi& gl, const IndexedVertexArray& buffers) {
    buffers.bind();
    const GLsizei stride = sizeof(Vertex);
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, (void*)offsetof(Vertex, position));
    gl.EnableVertexAttribArray(1);
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, (void*)offsetof(Vertex, normal));
    gl.EnableVertexAttribArray(2);
    gl.VertexAttribIPointer(2, 1, GL_INT, stride, (void*)offsetof(Vertex, material));
    gl.BindVertexArray(0);
}

}  // namespace

bool MeshPass::MeshKey::operator==(const MeshKey& o) const {
    return object == o.object && shape == o.shape && center == o.center && axis == o.axis &&
           rotation_deg == o.rotation_deg && radius == o.radius && size == o.size && height == o.height &&
           major_radius == o.major_radius && minor_radius == o.minor_radius && capped == o.capped &&
           segments == o.segments && model == o.model && opaque_groups == o.opaque_groups &&
           more_records == o.more_records;
}

double far_to_near_mesh_key(const CameraFrame& frame, const Object& object) {
    const dvec3 d = object.center - frame.position;
    if (frame.projection == Projection::orthographic) return glm::dot(d, frame.forward);
    return glm::dot(d, d);
}

MeshPass::MeshPass(const GlApi& gl) : gl_(gl), buffers_(gl), translucent_buffers_(gl) {
    set_attributes(gl_, buffers_);
    set_attributes(gl_, translucent_buffers_);
}

void MeshPass::prepare(const Scene& scene, const CameraFrame& frame) {
    opaque_objects_.clear();
    translucent_objects_.clear();
    translucent_.clear();
    opaque_ranges_.clear();
    const MaterialSlots slots = material_slots(scene.objects);
    auto records_of = [&](std::size_t i) {
        std::vector<int> records;
        for (std::size_t g = 0; g < std::max<std::size_t>(1, scene.objects[i].groups.size()); ++g)
            records.push_back(slots.record(i, g));
        return records;
    };

    // The opaque batch: kept when it would hold the same meshes.
    std::vector<MeshKey> key;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& o = scene.objects[i];
        if (o.shape == Shape::sphere) continue;
        std::vector<bool> opaque = groups_in_pass(o, false);
        if (!any(opaque)) continue;
        key.push_back({i, o.shape, o.center, o.axis, o.rotation_deg, o.radius, o.size, o.height, o.major_radius,
                       o.minor_radius, o.capped, o.segments, o.model, std::move(opaque), slots.more[i]});
    }
    reused_opaque_ = !key.empty() && key == opaque_key_;
    if (!reused_opaque_) {
        std::vector<Vertex> vertices;
        std::vector<std::uint32_t> indices;
        opaque_layout_.clear();
        for (const MeshKey& mesh : key) {
            const std::size_t first = indices.size();
            append(geometry::make_mesh(scene.objects[mesh.object]), mesh.opaque_groups, records_of(mesh.object),
                   nullptr, vertices, indices);
            opaque_layout_.push_back({first, indices.size() - first, mesh.object});
        }
        opaque_count_ = indices.size();
        opaque_key_ = std::move(key);
        if (!indices.empty())
            buffers_.upload(vertices.data(), vertices.size() * sizeof(Vertex), indices.data(),
                            indices.size() * sizeof(std::uint32_t), GL_STATIC_DRAW);
        gl_.BindVertexArray(0);
    }
    for (const OpaqueRange& range : opaque_layout_) {
        const Object& object = scene.objects[range.object];
        opaque_objects_.push_back(&object);
        opaque_ranges_.push_back({range.first, range.count, &object});
    }

    // The translucent meshes, each sorted from the eye.
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        if (object.shape == Shape::sphere) continue;
        const std::vector<bool> translucent = groups_in_pass(object, true);
        if (!any(translucent)) continue;
        const std::size_t first = indices.size();
        append(geometry::make_mesh(object), translucent, records_of(i), &frame, vertices, indices);
        translucent_objects_.push_back(&object);
        translucent_.push_back({far_to_near_mesh_key(frame, object), first, indices.size() - first, &object});
    }
    if (indices.empty()) return;
    translucent_buffers_.upload(vertices.data(), vertices.size() * sizeof(Vertex), indices.data(),
                                indices.size() * sizeof(std::uint32_t), GL_STREAM_DRAW);
    gl_.BindVertexArray(0);
}

void MeshPass::draw(std::size_t first, std::size_t count, bool translucent) const {
    if (!count) return;
    gl_.Enable(GL_CULL_FACE);  // GL's default: cull clockwise (back) faces
    gl_.BindVertexArray(translucent ? translucent_buffers_.vao() : buffers_.vao());
    gl_.DrawElements(GL_TRIANGLES, GLsizei(count), GL_UNSIGNED_INT, (void*)(first * sizeof(std::uint32_t)));
    gl_.BindVertexArray(0);
    gl_.Disable(GL_CULL_FACE);
}

void MeshPass::draw_opaque() const { draw(0, opaque_count_); }
void MeshPass::draw_translucent(const Translucent& mesh) const { draw(mesh.first, mesh.count, true); }

}  // namespace m3055
