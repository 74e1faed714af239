// The closed form of a Phong lobe over a spherical polygon: the integral of
// ((D . u)+)^n over the directions u of a rect or of the sky above a point's
// horizon (and D's), and over a disk (disk_lobe_integral), n a whole number (Arvo 1995, "Applications of irradiance tensors to
// the simulation of non-Lambertian phenomena", the axial moments). With it the
// samples of an area light integrate a highlight (R_V . L)^m as exactly as
// Lambert's formula makes them integrate N . L (common/lights.glsl:
// light_walk). C++ twin: reference/lobe_moment.h (same names). Needs
// complete_frame (common/area_lights.glsl).
//
// The region is an intersection of hemispheres {u : m . u >= 0}: the rect's four
// edges' (the sky's one horizon), N's and D's. Its boundary is an arc of each
// plane's great circle, the part inside all the other hemispheres; each arc is
// found on its own (no polygon is clipped and stored: llvmpipe compiled the
// clipping's indexed arrays for 45 s, docs/lights.md). The recurrence, from the
// sphere's Laplacian of (D.u)^k over the region and Green's theorem on its
// boundary (m_i each arc's plane normal, inwards):
//     I_k = (k - 1) / (k + 1) I_{k-2} + 1 / (k + 1) sum_i (D . m_i) F_{i,k-1},
//     I_0 = the solid angle, I_1 = Lambert's formula about D
// (its factors telescope: lobe_integral_in_hemispheres sums each arc's F_j alone),
// and along an arc of length T, f(t) = D . u(t) = a cos t + b sin t:
//     F_j = ((j - 1) (a^2 + b^2) F_{j-2} - [f^{j-1} f']_0^T) / j, F_0 = T.
// Precision: float keeps the sum to about 1e-6 of the lobe's whole integral
// 2 pi / (n + 1); kLobeMomentMaxExponent bounds the terms the recurrence adds.

const int kLobeMomentMaxExponent = 64;
const int kLobeHemispheres = 6;      // a rect's four edges (the sky: its horizon, repeated), N's and D's horizons
const float kLobeSameCircle = 1e-6;  // two planes' normals this close to parallel: one great circle

// The part [lo, hi] (none: hi <= lo) of plane k's great circle inside every other
// hemisphere, as angles t of u(t) = cos t e1 + sin t e2, e2 = m[k] x e1 (moving
// along it keeps the region on the left). Each other hemisphere is a half
// circle, [c - pi/2, c + pi/2] about the angle c of its normal in the circle's
// frame; half circles meet in one arc.
vec2 arc_on_circle(vec3 m[kLobeHemispheres], int k, vec3 e1, vec3 e2) {
    vec2 arc = vec2(0.0, 2.0 * PI);
    bool whole = true;
    for (int j = 0; j < kLobeHemispheres; ++j) {
        if (j == k) continue;
        vec2 ab = vec2(dot(m[j], e1), dot(m[j], e2));
        if (length(ab) < kLobeSameCircle) continue;  // the same circle (an opposite one: no region, tested before)
        float c = atan(ab.y, ab.x);
        if (!whole) c -= 2.0 * PI * floor((c - 0.5 * (arc.x + arc.y)) / (2.0 * PI) + 0.5);
        arc = whole ? vec2(c - 0.5 * PI, c + 0.5 * PI) : vec2(max(arc.x, c - 0.5 * PI), min(arc.y, c + 0.5 * PI));
        whole = false;
    }
    return arc;
}

// The signed solid angle of the spherical triangle (pole, a, b) (Van Oosterom and Strackee 1983).
float triangle_solid_angle(vec3 pole, vec3 a, vec3 b) {
    return 2.0 * atan(dot(pole, cross(a, b)), 1.0 + dot(pole, a) + dot(pole, b) + dot(a, b));
}

