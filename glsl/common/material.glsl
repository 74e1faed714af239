// Per-object materials, read from a buffer texture (one record per object).
// Layout written by renderer/passes/material_buffer.cpp; keep the two in step.

#define MODEL_HIGHLIGHT 0
#define MODEL_TRANSLUCENT 1
#define MODEL_METAL 2
#define MODEL_METAL_BLINN 3
#define MODEL_METAL_PHONG 4

#define MATERIAL_TEXELS 5
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
    return mat;
}
