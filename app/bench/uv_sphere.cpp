#include "uv_sphere.h"

#include <cmath>
#include <stdexcept>

namespace m3055::bench {

UvSphere make_uv_sphere(int slices, int stacks) {
    if (slices < 3 || stacks < 2) throw std::invalid_argument("a UV sphere needs >= 3 slices and >= 2 stacks");
    const double pi = 3.14159265358979323846;
    UvSphere mesh;
    // Vertex (i, j): stack i from the north pole (theta = 0) to the south, slice j
    // around the y axis; the seam column j = slices repeats j = 0.
    for (int i = 0; i <= stacks; ++i) {
        const double theta = pi * i / stacks;
        for (int j = 0; j <= slices; ++j) {
            const double phi = 2.0 * pi * j / slices;
            mesh.positions.push_back(float(std::sin(theta) * std::cos(phi)));
            mesh.positions.push_back(float(std::cos(theta)));
            mesh.positions.push_back(float(-std::sin(theta) * std::sin(phi)));
        }
    }
    auto index = [&](int i, int j) { return std::uint32_t(i * (slices + 1) + j); };
    for (int i = 0; i < stacks; ++i) {
        for (int j = 0; j < slices; ++j) {
            const std::uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
            // Counter-clockwise from outside: down the stack, then along phi.
            if (i != 0) mesh.indices.insert(mesh.indices.end(), {a, b, d});  // the north cap has no a-d edge
            if (i != stacks - 1) mesh.indices.insert(mesh.indices.end(), {d, b, c});
        }
    }
    return mesh;
}

}  // namespace m3055::bench
