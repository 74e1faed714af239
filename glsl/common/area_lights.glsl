// Rect, disk and sky lights (docs/spec.md#75-area-lights-the-sky-and-shadows) as what
// the models take: directional lights, one per sample of the emitter. What a
// light adds is the integral of L(w) r(w) dw over the directions w in which
// the point sees it, r being what a unit directional light from w adds; the
// samples estimate it, and the models are the integrand untouched.
//
// The estimate (docs/lights.md). n x n points of the unit square, one a
// stratum (stratum_point: a (0, 2)-net), randomized per pixel and light (so
// the error is fine noise, not bands, and the same pixel gets the same samples
// in every render, desktop and browser), mapped onto the emitter (uniform in area for a
// rect or disk, cosine-weighted about N for the sky) and, for a model with a
// highlight, onto a Phong lobe about V's mirror direction too; the two are
// combined by the balance heuristic (common/lights.glsl: walk_direction).
// Then every sample is scaled by E / E_s, E the exact projected solid angle
// (what a Lambert surface integrates: Lambert's polygon formula for the rect
// clipped to the horizon, the disk's boundary integral, the sky's lune) and
// E_s the samples' own estimate of it. This ratio makes a Lambert term exact
// whatever n, leaves the others consistent (the factor tends to 1), and with
// shadows it is the ratio estimator of Heitz et al. 2018, "Combining analytic
// direct illumination and stochastic shadows": analytic unshadowed light times
// the sampled shadowed / unshadowed fraction. C++ twin: the reference
// integrates the same emitters adaptively (reference/emitters.h).
//
// Precision. Lambert's formula sums one term per edge; for an emitter that
// subtends little the terms cancel (float keeps 1e-7 of each), and the samples
// are accurate there anyway (the integrand hardly varies across the light), so
// below kExactMinSize the factor is 1. Edge angles by atan(|a x b|, a . b),
// which keeps small angles that acos(a . b) loses.

#include "common/constants.glsl"

#define LIGHT_RECT 3
#define LIGHT_DISK 4
#define LIGHT_SKY 5

uniform vec4 u_light_extent[MAX_LIGHTS * 2];  // rect: half-side vectors; disk: radius x two unit axes
uniform int u_area_samples;                   // strata along each side of the square (n)

// Below this angular size (extent / distance) the samples alone are used.
const float kExactMinSize = 0.01;

// One step of the PCG hash (O'Neill 2014; the RXS-M-XS output of Jarzynski
// and Olano 2020, "Hash functions for GPU rendering").
uint pcg_hash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// The rotation of light i's strata at this pixel, in [0, 1)^2.
vec2 strata_rotation(int i) {
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uint h = pcg_hash(pixel.x + pcg_hash(pixel.y + pcg_hash(uint(i))));
    return vec2(float(h >> 8u), float(pcg_hash(h) >> 8u)) * (1.0 / 16777216.0);
}

// k's 32 bits in reverse order (GLSL ES 3.00 has no bitfieldReverse): the
// top 24 of them are k's radical inverse in base 2 (van der Corput).
uint reverse_bits(uint v) {
    v = ((v >> 1u) & 0x55555555u) | ((v & 0x55555555u) << 1u);
    v = ((v >> 2u) & 0x33333333u) | ((v & 0x33333333u) << 2u);
    v = ((v >> 4u) & 0x0F0F0F0Fu) | ((v & 0x0F0F0F0Fu) << 4u);
    v = ((v >> 8u) & 0x00FF00FFu) | ((v & 0x00FF00FFu) << 8u);
    return (v >> 16u) | (v << 16u);
}

// Point k of `count` (a power of two) of Hammersley's net in base 2 (x = k / count,
// y = k's bits reversed), shifted digitally by `rotation` (stratum_point, below).
vec2 net_point(int k, int count, vec2 rotation) {
    // 2^24 / count in float (exact: a power of two): llvmpipe has no vector integer
    // division, and a udiv here made the softbox's render twice as slow.
    uint column = uint(16777216.0 / float(count));
    uvec2 net = uvec2(uint(k) * column, reverse_bits(uint(k)) >> 8u);
    uvec2 shift = uvec2(rotation * 16777216.0);  // exact: rotation is a 24-bit fraction (strata_rotation)
    return vec2(net ^ shift) * (1.0 / 16777216.0);
}

