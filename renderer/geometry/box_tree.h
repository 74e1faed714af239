// A bounding-volume hierarchy over boxes: the shadow rays' walk through the
// scene on the GPU (passes/occluders.h, glsl/common/shadows.glsl). Built by
// median splits of the boxes' centres along the widest axis (every level
// halves the primitives, so the depth is about log2 of their number and the
// build O(n log n): a million triangles in well under a second).
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace m3055::geometry {

struct BoxTree {
    // Nodes in depth-first order: an inner node's first child is the next
    // node, its second `second`; a leaf holds primitives order[first ..
    // first + count).
    struct Node {
        dvec3 lo, hi;
        std::uint32_t first = 0;   // leaf: first entry of `order`
        std::uint32_t count = 0;   // leaf: primitives (> 0); inner: 0
        std::uint32_t second = 0;  // inner: the second child
    };
    std::vector<Node> nodes;
    std::vector<std::uint32_t> order;  // primitive indices, leaf after leaf
    int depth = 0;                     // of the deepest leaf (the root's is 0)
};

// The tree over boxes [lo[i], hi[i]]: leaves of at most `leaf_size`
// primitives, except at `max_depth`, where a node stays a leaf with all of
// its own. Every split halves, so below max_depth the depth is at most
// log2(n / leaf_size) + 1. No primitives: no nodes.
BoxTree build_box_tree(const std::vector<dvec3>& lo, const std::vector<dvec3>& hi, int leaf_size, int max_depth);

}  // namespace m3055::geometry
