// Lights: docs/spec.md#3-geometry (directional, point) and the lecture's spot and attenuation,
// the rect, disk and sky lights and the shadows of docs/spec.md#75-area-lights-the-sky-and-shadows.
// C++ twin: ref::sample_light. Disabled and zero-intensity lights never reach
// the shader: the renderer drops them.
//
// Every model sums over its lights the same way:
//     for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, lobe_exponents(mat, i)) {
//         LightSample light = light_sample_of(i, P, N);
// Without area lights and shadows (HAS_AREA_LIGHTS, HAS_SHADOWS) that is the
// plain loop over the lights, token for token, so those programs and their
// pixels are exactly what they were. With them each light is walked sample
// by sample: one sample for a directional, point or spot light (blocked, scale
// 0, where a shadow falls), n x n for an area light (common/area_lights.glsl).
// A light's own data (its lobes, spectral tables, ambient) stay indexed by i.

#define LIGHT_DIRECTIONAL 0
#define LIGHT_POINT 1
#define LIGHT_SPOT 2

// The kinds of a light's own lobes (scene.h LobeKind): Beckmann {w, m}, exponent {w, n}.
#define LIGHT_LOBES_BECKMANN 0
#define LIGHT_LOBES_EXPONENT 1

uniform int u_light_count;
uniform vec4 u_light_vector[MAX_LIGHTS];   // xyz: direction towards the light, or position; w: type
uniform vec3 u_light_scale[MAX_LIGHTS];    // a_l * c_l
uniform vec4 u_light_spot[MAX_LIGHTS];     // xyz: spot direction (unit); w: spot exponent
uniform vec3 u_light_att[MAX_LIGHTS];      // S_c, S_l, S_q
uniform int u_light_lobe_count[MAX_LIGHTS];  // 0: the light uses the material's lobes
uniform int u_light_lobe_kind[MAX_LIGHTS];   // LIGHT_LOBES_BECKMANN or LIGHT_LOBES_EXPONENT
uniform vec4 u_light_lobes[MAX_LIGHTS * 2];  // (w0, m0, w1, m1), (w2, m2, w3, m3)

struct LightSample {
    vec3 L;      // unit vector towards the light
    vec3 scale;  // a_l c_l x attenuation x spot factor; an area light's sample: L dw
    float spot;  // the spot factor C_spot alone (1 unless a spot): classic models' ambient
#ifdef HAS_AREA_LIGHTS
    bool area;   // a sample of an area or sky light: one of ever more, ever weaker lights
#endif
};

// Distance attenuation 1 / (S_c + S_l r + S_q r^2) (lecture notes, seed 003).
float distance_attenuation(vec3 att, float r) {
    return 1.0 / max(att.x + att.y * r + att.z * r * r, 1e-6);
}

// C_spot = ((-L . L_dir)+)^L_exp (lecture notes, seed 003).
float spot_factor(vec3 L, vec4 spot) {
    return pow_safe(max(dot(-L, spot.xyz), 0.0), spot.w);
}

LightSample light_sample(int i, vec3 P) {
    LightSample s;
    s.spot = 1.0;
    int type = int(u_light_vector[i].w);
    if (type == LIGHT_DIRECTIONAL) {
        s.L = u_light_vector[i].xyz;
        s.scale = u_light_scale[i];
        return s;
    }
#ifdef HAS_POINT_LIGHTS
    vec3 to_light = u_light_vector[i].xyz - P;
    float r = length(to_light);
    s.L = to_light / max(r, 1e-30);
    float factor = distance_attenuation(u_light_att[i], r);
#ifdef HAS_SPOT_LIGHTS
    if (type == LIGHT_SPOT) {
        s.spot = spot_factor(s.L, u_light_spot[i]);
        factor *= s.spot;
    }
#endif
    s.scale = u_light_scale[i] * factor;
#endif
    return s;
}

// How many lobes of `kind` light i carries (0: the material's lobes apply).
// Its own lobes replace the material's for the models that read that kind
// (docs/spec.md#43-metal, the paper's Fig. 11).
int light_lobe_count(int i, int kind) {
#ifndef HAS_LIGHT_LOBES
    return 0;
#endif
    return (u_light_lobe_count[i] > 0 && u_light_lobe_kind[i] == kind) ? u_light_lobe_count[i] : 0;
}