// Sample k of n x n. Where n = 2^m (2, 4, 8, 16), a point of Hammersley's
// (0, 2m, 2)-net in base 2 (x = k / n², y = k's 2m bits reversed): one point in
// each of the n x n strata, and also in each of n² columns and n² rows and
// every other dyadic box of area 1 / n², so a shadow edge along a side of a
// rect moves the visible share in n² steps where a grid's whole rows of
// samples go dark at once (n steps). Randomized by a digital shift (the 24
// bits of `rotation` XORed in), which keeps every one of those boxes (Kollig
// and Keller 2002, "Efficient multidimensional sampling"); Cranley and
// Patterson's shift mod 1 would not. Other n: the stratum's centre, shifted
// by `rotation` (mod 1); n = 1, unrotated, is the emitter's centre.
vec2 stratum_point(int k, int n, vec2 rotation) {
    if (n >= 2 && (n & (n - 1)) == 0) return net_point(k, n * n, rotation);
    vec2 cell = vec2(float(k % n), float(k / n));
    return fract((cell + 0.5) / float(n) + rotation);
}

// Shirley and Chiu 1997's concentric map from [0, 1)^2 to the unit disk
// (area-preserving, so strata stay strata).
vec2 concentric_disk(vec2 u) {
    vec2 a = 2.0 * u - 1.0;
    if (a.x == 0.0 && a.y == 0.0) return vec2(0.0);
    float r, phi;
    if (abs(a.x) > abs(a.y)) {
        r = a.x;
        phi = (PI / 4.0) * (a.y / a.x);
    } else {
        r = a.y;
        phi = (PI / 2.0) - (PI / 4.0) * (a.x / a.y);
    }
    return r * vec2(cos(phi), sin(phi));
}

// A direction towards an emitter seen from P: the unit direction, the
// density (per solid angle) with which the emitter's own sampling draws it
// (0: it adds nothing), and how far the emitter is along it (< 0: infinitely).
struct AreaSample {
    vec3 L;
    float pdf;
    float distance;
};

// Two unit vectors completing the unit Z to a right-handed frame.
void complete_frame(vec3 Z, out vec3 T, out vec3 B) {
    T = normalize(abs(Z.x) > 0.5 ? cross(Z, vec3(0.0, 1.0, 0.0)) : cross(Z, vec3(1.0, 0.0, 0.0)));
    B = cross(Z, T);
}

// A point X of a rect or disk of area `area` and unit normal `normal`, drawn uniformly in area.
AreaSample emitter_sample(vec3 P, vec3 X, vec3 normal, float area) {
    AreaSample s;
    vec3 d = X - P;
    float d2 = dot(d, d);
    s.distance = sqrt(d2);
    s.L = d / s.distance;
    float cos_e = -dot(s.L, normal);  // one-sided: the back of the emitter gives nothing
    s.pdf = cos_e > 0.0 ? d2 / (area * cos_e) : 0.0;
    return s;
}

// The sky's density at w: cosine-weighted about N, none where the sky is not.
float sky_pdf(vec3 N, vec3 up, vec3 w) {
    float z = dot(N, w);
    return (dot(w, up) > 0.0 && z > 0.0) ? z / PI : 0.0;
}

// The sky's sample from u: cosine-weighted about N.
AreaSample sky_sample(vec3 N, vec3 up, vec2 u) {
    vec2 disk = concentric_disk(u);
    float z = sqrt(max(1.0 - dot(disk, disk), 0.0));
    vec3 T, B;
    complete_frame(N, T, B);
    AreaSample s;
    s.L = normalize(disk.x * T + disk.y * B + z * N);
    s.distance = -1.0;
    s.pdf = sky_pdf(N, up, s.L);
    return s;
}

float emitter_area(int i, int type) {
    float r0 = length(u_light_extent[2 * i].xyz), r1 = length(u_light_extent[2 * i + 1].xyz);
    return type == LIGHT_RECT ? 4.0 * r0 * r1 : PI * r0 * r1;
}

