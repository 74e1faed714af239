// The closed form of a Phong lobe over a spherical polygon: the integral of
// ((D . u)+)^n over the directions u of a rect or of the sky above a point's
// horizon, n a whole number (Arvo 1995, "Applications of irradiance tensors to
// the simulation of non-Lambertian phenomena", the axial moments). With it the
// samples of an area light integrate a highlight (R_V . L)^m as exactly as
// Lambert's formula makes them integrate N . L (common/lights.glsl:
// light_walk). C++ twin: reference/lobe_moment.h (same names).
//
// The recurrence, from the sphere's Laplacian of (D.u)^k over the polygon and
// Green's theorem on its boundary (m_i each edge's plane normal, inwards):
//     I_k = (k - 1) / (k + 1) I_{k-2} + 1 / (k + 1) sum_i (D . m_i) F_{i,k-1},
//     I_0 = the solid angle, I_1 = Lambert's formula about D
// (its factors telescope: clipped_lobe_integral sums each edge's F_j alone),
// and along an edge of length T, f(t) = D . u(t) = a cos t + b sin t:
//     F_j = ((j - 1) (a^2 + b^2) F_{j-2} - [f^{j-1} f']_0^T) / j, F_0 = T.
// Precision: float keeps the sum to about 1e-6 of the lobe's whole integral
// 2 pi / (n + 1); kLobeMomentMaxExponent bounds the terms the recurrence adds.

const int kLobeMomentMaxExponent = 64;
const int kLobePolygonMax = 8;  // a rect's 4 corners, one per cut by two planes, and a quarter-circle corner each

// Which side of the plane through the origin with normal `plane` q lies on (0: on it, to rounding).
int side_of_plane(vec3 q, vec3 plane) {
    float d = dot(q, plane), tolerance = 1e-6 * length(q);
    return d > tolerance ? 1 : (d < -tolerance ? -1 : 0);
}

// Sutherland-Hodgman: the part of the convex polygon v[0 .. count) (wound by
// `winding` about its inside: +1 counter-clockwise) where plane . u >= 0. A
// cut spanning more than a quarter of the plane's great circle (the sky's
// hemisphere cut by any plane: half of it) gets the corner a quarter along.
int clip_polygon_to_plane(inout vec3 v[kLobePolygonMax], int count, vec3 plane, float winding) {
    vec3 kept[kLobePolygonMax];
    bool on_plane[kLobePolygonMax];
    int n = 0;
    for (int i = 0; i < count; ++i) {
        vec3 a = v[i], b = v[(i + 1) % count];
        int sa = side_of_plane(a, plane), sb = side_of_plane(b, plane);
        if (sa >= 0 && n < kLobePolygonMax) {
            kept[n] = a;
            on_plane[n++] = sa == 0;
        }
        if (sa * sb < 0 && n < kLobePolygonMax) {
            float da = dot(a, plane), db = dot(b, plane);
            kept[n] = a + (da / (da - db)) * (b - a);
            on_plane[n++] = true;
        }
    }
    int count_out = 0;
    for (int i = 0; i < n; ++i) {
        if (count_out < kLobePolygonMax) v[count_out++] = kept[i];
        int j = (i + 1) % n;
        if (on_plane[i] && on_plane[j] && dot(kept[i], kept[j]) < 0.0 && count_out < kLobePolygonMax)
            v[count_out++] = winding * cross(plane, normalize(kept[i]));
    }
    return count_out;
}

// The integral of ((D . u)+)^e dw over the directions u of the convex polygon
// v[0 .. count) (within a hemisphere, `inside` a direction inside it) above the
// horizons of N and D; e a whole number in [1, kLobeMomentMaxExponent].
float clipped_lobe_integral(vec3 v[kLobePolygonMax], int count, vec3 inside, vec3 N, vec3 D, int e) {
    float winding = dot(cross(v[0], v[1]), inside) >= 0.0 ? 1.0 : -1.0;
    count = clip_polygon_to_plane(v, count, N, winding);
    count = clip_polygon_to_plane(v, count, D, winding);
    // Unit corners, none repeating its predecessor (an edge of no length has no plane).
    vec3 u[kLobePolygonMax];
    int n = 0;
    for (int i = 0; i < count; ++i) {
        vec3 q = normalize(v[i]);
        if (n == 0 || length(cross(u[n - 1], q)) > 1e-6) u[n++] = q;
    }
    if (n > 1 && length(cross(u[n - 1], u[0])) <= 1e-6) --n;
    if (n < 3) return 0.0;
    // The recurrence's factors telescope: I_e = (I_0 [e even] + sum over edges of
    // (D . m) sum_{j = e - 1, e - 3, ... >= 0} F_j) / (e + 1). So each edge is
    // walked alone, its F_j in scalars (arrays indexed in loops are slow on llvmpipe).
    bool odd = e % 2 == 1;
    float sum = 0.0, turns = 0.0;
    vec3 m_first = vec3(0.0), m_before = vec3(0.0);
    for (int i = 0; i < n; ++i) {
        vec3 a = u[i], b = u[i + 1 < n ? i + 1 : 0];
        vec3 axb = cross(a, b);
        float s = length(axb);
        float len = atan(s, dot(a, b));
        vec3 m = winding * axb / s;  // the edge's plane normal, inwards
        if (i == 0) m_first = m;
        else turns += atan(length(cross(m_before, m)), dot(m_before, m));
        m_before = m;
        // f = D . u along the edge, and f' (the tangent at a towards b, and at b onwards).
        float f0 = dot(D, a), df0 = winding * dot(D, cross(m, a));
        float f1 = dot(D, b), df1 = winding * dot(D, cross(m, b));
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
        sum += dot(D, m) * edge_sum;
    }
    if (!odd) {  // I_0, the solid angle by Gauss-Bonnet: 2 pi less the turns at the corners
        turns += atan(length(cross(m_before, m_first)), dot(m_before, m_first));
        sum += 2.0 * PI - turns;
    }
    return sum / float(e + 1);
}
