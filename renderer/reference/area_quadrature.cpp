#include "reference/area_quadrature.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <queue>

namespace m3055::ref {

namespace {

// Gauss-Legendre on [0, 1]: 3 points (exact to degree 5) and 2 (degree 3).
const double kGauss3[3] = {0.5 - 0.5 * 0.7745966692414834, 0.5, 0.5 + 0.5 * 0.7745966692414834};
const double kWeight3[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
const double kGauss2[2] = {0.5 - 0.5 * 0.5773502691896258, 0.5 + 0.5 * 0.5773502691896258};

// Cells this small (in their patch's coordinates) are not probed again: the
// probe has found what it can, and a peak left unresolved falls to max_cells.
constexpr double kSmallestProbedCell = 1.0 / 1048576.0;

// Cells a side of each patch to start from with shadows (2 without).
constexpr int kFirstCellsShadowed = 4;

struct Cell {
    int patch;
    double u0, v0, size;  // the square [u0, u0 + size] x [v0, v0 + size]
    std::vector<QuadratureNode> nodes;  // the 3 x 3 rule's, visible ones
    Shade6 value;                       // their share
    double error;                       // the estimate of its error, the largest channel
};

double largest(const Shade6& s) {
    double m = 0.0;
    for (double x : s) m = std::max(m, std::fabs(x));
    return m;
}

double largest_difference(const Shade6& a, const Shade6& b) {
    double m = 0.0;
    for (int c = 0; c < 6; ++c) m = std::max(m, std::fabs(a[c] - b[c]));
    return m;
}

double direction_angle(const dvec3& a, const dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The Gauss-Legendre weight intervals: the share of [0, 1] each node stands
// for, so that a node's box is the part of the cell its weight covers.
const double kBox3[4] = {0.0, 5.0 / 18.0, 13.0 / 18.0, 1.0};
const double kBox2[3] = {0.0, 0.5, 1.0};

// Bisection steps: a shadow's edge found to 2^-12 of a cell's side.
constexpr int kEdgeSteps = 12;

// A point of a cell in its own coordinates, [0, 1]^2.
struct Local {
    double x, y;
};

// An occluder's edge across a cell, as the chord between the two points where
// it crosses the cell's sides: visible where a x + b y + c >= 0. `bulge`: the
// area between the chord and the edge itself, estimated from the edge's
// distance from the chord's middle (a parabola's segment, 2/3 of chord x
// sagitta), in units of the cell's area.
struct Edge {
    double a, b, c;
    double bulge;
    double side(const Local& p) const { return a * p.x + b * p.y + c; }
};

// The area of the box [x0, x1] x [y0, y1] on the visible side of `edge`.
double visible_area(const Edge& edge, double x0, double x1, double y0, double y1) {
    const Local corners[4] = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    std::vector<Local> kept;
    for (int i = 0; i < 4; ++i) {
        const Local& p = corners[i];
        const Local& q = corners[(i + 1) % 4];
        const double sp = edge.side(p), sq = edge.side(q);
        if (sp >= 0.0) kept.push_back(p);
        if ((sp >= 0.0) != (sq >= 0.0)) {
            const double t = sp / (sp - sq);
            kept.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
        }
    }
    double twice = 0.0;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        const Local& p = kept[i];
        const Local& q = kept[(i + 1) % kept.size()];
        twice += p.x * q.y - q.x * p.y;
    }
    return 0.5 * std::fabs(twice);
}

class Integrator {
public:
    Integrator(const std::vector<Patch>& patches, const AreaIntegrand& integrand, AreaStats* stats)
        : patches_(patches), integrand_(integrand), stats_(stats) {}

    void evaluate(Cell& cell) const {
        // The 3 x 3 rule's nodes and the 2 x 2 rule's, unshadowed, and whether each is seen.
        std::vector<QuadratureNode> fine, coarse;
        std::vector<Local> fine_at, coarse_at;
        std::vector<bool> fine_seen, coarse_seen;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) add(cell, {kGauss3[i], kGauss3[j]}, kWeight3[i] * kWeight3[j], fine, fine_at, fine_seen);
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) add(cell, {kGauss2[i], kGauss2[j]}, 0.25, coarse, coarse_at, coarse_seen);
        if (stats_) stats_->nodes += 13;
        double covered = 0.0;  // the cell's solid angle by the 3 x 3 rule, seen or not
        for (const QuadratureNode& node : fine) covered += node.solid_angle;

        const Shadowing shadowing = integrand_.visible ? shadowing_of(cell, fine_seen, coarse_seen)
                                                      : Shadowing{Shadowing::untested, {}};
        if (shadowing.kind == Shadowing::fitted) {
            // The edge's side of each node's box: the nodes' weights times their share of it.
            weigh_by_edge(fine, fine_at, shadowing.edge, kBox3);
            weigh_by_edge(coarse, coarse_at, shadowing.edge, kBox2);
        } else {
            keep_seen(fine, fine_seen);
            keep_seen(coarse, coarse_seen);
        }
        cell.nodes = fine;
        cell.value = share(fine);
        const Shade6 coarse_value = share(coarse);
        cell.error = largest_difference(cell.value, coarse_value);
        if (shadowing.kind != Shadowing::untested && shadowing.kind != Shadowing::uniform) {
            const double open = largest(share(unshadowed(cell)));
            // The chord's error; an edge not fitted: a quarter of the cell, so it is split.
            cell.error += shadowing.kind == Shadowing::fitted ? shadowing.edge.bulge * open : 0.0;
            if (shadowing.kind == Shadowing::tangled) cell.error = std::max(cell.error, 0.25 * open);
        }
        probe_peak(cell, covered, std::max(largest(cell.value), largest(coarse_value)));
    }

private:
    // How an occluder's shadow lies across a cell: none to test, the same
    // everywhere the cell is sampled, one edge from side to side (fitted), or
    // anything else (split until it is one of those).
    struct Shadowing {
        enum Kind { untested, uniform, fitted, tangled } kind;
        Edge edge;
    };