// The point u of the unit square mapped onto area light i (of type `type`) seen from P (normal N).
AreaSample area_sample_at(int i, int type, vec2 u, vec3 P, vec3 N) {
    vec3 centre = u_light_vector[i].xyz;
    vec3 e0 = u_light_extent[2 * i].xyz, e1 = u_light_extent[2 * i + 1].xyz;
    if (type == LIGHT_SKY) return sky_sample(N, centre, u);
    vec3 normal = u_light_spot[i].xyz;
    vec2 at = type == LIGHT_RECT ? 2.0 * u - 1.0 : concentric_disk(u);
    return emitter_sample(P, centre + at.x * e0 + at.y * e1, normal, emitter_area(i, type));
}

// The sky's direction w seen from a point of normal N, as a sample of it.
AreaSample sky_direction(vec3 N, vec3 up, vec3 w) {
    AreaSample s;
    s.L = w;
    s.distance = -1.0;
    s.pdf = sky_pdf(N, up, w);
    return s;
}

// The sky's one sample (n = 1): midway between N and up, inside the part of
// the sky above N's horizon whatever way N faces (N itself, the centre of the
// cosine's square, is no part of the sky for a face turned sideways or down).
AreaSample sky_centre(vec3 N, vec3 up) {
    return sky_direction(N, up, normalize(N + up));
}

// The explorer's preview (n = 1) takes two points of an emitter for a model
// whose highlight the lobe's closed form integrates wholly (ModelSpec::
// glsl_lobe_exact): one where the highlight about D is (the representative
// point Karis 2013 takes for sphere and tube lights: where the ray P + t D
// meets the emitter's plane, moved onto the rect or disk if it falls outside;
// far along D's trace on the plane where D points away from it), and one on
// the emitter's far side from it: the pair's two factors (common/lights.glsl)
// need two points that the cosine and the lobe tell apart, and are positive
// where the two bracket the lobe's share of the light. For the sky, D itself,
// lifted above the sky's horizon (its lobe's tail is what is seen), and a
// direction between N and up, away from D.
// The point `at` of a rect's square or a disk's circle nearest to it.
vec2 onto_emitter(int type, vec2 at) {
    return type == LIGHT_RECT ? clamp(at, -1.0, 1.0) : at / max(length(at), 1.0);
}

vec2 emitter_point_towards(int i, int type, vec3 P, vec3 D) {
    vec3 centre = u_light_vector[i].xyz, normal = u_light_spot[i].xyz;
    vec3 e0 = u_light_extent[2 * i].xyz, e1 = u_light_extent[2 * i + 1].xyz;
    float facing = -dot(D, normal), height = dot(P - centre, normal);
    vec3 offset = facing > 0.0 ? P + (height / facing) * D - centre
                               : P - height * normal - centre + 1e4 * (D + facing * normal);
    return onto_emitter(type, vec2(dot(offset, e0) / dot(e0, e0), dot(offset, e1) / dot(e1, e1)));
}

// The emitter's far side from `at`: 0.9 of a half-side out, opposite at's
// direction from the centre (along e0's negative for the centre itself).
vec2 emitter_point_apart(vec2 at) {
    float r = length(at);
    return -0.9 * (r > 1e-3 ? at / r : vec2(1.0, 0.0));
}

// The point `at` of emitter i moved, where N's horizon crosses the emitter and
// `at` is below it, across the horizon's line into the part P sees (0.05 of a
// half-side in), then back onto the rect or disk: a point below the horizon
// adds nothing, and the pair needs two that do.
vec2 emitter_point_above(int i, int type, vec3 P, vec3 N, vec2 at) {
    vec3 c = u_light_vector[i].xyz - P;
    vec2 g = vec2(dot(N, u_light_extent[2 * i].xyz), dot(N, u_light_extent[2 * i + 1].xyz));
    float h = dot(N, c) + dot(at, g), gg = dot(g, g);
    if (h > 0.0 || gg <= 0.0) return at;
    return onto_emitter(type, at + (0.05 * sqrt(gg) - h) / gg * g);
}

