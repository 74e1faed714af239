// Shadows (docs/spec.md#75-area-lights-the-sky-and-shadows): whether anything lies
// between a shaded point and a light. Every object blocks: spheres exactly,
// the meshes' triangles from both sides (planes, cubes, cylinders, tori, the
// same triangles the mesh pass draws). They come as one RGBA32F texture
// (renderer/passes/occluders.h): a bounding-volume hierarchy, two texels a
// node, then the primitives, three texels each. C++ twin: ref::SceneBvh, the
// reference's exact visibility in double.
//
// Node n (texels 2n, 2n + 1): (lo, leaf), (hi, skip). The nodes are in
// depth-first order, so the walk needs no stack (llvmpipe's per-lane stacks
// are slow): a node whose box the ray meets goes on to n + 1 (its first
// child, or the next node after a leaf); one it misses, and a leaf once its
// primitives are tested, go on to `skip`, the next node after its subtree
// (skip = the node count ends the walk). leaf = 4 first + count - 1 for a
// leaf of `count` (1 to 4) primitives from primitive `first`; -1 for an inner node.
// Primitive p (texels u_occluder_primitives + 3p ...): a triangle (v0, 0),
// (v1, 0), (v2, 0), or a sphere (centre, 1), (radius, 0, 0, 0), unused.
//
// The ray leaves P + eps N, eps = 1e-4 max(1, |P|_inf): P comes out of
// float arithmetic to within ~1e-6 |P| and must not shadow itself; the
// reference, in double, offsets by 1e-9. Geometry within eps of P does not
// block (a contact, a sphere resting on a plane, differs there only).

uniform sampler2D u_occluders;
uniform int u_occluder_width;       // texels a row
uniform int u_occluder_primitives;  // first texel of the primitives; 0: no occluders at all

vec4 occluder_texel(int index) {
    return texelFetch(u_occluders, ivec2(index % u_occluder_width, index / u_occluder_width), 0);
}

// Whether the ray o + t d, t in (0, t_max), meets the box [lo, hi] (inv = 1 / d).
bool ray_meets_box(vec3 o, vec3 inv, vec3 lo, vec3 hi, float t_max) {
    vec3 t0 = (lo - o) * inv, t1 = (hi - o) * inv;
    vec3 near = min(t0, t1), far = max(t0, t1);
    float enter = max(max(near.x, near.y), max(near.z, 0.0));
    float leave = min(min(far.x, far.y), min(far.z, t_max));
    return enter <= leave;
}

// Moller-Trumbore, both sides: whether the ray meets the triangle for t in (0, t_max).
bool ray_meets_triangle(vec3 o, vec3 d, vec3 v0, vec3 v1, vec3 v2, float t_max) {
    vec3 e1 = v1 - v0, e2 = v2 - v0;
    vec3 p = cross(d, e2);
    float det = dot(e1, p);
    if (det == 0.0) return false;
    float inv_det = 1.0 / det;
    vec3 s = o - v0;
    float u = dot(s, p) * inv_det;
    if (u < 0.0 || u > 1.0) return false;
    vec3 q = cross(s, e1);
    float v = dot(d, q) * inv_det;
    if (v < 0.0 || u + v > 1.0) return false;
    float t = dot(e2, q) * inv_det;
    return t > 0.0 && t < t_max;
}

// Whether the ray (unit d) crosses the sphere's surface for t in (0, t_max).
// The line's squared distance from the centre comes from q = oc - b d,
// without the cancellation of b^2 - (oc.oc - r^2) (as intersect_sphere).
bool ray_meets_sphere(vec3 o, vec3 d, vec3 centre, float radius, float t_max) {
    vec3 oc = o - centre;
    float b = dot(oc, d);
    vec3 q = oc - b * d;
    float h2 = radius * radius - dot(q, q);
    if (h2 < 0.0) return false;
    float h = sqrt(h2);
    float near_t = -b - h, far_t = -b + h;
    return (near_t > 0.0 && near_t < t_max) || (far_t > 0.0 && far_t < t_max);
}

bool primitive_blocks(int p, vec3 o, vec3 d, float t_max) {
    int at = u_occluder_primitives + 3 * p;
    vec4 a = occluder_texel(at);
    if (a.w > 0.5) return ray_meets_sphere(o, d, a.xyz, occluder_texel(at + 1).x, t_max);
    return ray_meets_triangle(o, d, a.xyz, occluder_texel(at + 1).xyz, occluder_texel(at + 2).xyz, t_max);
}

// Where a shadow ray from P (unit normal N) starts: P + eps N (above).
vec3 shadow_ray_origin(vec3 P, vec3 N) {
    float eps = 1e-4 * max(1.0, max(abs(P.x), max(abs(P.y), abs(P.z))));
    return P + eps * N;
}

// Whether anything blocks the way from P (unit normal N) along unit L for
// `distance` (< 0: to infinity).
bool occluded(vec3 P, vec3 N, vec3 L, float distance) {
    if (u_occluder_primitives == 0) return false;
    vec3 o = shadow_ray_origin(P, N);
    float t_max = distance < 0.0 ? 3.4e38 : distance;
    vec3 safe = mix(L, sign(L) * 1e-30 + L, lessThan(abs(L), vec3(1e-30)));
    vec3 inv = 1.0 / safe;
    int end = u_occluder_primitives / 2;  // the node count
    for (int node = 0; node < end;) {
        vec4 lo = occluder_texel(2 * node), hi = occluder_texel(2 * node + 1);
        if (!ray_meets_box(o, inv, lo.xyz, hi.xyz, t_max)) {
            node = int(hi.w);
            continue;
        }
        if (lo.w < 0.0) {
            ++node;
            continue;
        }
        int leaf = int(lo.w), first = leaf / 4, count = leaf % 4 + 1;
        for (int p = first; p < first + count; ++p)
            if (primitive_blocks(p, o, L, t_max)) return true;
        node = int(hi.w);
    }
    return false;
}
