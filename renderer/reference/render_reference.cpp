// The whole reference image: one exact ray per pixel centre (docs/spec.md#3-geometry), the
// nearest opaque front face (or the background), then the translucent front
// faces in front of it composited back to front (docs/spec.md#42-translucent, Fig. 9),
// every point lit with shadows and area lights (reference/lit_point.h).
#include "reference/reference.h"
#include "reference/hooks.h"

#include "models/model_spec.h"

#include "reference/mesh_hits.h"
#include "reference/scene_bvh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <thread>

namespace m3055::ref {

namespace {

struct Hit {
    double t;
    int object;
    std::uint32_t part = 0;   // meshes: the triangle's smooth piece (geometry/mesh.h)
    std::uint32_t group = 0;  // meshes from files: the triangle's group (its material: material_of)
    dvec3 N = dvec3(0.0);   // meshes: the interpolated normal
};

// Every front-face hit of the ray, nearest first (ties by object index, so the
// order never depends on the sort's whims). The meshes are the scene's, made
// once (reference/scene_bvh.h).
std::vector<Hit> all_hits(const Scene& scene, const SceneBvh& bvh, const Ray& ray) {
    std::vector<Hit> hits;
    for (int i = 0; i < int(scene.objects.size()); ++i) {
        if (const MeshIntersector* mesh = bvh.mesh(std::size_t(i))) {
            // A mesh's own bounding sphere first: most rays miss most meshes.
            const Object& object = scene.objects[i];
            const double reach = geometry::bounding_radius(object) * (1 + 1e-9);
            const dvec3 oc = ray.origin - object.center;
            const double b = glm::dot(oc, ray.dir);
            if (glm::dot(oc, oc) > reach * reach && (b > 0 || glm::dot(oc - b * ray.dir, oc - b * ray.dir) > reach * reach))
                continue;
            for (const MeshHit& hit : mesh->intersect_all(ray)) hits.push_back({hit.t, i, hit.part, hit.group, hit.N});
            continue;
        }
        double t = 0.0;
        if (intersect_sphere(ray, scene.objects[i].center, scene.objects[i].radius, &t))
            hits.push_back({t, i});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
        return a.t != b.t ? a.t < b.t : a.object < b.object;
    });
    return hits;
}

// A 64-bit signature of the SET of objects hit (splitmix64 over the sorted
// indices); 0 only when nothing is hit.
std::uint64_t coverage_signature(std::vector<Hit> hits) {
    if (hits.empty()) return 0;
    std::vector<std::uint64_t> ids;  // object and part: a mesh's creases separate pixels like silhouettes
    for (const Hit& h : hits) ids.push_back(std::uint64_t(h.object) << 32 | h.part);
    std::sort(ids.begin(), ids.end());
    std::uint64_t sig = 0x9e3779b97f4a7c15ULL;
    for (std::uint64_t id : ids) {
        std::uint64_t z = sig + id + 0x9e3779b97f4a7c15ULL;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        sig = z ^ (z >> 31);
    }
    return sig == 0 ? 1 : sig;
}

// docs/spec.md#3-geometry: N = (P - C) / radius (normalized again for rounding), V = -ray direction.
// Meshes: P on the triangle, N the interpolated normal of the hit.
SurfacePoint surface_point(const Object& object, const Ray& ray, const Hit& hit) {
    const double t = hit.t;
    SurfacePoint point;
    point.P = ray.origin + t * ray.dir;
    point.N = object.shape == Shape::sphere ? glm::normalize((point.P - object.center) / object.radius) : hit.N;
    point.V = -ray.dir;
    return point;
}

dvec3 shade_pixel(const Scene& scene, const Ray& ray, const std::vector<Hit>& hits, const LightingOptions& options) {
    // The nearest opaque hit, or the background.
    dvec3 color = scene.background;
    double t_opaque = std::numeric_limits<double>::infinity();
    for (const Hit& hit : hits) {
        const Object& object = scene.objects[hit.object];
        const Material& material = material_of(object, hit.group);
        if (is_translucent(material)) continue;
        color = shade_opaque(material, scene.lights, surface_point(object, ray, hit), scene.ambient, options);
        t_opaque = hit.t;
        break;
    }
    // Translucent front faces in front of it, farthest first: C = color + T * C_behind.
    for (auto it = hits.rbegin(); it != hits.rend(); ++it) {
        const Object& object = scene.objects[it->object];
        const Material& material = material_of(object, it->group);
        if (!is_translucent(material) || !(it->t < t_opaque)) continue;
        const TranslucentShade shade =
            shade_translucent_model(material, scene.lights, surface_point(object, ray, *it), options);
        color = shade.color + shade.transmittance * color;
    }
    return color;
}

}  // namespace