AreaSample emitter_point(int i, int type, vec2 at, vec3 P) {
    vec3 centre = u_light_vector[i].xyz;
    vec3 e0 = u_light_extent[2 * i].xyz, e1 = u_light_extent[2 * i + 1].xyz;
    return emitter_sample(P, centre + at.x * e0 + at.y * e1, u_light_spot[i].xyz, emitter_area(i, type));
}

// Point k (0 or 1) of the preview's two.
AreaSample preview_point(int i, int type, int k, vec3 P, vec3 N, vec3 D) {
    vec3 up = u_light_vector[i].xyz;
    if (type == LIGHT_SKY) {
        if (k == 1) return sky_direction(N, up, normalize(D + max(0.1 - dot(D, up), 0.0) * up));
        // Midway between N and up, moved 39 degrees away from D (on a face turned down, below a horizon: no pair).
        vec3 mid = normalize(N + up), away = D - dot(D, mid) * mid, T, B;
        complete_frame(mid, T, B);
        away = dot(away, away) > 1e-6 ? normalize(away) : T;
        return sky_direction(N, up, normalize(mid - 0.8 * away));
    }
    vec2 at = emitter_point_towards(i, type, P, D);
    if (k == 0) at = emitter_point_apart(at);
    return emitter_point(i, type, emitter_point_above(i, type, P, N, at), P);
}

// Sample k of n x n of area light i (of type `type`) from the point P of normal N.
// n = 1 (the preview's one point): the centre, moved into the part above N's
// horizon where the emitter crosses it (the centre below it lit nothing, though
// Lambert's E is exact for what P sees).
AreaSample area_sample(int i, int type, int k, int n, vec2 rotation, vec3 P, vec3 N) {
    if (n == 1 && type == LIGHT_SKY) return sky_centre(N, u_light_vector[i].xyz);
    if (n == 1) return emitter_point(i, type, emitter_point_above(i, type, P, N, vec2(0.0)), P);
    return area_sample_at(i, type, stratum_point(k, n, rotation), P, N);
}

// The density with which area_sample draws the direction w (0 where w misses
// the emitter or meets its back), and the emitter's distance along w.
AreaSample area_sample_towards(int i, int type, vec3 P, vec3 N, vec3 w) {
    AreaSample s;
    s.L = w;
    s.distance = -1.0;
    vec3 centre = u_light_vector[i].xyz;
    if (type == LIGHT_SKY) return sky_direction(N, centre, w);
    s.pdf = 0.0;
    vec3 normal = u_light_spot[i].xyz;
    float facing = -dot(w, normal);
    if (facing <= 0.0) return s;
    float t = dot(P - centre, normal) / facing;
    if (t <= 0.0) return s;
    vec3 e0 = u_light_extent[2 * i].xyz, e1 = u_light_extent[2 * i + 1].xyz;
    vec3 offset = P + t * w - centre;
    vec2 at = vec2(dot(offset, e0) / dot(e0, e0), dot(offset, e1) / dot(e1, e1));
    bool inside = type == LIGHT_RECT ? max(abs(at.x), abs(at.y)) <= 1.0 : dot(at, at) <= 1.0;
    if (!inside) return s;
    s.distance = t;
    s.pdf = t * t / (emitter_area(i, type) * facing);
    return s;
}

// The unit direction at cos c and sin s from the unit D, turned 2 pi u about it (in
// complete_frame's frame): where the lobe techniques below put their samples.
vec3 direction_about(vec3 D, float c, float s, float u) {
    float phi = 2.0 * PI * u;
    vec3 T, B;
    complete_frame(D, T, B);
    return s * cos(phi) * T + s * sin(phi) * B + c * D;
}

// A Phong lobe ((D . w)+)^e about the unit D, as a density over directions
// ((e + 1) / 2 pi (D . w)^e) and a sample of it from u (Phong's inversion:
// cos = u^(1 / (e + 1))). The models' highlights resemble such lobes about
// V's mirror direction (generated/models.glsl: lobe_exponents); drawing
// directions from them as well as from the emitter keeps a sharp highlight of
// a large light from being a few bright pixels.
float phong_lobe_pdf(vec3 w, vec3 D, float e) {
    float c = dot(w, D);
    return c > 0.0 ? (e + 1.0) / (2.0 * PI) * pow(c, e) : 0.0;
}