vec2 light_lobe(int i, int j) {
    vec4 pair = u_light_lobes[i * 2 + j / 2];
    return (j % 2 == 0) ? pair.xy : pair.zw;
}

#ifdef HAS_SHADOWS
#include "common/shadows.glsl"
uniform int u_light_shadow[MAX_LIGHTS];  // 1: the light casts shadows
uniform int u_shadow_samples;            // a rect's or disk's probe: this squared rays (at most 3 x 3)
#endif
#ifdef HAS_AREA_LIGHTS
#include "common/area_lights.glsl"
#endif
#if defined(HAS_AREA_LIGHTS) && defined(HAS_SHADOWS)
#include "common/sky_occluders.glsl"
#endif

#if defined(HAS_AREA_LIGHTS) || defined(HAS_SHADOWS)
// Where a model's walk over light i's samples stands.
struct LightWalk {
    int k, n;            // the sample, and how many the light has (0: it cannot reach the point)
    int type;
    vec2 rotation;       // the strata's rotation (area lights)
    float ratio;         // area lights: E / E_s (common/area_lights.glsl); else 1
    vec4 exact_pair;     // area lights, with the lobe's closed form: (alpha, beta, lambda, e) of pair_factor; else 0
    bool traced;         // area lights: each sample's own shadow ray decides whether it is seen (a penumbra)
    int from_emitter;    // area lights: samples 0 .. from_emitter - 1 drawn from the emitter, the rest from the lobe
    int side;            // area lights: the emitter's samples and the lobe's are each side x side strata
    vec3 lobe_axis;      // V's mirror direction
    int occluder_from;   // a shadowed sky: samples occluder_from .. n - 1 are of what the objects block
    int occluder_mask;   // ... drawn about the objects of these bits (common/sky_occluders.glsl)
    int occluder_per;    // ... so many about each object
    vec4 occluder_lobe;  // ... and as many from the highlight's lobe (axis, exponent; 0: none)
    int occluder_exact;   // ... of them, the spheres and boxes whose part is exact (occluder_exact_ratio)
    float occluder_ratio; // ... and the scale of the samples that meet them
    float lobe_exponent; // the model's lobe about it that samples are drawn from (generated/models.glsl: lobe_exponents)
    bool two_points;     // the preview (n = 1): a point where the highlight is beside the centre (preview_point)
};

#ifdef HAS_AREA_LIGHTS
// Below this exponent the lobe is about as wide as the cosine the emitter's
// samples follow. Above it, even a wide lobe needs its own samples: a
// highlight's (R.V)^m has no N.L to cancel the sky's 1 / cos at grazing angles.
const float kLobeMinExponent = 1.0;

// Sample k of the walk: its direction, and the weight that makes the sum over
// the walk of weight x L x r an estimate of the light's integral: the balance
// heuristic of the two ways of drawing directions (Veach 1997, multiple
// importance sampling), 1 / (n_e p_e + n_l p_l); 0 off the emitter.
AreaSample walk_direction(int i, LightWalk walk, vec3 P, vec3 N, out float weight) {
    int n = walk.side;
    int from_lobe = (walk.occluder_mask != 0 ? walk.occluder_from : walk.n) - walk.from_emitter;
    AreaSample s;
    if (walk.two_points) {
        // The preview's two points (light_walk), each an estimate of its own: the pair's
        // factors make the two one.
        s = preview_point(i, walk.type, walk.k, P, N, walk.lobe_axis);
        weight = s.pdf > 0.0 ? 1.0 / s.pdf : 0.0;
        return s;
    }
    if (walk.k < walk.from_emitter) {
        s = area_sample(i, walk.type, walk.k, n, walk.rotation, P, N);
    } else {
        vec2 u = stratum_point(walk.k - walk.from_emitter, walk.side, walk.rotation.yx);
        vec3 w = lobe_technique_direction(u, walk.lobe_axis, walk.lobe_exponent, walk.type);
        s = area_sample_towards(i, walk.type, P, N, w);
    }
    float lobe_pdf = from_lobe > 0 ? lobe_technique_pdf(s.L, walk.lobe_axis, walk.lobe_exponent, walk.type) : 0.0;
    weight = s.pdf > 0.0 ? 1.0 / (float(walk.from_emitter) * s.pdf + float(from_lobe) * lobe_pdf) : 0.0;
    return s;
}
#endif

