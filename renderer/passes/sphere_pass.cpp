#include "passes/sphere_pass.h"

#include "models/model_spec.h"
#include "passes/sphere_bounds.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstddef>

namespace m3055 {

// The power of the eye with respect to the sphere, |eye - c|^2 - r^2. For
// disjoint spheres the radical plane separates them, and the eye is on the
// side of the sphere with the smaller power, so this order is exact per pixel
// (sorting centres by distance is not, for unequal radii). Orthographic: the
// eye is at infinity along -f, where the order is by the centres' depth along f.
double far_to_near_sphere_key(const CameraFrame& frame, const Object& object) {
    const dvec3 d = object.center - frame.position;
    if (frame.projection == Projection::orthographic) return glm::dot(d, frame.forward);
    return glm::dot(d, d) - object.radius * object.radius;
}

SphereSets sort_spheres(const Scene& scene, const CameraFrame& frame) {
    SphereSets sets;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const Object& object = scene.objects[i];
        if (object.shape != Shape::sphere) continue;  // a mesh: MeshPass
        auto rect = sphere_ndc_rect(frame, object.center, object.radius);
        if (!rect) continue;
        SphereInstance instance{
            {float(object.center.x), float(object.center.y), float(object.center.z), float(object.radius)},
            {(*rect)[0], (*rect)[1], (*rect)[2], (*rect)[3]},
            int(i)};
        if (is_translucent(object.material)) {
            sets.translucent.emplace_back(far_to_near_sphere_key(frame, object), instance);
            sets.translucent_objects.push_back(&object);
        } else {
            sets.opaque.push_back(instance);
            sets.opaque_objects.push_back(&object);
        }
    }
    std::stable_sort(sets.translucent.begin(), sets.translucent.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    return sets;
}

SpherePass::SpherePass(const GlApi& gl) : gl_(gl), instance_buffer_(gl), vao_(gl) {
    gl_.BindVertexArray(vao_.id());
    gl_.BindBuffer(GL_ARRAY_BUFFER, instance_buffer_.id());
    for (unsigned attribute = 0; attribute < 3; ++attribute) {
        gl_.EnableVertexAttribArray(attribute);
        gl_.VertexAttribDivisor(attribute, 1);
    }
    point_instances(0);
    gl_.BindVertexArray(0);
}

// The VAO's attributes start at instance `first` of the instance buffer
// (bound to GL_ARRAY_BUFFER): chunked draws have no base instance in GL 3.3.
void SpherePass::point_instances(std::size_t first) {
    const GLsizei stride = sizeof(SphereInstance);
    const std::size_t base = first * sizeof(SphereInstance);
    gl_.VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride, (void*)(base + offsetof(SphereInstance, sphere)));
    gl_.VertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, (void*)(base + offsetof(SphereInstance, rect)));
    gl_.VertexAttribIPointer(2, 1, GL_INT, stride, (void*)(base + offsetof(SphereInstance, material)));
}

struct SpherePass::Rewind {  // the next draw starts at instance 0 again, even after a RenderTimeout
    SpherePass& pass;
    ~Rewind() { pass.point_instances(0); }
};

// With the two-pass blend, in groups of consecutive spheres whose quads, one
// pixel wider, do not overlap: no pixel is covered twice in a group (a
// sphere's quad covers a pixel once), so a multiply and an add draw per group
// are exact without the stencil's layers, whose cost grows with the overlap.
// A group is at most kMaxGroup spheres, which bounds the overlap tests.
void SpherePass::draw_instances(const std::vector<SphereInstance>& instances, std::size_t first, std::size_t count,
                                TranslucentBlender* two_pass, unsigned program, int width, int height) {
    if (!two_pass) {
        point_instances(first);
        gl_.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(count));
        return;
    }
    constexpr std::size_t kMaxGroup = 256;
    const float margin_x = 2.0f / float(width), margin_y = 2.0f / float(height);
    auto apart = [&](const float* a, const float* b) {  // NDC rectangles {x0, y0, x1, y1}
        return a[2] + margin_x < b[0] || b[2] + margin_x < a[0] || a[3] + margin_y < b[1] || b[3] + margin_y < a[1];
    };
    for (std::size_t start = first, end; start < first + count; start = end) {
        for (end = start + 1; end < first + count && end - start < kMaxGroup; ++end) {
            bool overlaps = false;
            for (std::size_t i = start; i < end && !overlaps; ++i)
                overlaps = !apart(instances[i].rect, instances[end].rect);
            if (overlaps) break;
        }
        point_instances(start);
        const GLsizei n = GLsizei(end - start);
        two_pass->draw_two_pass(program, [&] { gl_.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, n); }, true);
    }
}

void SpherePass::draw(const std::vector<SphereInstance>& instances, ChunkedDraws* chunks, std::size_t lights,
                      TranslucentBlender* two_pass, unsigned program, int width, int height) {
    if (instances.empty()) return;
    gl_.BindVertexArray(vao_.id());
    gl_.BindBuffer(GL_ARRAY_BUFFER, instance_buffer_.id());
    gl_.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(instances.size() * sizeof(SphereInstance)), instances.data(),
                   GL_STREAM_DRAW);
    if (!chunks && !two_pass) return gl_.DrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(instances.size()));
    const Rewind rewind{*this};
    if (!chunks) return draw_instances(instances, 0, instances.size(), two_pass, program, width, height);
    std::vector<DrawSpan> spans;
    for (std::size_t i = 0; i < instances.size(); ++i)
        spans.push_back(chunks->span_of(i, 1, 1, instances[i].rect, lights));
    chunks->run(plan_chunks(spans, kChunkWork, 1), [&](std::size_t first, std::size_t count) {
        draw_instances(instances, first, count, two_pass, program, width, height);
    });
}

}  // namespace m3055
