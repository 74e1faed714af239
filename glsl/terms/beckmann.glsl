// eq. 13 / 17: Beckmann distribution, the paper's delta(m, alpha):
//   delta = exp(-tan^2(alpha) / m^2) / (m^2 cos^4(alpha)),   cos(alpha) = N.H
// C++ twin: ref::beckmann_D. one_minus_NoH = 1 - N.H computed accurately
// (common/math.glsl: one_minus_cos), because m = 0.001 turns a 1e-7 error in
// N.H into a visible one.
float beckmann_D(float m, float NoH, float one_minus_NoH) {
    if (NoH <= 0.0) return 0.0;
    float m2 = m * m;
    // tan^2 = (1 - c^2) / c^2 = delta (2 - delta) / c^2
    float tan2 = one_minus_NoH * (2.0 - one_minus_NoH) / (NoH * NoH);
    float x = tan2 / m2;
    // exp(-80) / (m^2 cos^4) < 1e-28 for every legal m: skip, and with it the
    // 0 * inf of exp(-inf) / cos^4 at grazing N.H.
    if (x > 80.0) return 0.0;
    float NoH2 = NoH * NoH;
    return exp(-x) / (m2 * NoH2 * NoH2);
}
