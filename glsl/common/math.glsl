// Numeric helpers shared by every term. C++ twin: renderer/reference/terms.cpp.

// x^e with x^0 = 1 for every x >= 0 (docs/spec.md#4-paper-models). GLSL leaves pow(0, 0) undefined.
float pow_safe(float x, float e) {
    if (e <= 0.0) return 1.0;
    if (x <= 0.0) return 0.0;
    return pow(x, e);
}

// 1 - cos of the angle between a and b (any lengths). Near 0 the float
// 1 - dot(a, b) keeps no digits, so use 1 - cos = sin^2 / (1 + cos) with sin
// from the cross product, which stays accurate for tiny angles.
float one_minus_cos(vec3 a, vec3 b) {
    float inv_len2 = 1.0 / (dot(a, a) * dot(b, b));
    float inv_len = sqrt(inv_len2);
    float c = dot(a, b) * inv_len;
    if (c <= 0.0) return 1.0 - c;
    vec3 x = cross(a, b);
    float sin2 = dot(x, x) * inv_len2;
    return sin2 / (1.0 + c);
}

// log(1 - delta), accurate for small delta (GLSL has no log1p).
float log_one_minus(float delta) {
    if (delta < 0.01) {
        return -delta * (1.0 + delta * (1.0 / 2.0 + delta * (1.0 / 3.0 + delta * (1.0 / 4.0 + delta / 5.0))));
    }
    return log(1.0 - delta);
}

// cos of the angle between a and b (any lengths), as one_minus_cos computes it.
float cos_between(vec3 a, vec3 b) {
    return dot(a, b) * sqrt(1.0 / (dot(a, a) * dot(b, b)));
}

// (cos+)^e with x^0 = 1, from c = cos and delta = 1 - cos (from one_minus_cos).
// Near cos = 1 the delta form: exponents up to 10000 amplify the error of cos
// ten-thousandfold. Elsewhere pow(c, e): a delta near 1 keeps cos only to
// 6e-8, and exponents below 1 turn that into large errors at cos ~ 0
// (n = 0.3, cos = 2e-7: 7% off; the stress test found it).
float pow_cos(float c, float delta, float e) {
    if (e <= 0.0) return 1.0;
    if (delta < 0.5) return exp(e * log_one_minus(delta));
    return pow_safe(c, e);
}
