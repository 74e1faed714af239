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
//     I_0 = the solid angle, I_1 = Lambert's formula about D,
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
    // Each edge: its length, D . m (m its plane's normal, inwards), f and f' at both ends.
    float len[kLobePolygonMax], Dm[kLobePolygonMax], f0[kLobePolygonMax], df0[kLobePolygonMax];
    float f1[kLobePolygonMax], df1[kLobePolygonMax], F[kLobePolygonMax];
    vec3 m[kLobePolygonMax];
    for (int i = 0; i < n; ++i) {
        vec3 a = u[i], b = u[(i + 1) % n];
        vec3 axb = cross(a, b);
        float s = length(axb);
        len[i] = atan(s, dot(a, b));
        m[i] = winding * axb / s;
        Dm[i] = dot(D, m[i]);
        f0[i] = dot(D, a);
        df0[i] = winding * dot(D, cross(m[i], a));
        f1[i] = dot(D, b);
        df1[i] = winding * dot(D, cross(m[i], b));
    }
    bool odd = e % 2 == 1;
    float I = 0.0;  // I_{-1} (its weight is 0) or I_0, the solid angle by Gauss-Bonnet
    if (!odd) {
        float turns = 0.0;
        for (int i = 0; i < n; ++i) {
            vec3 before = m[(i + n - 1) % n];
            turns += atan(length(cross(before, m[i])), dot(before, m[i]));
        }
        I = 2.0 * PI - turns;
    }
    float power0[kLobePolygonMax], power1[kLobePolygonMax];  // f^{j-1} at both ends for the next j
    for (int i = 0; i < n; ++i) {
        F[i] = odd ? len[i] : f0[i] * sin(len[i]) + df0[i] * (1.0 - cos(len[i]));  // F_0 or F_1
        power0[i] = odd ? f0[i] : f0[i] * f0[i];
        power1[i] = odd ? f1[i] : f1[i] * f1[i];
    }
    for (int k = odd ? 1 : 2; k <= e; k += 2) {
        int j = k - 1;  // F holds F_j
        float boundary = 0.0;
        for (int i = 0; i < n; ++i) {
            if (j >= 2) {
                float c2 = f0[i] * f0[i] + df0[i] * df0[i];
                F[i] = (float(j - 1) * c2 * F[i] - (power1[i] * df1[i] - power0[i] * df0[i])) / float(j);
                power0[i] *= f0[i] * f0[i];
                power1[i] *= f1[i] * f1[i];
            }
            boundary += Dm[i] * F[i];
        }
        I = (float(k - 1) * I + boundary) / float(k + 1);
    }
    return I;
}