#if defined(HAS_AREA_LIGHTS) && defined(HAS_SHADOWS)
// Light i's emitter from P: 1 wholly seen, 0 wholly hidden, -1 in part (a
// penumbra) or not probed. A rect or disk is probed with u_shadow_samples^2
// rays (at most 3 x 3; 2 x 2 probes missed the edges of penumbrae: 1.6 % of a
// floor's pixels a level off, docs/lights.md); the sky, large enough that what
// stands beside a point hides part of it almost everywhere, is never probed: its
// shadow is what the objects block (common/sky_occluders.glsl), or, with more
// than MAX_SKY_OCCLUDERS objects, a ray a sample.
// The preview (n = 1), the sky's too: its one point (a rect's or disk's centre,
// or the point nearest it above N's horizon; the sky's between N and up), the
// one ray of a hard shadow for its two points (a ray each drew the objects'
// mirror images on a floor under the sky, where its highlight's point met them).
float emitter_seen(int i, int type, vec2 rotation, vec3 P, vec3 N) {
    int probe = u_area_samples <= 1 ? 1 : min(3, u_shadow_samples);
    if (type == LIGHT_SKY && probe > 1) return -1.0;
    bool some_seen = false, some_hidden = false;
    for (int k = 0; k < probe * probe; ++k) {
        // The probes on a lattice that takes in the emitter's edge (u = 0 and 1:
        // its corners and edges' midpoints, and its centre at 3 x 3), the same
        // for every pixel: an occluder's edge enters a penumbra across the
        // emitter's boundary, where rotated strata's centres, 1/6 in, missed it.
        vec2 u = probe > 1 ? vec2(float(k % probe), float(k / probe)) / float(probe - 1) : vec2(0.5);
        AreaSample s;  // (no ?: between structures in GLSL ES)
        if (probe > 1) s = area_sample_at(i, type, u, P, N);
        else s = area_sample(i, type, 0, 1, rotation, P, N);
        if (!(s.pdf > 0.0 && dot(N, s.L) > 0.0)) continue;
        if (occluded(P, N, s.L, s.distance)) some_hidden = true;
        else some_seen = true;
        if (some_seen && some_hidden) return -1.0;
    }
    if (some_seen == some_hidden) return -1.0;  // no probe above the horizon
    return some_seen ? 1.0 : 0.0;
}
#endif

#ifdef HAS_AREA_LIGHTS
// The highlight's lobe ((D . L)+)^e above N's horizon: what area_exact_lobe integrates.
float lobe_value(vec3 L, vec3 N, vec3 D, float e) {
    float c = dot(D, L);
    return dot(N, L) > 0.0 && c > 0.0 ? pow(c, e) : 0.0;
}

// A sample's share p of the cosine in cosine + lambda x lobe (lambda = E / A: the
// two alike in size); 1 - p is the lobe's.
float cosine_share(float c, float l, float lambda) {
    float sum = c + lambda * l;
    return sum > 0.0 ? c / sum : 1.0;
}

// Where both closed forms apply (a highlight's lobe under a rect, a disk or the sky), each
// sample is scaled by alpha p + beta (1 - p) instead of E / E_s: the two factors
// that make the samples' sums of N . L and of the lobe ((D . L)+)^e both exact
// (E, Lambert's formula, and A, common/lobe_moment.glsl; e = exact_pair.w, the
// model's lobe exponent rounded to a whole number). The estimate is then exact
// for any mix of the two (a highlight's diffuse and its (R_V . L)^m, Phong's),
// and the factors tend to 1 as the samples grow, so every other model (a
// microfacet lobe, a metal's, whose exponent the whole e only approximates)
// converges as before, with less noise the closer its lobe is to the pair:
// control variates with two closed forms.
float pair_share(vec4 exact_pair, vec3 L, vec3 N, vec3 D) {
    return cosine_share(max(dot(N, L), 0.0), lobe_value(L, N, D, exact_pair.w), exact_pair.z);
}

