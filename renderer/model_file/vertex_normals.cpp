#include "model_file/vertex_normals.h"

#include "model_file/model_limits.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace m3055::model_file {

namespace {

bool finite(const dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

struct UnionFind {
    std::vector<std::uint32_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::uint32_t a, std::uint32_t b) {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

// The corners at each position: corners_at[offset[p] .. offset[p + 1]).
struct CornersAt {
    std::vector<std::uint32_t> offset, corners;
    CornersAt(const std::vector<Corner>& all, std::size_t positions) : offset(positions + 1, 0), corners(all.size()) {
        for (const Corner& c : all) ++offset[c.position + 1];
        for (std::size_t p = 0; p < positions; ++p) offset[p + 1] += offset[p];
        std::vector<std::uint32_t> next(offset.begin(), offset.end() - 1);
        for (std::uint32_t i = 0; i < all.size(); ++i) corners[next[all[i].position]++] = i;
    }
};

// The angle of triangle t's corner k.
double corner_angle(const std::vector<dvec3>& positions, const std::vector<Corner>& corners, std::size_t t, int k) {
    const dvec3& a = positions[corners[3 * t + k].position];
    const dvec3 e1 = glm::normalize(positions[corners[3 * t + (k + 1) % 3].position] - a);
    const dvec3 e2 = glm::normalize(positions[corners[3 * t + (k + 2) % 3].position] - a);
    return std::acos(std::clamp(glm::dot(e1, e2), -1.0, 1.0));
}

// Generated normals for the corners without one: at each position, the faces
// joined through shared edges whose normals are within the crease angle are
// one smooth fan; a corner's normal is its fan's angle-weighted face normal.
// `key` gets a number per fan (above the file's normal indices).
void generate_normals(const Soup& soup, const std::vector<dvec3>& face, const CornersAt& at,
                      std::vector<dvec3>& normal, std::vector<std::int64_t>& key) {
    const double cos_crease = std::cos(kCreaseAngleDeg * 3.14159265358979323846 / 180.0);
    std::int64_t next_key = std::int64_t(soup.normals.size());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;  // (the other end, local corner)
    for (std::size_t p = 0; p + 1 < at.offset.size(); ++p) {
        const std::uint32_t begin = at.offset[p], end = at.offset[p + 1];
        bool needed = false;
        for (std::uint32_t i = begin; i < end && !needed; ++i) needed = key[at.corners[i]] < 0;
        if (!needed) continue;
        const std::uint32_t count = end - begin;
        edges.clear();
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::uint32_t c = at.corners[begin + i];
            const std::size_t t = c / 3;
            const int k = int(c % 3);
            edges.push_back({soup.corners[3 * t + (k + 1) % 3].position, i});
            edges.push_back({soup.corners[3 * t + (k + 2) % 3].position, i});
        }
        std::sort(edges.begin(), edges.end());
        UnionFind fans(count);
        for (std::size_t e = 0; e < edges.size();) {
            std::size_t f = e + 1;
            while (f < edges.size() && edges[f].first == edges[e].first) ++f;
            for (std::size_t a = e; a < f; ++a)
                for (std::size_t b = a + 1; b < f && b < a + 8; ++b) {  // an edge has two faces; more is bounded
                    const std::uint32_t ta = at.corners[begin + edges[a].second] / 3;
                    const std::uint32_t tb = at.corners[begin + edges[b].second] / 3;
                    if (glm::dot(face[ta], face[tb]) >= cos_crease) fans.join(edges[a].second, edges[b].second);
                }
            e = f;
        }
        std::vector<dvec3> sum(count, dvec3(0.0));
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::uint32_t c = at.corners[begin + i];
            sum[fans.find(i)] += corner_angle(soup.positions, soup.corners, c / 3, int(c % 3)) * face[c / 3];
        }
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::uint32_t c = at.corners[begin + i];
            if (key[c] >= 0) continue;
            const std::uint32_t root = fans.find(i);
            const dvec3 n = sum[root];
            const double length = glm::length(n);
            normal[c] = length > 0 && std::isfinite(length) ? n / length : face[c / 3];
            key[c] = next_key + root;
        }
        next_key += count;
    }
}

}  // namespace

