// The shadow rays' hierarchy (geometry/box_tree.h): every primitive in one
// leaf, every box around what it holds, and a depth that grows as log2 n.
#include "geometry/box_tree.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace m3055::geometry {
namespace {

struct Boxes {
    std::vector<dvec3> lo, hi;
};

Boxes random_boxes(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> at(-10.0, 10.0), size(0.0, 0.5);
    Boxes b;
    for (int i = 0; i < n; ++i) {
        const dvec3 lo(at(rng), at(rng), at(rng));
        b.lo.push_back(lo);
        b.hi.push_back(lo + dvec3(size(rng), size(rng), size(rng)));
    }
    return b;
}

bool contains(const BoxTree::Node& node, const dvec3& lo, const dvec3& hi) {
    for (int a = 0; a < 3; ++a)
        if (lo[a] < node.lo[a] || hi[a] > node.hi[a]) return false;
    return true;
}

// Checks node `n`'s subtree and returns the node after it (depth-first order).
std::uint32_t check_subtree(const BoxTree& tree, const Boxes& b, std::uint32_t n, std::vector<int>& seen,
                            std::uint32_t leaf_limit = 4) {
    const BoxTree::Node& node = tree.nodes.at(n);
    if (node.count > 0) {
        EXPECT_LE(node.count, leaf_limit);
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            const std::uint32_t p = tree.order.at(k);
            ++seen.at(p);
            EXPECT_TRUE(contains(node, b.lo[p], b.hi[p])) << "primitive " << p << " outside its leaf";
        }
        return n + 1;
    }
    EXPECT_TRUE(contains(node, tree.nodes.at(n + 1).lo, tree.nodes.at(n + 1).hi));
    const std::uint32_t after_first = check_subtree(tree, b, n + 1, seen, leaf_limit);
    EXPECT_EQ(after_first, node.second) << "the second child follows the first's subtree";
    EXPECT_TRUE(contains(node, tree.nodes.at(node.second).lo, tree.nodes.at(node.second).hi));
    return check_subtree(tree, b, node.second, seen, leaf_limit);
}

TEST(BoxTree, EveryPrimitiveSitsInExactlyOneLeafInsideEveryBoxAboveIt) {
    for (int n : {1, 2, 5, 100, 4097}) {
        const Boxes b = random_boxes(n, 7u + unsigned(n));
        const BoxTree tree = build_box_tree(b.lo, b.hi, 4, 64);
        std::vector<int> seen(std::size_t(n), 0);
        EXPECT_EQ(check_subtree(tree, b, 0, seen), tree.nodes.size());
        for (int p = 0; p < n; ++p) EXPECT_EQ(seen[std::size_t(p)], 1) << "primitive " << p;
    }
}

TEST(BoxTree, HalvingSplitsKeepTheDepthLogarithmic) {
    const Boxes b = random_boxes(100000, 3u);
    const BoxTree tree = build_box_tree(b.lo, b.hi, 4, 64);
    EXPECT_LE(tree.depth, int(std::ceil(std::log2(100000.0 / 4.0))) + 1);
}

TEST(BoxTree, IdenticalBoxesStopAtTheDepthLimit) {
    Boxes b;
    for (int i = 0; i < 64; ++i) {
        b.lo.push_back(dvec3(0.0));
        b.hi.push_back(dvec3(1.0));
    }
    const BoxTree tree = build_box_tree(b.lo, b.hi, 4, 3);
    EXPECT_EQ(tree.depth, 3);
    std::vector<int> seen(64, 0);
    EXPECT_EQ(check_subtree(tree, b, 0, seen, 64 / 8), tree.nodes.size());  // 8 leaves of 8
}

TEST(BoxTree, NoPrimitivesNoNodes) {
    EXPECT_TRUE(build_box_tree({}, {}, 4, 64).nodes.empty());
}

}  // namespace
}  // namespace m3055::geometry
