// Scene light to the display: the exposure of the moment, the night's blue shift, a filmic tone curve (ACES fit by
// Narkowicz 2015), then the sRGB transfer. Engine: org.openworld.engine.environment.Exposure (frame.exposure.x).
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

// The Purkinje shift (engine: org.openworld.engine.sky.Adaptation, which gives s = frame.exposure.y): the colour
// mixed by s towards what the rods see, the scotopic luminance V = Y (1.33 (1 + (Y + Z) / X) - 1.68) of its CIE XYZ
// over D65 white's 2.573, in the night's grey-blue, chromaticity (0.25, 0.25) as linear sRGB of luminance 1.
vec3 purkinje(vec3 c, float s) {
    const mat3 SRGB_TO_XYZ = mat3(0.4124, 0.2126, 0.0193, 0.3576, 0.7152, 0.1192, 0.1805, 0.0722, 0.9505);
    const vec3 NIGHT_BLUE = vec3(0.7062, 0.9899, 1.9657);
    vec3 xyz = SRGB_TO_XYZ * c;
    float v = xyz.y * (1.33 * (1.0 + (xyz.y + xyz.z) / max(xyz.x, 1e-20)) - 1.68) / 2.573;
    return mix(c, max(v, 0.0) * NIGHT_BLUE, s);
}

// Exposed and tone-mapped, before the sRGB encoding: the display's linear light, 0..1. Pictures already in the
// scene target (the water's reflection and refraction) are mixed in this space, after decoding their sRGB.
vec3 toneMapped(vec3 linear) {
    vec3 exposed = linear * frame.exposure.x;
    if (frame.exposure.y > 0.0) {
        exposed = purkinje(exposed, frame.exposure.y);
    }
    return toneMapAces(exposed);
}

// Exposed, tone-mapped and sRGB-encoded: the last step of every shader that writes the scene colour.
vec3 displayColor(vec3 linear) {
    return linearToSrgb(toneMapped(linear));
}