    PatchSample at(const Cell& cell, const Local& p) const {
        return patches_[std::size_t(cell.patch)](cell.u0 + p.x * cell.size, cell.v0 + p.y * cell.size);
    }

    bool seen_at(const Cell& cell, const Local& p) const {
        const PatchSample s = at(cell, p);
        if (stats_) ++stats_->rays;
        return integrand_.visible({s.direction, s.density, s.distance});
    }

    void add(const Cell& cell, const Local& p, double weight, std::vector<QuadratureNode>& nodes,
             std::vector<Local>& where, std::vector<bool>& seen) const {
        const PatchSample s = at(cell, p);
        nodes.push_back({s.direction, s.density * weight * cell.size * cell.size, s.distance});
        where.push_back(p);
        seen.push_back(!integrand_.visible || seen_at(cell, p));
    }

    static void keep_seen(std::vector<QuadratureNode>& nodes, const std::vector<bool>& seen) {
        std::vector<QuadratureNode> kept;
        for (std::size_t i = 0; i < nodes.size(); ++i)
            if (seen[i] && nodes[i].solid_angle > 0.0) kept.push_back(nodes[i]);
        nodes.swap(kept);
    }

    template <std::size_t N>
    static void weigh_by_edge(std::vector<QuadratureNode>& nodes, const std::vector<Local>& where, const Edge& edge,
                              const double (&box)[N]) {
        std::vector<QuadratureNode> kept;
        for (std::size_t k = 0; k < nodes.size(); ++k) {
            // The node's box: the weight interval around it on each axis.
            std::size_t i = 0, j = 0;
            while (i + 2 < N && where[k].x > box[i + 1]) ++i;
            while (j + 2 < N && where[k].y > box[j + 1]) ++j;
            const double area = (box[i + 1] - box[i]) * (box[j + 1] - box[j]);
            QuadratureNode node = nodes[k];
            node.solid_angle *= visible_area(edge, box[i], box[i + 1], box[j], box[j + 1]) / area;
            if (node.solid_angle > 0.0) kept.push_back(node);
        }
        nodes.swap(kept);
    }

    std::vector<QuadratureNode> unshadowed(const Cell& cell) const {
        std::vector<QuadratureNode> open;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const PatchSample s = at(cell, {kGauss3[i], kGauss3[j]});
                const double w = s.density * kWeight3[i] * kWeight3[j] * cell.size * cell.size;
                if (w > 0.0) open.push_back({s.direction, w, s.distance});
            }
        return open;
    }