float pair_factor(vec4 exact_pair, vec3 L, vec3 N, vec3 D) {
    float p = pair_share(exact_pair, L, N, D);
    return exact_pair.x * p + exact_pair.y * (1.0 - p);
}
#endif

#ifdef HAS_AREA_LIGHTS
// The strata along each side of light i's squares of samples: u_area_samples, the sky's
// twice as many where the model has a lobe the pair's closed forms do not make exact (a
// metal's, a microfacet lobe's): the whole sky reaches all of such a lobe, and its noise
// was the unshadowed sky's error (docs/lights.md, "eighth"). So also for a lobe too wide
// to draw samples from (e < kLobeMinExponent: a principled surface of roughness over
// 0.84, its retro-reflection and grazing Fresnel left to the cosine's samples: a floor
// 94.0 -> 98.2 % on the same level, "fourteenth"). Not where each sample would
// trace its own ray (a shadowed sky over more objects than are drawn about): four times
// the rays. Only up to kMaxSkySide: llvmpipe leaves every loop of a pixel after 65 535
// iterations in all (docs/lights.md, "fourth"; at 12 a side, 24 doubled or 16, the sky
// fill's metal cylinder reached it).
const int kMaxSkySide = 16;
bool doubled_sky_side_fits() {
    return 2 * u_area_samples <= kMaxSkySide;
}

int area_side(int i, int type, vec3 lobes) {
    bool inexact_lobe = lobes.x > 0.0 && lobes.z == 0.0;
    bool untraced = true;
#ifdef HAS_SHADOWS
    untraced = u_light_shadow[i] == 0 || u_sky_occluder_count > 0;
#endif
    bool twice = type == LIGHT_SKY && inexact_lobe && untraced && u_area_samples > 1 && doubled_sky_side_fits();
    return twice ? 2 * u_area_samples : u_area_samples;
}
#endif

#if defined(HAS_AREA_LIGHTS) && defined(HAS_SHADOWS)
// The most objects drawn about (each a sphere or a box) for which a shadowed sky's blocked
// part takes four times the samples: every sample walks every object (docs/lights.md, "eighth").
const int kMaxDenseOccluders = 2;
#endif

