// The sky's shadow as what the objects take away from it: the integral of
// L r(w) V(w) over the sky is the unshadowed integral (the sky's samples with
// their closed forms, as without a shadow) less the integral of L r(w) over
// the directions some object blocks. That second integral is drawn only where
// objects can be: from a cone about each object's bounding sphere (uniform in
// the cone's solid angle), or, for an object whose bounding sphere holds the
// point, uniformly from the hemisphere about N (not by the cosine: a highlight
// (R.V)^m has no N.L to cancel its 1 / cos near the horizon, where objects
// stand as a floor's point sees them); the techniques combined by the balance
// heuristic (Veach 1997), every sample its own shadow ray. Where the sky's
// samples traced rays over the whole hemisphere, a small or distant object was
// hit by a few of them, and its shadow was noise; drawn from its cone it is hit
// by all of a technique's samples that its silhouette covers (a sphere: every
// one). Unbiased as long as every blocked direction lies in some technique's
// domain: an object is left out only where it cannot block the sky above P
// (a plane through P, a box wholly below N's or the sky's horizon).
// renderer/passes/occluders.h uploads the bounding spheres and boxes of at
// most MAX_SKY_OCCLUDERS objects; with more, u_sky_occluder_count is 0 and the
// sky's samples trace their own rays (common/lights.glsl). The reference
// integrates visibility adaptively (reference/area_quadrature.h): no twin.

#define MAX_SKY_OCCLUDERS 8  // renderer/passes/occluders.h: kMaxSkyOccluders

uniform int u_sky_occluder_count;                         // 0: not drawn this way
uniform vec4 u_sky_occluder_sphere[MAX_SKY_OCCLUDERS];    // bounding sphere: centre, radius
uniform vec4 u_sky_occluder_centre[MAX_SKY_OCCLUDERS];    // the box's centre; w: 1 for a plane
uniform vec4 u_sky_occluder_half[MAX_SKY_OCCLUDERS];      // the box's half extents
uniform vec4 u_sky_occluder_normal[MAX_SKY_OCCLUDERS];    // a plane's unit normal

// Samples of each technique, for the sky's n x n: half as many (a power of two
// for n = 2, 4, 8, 16), so that four objects take as many rays as the n x n
// emitter and n x n lobe samples traced before.
int sky_occluder_samples(int n) {
    return max(n * n / 2, 1);
}

// How technique k draws from P: uniformly in a cone of half-angle cos^-1(z)
// about `axis` (N's hemisphere: z = 0 about N), or nothing (z = kOccluderNone:
// object k cannot block the sky above P).
const float kOccluderNone = 2.0;

struct OccluderCone {
    vec3 axis;
    float z;          // cos of the half-angle, or kOccluderNone
    float one_minus;  // 1 - z, kept where z is near 1 (a small, distant object)
};

OccluderCone occluder_cone(int k, vec3 P, vec3 N, vec3 up) {
    OccluderCone cone;
    cone.axis = N;
    cone.z = kOccluderNone;
    cone.one_minus = 0.0;
    vec4 box = u_sky_occluder_centre[k];
    vec3 half_size = u_sky_occluder_half[k].xyz;
    vec3 to_box = box.xyz - P;
    // Its box wholly below a horizon: its corner furthest up is not above it.
    if (dot(N, to_box) + dot(abs(N), half_size) <= 0.0 || dot(up, to_box) + dot(abs(up), half_size) <= 0.0)
        return cone;
    // A plane through P blocks only directions along it.
    float eps = 1e-4 * max(1.0, max(abs(P.x), max(abs(P.y), abs(P.z))));
    if (box.w > 0.5 && abs(dot(u_sky_occluder_normal[k].xyz, to_box)) <= eps) return cone;
    vec4 sphere = u_sky_occluder_sphere[k];
    vec3 to_sphere = sphere.xyz - P;
    float d2 = dot(to_sphere, to_sphere), r2 = sphere.w * sphere.w;
    if (d2 <= r2) {  // the hemisphere about N
        cone.z = 0.0;
        cone.one_minus = 1.0;
        return cone;
    }
    float d = sqrt(d2);
    cone.axis = to_sphere / d;
    float sin2 = r2 / d2;
    cone.z = sqrt(1.0 - sin2);
    cone.one_minus = sin2 / (1.0 + cone.z);
    // Narrower where the box's corners all lie closer to the axis (a flat torus, a cube:
    // their spheres are wide); a cone within 90 degrees holds the box when it holds its corners.
    if (box.w < 0.5 && any(greaterThan(abs(to_box), half_size))) {
        float z = 1.0;
        for (int corner = 0; corner < 8; ++corner) {
            vec3 side = vec3(float(corner & 1), float((corner >> 1) & 1), float((corner >> 2) & 1)) * 2.0 - 1.0;
            z = min(z, dot(cone.axis, normalize(to_box + side * half_size)));
        }
        if (z > cone.z) {
            cone.z = z;
            cone.one_minus = 1.0 - z;
        }
    }
    return cone;
}

// Technique `cone`'s density at w (per solid angle).
float occluder_pdf(OccluderCone cone, vec3 w) {
    if (cone.z == kOccluderNone) return 0.0;
    return dot(cone.axis, w) >= cone.z ? 1.0 / (2.0 * PI * cone.one_minus) : 0.0;
}

// Technique `cone`'s direction for the point u of the unit square.
vec3 occluder_direction(OccluderCone cone, vec2 u) {
    float one_minus = u.x * cone.one_minus;  // 1 - cos, uniform in solid angle
    float c = 1.0 - one_minus, s = sqrt(max(one_minus * (2.0 - one_minus), 0.0));
    float phi = 2.0 * PI * u.y;
    vec3 T, B;
    complete_frame(cone.axis, T, B);
    return normalize(s * cos(phi) * T + s * sin(phi) * B + c * cone.axis);
}

// The objects that can block the sky above P, as bits.
int occluder_mask(vec3 P, vec3 N, vec3 up) {
    int mask = 0;
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k)
        if (k < u_sky_occluder_count && occluder_cone(k, P, N, up).z != kOccluderNone) mask |= 1 << k;
    return mask;
}

int bit_count(int mask) {
    int count = 0;
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k) count += (mask >> k) & 1;
    return count;
}

// Sample j of the blocked part, `per` samples a technique of `mask`: its
// direction, and the balance heuristic's weight 1 / sum_k per p_k(w).
vec3 occluder_sample(int j, int per, int mask, vec2 rotation, vec3 P, vec3 N, vec3 up, out float weight) {
    int technique = j / per, seen = 0, k_of = 0;
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k) {
        if (((mask >> k) & 1) == 0) continue;
        if (seen == technique) k_of = k;
        ++seen;
    }
    // Each technique's strata shifted on their own (the same pixel, another hash).
    vec2 shift = fract(rotation + vec2(0.618034, 0.754878) * float(k_of + 1));
    OccluderCone own = occluder_cone(k_of, P, N, up);
    vec3 w = occluder_direction(own, net_point(j - technique * per, per, shift));
    // The drawing technique's own density whatever its cone test says of w: a
    // direction drawn at a narrow cone's rim can fail the test by rounding (SwiftShader
    // did), and weighed by a wide technique's density alone it was a firefly.
    float density = float(per) / (2.0 * PI * own.one_minus);
    for (int k = 0; k < MAX_SKY_OCCLUDERS; ++k)
        if (k != k_of && ((mask >> k) & 1) != 0) density += float(per) * occluder_pdf(occluder_cone(k, P, N, up), w);
    weight = density > 0.0 ? 1.0 / density : 0.0;
    return w;
}
