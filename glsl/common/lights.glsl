// Lights: docs/spec.md#3-geometry (directional, point) and the lecture's spot and attenuation,
// the rect, disk and sky lights and the shadows of docs/spec.md#75-area-lights-the-sky-and-shadows.
// C++ twin: ref::sample_light. Disabled and zero-intensity lights never reach
// the shader: the renderer drops them.
//
// Every model sums over its lights the same way:
//     for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, lobe_exponent(mat, i)) {
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
uniform int u_shadow_samples;            // an area light's penumbra: this squared rays
#endif
#ifdef HAS_AREA_LIGHTS
#include "common/area_lights.glsl"
#endif

#if defined(HAS_AREA_LIGHTS) || defined(HAS_SHADOWS)
// Where a model's walk over light i's samples stands.
struct LightWalk {
    int k, n;            // the sample, and how many the light has (0: it cannot reach the point)
    int type;
    vec2 rotation;       // the strata's rotation (area lights)
    float ratio;         // area lights: E / E_s (common/area_lights.glsl) x the part seen past the objects; else 1
    int from_emitter;    // area lights: samples 0 .. from_emitter - 1 drawn from the emitter, the rest from the lobe
    vec3 lobe_axis;      // V's mirror direction
    float lobe_exponent; // the model's lobe about it (generated/models.glsl: lobe_exponent)
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
    int n = u_area_samples;
    int from_lobe = walk.n - walk.from_emitter;
    AreaSample s;
    if (walk.k < walk.from_emitter) {
        s = area_sample(i, walk.type, walk.k, n, walk.rotation, P, N);
    } else {
        vec2 u = stratum_point(walk.k - walk.from_emitter, n, walk.rotation.yx);
        s = area_sample_towards(i, walk.type, P, N, phong_lobe_direction(u, walk.lobe_axis, walk.lobe_exponent));
    }
    float lobe_pdf = from_lobe > 0 ? phong_lobe_pdf(s.L, walk.lobe_axis, walk.lobe_exponent) : 0.0;
    weight = s.pdf > 0.0 ? 1.0 / (float(walk.from_emitter) * s.pdf + float(from_lobe) * lobe_pdf) : 0.0;
    return s;
}
#endif

#if defined(HAS_AREA_LIGHTS) && defined(HAS_SHADOWS)
// Of n x n rays towards area light i, the projected solid angle they stand for
// (y) and the part of it that reaches the light past the objects (x).
vec2 seen_share(int i, int type, int n, vec2 rotation, vec3 P, vec3 N) {
    vec2 share = vec2(0.0);
    for (int k = 0; k < n * n; ++k) {
        AreaSample s = area_sample(i, type, k, n, rotation, P, N);
        float g = s.pdf > 0.0 ? max(dot(N, s.L), 0.0) / s.pdf : 0.0;
        if (g <= 0.0) continue;
        share.y += g;
        if (!occluded(P, N, s.L, s.distance)) share.x += g;
    }
    return share;
}

// The part of area light i that P sees past the objects, weighted as a Lambert
// surface takes it (projected solid angle). Every sample of the light is
// scaled by it: the ratio estimator's shadowed / unshadowed (Heitz et al.
// 2018), exact where the light is wholly seen or wholly hidden. A rect or disk
// is probed with 3 x 3 rays first, and only where they disagree (a penumbra)
// are u_shadow_samples^2 traced (2 x 2 probes missed the edges of penumbrae:
// 1.6 % of a floor's pixels a level off, docs/lights.md). The sky, large
// enough that what stands beside a point hides part of it almost everywhere,
// always takes them all.
float area_visibility(int i, int type, vec2 rotation, vec3 P, vec3 N) {
    int m = u_shadow_samples;
    int probe = min(3, m);
    if (type != LIGHT_SKY && probe < m) {
        vec2 share = seen_share(i, type, probe, rotation, P, N);
        if (share.y > 0.0 && (share.x == 0.0 || share.x == share.y)) return share.x / share.y;
    }
    vec2 share = seen_share(i, type, m, rotation, P, N);
    return share.y > 0.0 ? share.x / share.y : 1.0;
}
#endif