// `lobes`: the Phong exponents of the model's highlight about V's mirror direction (0: none),
// the one its samples are drawn from and the one its closed form controls (ModelSpec::glsl_lobe,
// glsl_control_lobe), and 1 where the highlight is exactly that lobe (glsl_lobe_exact).
LightWalk light_walk(int i, vec3 P, vec3 N, vec3 V, vec3 lobes) {
    float lobe = lobes.x;
    LightWalk walk;
    walk.k = 0;
    walk.n = 1;
    walk.type = int(u_light_vector[i].w);
    walk.rotation = vec2(0.0);
    walk.ratio = 1.0;
    walk.exact_pair = vec4(0.0);
    walk.traced = false;
    walk.from_emitter = 1;
    walk.side = 1;
    walk.lobe_axis = 2.0 * dot(N, V) * N - V;
    walk.occluder_from = 0;
    walk.occluder_mask = 0;
    walk.occluder_per = 0;
    walk.occluder_lobe = vec4(0.0);
    walk.occluder_exact = 0;
    walk.occluder_ratio = 1.0;
    walk.lobe_exponent = lobe;
    walk.two_points = false;
#ifdef HAS_AREA_LIGHTS
    if (walk.type < LIGHT_RECT) return walk;
    if (!faces_emitter(i, walk.type, P)) {
        walk.n = 0;
        return walk;
    }
    int n = area_side(i, walk.type, lobes);
    walk.from_emitter = n * n;
    // One sample: the emitter's centre (the explorer's fast path), not a random point.
    walk.rotation = n > 1 ? strata_rotation(i) : vec2(0.0);
    // As many lobe samples as the emitter's, the sky's too (a quarter as many left a shadowed sky
    // that traced them 3 levels off in places).
    walk.side = n;
    walk.n = walk.from_emitter + ((n > 1 && lobe >= kLobeMinExponent) ? n * n : 0);
#ifdef HAS_SHADOWS
    if (u_light_shadow[i] != 0) {
        float seen = emitter_seen(i, walk.type, walk.rotation, P, N);
        if (seen == 0.0) {
            walk.n = 0;
            return walk;
        }
        walk.traced = seen < 0.0;
    }
#endif
    float exact = area_exact_projected(i, walk.type, P, N);
    if (exact < 0.0) return walk;
#ifdef HAS_LOBE_CLOSED_FORM
    // The preview's one sample and, with the lobe's closed form, a second where the
    // highlight is: the pair below then makes the two exact for a highlight's cosine
    // and lobe together (kept only where the pair holds).
    walk.two_points = n == 1 && lobe >= kLobeMinExponent && lobes.z > 0.0;
    if (walk.two_points) walk.n = 2;
#endif
    // The pair's lobe, exact for the paper's m and Phong's, near for the rest. Of a mixture's lobes
    // (lobes.x the sharpest, lobes.y the one that reflects most light) the one the emitter's own
    // samples resolve worst: across a rect or disk, sampled uniformly in area, the heaviest
    // (a broad lobe that varies over the whole emitter); under the sky, whose cosine-weighted
    // samples follow a broad lobe, the sharpest (docs/lights.md, "fourth").
    float whole = max(floor((walk.type == LIGHT_SKY ? lobes.x : lobes.y) + 0.5), 1.0);
    float exact_lobe = walk.n > walk.from_emitter ? area_exact_lobe(i, walk.type, P, N, walk.lobe_axis, whole) : -1.0;
    // Too little of the lobe on the emitter (under 1e-3 of its whole, 2 pi / (e + 1)) for
    // float to keep its integral: E / E_s alone. The preview's two points take the pair down
    // to 1e-6 of it: a highlight's tail there, its value at one point times E / cos, was up
    // to 6e-4 off; the pair's error is A's, a float's share of an integral that small.
    bool pair = exact > 0.0 && exact_lobe > (walk.two_points ? 1e-6 : 1e-3) * 2.0 * PI / (whole + 1.0);
    float lambda = pair ? exact / exact_lobe : 0.0;
    float sampled = 0.0;
    vec4 sums = vec4(0.0);  // sum of weight x (p cos, (1 - p) cos, p lobe, (1 - p) lobe)
    vec2 shares = vec2(0.0);  // the preview's two points: their p
    for (LightWalk w = walk; w.k < w.n; ++w.k) {
        float weight;
        AreaSample s = walk_direction(i, w, P, N, weight);
        float c = max(dot(N, s.L), 0.0);
        sampled += weight * c;
        if (pair) {
            float l = lobe_value(s.L, N, walk.lobe_axis, whole), p = cosine_share(c, l, lambda);
            sums += weight * vec4(p * c, (1.0 - p) * c, p * l, (1.0 - p) * l);
            if (w.k == 0) shares.x = p;
            else if (w.k == 1) shares.y = p;
        }
    }
    if (sampled > 0.0) walk.ratio = exact / sampled;
    if (pair) {
        // alpha sums.x + beta sums.y = E and alpha sums.z + beta sums.w = A.
        float det = sums.x * sums.w - sums.y * sums.z;
        float alpha = (exact * sums.w - exact_lobe * sums.y) / det;
        float beta = (exact_lobe * sums.x - exact * sums.z) / det;
        // Only where the two are told apart well and both factors stay positive (else E / E_s alone).
        // The preview's two points need only their own factors positive (each point's
        // alpha p + beta (1 - p)); of many samples, with shares between 0 and 1, the factors.
        vec2 factors = walk.two_points ? alpha * shares + beta * (1.0 - shares) : vec2(alpha, beta);
        if (abs(det) > 1e-3 * (sums.x * sums.w + sums.y * sums.z) && factors.x > 0.0 && factors.y > 0.0)
            walk.exact_pair = vec4(alpha, beta, lambda, whole);
    }
#ifdef HAS_LOBE_CLOSED_FORM
    // Without the pair the preview's second point would weigh a sharp highlight's peak
    // as if it covered the emitter: the centre alone, as before.
    if (walk.two_points && walk.exact_pair.x <= 0.0) {
        walk.n = 1;
        walk.two_points = false;
        float weight;
        AreaSample s = walk_direction(i, walk, P, N, weight);
        float c = weight * max(dot(N, s.L), 0.0);
        walk.ratio = c > 0.0 ? exact / c : 1.0;
    }
#endif
#ifdef HAS_SHADOWS
    // A shadowed sky: its samples as unshadowed, then what the objects block
    // (common/sky_occluders.glsl), where they are few enough to be drawn about.
    if (walk.type == LIGHT_SKY && walk.traced && u_sky_occluder_count > 0 && n > 1) {
        walk.traced = false;
        vec3 up = u_light_vector[i].xyz;
        walk.occluder_mask = occluder_mask(P, N, up);
        walk.occluder_from = walk.n;
        float exact_part = occluder_exact_part(walk.occluder_mask, P, N, up, walk.occluder_exact);
        // Four times the samples about each object for a highlight's lobe (which the
        // closed forms leave to them), and for the estimate of two exact silhouettes'
        // overlap, where at most kMaxDenseOccluders objects are drawn about, each a
        // sphere or a box: a sample that meets one traces no ray. Every sample walks
        // every object drawn about (its density), and llvmpipe leaves all loops of a
        // pixel after 65 535 iterations: with more objects, or a mesh's rays, a scene of
        // eight objects lost its light (docs/lights.md, "eighth"). Not for a sharp lobe,
        // which draws its own samples below: the two together passed that limit on a
        // mirror sphere beside a cube, which lost what the cube blocks (0.48 where it is 0,
        // "fifteenth").
        bool dense_fits = walk.occluder_exact == walk.occluder_mask && lobe <= kSharpLobeFrom &&
                          bit_count(walk.occluder_mask) <= kMaxDenseOccluders && doubled_sky_side_fits();
        int per = sky_occluder_samples(u_area_samples);
        int dense = dense_fits ? sky_occluder_samples(2 * u_area_samples) : per;
        walk.occluder_per = lobe >= kLobeMinExponent ? dense : per;
        // With more objects than that, or a sharp lobe, as many samples again from the
        // highlight's lobe, which the cones meet too seldom ("thirteenth"; "fifteenth": a
        // glossy floor lost two objects' mirror images to the cones' samples, and one that
        // met the lobe's peak drew a pixel at -5.5). With fewer objects and a broad lobe,
        // its samples moved the matrix by a few hundredths of a percent for a fifth more
        // time ("eleventh").
        bool many = bit_count(walk.occluder_mask) > kMaxDenseOccluders;
        if (lobe >= kLobeMinExponent && walk.occluder_mask != 0 && (many || lobe > kSharpLobeFrom))
            walk.occluder_lobe = vec4(walk.lobe_axis, lobe);
        walk.n += occluder_techniques(walk.occluder_mask, walk.occluder_lobe) * walk.occluder_per;
        if (walk.occluder_mask != 0)
            walk.occluder_ratio = occluder_exact_ratio(walk.occluder_per, dense, walk.occluder_mask, walk.occluder_lobe,
                                                       walk.rotation, P, N, up, walk.occluder_exact, exact_part);
    }
#endif
#endif
    return walk;
}