// The integral of ((D . u)+)^e dw over the intersection of the hemispheres of
// unit m[0 .. kLobeHemispheres), m[kLobeHemispheres - 2] = N and the last = D;
// e a whole number in [1, kLobeMomentMaxExponent].
float lobe_integral_in_hemispheres(vec3 m[kLobeHemispheres], vec3 D, int e) {
    for (int k = 1; k < kLobeHemispheres; ++k)
        for (int j = 0; j < k; ++j)
            if (length(cross(m[j], m[k])) < kLobeSameCircle && dot(m[j], m[k]) < 0.0) return 0.0;
    vec3 N = m[kLobeHemispheres - 2];  // the fan's pole: the region lies in its hemisphere
    // The recurrence's factors telescope: I_e = (I_0 [e even] + sum over arcs of
    // (D . m) sum_{j = e - 1, e - 3, ... >= 0} F_j) / (e + 1). So each arc is
    // walked alone, its F_j in scalars.
    bool odd = e % 2 == 1;
    float sum = 0.0;
    for (int k = 0; k < kLobeHemispheres; ++k) {
        bool repeated = false;
        for (int j = 0; j < k; ++j) repeated = repeated || length(cross(m[j], m[k])) < kLobeSameCircle;
        if (repeated) continue;
        vec3 e1, e2;
        complete_frame(m[k], e1, e2);  // e2 = m[k] x e1
        vec2 arc = arc_on_circle(m, k, e1, e2);
        if (arc.y <= arc.x) continue;
        float len = arc.y - arc.x;
        vec3 a = cos(arc.x) * e1 + sin(arc.x) * e2, b = cos(arc.y) * e1 + sin(arc.y) * e2;
        // f = D . u along the arc, and f' (the tangent m x u) at both ends.
        float f0 = dot(D, a), df0 = dot(D, cross(m[k], a));
        float f1 = dot(D, b), df1 = dot(D, cross(m[k], b));
        float c2 = f0 * f0 + df0 * df0;
        float F = odd ? len : f0 * sin(len) + df0 * (1.0 - cos(len));  // F_0 or F_1
        float power0 = odd ? f0 : f0 * f0, power1 = odd ? f1 : f1 * f1;  // f^{j-1} at both ends for the next j
        float edge_sum = F;
        for (int j = odd ? 2 : 3; j < e; j += 2) {
            F = (float(j - 1) * c2 * F - (power1 * df1 - power0 * df0)) / float(j);
            power0 *= f0 * f0;
            power1 *= f1 * f1;
            edge_sum += F;
        }
        sum += dot(D, m[k]) * edge_sum;
        if (!odd) {  // I_0, the region's solid angle: a fan from N, a quarter of each arc a triangle
            vec3 from = a;
            for (int piece = 1; piece <= 4; ++piece) {
                float t = arc.x + len * (float(piece) / 4.0);
                vec3 to = cos(t) * e1 + sin(t) * e2;
                sum += triangle_solid_angle(N, from, to);
                from = to;
            }
        }
    }
    return sum / float(e + 1);
}

// Nodes of the trapezoid rule along a disk's rim: the integrands are smooth and
// periodic, so the rule converges geometrically (against 2-D quadrature, a lobe
// of n = 64 off the centre of a disk 50 degrees across: 4e-2 at 8 nodes, 2e-5 at
// 16, 1e-10 at 24; wider lobes 1e-10 at 16; tests/lobe_moment_test.cpp).
const int kDiskRimNodes = 24;

// The integral of ((D . u)+)^e dw over the directions u towards the disk
// c + cos t e0 + sin t e1 (c its centre from the shaded point, e0 and e1 its
// radii along two perpendicular axes), where every point of its rim is above
// the horizons of unit N and unit D; -1 where one is not (the region would
// need the horizons' arcs too). The same recurrence as for a polygon, its
// boundary the rim: with u(t) the rim's direction and f = D . u,
//     (e + 1) I_e = I_0 [e even] + oint (sum_{j = e-1, e-3, ... >= 0} f^j) D . (u x u') dt,
// u x u' = (r x r') / |r|^2 for r(t) the rim point (Green's theorem on the
// sphere with the conormal u x u' / |u'|), and I_0, the solid angle, as the
// flux of a vector potential with its singularity behind the disk (at -c):
//     I_0 = oint (c^ x u) . u' / (1 + c^ . u) dt.
// The rim's orientation is whichever makes I_0 positive.
float disk_lobe_integral(vec3 c, vec3 e0, vec3 e1, vec3 N, vec3 D, int e) {
    if (dot(N, c) <= length(vec2(dot(N, e0), dot(N, e1))) || dot(D, c) <= length(vec2(dot(D, e0), dot(D, e1))))
        return -1.0;
    vec3 pole = normalize(c);
    bool odd = e % 2 == 1;
    float solid = 0.0, boundary = 0.0;
    for (int k = 0; k < kDiskRimNodes; ++k) {
        float t = (2.0 * PI / float(kDiskRimNodes)) * float(k);
        vec3 r = c + cos(t) * e0 + sin(t) * e1, dr = -sin(t) * e0 + cos(t) * e1;
        float r2 = dot(r, r), len = sqrt(r2);
        vec3 u = r / len;
        vec3 du = (dr - dot(u, dr) * u) / len;
        float f = dot(D, u), power = odd ? 1.0 : f, powers = 0.0;
        for (int j = odd ? 0 : 1; j < e; j += 2) {
            powers += power;
            power *= f * f;
        }
        boundary += powers * dot(D, cross(r, dr)) / r2;
        solid += dot(cross(pole, u), du) / (1.0 + dot(pole, u));
    }
    float turn = solid >= 0.0 ? 1.0 : -1.0;
    return turn * (odd ? boundary : solid + boundary) * (2.0 * PI / float(kDiskRimNodes)) / float(e + 1);
}