vec3 phong_lobe_direction(vec2 u, vec3 D, float e) {
    float c = pow(max(u.x, 1e-30), 1.0 / (e + 1.0));
    float s = sqrt(max(1.0 - c * c, 0.0));
    return normalize(direction_about(D, c, s, u.y));
}

// The walk's lobe technique, about D with the model's Phong exponent e
// (common/lobe_hints.glsl). Up to kSharpLobeFrom the Phong lobe above. Beyond it,
// under the sky, a GGX lobe of the same width: a Phong lobe falls off as
// exp(-e theta^2 / 2) beside its peak, a GGX lobe (the principled model's, Burley
// 2012) as 1 / theta^4, and the sky's cosine-weighted samples are sparse where that
// tail is still large: a glossy principled floor under the sky (roughness 0 ... 0.2,
// e ~ 5e5 ... 300) showed white fireflies of 3 where it is 0.7 (64 x 40, all pixels:
// 64.7 % on the same level at roughness 0, 79.3 % at 0.1, 91.6 % at 0.2; with GGX
// 98.1, 97.6, 97.6 %). Under a rect or disk, whose own samples cover the tails
// densely, the sharp Phong lobe without cancellation: the GGX lobe there set a
// floor of roughness 0.05 under a rect right (95.8 -> 97.9 %) and one of 0.2 under
// a disk worse (98.0 -> 97.3 %, max 0.28 -> 0.43), and is not used.
const float kSharpLobeFrom = 100.0;

// A sharp Phong lobe's density and sample, without cancellation: at e ~ 5e5 the
// float cos of dot(w, D) and of u^(1 / (e + 1)) holds a handful of values across
// the lobe, and its density read at them left a glossy floor under the sky 12 %
// dark where the view grazes it (before its GGX lobe; under a rect, roughness 0.05:
// 95.4 -> 95.8 % on the same level). 1 - cos from the cross product (common/math.glsl, included
// ahead of this file), and the drawn 1 - cos as -expm1(log(u) / (e + 1)).
float sharp_lobe_pdf(vec3 w, vec3 D, float e) {
    float c = dot(w, D);
    return c > 0.0 ? (e + 1.0) / (2.0 * PI) * pow_cos(c, one_minus_cos(w, D), e) : 0.0;
}

vec3 sharp_lobe_direction(vec2 u, vec3 D, float e) {
    float y = log(max(u.x, 1e-30)) / (e + 1.0);  // log cos
    float x = y > -0.01 ? -y * (1.0 + y * (0.5 + y / 6.0)) : 1.0 - exp(y);  // 1 - cos
    float s = sqrt(max(x * (2.0 - x), 0.0));
    return normalize(direction_about(D, 1.0 - x, s, u.y));
}

// A GGX lobe about D (Walter et al. 2007), of the roughness whose Phong exponent is e
// (common/lobe_hints.glsl: e = 0.5 / alpha^2): half vectors h about D of density
// D_alpha(h) (h . D), and the direction w = 2 (D . h) h - D, D reflected about h, of
// density D_alpha(h) / 4 (the reflection's Jacobian 4 h . w). The bracket of D_alpha
// as alpha^2 cos^2 + sin^2, sin^2 from the cross product, and cos from tan (no
// cancellation at alpha = 0.001).
float ggx_lobe_pdf(vec3 w, vec3 D, float e) {
    vec3 h = w + D;
    if (!(dot(h, h) > 0.0)) return 0.0;
    h = normalize(h);
    float c = dot(h, D);
    if (c <= 0.0) return 0.0;
    vec3 x = cross(h, D);
    float a2 = 0.5 / e, t = a2 * c * c + dot(x, x);
    return 0.25 * a2 / (PI * t * t);
}

