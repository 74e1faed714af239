// The models' highlights as Phong lobes ((R_V . L)+)^e about V's mirror
// direction R_V, for area lights' second way of drawing directions
// (common/lights.glsl). Only where samples go: any e gives the same converged
// image, a close one converges faster. Each model's expression is its
// ModelSpec::glsl_lobe and glsl_control_lobe (renderer/models/builtin_models.cpp).

// (N.H)^n is (R_V . L)^(n / 4) near the peak (the half-angle doubles the angle).
float exponent_on_half_vector(float n) {
    return 0.25 * n;
}

// A roughness alpha's exp(-tan^2 / alpha^2) on N.H is about (N.H)^(2 / alpha^2).
float exponent_of_roughness(float alpha) {
    return exponent_on_half_vector(2.0 / max(alpha * alpha, 1e-6));
}

// The sharpest of a paper metal's lobes: light i's own (Fig. 11) or the material's.
float sharpest_lobe(Material mat, int i, int kind) {
    int own = light_lobe_count(i, kind);
    int count = own > 0 ? own : mat.lobes_count;
    float sharpest = 0.0;
    for (int j = 0; j < count; ++j) {
        vec2 lobe = own > 0 ? light_lobe(i, j) : mat.lobes[j];
        if (lobe.x > 0.0)
            sharpest = max(sharpest, kind == LIGHT_LOBES_BECKMANN ? exponent_of_roughness(lobe.y) : lobe.y);
    }
    return sharpest;
}

// The classic microfacet model's lobes: exponents (Blinn-Phong D) or roughnesses.
float microfacet_lobe(Material mat) {
    float sharpest = 0.0;
    for (int j = 0; j < mat.lobes_count; ++j) {
        float value = mat.lobes[j].y;
        if (mat.lobes[j].x > 0.0)
            sharpest = max(sharpest, mat.distribution == DISTRIBUTION_BLINN_PHONG ? exponent_on_half_vector(value)
                                                                                  : exponent_of_roughness(value));
    }
    return sharpest;
}

// The lobe of a mixture whose closed form is the samples' control variate under
// a rect or disk (ModelSpec::glsl_control_lobe; the sky's is the sharpest,
// common/lights.glsl: light_walk): the one that reflects most light, which
// varies across the whole of a large emitter that its samples cover uniformly;
// the sharp lobe has samples of its own. A lobe's share is its weight times
// its integral over directions: w for the paper's Beckmann delta and the
// normalized microfacet distributions whatever their roughness, w / (n + 1)
// for w (c+)^n. On a tie the sharper. The paper's metal ({0.013, 0.2},
// {0.1, 0.4}) reflects 8 times as much through its broad lobe as through its
// sharp one, which the samples follow (docs/lights.md).
struct WeighedLobe {
    float share, exponent;
};

WeighedLobe heavier_lobe(WeighedLobe best, float share, float exponent) {
    // (No ?: between structures: WebGL forbids it.)
    if (share > best.share || (share == best.share && exponent > best.exponent)) return WeighedLobe(share, exponent);
    return best;
}

// A paper metal's lobes: light i's own (Fig. 11) or the material's.
float dominant_lobe(Material mat, int i, int kind) {
    int own = light_lobe_count(i, kind);
    int count = own > 0 ? own : mat.lobes_count;
    WeighedLobe best = WeighedLobe(0.0, 0.0);
    for (int j = 0; j < count; ++j) {
        vec2 lobe = own > 0 ? light_lobe(i, j) : mat.lobes[j];
        if (lobe.x <= 0.0) continue;
        if (kind == LIGHT_LOBES_BECKMANN)
            best = heavier_lobe(best, lobe.x, exponent_of_roughness(lobe.y));
        else
            best = heavier_lobe(best, lobe.x / (lobe.y + 1.0), lobe.y);
    }
    return best.exponent;
}

// The classic microfacet model's lobes, their distributions normalized.
float microfacet_dominant_lobe(Material mat) {
    WeighedLobe best = WeighedLobe(0.0, 0.0);
    for (int j = 0; j < mat.lobes_count; ++j) {
        float value = mat.lobes[j].y;
        if (mat.lobes[j].x > 0.0)
            best = heavier_lobe(best, mat.lobes[j].x,
                                mat.distribution == DISTRIBUTION_BLINN_PHONG ? exponent_on_half_vector(value)
                                                                             : exponent_of_roughness(value));
    }
    return best.exponent;
}
