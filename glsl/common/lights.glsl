// Lights: docs/spec.md#3-geometry (directional, point) and the lecture's spot and attenuation.
// C++ twin: ref::sample_light. Disabled and zero-intensity lights never reach
// the shader: the renderer drops them.

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
    vec3 scale;  // a_l c_l x attenuation x spot factor
    float spot;  // the spot factor C_spot alone (1 unless a spot): classic models' ambient
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