vec3 ggx_lobe_direction(vec2 u, vec3 D, float e) {
    float tan2 = 0.5 / e * u.x / max(1.0 - u.x, 1e-30);
    float c = inversesqrt(1.0 + tan2), s = sqrt(tan2) * c;
    vec3 h = direction_about(D, c, s, u.y);
    return normalize(2.0 * dot(D, h) * h - D);
}

float lobe_technique_pdf(vec3 w, vec3 D, float e, int type) {
    if (e <= kSharpLobeFrom) return phong_lobe_pdf(w, D, e);
    return type == LIGHT_SKY ? ggx_lobe_pdf(w, D, e) : sharp_lobe_pdf(w, D, e);
}

vec3 lobe_technique_direction(vec2 u, vec3 D, float e, int type) {
    if (e <= kSharpLobeFrom) return phong_lobe_direction(u, D, e);
    return type == LIGHT_SKY ? ggx_lobe_direction(u, D, e) : sharp_lobe_direction(u, D, e);
}

// An edge's share of Lambert's formula, from a to b (directions from the
// shaded point): the angle it subtends times N . (a x b) / |a x b|.
float lambert_edge(vec3 a, vec3 b, vec3 N) {
    vec3 c = cross(a, b);
    float s = length(c);
    return s > 0.0 ? atan(s, dot(a, b)) * dot(N, c) / s : 0.0;
}

// The projected solid angle of the rect with corners P + v[0..3] (in order)
// above the horizon of N: Sutherland-Hodgman against N . x > 0 (a convex
// quadrilateral keeps at most five corners), then Lambert's formula (Lambert
// 1760; Arvo 1995, "Applications of irradiance tensors", eq. 1).
float rect_projected_solid_angle(vec3 v0, vec3 v1, vec3 v2, vec3 v3, vec3 N) {
    vec3 v[4] = vec3[4](v0, v1, v2, v3);
    vec3 clipped[5];
    int count = 0;
    for (int j = 0; j < 4; ++j) {
        vec3 a = v[j], b = v[(j + 1) % 4];
        float ha = dot(N, a), hb = dot(N, b);
        if (ha > 0.0) clipped[count++] = a;
        if ((ha > 0.0) != (hb > 0.0)) clipped[count++] = a + (ha / (ha - hb)) * (b - a);
    }
    float sum = 0.0;
    for (int j = 0; j < count; ++j) sum += lambert_edge(clipped[j], clipped[(j + 1) % count], N);
    return 0.5 * abs(sum);
}

// Gauss-Legendre nodes and weights on [-1, 1], the positive half (16 points).
const float kGaussX[8] = float[8](0.0950125098, 0.2816035508, 0.4580167777, 0.6178762444, 0.7554044084,
                                  0.8656312024, 0.9445750231, 0.9894009350);
const float kGaussW[8] = float[8](0.1894506105, 0.1826034150, 0.1691565194, 0.1495959888, 0.1246289713,
                                  0.0951585117, 0.0622535239, 0.0271524594);

// The disk's projected solid angle: its boundary integral
// 1/2 oint N . (r x dr) / |r|^2 (Lambert's formula, the edge made a curve) over
// the arc above the horizon, by Gauss-Legendre in the angle, closed by the
// horizon's chord (a straight edge, exact). `c`: centre - P; e0, e1: radius x axes.
float disk_projected_solid_angle(vec3 c, vec3 e0, vec3 e1, vec3 N) {
    float hc = dot(N, c), h0 = dot(N, e0), h1 = dot(N, e1);
    float rho = sqrt(h0 * h0 + h1 * h1);
    if (hc <= -rho) return 0.0;
    float t0 = 0.0, t1 = 2.0 * PI;
    bool cut = hc < rho;
    if (cut) {  // above the horizon where cos(t - phi) > -hc / rho
        float phi = atan(h1, h0), half_arc = acos(clamp(-hc / rho, -1.0, 1.0));
        t0 = phi - half_arc;
        t1 = phi + half_arc;
    }
    float mid = 0.5 * (t0 + t1), half_len = 0.5 * (t1 - t0), sum = 0.0;
    for (int j = 0; j < 16; ++j) {
        float x = (j < 8 ? -1.0 : 1.0) * kGaussX[j % 8];
        float t = mid + half_len * x;
        vec3 r = c + cos(t) * e0 + sin(t) * e1;
        vec3 dr = -sin(t) * e0 + cos(t) * e1;
        sum += kGaussW[j % 8] * dot(N, cross(r, dr)) / dot(r, r);
    }
    sum *= half_len;
    if (cut) sum += lambert_edge(c + cos(t1) * e0 + sin(t1) * e1, c + cos(t0) * e0 + sin(t0) * e1, N);
    return 0.5 * abs(sum);
}

