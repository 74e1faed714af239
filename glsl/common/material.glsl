// Per-object materials, read from a buffer texture (one record per object).
// Layout written by renderer/passes/material_buffer.cpp; keep the two in step.

#define MODEL_HIGHLIGHT 0
#define MODEL_TRANSLUCENT 1
#define MODEL_METAL 2
#define MODEL_METAL_BLINN 3
#define MODEL_METAL_PHONG 4
// The classic models (SPEC 5, models/classic.glsl), in scene.h's order.
#define MODEL_LAMBERT 5
#define MODEL_HALF_LAMBERT 6
#define MODEL_HALF_LAMBERT_CLAMPED 7
#define MODEL_HALF_LAMBERT_NORMALIZED 8
#define MODEL_OREN_NAYAR 9
#define MODEL_PHONG 10
#define MODEL_BLINN_PHONG 11
#define MODEL_MICROFACET 12
#define MODEL_WARD 13
#define MODEL_HEIDRICH_SEIDEL 14

#define FRESNEL_NONE 0
#define FRESNEL_SCHLICK 1
#define FRESNEL_DIELECTRIC 2

#define MATERIAL_TEXELS 11
#define MAX_LOBES 4

uniform samplerBuffer u_materials;

struct Material {
    int model;
    vec3 color;       // C0
    float d;
    float w;          // highlight brightness
    float m;          // highlight exponent
    float t_n;
    float t_p;
    int lobe_count;
    vec2 lobe[MAX_LOBES];  // (w_j, m_j) or (w_j, n_j)
    // The classic models (texels 5-10, read only for them).
    vec3 kd, ka, ks, emission;  // K_diff, K_amb, K_spec, L_emi
    float shininess, sigma, ior, alpha_x, alpha_y;
    vec3 axis;                  // tangent frame axis (unit)
    int distribution, fresnel;  // microfacet
    vec4 lobe_norm;             // microfacet gaussian: b per lobe
};

Material fetch_material(int index) {
    int base = index * MATERIAL_TEXELS;
    vec4 t0 = texelFetch(u_materials, base + 0);
    vec4 t1 = texelFetch(u_materials, base + 1);
    vec4 t2 = texelFetch(u_materials, base + 2);
    vec4 t3 = texelFetch(u_materials, base + 3);
    vec4 t4 = texelFetch(u_materials, base + 4);
    Material mat;
    mat.color = t0.rgb;
    mat.model = int(t0.a);
    mat.d = t1.x;
    mat.w = t1.y;
    mat.m = t1.z;
    mat.t_n = t1.w;
    mat.t_p = t2.x;
    mat.lobe_count = int(t2.y);
    mat.lobe[0] = t3.xy;
    mat.lobe[1] = t3.zw;
    mat.lobe[2] = t4.xy;
    mat.lobe[3] = t4.zw;
#ifdef HAS_CLASSIC_FAMILY
    if (mat.model >= MODEL_LAMBERT) {
        mat.distribution = int(t2.z);
        mat.fresnel = int(t2.w);
        vec4 t5 = texelFetch(u_materials, base + 5);
        vec4 t6 = texelFetch(u_materials, base + 6);
        vec4 t7 = texelFetch(u_materials, base + 7);
        vec4 t8 = texelFetch(u_materials, base + 8);
        vec4 t9 = texelFetch(u_materials, base + 9);
        mat.kd = t5.rgb;
        mat.shininess = t5.a;
        mat.ka = t6.rgb;
        mat.sigma = t6.a;
        mat.ks = t7.rgb;
        mat.ior = t7.a;
        mat.emission = t8.rgb;
        mat.alpha_x = t8.a;
        mat.axis = t9.xyz;
        mat.alpha_y = t9.w;
        mat.lobe_norm = texelFetch(u_materials, base + 10);
    }
#endif
    return mat;
}
