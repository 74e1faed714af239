#version 330 core
// docs/spec.md#2-display: the M3055's post pass. Linear colour (no gamma) to display
// levels, then to the 8-bit value the PNG stores:
//   level = clamp(floor(v (2^bits - 1) + 0.5), 0, 2^bits - 1),  v = c clamped to [0, 1]
//   png   = round(level * 255 / (2^bits - 1))
// With the sRGB view transform (SRGB defined), v is c's sRGB encoding; with
// DITHER defined, an ordered 4x4 Bayer threshold replaces the 0.5 of rounding.
// Both are defines, not uniforms: a capture compiles only the path it takes
// (llvmpipe's code for the sRGB curve's pow alone cost 8 ms of a cold capture's
// 210, docs/bench/capture.md).
// The output is png / 255, which an RGBA8 target stores exactly as png.
// C++ twin: renderer/image/quantize.h.

uniform sampler2D u_colour;   // the unquantized frame (RGBA32F)
uniform int u_bits;           // 1..8

out vec4 o_display;

// Bayer threshold in (0, 1), mean 0.5, so dithering is unbiased against rounding.
// The 4x4 matrix's entry at (x, y), bit by bit: its bits from high to low are
// x0^y0, y0, x1^y1, y1 (rows 0 8 2 10 / 12 4 14 6 / 3 11 1 9 / 15 7 13 5; a
// constant array indexed at run time made llvmpipe build a table in memory).
float bayer4(ivec2 p) {
    int d = p.x ^ p.y;
    int m = ((d & 1) << 3) | ((p.y & 1) << 2) | (d & 2) | ((p.y >> 1) & 1);
    return (float(m) + 0.5) / 16.0;
}

// IEC 61966-2-1's encoding of a linear value in [0, 1] (C++ twin: srgb_encode).
float srgb_encode(float c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

float quantize(float c, float max_level, float offset) {
    c = c > 0.0 ? min(c, 1.0) : 0.0;  // also sends NaN to 0
#ifdef SRGB
    c = srgb_encode(c);
#endif
    float level = clamp(floor(c * max_level + offset), 0.0, max_level);
    return floor(level * 255.0 / max_level + 0.5) / 255.0;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = texelFetch(u_colour, p, 0).rgb;
    float max_level = float((1 << u_bits) - 1);
#ifdef DITHER
    float offset = bayer4(p);
#else
    float offset = 0.5;
#endif
    o_display = vec4(quantize(c.r, max_level, offset), quantize(c.g, max_level, offset),
                     quantize(c.b, max_level, offset), 1.0);
}
