// eq. 12: Cook-Torrance masking and shadowing (Blinn 1977),
//   G = min{1, 2 NoH NoV / VoH, 2 NoH NoL / VoH}.
// C++ twin: ref::ct_G.
float ct_G(float NoH, float NoV, float NoL, float VoH) {
    return min(1.0, min(2.0 * NoH * NoV / VoH, 2.0 * NoH * NoL / VoH));
}

// G / NoV, as eq. 12 uses it, without the 0/0 at grazing view:
//   G / NoV = min(2 NoH / VoH, min(1, 2 NoH NoL / VoH) / NoV)
// which is bounded by 2 NoH / VoH as NoV -> 0. C++ twin: ref::ct_G_over_NoV.
float ct_G_over_NoV(float NoH, float NoV, float NoL, float VoH) {
    if (VoH <= 0.0) return 0.0;  // degenerate H (L = -V), as the twin does
    return min(2.0 * NoH / VoH, min(1.0, 2.0 * NoH * NoL / VoH) / max(NoV, 1e-30));
}