#ifdef HAS_SHADOWS
// How far light i is from P along its sample (< 0: infinitely far).
float light_distance(int i, vec3 P) {
    return int(u_light_vector[i].w) == LIGHT_DIRECTIONAL ? -1.0 : length(u_light_vector[i].xyz - P);
}
#endif

#if defined(HAS_AREA_LIGHTS) && defined(HAS_SHADOWS)
// A blocked sample's share of the cosine, what the exact part's factor scales: the
// pair's share where it holds; else, for a model with a lobe, the cosine's share of
// the cosine's and the lobe technique's densities, c / (c + pi p_lobe); 1 without a
// lobe. (A sharp lobe without the pair, all of it scaled by the cosine's factor: a
// glossy floor under five objects 92.9 % on the same level, a mirror image of a cube
// at -0.059; with the densities' share 94.2 %, -0.0064: docs/lights.md, "fifteenth".)
float blocked_cosine_share(LightWalk walk, vec3 L, vec3 N) {
    if (walk.exact_pair.x > 0.0) return pair_share(walk.exact_pair, L, N, walk.lobe_axis);
    if (walk.lobe_exponent < kLobeMinExponent) return 1.0;
    float c = max(dot(N, L), 0.0);
    float lobe = PI * lobe_technique_pdf(L, walk.lobe_axis, walk.lobe_exponent, LIGHT_SKY);
    return c + lobe > 0.0 ? c / (c + lobe) : 1.0;
}
#endif

