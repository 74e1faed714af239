#include "geometry/box_tree.h"

#include <glm/common.hpp>

#include <algorithm>

namespace m3055::geometry {
namespace {

struct Builder {
    const std::vector<dvec3>& lo;
    const std::vector<dvec3>& hi;
    int leaf_size, max_depth;
    BoxTree tree;

    dvec3 centre(std::uint32_t i) const { return 0.5 * (lo[i] + hi[i]); }

    // The node over order[begin, end) at `depth`; returns its index.
    std::uint32_t build(std::uint32_t begin, std::uint32_t end, int depth) {
        const std::uint32_t index = std::uint32_t(tree.nodes.size());
        tree.nodes.emplace_back();
        dvec3 box_lo = lo[tree.order[begin]], box_hi = hi[tree.order[begin]];
        dvec3 c_lo = centre(tree.order[begin]), c_hi = c_lo;
        for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint32_t i = tree.order[k];
            box_lo = glm::min(box_lo, lo[i]);
            box_hi = glm::max(box_hi, hi[i]);
            c_lo = glm::min(c_lo, centre(i));
            c_hi = glm::max(c_hi, centre(i));
        }
        tree.nodes[index].lo = box_lo;
        tree.nodes[index].hi = box_hi;
        tree.depth = std::max(tree.depth, depth);
        const dvec3 extent = c_hi - c_lo;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
        if (end - begin <= std::uint32_t(leaf_size) || depth >= max_depth) {
            tree.nodes[index].first = begin;
            tree.nodes[index].count = end - begin;
            return index;
        }
        const std::uint32_t mid = begin + (end - begin) / 2;
        if (extent[axis] > 0.0)  // else every centre is the same: any halves do
            std::nth_element(tree.order.begin() + begin, tree.order.begin() + mid, tree.order.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) { return centre(a)[axis] < centre(b)[axis]; });
        build(begin, mid, depth + 1);
        const std::uint32_t second = build(mid, end, depth + 1);
        tree.nodes[index].second = second;
        return index;
    }
};

}  // namespace

BoxTree build_box_tree(const std::vector<dvec3>& lo, const std::vector<dvec3>& hi, int leaf_size, int max_depth) {
    Builder builder{lo, hi, std::max(leaf_size, 1), std::max(max_depth, 0), {}};
    if (lo.empty()) return {};
    builder.tree.order.resize(lo.size());
    for (std::uint32_t i = 0; i < lo.size(); ++i) builder.tree.order[i] = i;
    builder.tree.nodes.reserve(2 * lo.size() / std::size_t(builder.leaf_size) + 1);
    builder.build(0, std::uint32_t(lo.size()), 0);
    return std::move(builder.tree);
}

}  // namespace m3055::geometry
