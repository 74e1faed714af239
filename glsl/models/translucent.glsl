// docs/spec.md#42-translucent: a translucent object (eq. 5-8): Newell's blend with Kay's opacity,
// plus the highlight of 4.1. As a premultiplied "over":
//   C = color + transmittance * C_B,
//   color = S + (1 - S) t C1,  transmittance = (1 - S)(1 - t),  1 - S = keep.
// The translucent model's hook. C++ twin: ref::shade_translucent.
#include "models/highlight.glsl"
#include "terms/kay_opacity.glsl"

void shade_translucent(Material mat, vec3 P, vec3 N, vec3 V,
                       out vec3 color, out vec3 transmittance) {
    HighlightParts parts = highlight_parts(mat, P, N, V);
    float t = kay_opacity(mat.t_n, mat.t_p, dot(N, V));
    color = (1.0 - parts.keep) + parts.keep * t * parts.C1;
    transmittance = parts.keep * (1.0 - t);
}
