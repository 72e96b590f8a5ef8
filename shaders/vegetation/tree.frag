#version 330 core
// A plant's light (engine: org.openworld.engine.vegetation.TreeDraw): the terrain's own light, so plants and ground
// sit in one picture: the sun (Lambert, where the shadow maps see it: common/shadow.glsl), the sky's hemisphere
// light, then the air in front of it (common/fog.glsl) and the display transform (common/color.glsl). The leaves and
// the bark are patterns made here from the shape's own coordinates (no texture to download or bake): clumps of
// leaves that turn their own way, light through the leaves seen against the sun, bark in vertical streaks.
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"

in vec3 wsPos;
in vec3 wsNormal;
in vec3 msShape;
flat in float vPart;
flat in float vTint;
flat in float vFar;
out vec4 fragColor;

uniform vec3 uLod;  // z: 0 the full shape, 1 the simplified one
uniform int uKind;  // 0 conifer, 1 broadleaf, 2 bush

// Albedos, linear, dark and light ends of each kind's foliage: spruce needles reflect 3-8 % of visible light (dark,
// bluish green), beech and oak leaves 8-12 % (yellower), shrubs in between; bark a little more, brown.
const vec3 FOLIAGE_DARK[3] = vec3[](vec3(0.026, 0.050, 0.030), vec3(0.045, 0.075, 0.025), vec3(0.040, 0.060, 0.028));
const vec3 FOLIAGE_LIGHT[3] = vec3[](vec3(0.050, 0.080, 0.035), vec3(0.085, 0.120, 0.035), vec3(0.070, 0.095, 0.035));
const vec3 BARK = vec3(0.10, 0.065, 0.040);
// A crown is not a closed surface: light reaches a little round its edge. Lambert "wrapped" by this share of the
// hemisphere, cos' = (cos + WRAP) / (1 + WRAP), so the shaded side is not black under a low sun.
const float WRAP = 0.3;
// Leaves let through about as much light as they reflect, greener (a factor on the albedo): seen against the sun, a
// crown glows at its edges.
const vec3 TRANSMIT = vec3(0.8, 1.2, 0.5);
// Leaf clumps about 0.7 m across, needle tufts a little finer; they tilt the normal by up to this much.
const float CLUMP_PER_M = 1.4;
const float CLUMP_TILT = 0.45;

// 4 x 4 ordered dither (Bayer), 0..1: where a plant is in the cross-fade, a pixel is drawn by one shape or the other.
float bayer(ivec2 p) {
    const float M[16] = float[](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);
    return (M[(p.y & 3) * 4 + (p.x & 3)] + 0.5) / 16.0;
}

vec3 hash3(vec3 p) {
    p = fract(p * vec3(0.1031, 0.1030, 0.0973));
    p += dot(p, p.yxz + 33.33);
    return fract((p.xxy + p.yxx) * p.zyx);
}

void main() {
    float threshold = bayer(ivec2(gl_FragCoord.xy));
    if (uLod.z < 0.5 ? vFar > threshold : vFar <= threshold) {
        discard;
    }
    vec3 n = normalize(wsNormal);
    vec3 l = sunDir();
    bool foliage = vPart > 0.5;
    vec3 albedo;
    float wrap = 0.0;
    if (foliage) {
        // a clump of leaves: one random tilt and shade per cell of the shape's space
        vec3 cell = hash3(floor(msShape * CLUMP_PER_M * (uKind == 0 ? 1.5 : 1.0)) + vTint * 17.0);
        n = normalize(n + CLUMP_TILT * (cell - 0.5));
        albedo = mix(FOLIAGE_DARK[uKind], FOLIAGE_LIGHT[uKind], 0.5 * vTint + 0.5 * cell.x);
        wrap = WRAP;
    } else {
        // bark: streaks along the stem, a few centimetres across
        float streak = hash3(vec3(floor(atan(msShape.z, msShape.x) * 8.0), 0.0, vTint)).x;
        albedo = BARK * (0.7 + 0.6 * streak);
    }
    float nl = max((dot(n, l) + wrap) / (1.0 + wrap), 0.0);
    float visible = sunVisibility(wsPos, n);
    vec3 color = albedo * (frame.sunColor.rgb * nl * visible + skyIrradiance(n));
    if (foliage) {
        // through the leaves: strongest looking straight at the sun behind them (v from the eye, l towards the sun)
        vec3 v = normalize(wsPos - cameraPos());
        color += TRANSMIT * albedo * frame.sunColor.rgb * pow(max(dot(v, l), 0.0), 4.0) * visible;
    }
    fragColor = vec4(displayColor(applyFog(color, wsPos)), 1.0);
}
