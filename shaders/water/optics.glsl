// What the water's two programs share (engine: org.openworld.engine.water.WaterSystem): the scene behind the water,
// the ripples, the Fresnel table and the light inside the water. fresnel.frag draws the water seen from above,
// underwater.frag the view from below; the engine picks the program, so neither pays for the other's branch.
// The pictures arrive tone-mapped (each shader maps its own colours), so they are mixed in the display's linear
// light; the water's own light (body, glitter) is tone-mapped into that space first.
#include "common/frame.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"
#include "water/surface.glsl"

uniform sampler2D refraction;    // the scene before the water, display colours
uniform sampler2D depthCopy;     // its depth
uniform sampler2D fresnelTable;  // reflectance by cos(angle to the normal): row 0 from the air, row 1 from the water
uniform sampler2DArray ripples;  // slopes (RippleField): layer i holds frame i in rg and frame i + 1 in ba,
                                 // each 128 + 127 * slope / scale
uniform vec3 uExtinction;        // per metre, rgb
uniform vec4 uRipple;            // x: 1 / tile (1/m); y: frames; z: time / period; w: slope scale
uniform vec4 uRippleOrigin;      // the render origin in tiles, 0..1: xy of the first layer, zw of the second

// Where the second, smaller layer of ripples is drawn from: a scale unrelated to the first, so the two tiles never
// repeat together, and its weight (the two are summed, then rescaled to the first's slope).
const float SMALL_SCALE = 0.37;
const float SMALL_WEIGHT = 0.6;
const float WATER_INDEX = 1.333;

// The slopes at xz, `cycles` loops into the animation: one texture read gives two successive frames, blended.
vec2 slopes(vec2 xz, float scale, float cycles, vec2 origin) {
    float f = fract(cycles) * uRipple.y;
    float layer = floor(f);
    vec4 pair = texture(ripples, vec3(xz * uRipple.x / scale + origin, layer));
    return (mix(pair.rg, pair.ba, f - layer) * 255.0 - 128.0) / 127.0 * uRipple.w;
}

// The rippled surface's upward normal, the ripples' slopes times `amplitude` (1: as synthesised). The smaller layer
// runs slower by 1/sqrt(scale): deep-water waves' frequency goes as the square root of their wavenumber
// (omega^2 = g k), so geometrically smaller waves are also quicker.
vec3 rippleNormal(vec2 xz, float amplitude) {
    vec2 s = slopes(xz, 1.0, uRipple.z, uRippleOrigin.xy)
           + SMALL_WEIGHT * slopes(xz + vec2(17.3, -5.1), SMALL_SCALE, uRipple.z / sqrt(SMALL_SCALE), uRippleOrigin.zw);
    s *= amplitude / sqrt(1.0 + SMALL_WEIGHT * SMALL_WEIGHT);
    return normalize(vec3(-s.x, 1.0, -s.y));
}

vec3 rippleNormal(vec2 xz) {
    return rippleNormal(xz, 1.0);
}

float fresnel(float cosAngle, bool fromBelow) {
    return texture(fresnelTable, vec2(clamp(cosAngle, 0.0, 1.0), fromBelow ? 0.75 : 0.25)).r;
}

vec3 picture(sampler2D image, vec2 uv) {
    return srgbToLinear(texture(image, uv).rgb);
}

// The sun and sky light entering the water, dimmed on its way down to `depth` metres (scene units); `sunSeen` is
// how much of the sun reaches the surface there (0 in a shadow).
vec3 lightAtDepth(float depth, float sunSeen) {
    vec3 entering = frame.sunColor.rgb * max(sunDir().y, 0.0) * sunSeen + frame.ambientColor.rgb;
    return entering * exp(-uExtinction * max(depth, 0.0));
}