    // The rules' nodes, the cell's corners and the middles of its sides (the
    // edge between nodes that agree is found there: visibility only, no shading).
    Shadowing shadowing_of(const Cell& cell, const std::vector<bool>& fine_seen,
                           const std::vector<bool>& coarse_seen) const {
        const Local corner[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        bool corner_seen[4], middle_seen[4];
        for (int k = 0; k < 4; ++k) {
            corner_seen[k] = seen_at(cell, corner[k]);
            const Local& next = corner[(k + 1) % 4];
            middle_seen[k] = seen_at(cell, {0.5 * (corner[k].x + next.x), 0.5 * (corner[k].y + next.y)});
        }
        bool all = true, any = false;
        for (const std::vector<bool>* seen : {&fine_seen, &coarse_seen})
            for (bool s : *seen) all = all && s, any = any || s;
        for (int k = 0; k < 4; ++k) {
            all = all && corner_seen[k] && middle_seen[k];
            any = any || corner_seen[k] || middle_seen[k];
        }
        if (all || !any) return {Shadowing::uniform, {}};
        const std::optional<Edge> edge = fit_edge(cell, corner, corner_seen, middle_seen, fine_seen, coarse_seen);
        return edge ? Shadowing{Shadowing::fitted, *edge} : Shadowing{Shadowing::tangled, {}};
    }

    // Where visibility changes between p (seen: `p_seen`) and q (not), to kEdgeSteps halvings.
    Local crossing(const Cell& cell, Local p, Local q, bool p_seen) const {
        for (int step = 0; step < kEdgeSteps; ++step) {
            const Local m{0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
            (seen_at(cell, m) == p_seen ? p : q) = m;
        }
        return {0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
    }

    // One edge from side to side: exactly two sides change visibility, once
    // each, the rules' nodes agree with the chord (but within the edge's own
    // bulge of it), and the edge is found across the chord's middle inside the cell.
    std::optional<Edge> fit_edge(const Cell& cell, const Local (&corner)[4], const bool (&corner_seen)[4],
                                 const bool (&middle_seen)[4], const std::vector<bool>& fine_seen,
                                 const std::vector<bool>& coarse_seen) const {
        std::vector<Local> crossings;
        for (int k = 0; k < 4; ++k) {
            const Local& a = corner[k];
            const Local& b = corner[(k + 1) % 4];
            const Local middle{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
            const bool a_seen = corner_seen[k], b_seen = corner_seen[(k + 1) % 4];
            if (a_seen == b_seen) {
                if (middle_seen[k] != a_seen) return std::nullopt;  // in and out again along one side
                continue;
            }
            crossings.push_back(middle_seen[k] == a_seen ? crossing(cell, middle, b, a_seen)
                                                          : crossing(cell, a, middle, a_seen));
        }
        if (crossings.size() != 2) return std::nullopt;
        const Local p = crossings[0], q = crossings[1];
        const double dx = q.x - p.x, dy = q.y - p.y, length = std::hypot(dx, dy);
        if (!(length > 0.0)) return std::nullopt;
        Edge edge{-dy / length, dx / length, 0.0, 0.0};
        edge.c = -(edge.a * p.x + edge.b * p.y);
        for (int k = 0; k < 4; ++k)  // the visible side is the seen corners'
            if (corner_seen[k] != (edge.side(corner[k]) >= 0.0)) {
                edge.a = -edge.a, edge.b = -edge.b, edge.c = -edge.c;
                break;
            }
        // The edge across the chord's middle, along the chord's normal.
        const Local middle{0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
        const bool middle_is_seen = seen_at(cell, middle);
        const double toward = middle_is_seen ? -1.0 : 1.0;  // into the side the middle is not on
        double reach = 0.5;  // within the cell
        for (const double n : {edge.a, edge.b})
            if (n != 0.0) {
                const double from = n == edge.a ? middle.x : middle.y;
                reach = std::min(reach, toward * n > 0.0 ? (1.0 - from) / (toward * n) : from / (-toward * n));
            }
        const Local far{middle.x + toward * reach * edge.a, middle.y + toward * reach * edge.b};
        if (seen_at(cell, far) == middle_is_seen) return std::nullopt;  // it bulges out of the cell
        const Local found = crossing(cell, middle, far, middle_is_seen);
        const double sagitta = std::hypot(found.x - middle.x, found.y - middle.y);
        // And the bisections' own error, half their last step along the chord.
        edge.bulge = 2.0 / 3.0 * sagitta * length + std::ldexp(length, -kEdgeSteps);
        // The nodes on the wrong side of the chord must lie within the bulge.
        const auto agree = [&](const std::vector<bool>& seen, const double* at, int n) {
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const double s = edge.side({at[i], at[j]});
                    if (seen[std::size_t(i * n + j)] != (s >= 0.0) && std::fabs(s) > 2.0 * sagitta + 1.0 / 64.0)
                        return false;
                }
            return true;
        };
        if (!agree(fine_seen, kGauss3, 3) || !agree(coarse_seen, kGauss2, 2)) return std::nullopt;
        return edge;
    }

    Shade6 share(const std::vector<QuadratureNode>& nodes) const {
        return nodes.empty() ? Shade6{} : integrand_.value(nodes);
    }

    // A lobe narrower than the rule's spacing can hide between its nodes: a
    // cell near the peak direction is probed there, as if the whole cell were
    // as bright as its peak, and counts that as its error while it is more
    // than twice what the rules see.
    void probe_peak(Cell& cell, double covered, double seen_value) const {
        if (integrand_.peak == dvec3(0.0) || cell.size < kSmallestProbedCell || !(covered > 0.0)) return;
        const Patch& patch = patches_[std::size_t(cell.patch)];
        const double h = cell.size;
        const dvec3 centre = patch(cell.u0 + 0.5 * h, cell.v0 + 0.5 * h).direction;
        double reach = 0.0;
        for (const auto& [du, dv] : {std::pair{0.0, 0.0}, {h, 0.0}, {0.0, h}, {h, h}})
            reach = std::max(reach, direction_angle(centre, patch(cell.u0 + du, cell.v0 + dv).direction));
        if (direction_angle(centre, integrand_.peak) > 1.5 * reach) return;
        const double probe = largest(integrand_.value({{integrand_.peak, covered, 0.0}}));
        if (stats_) ++stats_->nodes;
        if (probe > 2.0 * seen_value) cell.error = std::max(cell.error, probe);
    }

    const std::vector<Patch>& patches_;
    const AreaIntegrand& integrand_;
    AreaStats* stats_;
};

}  // namespace

std::vector<QuadratureNode> integrate_area(const std::vector<Patch>& patches, const AreaIntegrand& integrand,
                                           const AreaQuadrature& options, AreaStats* stats) {
    const Integrator integrator(patches, integrand, stats);
    std::vector<Cell> cells;
    // Shadows start finer: an edge no node or probe of a cell sees is not refined.
    const int first = integrand.visible ? kFirstCellsShadowed : 2;
    for (int p = 0; p < int(patches.size()); ++p)
        for (int i = 0; i < first; ++i)
            for (int j = 0; j < first; ++j) {
                cells.push_back({p, double(i) / first, double(j) / first, 1.0 / first, {}, {}, 0.0});
                integrator.evaluate(cells.back());
            }
    const auto worse = [&](std::size_t a, std::size_t b) { return cells[a].error < cells[b].error; };
    std::priority_queue<std::size_t, std::vector<std::size_t>, decltype(worse)> queue(worse);
    Shade6 total{};
    double error = 0.0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        queue.push(i);
        for (int c = 0; c < 6; ++c) total[c] += cells[i].value[c];
        error += cells[i].error;
    }
    // The target: the tolerance of the shaded colour's largest channel, or of 1.
    const double tolerance = integrand.visible ? options.shadow_tolerance : options.tolerance;
    const auto target = [&]() {
        Shade6 shaded = integrand.base;
        for (int c = 0; c < 6; ++c) shaded[c] += total[c];
        return tolerance * std::max(1.0, largest(shaded));
    };
    std::size_t live = cells.size();
    while (!queue.empty() && error > target() && int(live) < options.max_cells) {
        const std::size_t worst = queue.top();
        queue.pop();
        const Cell parent = cells[worst];
        for (int c = 0; c < 6; ++c) total[c] -= parent.value[c];
        error -= parent.error;
        cells[worst].nodes.clear();
        cells[worst].nodes.shrink_to_fit();
        cells[worst].value = Shade6{};
        cells[worst].error = 0.0;
        const double h = 0.5 * parent.size;
        for (int i = 0; i < 2; ++i)
            for (int j = 0; j < 2; ++j) {
                Cell child{parent.patch, parent.u0 + h * i, parent.v0 + h * j, h, {}, {}, 0.0};
                integrator.evaluate(child);
                for (int c = 0; c < 6; ++c) total[c] += child.value[c];
                error += child.error;
                cells.push_back(std::move(child));
                queue.push(cells.size() - 1);
            }
        live += 3;
    }
    std::vector<QuadratureNode> nodes;
    double final_error = 0.0;
    while (!queue.empty()) {
        const Cell& cell = cells[queue.top()];
        queue.pop();
        nodes.insert(nodes.end(), cell.nodes.begin(), cell.nodes.end());
        final_error += cell.error;
    }
    if (stats) {
        ++stats->integrals;
        stats->cells += (long long)(live);
        const double relative = final_error / (target() / tolerance);
        stats->worst_error = std::max(stats->worst_error, relative);
        if (final_error > target()) ++stats->unconverged;
    }
    return nodes;
}

}  // namespace m3055::ref
