#include "passes/occluders.h"

#include "geometry/box_tree.h"
#include "geometry/mesh.h"
#include "passes/render_targets.h"
#include "scene/shape_limits.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace m3055 {
namespace {

struct Primitive {
    dvec3 a, b, c;     // a triangle's corners, or a sphere's centre in a
    double radius = -1.0;  // >= 0: a sphere
};

// Boxes grown by a little more than float rounding, so the float box of the
// shader holds its float primitive and a flat box (a plane's) has thickness.
void pad(dvec3& lo, dvec3& hi) {
    const double scale = std::max({1.0, std::fabs(lo.x), std::fabs(lo.y), std::fabs(lo.z), std::fabs(hi.x),
                                   std::fabs(hi.y), std::fabs(hi.z)});
    lo -= dvec3(1e-6 * scale);
    hi += dvec3(1e-6 * scale);
}

void put(std::vector<float>& out, const dvec3& v, double w) {
    out.insert(out.end(), {float(v.x), float(v.y), float(v.z), float(w)});
}

// The geometric fields of every object (materials left out): equal keys, equal occluders.
std::string geometry_key(const Scene& scene) {
    std::string key;
    key.reserve(scene.objects.size() * 128);
    auto add = [&](const void* p, std::size_t n) { key.append(static_cast<const char*>(p), n); };
    for (const Object& o : scene.objects) {
        const int shape = int(o.shape);
        add(&shape, sizeof shape);
        add(&o.center, sizeof o.center);
        add(&o.radius, sizeof o.radius);
        add(&o.axis, sizeof o.axis);
        add(&o.size, sizeof o.size);
        add(&o.rotation_deg, sizeof o.rotation_deg);
        add(&o.height, sizeof o.height);
        add(&o.capped, sizeof o.capped);
        add(&o.major_radius, sizeof o.major_radius);
        add(&o.minor_radius, sizeof o.minor_radius);
        add(&o.segments, sizeof o.segments);
        const void* model = o.model.get();  // a model file's triangles, shared while unchanged
        add(&model, sizeof model);
    }
    return key;
}

}  // namespace

float frame_texel_w(const SkyOccluder& o, int a) {
    return o.shape == SkyOccluderShape::prism && a == 2 ? float(o.segments) : float(o.half_sizes[a]);
}