ReferenceImage render_reference(const Scene& scene) { return render_reference(scene, AreaQuadrature{}); }

ReferenceImage render_reference(const Scene& scene, const AreaQuadrature& quadrature, AreaStats* stats) {
    return render_reference(scene, quadrature, stats, {});
}

ReferenceImage render_reference(const Scene& scene, const AreaQuadrature& quadrature, AreaStats* stats,
                                const std::function<void()>& row_done) {
    ReferenceImage image;
    image.width = scene.display.width;
    image.height = scene.display.height;
    image.rgb.assign(std::size_t(image.width) * image.height * 3, 0.0);
    image.coverage.assign(std::size_t(image.width) * image.height, 0);
    const SceneBvh bvh(scene);
    // Each thread takes the next row; every pixel is computed alone, so the image is the same for any count.
    const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
    std::vector<AreaStats> thread_stats(static_cast<std::size_t>(threads));
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
    std::atomic<int> next_row{0};
    std::mutex row_done_lock;
    const auto work = [&](int k) {
        try {
            const LightingOptions options{&bvh, quadrature, stats ? &thread_stats[std::size_t(k)] : nullptr};
            for (int y = next_row++; y < image.height; y = next_row++) {
                for (int x = 0; x < image.width; ++x) {
                    const Ray ray = camera_ray(scene.camera, image.width, image.height, x, y);
                    const std::vector<Hit> hits = all_hits(scene, bvh, ray);
                    const dvec3 c = shade_pixel(scene, ray, hits, options);
                    const std::size_t i = std::size_t(y) * image.width + x;
                    image.rgb[3 * i + 0] = c.r;
                    image.rgb[3 * i + 1] = c.g;
                    image.rgb[3 * i + 2] = c.b;
                    image.coverage[i] = coverage_signature(hits);
                }
                if (row_done) {
                    const std::lock_guard<std::mutex> lock(row_done_lock);
                    row_done();
                }
            }
        } catch (...) {
            errors[std::size_t(k)] = std::current_exception();
            next_row = image.height;  // the others stop too
        }
    };
    std::vector<std::thread> pool;
    for (int k = 1; k < threads; ++k) pool.emplace_back(work, k);
    work(0);
    for (std::thread& thread : pool) thread.join();
    for (const std::exception_ptr& error : errors)
        if (error) std::rethrow_exception(error);
    if (stats)
        for (const AreaStats& s : thread_stats) {
            stats->integrals += s.integrals;
            stats->closed += s.closed;
            stats->cells += s.cells;
            stats->nodes += s.nodes;
            stats->rays += s.rays;
            stats->unconverged += s.unconverged;
            stats->worst_error = std::max(stats->worst_error, s.worst_error);
        }
    return image;
}

bool is_interior(const ReferenceImage& image, int x, int y) {
    const std::uint64_t own = image.coverage[std::size_t(y) * image.width + x];
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= image.width || ny >= image.height) continue;
            if (image.coverage[std::size_t(ny) * image.width + nx] != own) return false;
        }
    }
    return true;
}

}  // namespace m3055::ref
