// eq. 3-4: the highlight blends the diffuse colour towards display white,
//   C = C1 + s (1 - C1),   s = w (cos alpha)^m,
// applied once per light: C = 1 - (1 - C1) prod_l (1 - s_l) (docs/spec.md#41-highlight).

// s_l = clamp(w a_l c_l ((R.V)+)^m, 0, 1), the power from R.V and 1 - R.V.
vec3 highlight_strength(float w, vec3 scale, float RoV, float one_minus_RoV, float m) {
    return clamp(w * scale * pow_cos(RoV, one_minus_RoV, m), 0.0, 1.0);
}

// keep = prod_l (1 - s_l): what is left of C1 after every light's blend.
vec3 highlight_to_white(vec3 C1, vec3 keep) {
    return 1.0 - (1.0 - C1) * keep;
}

// What light sample `light` leaves of C1: 1 - s_l. A sample of an area or sky
// light is one of ever more, ever weaker lights, whose product tends to
// exp(-w integral L ((R.V)+)^m dw): the limit, and the clamp never acts
// (docs/spec.md#75-area-lights-the-sky-and-shadows).
#ifdef HAS_AREA_LIGHTS
#define HIGHLIGHT_KEEP(w, light, RoV, one_minus_RoV, m) (light.area ? exp(-(w) * light.scale * pow_cos(RoV, one_minus_RoV, m)) : 1.0 - highlight_strength(w, light.scale, RoV, one_minus_RoV, m))
#else
#define HIGHLIGHT_KEEP(w, light, RoV, one_minus_RoV, m) (1.0 - highlight_strength(w, light.scale, RoV, one_minus_RoV, m))
#endif
