#version 330 core
// docs/spec.md#2-display: the M3055's post pass. Linear colour (no gamma) to display
// levels, then to the 8-bit value the PNG stores:
//   level = clamp(floor(c (2^bits - 1) + 0.5), 0, 2^bits - 1),  c clamped to [0, 1]
//   png   = round(level * 255 / (2^bits - 1))
// The output is png / 255, which an RGBA8 target stores exactly as png.
// C++ twin: renderer/image/quantize.h.

uniform sampler2D u_colour;   // the unquantized frame (RGBA32F)
uniform int u_bits;           // 1..8
uniform bool u_dither;        // ordered 4x4 Bayer dithering instead of rounding

out vec4 o_display;

// Bayer threshold in (0, 1), mean 0.5, so dithering is unbiased against rounding.
float bayer4(ivec2 p) {
    int m[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
    return (float(m[(p.y & 3) * 4 + (p.x & 3)]) + 0.5) / 16.0;
}

float quantize(float c, float max_level, float offset) {
    c = c > 0.0 ? min(c, 1.0) : 0.0;  // also sends NaN to 0
    float level = clamp(floor(c * max_level + offset), 0.0, max_level);
    return floor(level * 255.0 / max_level + 0.5) / 255.0;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 c = texelFetch(u_colour, p, 0).rgb;
    float max_level = float((1 << u_bits) - 1);
    float offset = u_dither ? bayer4(p) : 0.5;
    o_display = vec4(quantize(c.r, max_level, offset), quantize(c.g, max_level, offset),
                     quantize(c.b, max_level, offset), 1.0);
}