OccluderTexels pack_occluders(const Scene& scene) {
    std::vector<Primitive> primitives;
    std::vector<dvec3> lo, hi;
    std::vector<SkyOccluder> sky;
    for (const Object& object : scene.objects) {
        if (object.shape == Shape::sphere) {
            primitives.push_back({object.center, {}, {}, object.radius});
            lo.push_back(object.center - dvec3(object.radius));
            hi.push_back(object.center + dvec3(object.radius));
            pad(lo.back(), hi.back());
            SkyOccluder o;
            o.sphere_centre = object.center, o.radius = object.radius;
            o.box_centre = (lo.back() + hi.back()) * 0.5, o.box_half = (hi.back() - lo.back()) * 0.5;
            o.shape = SkyOccluderShape::sphere;
            sky.push_back(o);
            continue;
        }
        const geometry::Mesh mesh = geometry::make_mesh(object);
        dvec3 object_lo(std::numeric_limits<double>::max()), object_hi(-std::numeric_limits<double>::max());
        for (std::size_t t = 0; t < mesh.triangles(); ++t) {
            const dvec3& a = mesh.positions[mesh.indices[3 * t]];
            const dvec3& b = mesh.positions[mesh.indices[3 * t + 1]];
            const dvec3& c = mesh.positions[mesh.indices[3 * t + 2]];
            primitives.push_back({a, b, c, -1.0});
            lo.push_back(glm::min(a, glm::min(b, c)));
            hi.push_back(glm::max(a, glm::max(b, c)));
            pad(lo.back(), hi.back());
            object_lo = glm::min(object_lo, lo.back());
            object_hi = glm::max(object_hi, hi.back());
        }
        if (mesh.triangles() == 0) continue;
        // The box's sphere, grown as the boxes are, so the float cone holds every float triangle.
        const dvec3 centre = (object_lo + object_hi) * 0.5, half = (object_hi - object_lo) * 0.5;
        SkyOccluder o;
        o.sphere_centre = centre, o.radius = glm::length(half) * (1.0 + 1e-6);
        o.box_centre = centre, o.box_half = half;
        o.plane = object.shape == Shape::plane;
        o.normal = object.axis;
        if (object.shape == Shape::cube) {
            // make_cube's frame: the unit axes turned by rotate_xyz, the faces at +- size / 2.
            const dvec3 unit[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
            for (int a = 0; a < 3; ++a) o.axes[a] = geometry::rotate_xyz(unit[a], object.rotation_deg);
            o.half_sizes = dvec3(object.size / 2);
            o.shape = SkyOccluderShape::box;
            o.centre = object.center;
        } else if (object.shape == Shape::plane) {
            // make_plane's square: its edges along the normal's axis frame, no thickness.
            const geometry::AxisFrame frame = geometry::axis_frame(object.axis);
            o.axes[0] = frame.t, o.axes[1] = frame.b, o.axes[2] = frame.a;
            o.half_sizes = dvec3(object.size / 2, object.size / 2, 0.0);
            o.shape = SkyOccluderShape::box;
            o.centre = object.center;
        } else if (object.shape == Shape::cylinder && object.capped) {
            // make_cylinder's prism: its corners at radial(frame, 2 pi k / n) on both rims.
            const geometry::AxisFrame frame = geometry::axis_frame(object.axis);
            o.axes[0] = frame.a, o.axes[1] = frame.t, o.axes[2] = frame.b;
            o.half_sizes = dvec3(object.height / 2, object.radius, object.radius);
            o.segments = segments_of(object);
            o.shape = SkyOccluderShape::prism;
            o.centre = object.center;
        }
        sky.push_back(o);
    }
    OccluderTexels out;
    if (sky.size() <= kMaxSkyOccluders) out.sky = std::move(sky);
    if (primitives.empty()) return out;
    const geometry::BoxTree tree = geometry::build_box_tree(lo, hi, kOccluderLeafSize, kOccluderMaxDepth);
    out.depth = tree.depth;
    out.texels.reserve(4 * (2 * tree.nodes.size() + 3 * primitives.size()));
    // skip: the node after each subtree (the depth-first order's next node past it).
    std::vector<std::uint32_t> skip(tree.nodes.size(), std::uint32_t(tree.nodes.size()));
    for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
        const geometry::BoxTree::Node& node = tree.nodes[n];
        if (node.count) continue;
        skip[n + 1] = node.second;     // the first child's subtree ends where the second begins
        skip[node.second] = skip[n];   // the second child's where its parent's does
    }
    for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
        const geometry::BoxTree::Node& node = tree.nodes[n];
        if (node.count > std::uint32_t(kOccluderLeafSize)) throw std::logic_error("an occluder leaf over 4 primitives");
        put(out.texels, node.lo, node.count ? double(4 * node.first + node.count - 1) : -1.0);
        put(out.texels, node.hi, double(skip[n]));
    }
    out.primitives_at = int(2 * tree.nodes.size());
    for (const std::uint32_t index : tree.order) {
        const Primitive& p = primitives[index];
        if (p.radius >= 0.0) {
            put(out.texels, p.a, 1.0);
            put(out.texels, dvec3(p.radius, 0.0, 0.0), 0.0);
            put(out.texels, dvec3(0.0), 0.0);
        } else {
            put(out.texels, p.a, 0.0);
            put(out.texels, p.b, 0.0);
            put(out.texels, p.c, 0.0);
        }
    }
    return out;
}

OccluderTexture::OccluderTexture(const GlApi& gl) : gl_(gl), texture_(gl) {}