// `lobe`: the Phong exponent of the model's highlight about V's mirror direction (0: none).
LightWalk light_walk(int i, vec3 P, vec3 N, vec3 V, float lobe) {
    LightWalk walk;
    walk.k = 0;
    walk.n = 1;
    walk.type = int(u_light_vector[i].w);
    walk.rotation = vec2(0.0);
    walk.ratio = 1.0;
    walk.from_emitter = 1;
    walk.lobe_axis = 2.0 * dot(N, V) * N - V;
    walk.lobe_exponent = lobe;
#ifdef HAS_AREA_LIGHTS
    if (walk.type < LIGHT_RECT) return walk;
    if (!faces_emitter(i, walk.type, P)) {
        walk.n = 0;
        return walk;
    }
    int n = u_area_samples;
    walk.from_emitter = n * n;
    // One sample: the emitter's centre (the explorer's fast path), not a random point.
    walk.rotation = n > 1 ? strata_rotation(i) : vec2(0.0);
    walk.n = walk.from_emitter + ((n > 1 && lobe >= kLobeMinExponent) ? n * n : 0);
#ifdef HAS_SHADOWS
    if (u_light_shadow[i] != 0) {
        walk.ratio = area_visibility(i, walk.type, walk.rotation, P, N);
        if (walk.ratio == 0.0) {
            walk.n = 0;
            return walk;
        }
    }
#endif
    float exact = area_exact_projected(i, walk.type, P, N);
    if (exact < 0.0) return walk;
    float sampled = 0.0;
    for (LightWalk w = walk; w.k < w.n; ++w.k) {
        float weight;
        AreaSample s = walk_direction(i, w, P, N, weight);
        sampled += weight * max(dot(N, s.L), 0.0);
    }
    if (sampled > 0.0) walk.ratio *= exact / sampled;
#endif
    return walk;
}

#ifdef HAS_SHADOWS
// How far light i is from P along its sample (< 0: infinitely far).
float light_distance(int i, vec3 P) {
    return int(u_light_vector[i].w) == LIGHT_DIRECTIONAL ? -1.0 : length(u_light_vector[i].xyz - P);
}
#endif

LightSample light_walk_sample(int i, LightWalk walk, vec3 P, vec3 N) {
#ifdef HAS_AREA_LIGHTS
    if (walk.type >= LIGHT_RECT) {
        float weight;
        AreaSample a = walk_direction(i, walk, P, N, weight);
        LightSample s;
        s.L = a.L;
        s.spot = 1.0;
        s.area = true;
        // Nothing from below the horizon, whatever the model does with N . L < 0.
        bool lit = weight > 0.0 && dot(N, a.L) > 0.0;  // shadows: in walk.ratio
        s.scale = lit ? u_light_scale[i] * (weight * walk.ratio) : vec3(0.0);
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

// V: towards the viewer; LOBE: the model's lobe_exponent (area lights draw samples from it too;
// without them it is left unexpanded: lobe_exponent exists only with area lights).
// (One line: GLSL 3.30 and ES 3.00 have no line continuation.)
#ifdef HAS_AREA_LIGHTS
#define FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, LOBE) for (LightWalk light_walk_ = light_walk(i, P, N, V, LOBE); light_walk_.k < light_walk_.n; ++light_walk_.k)
#else
#define FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, LOBE) for (LightWalk light_walk_ = light_walk(i, P, N, V, 0.0); light_walk_.k < light_walk_.n; ++light_walk_.k)
#endif
#define light_sample_of(i, P, N) light_walk_sample(i, light_walk_, P, N)
#else
#define FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, LOBE)
#define light_sample_of(i, P, N) light_sample(i, P)
#endif
