// The meshes of the non-sphere shapes (geometry/mesh.h) on the GPU, drawn
// with glsl/passes/mesh.{vert,frag} by the Renderer in its opaque pass (one
// batch) and its translucent pass (one draw per mesh, interleaved with the
// spheres back to front). The opaque batch is built and uploaded again only
// when its meshes change (a frame that moves the camera or edits a material's
// values reuses it: a model of a million triangles is not rebuilt each
// frame); the translucent meshes, sorted from the eye, every frame. Each
// vertex carries its material record (passes/material_slots.h): a mesh from
// a file has one a group, its opaque groups drawn in the opaque batch and its
// translucent ones with the translucent meshes.
#pragma once

#include "gl/gl_api.h"
#include "gl/indexed_vertex_array.h"
#include "passes/camera_frame.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace m3055 {

class MeshPass {
public:
    explicit MeshPass(const GlApi& gl);

    // A translucent mesh in draw order terms: `key` sorts like the spheres'
    // far_to_near_key (larger = farther), see far_to_near_mesh_key.
    struct Translucent {
        double key;
        std::size_t first, count;  // its range in the index buffer
        const Object* object;
    };

    // Builds and uploads every non-sphere object's mesh: opaque ones in one
    // batch (unless the last frame's holds the same meshes); each translucent
    // one with its triangles sorted far to near.
    void prepare(const Scene& scene, const CameraFrame& frame);
    // Whether the last prepare() reused the opaque batch (tests, m3055 bench).
    bool reused_opaque() const { return reused_opaque_; }

    const std::vector<const Object*>& opaque_objects() const { return opaque_objects_; }
    // Each opaque mesh's range of the index buffer, in draw order (draw_opaque
    // draws them all at once; the Renderer draws them in chunks).
    struct Range {
        std::size_t first, count;
        const Object* object;
    };
    const std::vector<Range>& opaque_ranges() const { return opaque_ranges_; }
    const std::vector<const Object*>& translucent_objects() const { return translucent_objects_; }
    const std::vector<Translucent>& translucent() const { return translucent_; }

    // Draw with the program in use (camera, lights and materials already set).
    // Back faces are culled: only front faces are shaded (docs/spec.md#3-geometry).
    void draw_opaque() const;
    void draw_translucent(const Translucent& mesh) const;
    // Any part of the opaque batch's index buffer (or the translucent
    // meshes'), e.g. a chunk of the ranges above.
    void draw(std::size_t first, std::size_t count, bool translucent = false) const;

private:
    // What makes an opaque batch: each mesh's shape, placement, model and
    // material records, and which of its groups are opaque.
    struct MeshKey {
        std::size_t object;
        Shape shape;
        dvec3 center, axis, rotation_deg;
        double radius, size, height, major_radius, minor_radius;
        bool capped;
        int segments;
        std::shared_ptr<const model_file::Model> model;  // held, so its address names it alone
        std::vector<bool> opaque_groups;
        std::uint32_t more_records;
        bool operator==(const MeshKey& other) const;
    };

    const GlApi& gl_;
    IndexedVertexArray buffers_, translucent_buffers_;
    std::vector<MeshKey> opaque_key_;
    struct OpaqueRange {
        std::size_t first, count, object;
    };
    std::vector<OpaqueRange> opaque_layout_;
    bool reused_opaque_ = false;
    std::size_t opaque_count_ = 0;
    std::vector<const Object*> opaque_objects_, translucent_objects_;
    std::vector<Translucent> translucent_;
    std::vector<Range> opaque_ranges_;
};

// Back-to-front key of a translucent mesh, comparable with the spheres' power
// key: perspective |eye - center|^2 (the power of a sphere of radius 0),
// orthographic the centre's depth along f. Meshes are not exactly sortable
// (docs/shapes.md): this is exact for disjoint convex meshes only when their
// centres order them.
double far_to_near_mesh_key(const CameraFrame& frame, const Object& object);

}  // namespace m3055