void OccluderTexture::upload(const Scene& scene) {
    std::string key = geometry_key(scene);
    if (uploaded_ && key == key_) return;
    OccluderTexels packed = pack_occluders(scene);
    if (packed.texels.empty()) packed.texels.assign(4, 0.0f);  // never an empty texture
    const std::size_t texels = packed.texels.size() / 4, width = kOccluderTextureWidth;
    const int rows = int((texels + width - 1) / width);
    GLint max_size = 0;
    gl_.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (rows > max_size)
        throw std::runtime_error("the shadows' occluders need " + std::to_string(rows) + " rows of " +
                                 std::to_string(width) + " texels; GL_MAX_TEXTURE_SIZE is " +
                                 std::to_string(max_size));
    packed.texels.resize(std::size_t(rows) * width * 4, 0.0f);
    gl_.ActiveTexture(GL_TEXTURE0 + kOccluderUnit);
    define_texture_2d(gl_, texture_, kRgba32f, kOccluderTextureWidth, rows, packed.texels.data());
    gl_.ActiveTexture(GL_TEXTURE0);
    primitives_at_ = packed.primitives_at;
    sky_ = std::move(packed.sky);
    key_ = std::move(key);
    uploaded_ = true;
}

void OccluderTexture::set_uniforms(unsigned program) const {
    gl_.ActiveTexture(GL_TEXTURE0 + kOccluderUnit);
    gl_.BindTexture(GL_TEXTURE_2D, uploaded_ ? texture_.id() : 0);
    gl_.ActiveTexture(GL_TEXTURE0);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_occluders"), kOccluderUnit);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_occluder_width"), kOccluderTextureWidth);
    gl_.Uniform1i(gl_.GetUniformLocation(program, "u_occluder_primitives"), uploaded_ ? primitives_at_ : 0);
    const GLint count = gl_.GetUniformLocation(program, "u_sky_occluder_count");
    if (count < 0) return;  // a program without a shadowed sky
    const std::size_t n = uploaded_ ? sky_.size() : 0;
    std::vector<float> sphere(4 * kMaxSkyOccluders, 0.0f), centre(sphere), half(sphere), normal(sphere);
    std::vector<float> frame(4 * 4 * kMaxSkyOccluders, 0.0f);
    for (std::size_t k = 0; k < n; ++k) {
        const SkyOccluder& o = sky_[k];
        const float values[4][4] = {
            {float(o.sphere_centre.x), float(o.sphere_centre.y), float(o.sphere_centre.z), float(o.radius)},
            {float(o.box_centre.x), float(o.box_centre.y), float(o.box_centre.z), o.plane ? 1.0f : 0.0f},
            {float(o.box_half.x), float(o.box_half.y), float(o.box_half.z), float(int(o.shape))},
            {float(o.normal.x), float(o.normal.y), float(o.normal.z), 0.0f}};
        std::vector<float>* arrays[4] = {&sphere, &centre, &half, &normal};
        for (int a = 0; a < 4; ++a) std::copy(values[a], values[a] + 4, arrays[a]->begin() + 4 * k);
        for (int a = 0; a < 4; ++a) {  // a box's or prism's three axes (frame_texel_w), then its centre
            const dvec3 v = a < 3 ? o.axes[a] : o.centre;
            const float texel[4] = {float(v.x), float(v.y), float(v.z), a < 3 ? frame_texel_w(o, a) : 0.0f};
            std::copy(texel, texel + 4, frame.begin() + 4 * (4 * k + std::size_t(a)));
        }
    }
    gl_.Uniform1i(count, GLint(n));
    const GLsizei size = GLsizei(kMaxSkyOccluders);
    gl_.Uniform4fv(gl_.GetUniformLocation(program, "u_sky_occluder_sphere"), size, sphere.data());
    gl_.Uniform4fv(gl_.GetUniformLocation(program, "u_sky_occluder_centre"), size, centre.data());
    gl_.Uniform4fv(gl_.GetUniformLocation(program, "u_sky_occluder_half"), size, half.data());
    gl_.Uniform4fv(gl_.GetUniformLocation(program, "u_sky_occluder_normal"), size, normal.data());
    gl_.Uniform4fv(gl_.GetUniformLocation(program, "u_sky_occluder_frame"), 4 * size, frame.data());
}

}  // namespace m3055