// E, the exact projected solid angle of area light i from P (N), or -1 where
// the samples alone are used (kExactMinSize).
float area_exact_projected(int i, int type, vec3 P, vec3 N) {
    vec3 centre = u_light_vector[i].xyz;
    if (type == LIGHT_SKY) return 0.5 * PI * (1.0 + clamp(dot(N, centre), -1.0, 1.0));
    vec3 e0 = u_light_extent[2 * i].xyz, e1 = u_light_extent[2 * i + 1].xyz;
    vec3 c = centre - P;
    if (max(length(e0), length(e1)) < kExactMinSize * length(c)) return -1.0;
    if (type == LIGHT_RECT) return rect_projected_solid_angle(c - e0 - e1, c + e0 - e1, c + e0 + e1, c - e0 + e1, N);
    return disk_projected_solid_angle(c, e0, e1, N);
}

#ifdef HAS_LOBE_CLOSED_FORM  // AreaSampling::lobe_closed_form
#include "common/lobe_moment.glsl"
#endif

// The integral over area light i seen from P above N's horizon of the Phong
// lobe ((D . w)+)^e, or -1 where it has no closed form here: an emitter below
// kExactMinSize, a disk whose rim crosses N's or D's horizon, e not a whole
// number in [1, kLobeMomentMaxExponent] (common/lobe_moment.glsl).
float area_exact_lobe(int i, int type, vec3 P, vec3 N, vec3 D, float e) {
#ifndef HAS_LOBE_CLOSED_FORM
    return -1.0;
#else
    if (e < 1.0 || e > float(kLobeMomentMaxExponent) || e != floor(e)) return -1.0;
    vec3 m[kLobeHemispheres];
    vec3 centre = u_light_vector[i].xyz;
    if (type == LIGHT_DISK) {
        vec3 c = centre - P, e0 = u_light_extent[2 * i].xyz, e1 = u_light_extent[2 * i + 1].xyz;
        if (max(length(e0), length(e1)) < kExactMinSize * length(c)) return -1.0;
        return disk_lobe_integral(c, e0, e1, N, D, int(e));
    }
    if (type == LIGHT_SKY) {  // the hemisphere about up; the same plane again counts once
        m[0] = centre, m[1] = centre, m[2] = centre, m[3] = centre;
    } else {
        vec3 e0 = u_light_extent[2 * i].xyz, e1 = u_light_extent[2 * i + 1].xyz;
        vec3 c = centre - P;
        if (max(length(e0), length(e1)) < kExactMinSize * length(c)) return -1.0;
        // The rect's corners seen from P, and each edge's plane, its normal turned inwards.
        vec3 q0 = c - e0 - e1, q1 = c + e0 - e1, q2 = c + e0 + e1, q3 = c - e0 + e1;
        float winding = dot(cross(q0, q1), c) >= 0.0 ? 1.0 : -1.0;
        m[0] = winding * normalize(cross(q0, q1)), m[1] = winding * normalize(cross(q1, q2));
        m[2] = winding * normalize(cross(q2, q3)), m[3] = winding * normalize(cross(q3, q0));
    }
    m[4] = N, m[5] = D;
    return lobe_integral_in_hemispheres(m, D, int(e));
#endif
}

// Whether P is in front of light i's emitter (a sky is in front of every point).
bool faces_emitter(int i, int type, vec3 P) {
    return type == LIGHT_SKY || dot(P - u_light_vector[i].xyz, u_light_spot[i].xyz) > 0.0;
}
