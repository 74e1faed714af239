// eq. 6: Kay's opacity, t = t_n ((1 - cos beta)+)^t_p with cos beta = (N.V)+:
// faces towards the viewer are clearer, faces seen edge-on more opaque.
// t = 1 opaque, t = 0 clear; t_p = 0 gives Newell's constant t_n (x^0 = 1).
// C++ twin: ref::kay_opacity.
float kay_opacity(float t_n, float t_p, float NoV) {
    return t_n * pow_safe(max(1.0 - max(NoV, 0.0), 0.0), t_p);
}
