// The family of models read from BRDF Explorer files (renderer/brdf_file/):
// f(L, V, N, X, Y) is the file's BRDF, reached through the generated
// dispatcher brdf_eval. On the classic models' scale (docs/models.md, "Units"),
// each light adds pi f (N.L)+ a_l c_l (light.scale: a_l c_l att_l C_spot,l);
// X, Y are the tangent frame of the material's axis (T, B of docs/models.md).
// No CPU twin: the file's code exists only as GLSL.
#include "terms/anisotropic.glsl"

vec3 shade_brdf(Material mat, vec3 P, vec3 N, vec3 V) {
    vec3 X, Y;
    tangent_frame(mat.axis, N, X, Y);
    vec3 I = vec3(0.0);
    for (int i = 0; i < LIGHT_LOOP_END; ++i) FOR_EACH_SAMPLE_OF_LIGHT(i, P, N, V, vec3(0.0)) {
        LightSample light = light_sample_of(i, P, N);
        float NoL = dot(N, light.L);
        if (NoL <= 0.0) continue;  // (N.L)+: the BRDF is not evaluated below the horizon
        I += light.scale * (PI * NoL) * brdf_eval(mat, light.L, V, N, X, Y);
    }
    return I;
}