LightSample light_walk_sample(int i, LightWalk walk, vec3 P, vec3 N) {
#if defined(HAS_AREA_LIGHTS) && defined(HAS_SHADOWS)
    if (walk.occluder_mask != 0 && walk.k >= walk.occluder_from) {
        // What an object blocks of the sky: taken away, as a sample of negative light.
        vec3 up = u_light_vector[i].xyz;
        float weight;
        LightSample s;
        s.L = occluder_sample(walk.k - walk.occluder_from, walk.occluder_per, walk.occluder_mask, walk.occluder_lobe,
                              walk.rotation, P, N, up, weight);
        s.spot = 1.0;
        s.area = true;
        int blocker = weight > 0.0 && dot(N, s.L) > 0.0 && dot(up, s.L) > 0.0
                          ? occluder_blocker(walk.occluder_mask, walk.occluder_exact, P, N, s.L)
                          : kBlockedByNothing;
        // Met by an exact shape: the exact part's factor on the sample's share of the
        // cosine: a highlight's lobe, which the cones sample poorly, is not scaled by a
        // factor the cosine alone set (that drew a metal's top under a wall below zero).
        float factor = 1.0;
        if (blocker == kBlockedByExactShape)
            factor = 1.0 + (walk.occluder_ratio - 1.0) * blocked_cosine_share(walk, s.L, N);
        s.scale = blocker != kBlockedByNothing ? -u_light_scale[i] * (weight * factor) : vec3(0.0);
        return s;
    }
#endif
#ifdef HAS_AREA_LIGHTS
    if (walk.type >= LIGHT_RECT) {
        float weight;
        AreaSample a = walk_direction(i, walk, P, N, weight);
        LightSample s;
        s.L = a.L;
        s.spot = 1.0;
        s.area = true;
        // Nothing from below the horizon, whatever the model does with N . L < 0.
        bool lit = weight > 0.0 && dot(N, a.L) > 0.0;
#ifdef HAS_SHADOWS
        // Each sample its own ray: the shadowed integral's estimate, consistent for every
        // model (one visibility for the whole light, weighted by N.L, biased a highlight
        // whose lobe sees the occluders more or less than the cosine does).
        if (lit && walk.traced) lit = !occluded(P, N, a.L, a.distance);
#endif
        float factor = walk.exact_pair.x > 0.0
                           ? pair_factor(walk.exact_pair, a.L, N, walk.lobe_axis)
                           : walk.ratio;
        s.scale = lit ? u_light_scale[i] * (weight * factor) : vec3(0.0);
        return s;
    }
#endif
    LightSample s = light_sample(i, P);
#ifdef HAS_AREA_LIGHTS
    s.area = false;
#endif
#ifdef HAS_SHADOWS
    if (u_light_shadow[i] != 0 && occluded(P, N, s.L, light_distance(i, P))) s.scale = vec3(0.0);
#endif
    return s;
}

// V: towards the viewer; LOBE: the model's lobe_exponents (area lights draw samples from it too;
// without area lights it is not declared, and a shadow's one ray needs none).
// (One line: GLSL 3.30 and ES 3.00 have no line continuation.)
#ifdef HAS_AREA_LIGHTS
#define FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, LOBE) for (LightWalk light_walk_ = light_walk(i, P, N, V, LOBE); light_walk_.k < light_walk_.n; ++light_walk_.k)
#else
// Shadows without area lights: one sample a light, none drawn from a lobe (nor is lobe_exponents generated).
#define FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, LOBE) for (LightWalk light_walk_ = light_walk(i, P, N, V, vec3(0.0)); light_walk_.k < light_walk_.n; ++light_walk_.k)
#endif
#define light_sample_of(i, P, N) light_walk_sample(i, light_walk_, P, N)
#else
#define FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, LOBE)
#define light_sample_of(i, P, N) light_sample(i, P)
#endif
