// Scene light to the display: the exposure of the moment, a filmic tone curve (ACES fit by Narkowicz 2015), then
// the sRGB transfer. Engine: org.openworld.engine.environment.Exposure (frame.exposure.x).
#include "common/frame.glsl"

vec3 toneMapAces(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

// The sRGB encoding. Its power 1/2.4 by three square roots (Ian Taylor's fit, 2012): within a quarter of an 8-bit
// level of 1.055 c^(1/2.4) - 0.055 over the curve's power part, and a square root is one instruction on any CPU or
// GPU where a pow is a logarithm and an exponential; every pixel of every picture pays for this.
vec3 linearToSrgb(vec3 c) {
    vec3 lo = c * 12.92;
    vec3 r1 = sqrt(c);
    vec3 r2 = sqrt(r1);
    vec3 r3 = sqrt(r2);
    vec3 hi = 0.662002687 * r1 + 0.684122060 * r2 - 0.323583601 * r3 - 0.0225411470 * c;
    return mix(lo, hi, step(vec3(0.0031308), c));
}

vec3 srgbToLinear(vec3 c) {
    vec3 lo = c / 12.92;
    vec3 hi = pow((c + 0.055) / 1.055, vec3(2.4));
    return mix(lo, hi, step(vec3(0.04045), c));
}

// Exposed and tone-mapped, before the sRGB encoding: the display's linear light, 0..1. Pictures already in the
// scene target (the water's reflection and refraction) are mixed in this space, after decoding their sRGB.
vec3 toneMapped(vec3 linear) {
    return toneMapAces(linear * frame.exposure.x);
}

// Exposed, tone-mapped and sRGB-encoded: the last step of every shader that writes the scene colour.
vec3 displayColor(vec3 linear) {
    return linearToSrgb(toneMapped(linear));
}