Model finish_model(Soup soup) {
    for (const dvec3& p : soup.positions)
        if (!finite(p)) throw ModelError("a vertex position is not a finite number");
    for (const dvec3& n : soup.normals)
        if (!finite(n)) throw ModelError("a normal is not a finite number");

    // Triangles with an area (their unit face normals), the others dropped.
    std::vector<dvec3> face;
    {
        std::vector<Corner> corners;
        std::vector<std::uint32_t> groups;
        for (std::size_t t = 0; t < soup.groups.size(); ++t) {
            const dvec3& a = soup.positions[soup.corners[3 * t].position];
            const dvec3 n = glm::cross(soup.positions[soup.corners[3 * t + 1].position] - a,
                                       soup.positions[soup.corners[3 * t + 2].position] - a);
            const double length = glm::length(n);
            if (!(length > 0) || !std::isfinite(length)) continue;
            face.push_back(n / length);
            corners.insert(corners.end(), soup.corners.begin() + std::ptrdiff_t(3 * t),
                           soup.corners.begin() + std::ptrdiff_t(3 * t + 3));
            groups.push_back(soup.groups[t]);
        }
        soup.corners.swap(corners);
        soup.groups.swap(groups);
    }
    if (soup.groups.empty()) throw ModelError("holds no triangles with an area");

    // Each corner's normal: the file's (normalized), or generated.
    const std::size_t n_corners = soup.corners.size();
    std::vector<dvec3> normal(n_corners);
    std::vector<std::int64_t> key(n_corners, -1);
    for (std::size_t c = 0; c < n_corners; ++c) {
        const std::int64_t given = soup.corners[c].normal;
        if (given < 0) continue;
        const double length = glm::length(soup.normals[std::size_t(given)]);
        if (!(length > 0)) continue;  // a zero normal: made like a missing one
        normal[c] = soup.normals[std::size_t(given)] / length;
        key[c] = given;
    }
    const CornersAt at(soup.corners, soup.positions.size());
    generate_normals(soup, face, at, normal, key);

    // One vertex per (position, normal, group), found per position.
    Model model;
    model.indices.resize(n_corners);
    std::vector<std::uint32_t> order;
    for (std::size_t p = 0; p + 1 < at.offset.size(); ++p) {
        order.assign(at.corners.begin() + at.offset[p], at.corners.begin() + at.offset[p + 1]);
        auto group_of = [&](std::uint32_t c) { return soup.groups[c / 3]; };
        std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            return group_of(a) != group_of(b) ? group_of(a) < group_of(b) : key[a] < key[b];
        });
        for (std::size_t i = 0; i < order.size(); ++i) {
            const std::uint32_t c = order[i];
            if (i == 0 || group_of(c) != group_of(order[i - 1]) || key[c] != key[order[i - 1]]) {
                model.positions.push_back(soup.positions[p]);
                model.normals.push_back(normal[c]);
            }
            model.indices[c] = std::uint32_t(model.positions.size() - 1);
        }
    }
    model.groups = std::move(soup.groups);
    model.materials = std::move(soup.materials);
    model.notes = std::move(soup.notes);

    // Smooth parts: triangles joined through shared vertices.
    const std::size_t triangles = model.groups.size();
    UnionFind vertex_sets(model.positions.size());
    for (std::size_t t = 0; t < triangles; ++t) {
        vertex_sets.join(model.indices[3 * t], model.indices[3 * t + 1]);
        vertex_sets.join(model.indices[3 * t], model.indices[3 * t + 2]);
    }
    model.parts.resize(triangles);
    for (std::size_t t = 0; t < triangles; ++t) model.parts[t] = vertex_sets.find(model.indices[3 * t]);

    model.lo = model.hi = model.positions[0];
    for (const dvec3& p : model.positions) model.lo = glm::min(model.lo, p), model.hi = glm::max(model.hi, p);
    return model;
}

}  // namespace m3055::model_file
