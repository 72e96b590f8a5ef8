// The sun's shadow (paper 3.2; engine: org.openworld.engine.shadow.ShadowSystem, which writes this block and draws
// the maps). Any lit shader multiplies its direct sunlight by
//
//   float sunVisibility(vec3 wsPos, vec3 wsNormal)   1 where the sun is seen from wsPos, 0 where it is hidden
//
// (times what the clouds let through, cloudShadow below).
//
// How: each cascade is an orthographic depth picture of the world seen from the sun. A point is looked up in the
// finest cascade whose picture holds it; it is shadowed where the picture recorded something nearer the sun than
// the point itself, by more than a bias:
//   margin       the paper's Z-buffer margin, in depth-buffer units (a fraction of the box's depth)
//   slope bias   metres of depth per texel of the map, times tan(angle of the sun to the normal): a tilted surface
//                covers a depth range within one texel, and its own nearer part must not shadow its farther part.
//                Scaled by the PCF kernel's reach, since the outer taps read the surface further away
//   normal offset the point moved along its normal by a fraction of a texel times sin(angle): off the surface, so
//                the lookup lands where the surface's own depth is behind it
// The paper's PCF filter averages N x N such tests a texel apart: a soft edge N texels wide. The sun is a disc, so
// a real edge blurs with the distance d between caster and ground, by d * 2 tan(0.27 deg) = 0.93 cm per metre
// (the penumbra); where the caster lies so far that this outgrows the filter, the tests spread (see
// percentageCloser). Near the border of a
// cascade the next one is blended in (its filter only where some pixel needs it, see sunVisibility), and at the
// shadow distance shadows fade out.
#include "common/frame.glsl"

layout(std140) uniform ShadowBlock {
    mat4 lightViewProjection[4]; // world -> each cascade's clip space (orthographic)
    vec4 cascadeTexel;           // metres per texel, per cascade
    vec4 cascadeDepth;           // metres from each box's sunward plane to its far plane (depth 0 .. 1)
    vec4 shadowParams;           // x: cascades (0: no shadow map, everything lit); y: PCF side N; z: margin; w: blend band
    vec4 biasParams;             // x: normal offset (texels); y: slope bias (texels); z: fade start, w: shadow distance
                                 //    (metres from the viewer; w = 0: no fade)
    vec4 viewerPos;              // xyz: the viewer's eye (the same in every pass, also the mirrored one); w: the
                                 //    penumbra's growth, metres of soft edge per metre from the caster (0: none)
} shadow;

uniform sampler2DArrayShadow shadowMap;

// The clouds' shadow (engine: org.openworld.engine.clouds, environment.CloudShadow): the transmittance of the sun's
// ray through the cloud volume, one texel per sample of the cloud field's tile, from the base upwards. A point is
// carried along the sun's direction to the cloud base and looked up there, at the field's coordinates (the field
// wraps, so the map does). Without volumetric clouds the engine binds a block of zeros: strength 0, all light through.
layout(std140) uniform CloudShadowBlock {
    vec4 cloudShadowPlace;    // x: the cloud base, metres above sea level; y: 1 / the field's tile (1/m);
                              // zw: the wind's offset of the field, metres (world x, z, from the world's origin)
    vec4 cloudShadowStrength; // x: 1 with clouds, 0 without; y: the field's tile (m); zw: 0
} cloudShadowBlock;

uniform sampler2D cloudShadowMap;

// Lowest sun-elevation sine used to carry a point to the cloud base: 3 degrees, beyond which the shadow is far
// away and spread thin anyway (the light crosses the volume over tens of kilometres).
const float CLOUD_SHADOW_MIN_SINE = 0.05;

// The cloud shadow map at a point of the cloud base (world x, z, from the render origin): r what the clouds let
// through along the sun's ray, g straight up.
vec2 cloudShadowAt(vec2 wsXz) {
    vec4 place = cloudShadowBlock.cloudShadowPlace;
    // the render origin modulo the tile, from this pass's frame block (not the block's writer's frame, which may
    // precede a step of the origin): its steps (whole numbers) times the step modulo the tile
    float tile = cloudShadowBlock.cloudShadowStrength.y;
    vec2 origin = mod(frame.origin.xz * mod(frame.origin.w, tile), tile);
    return texture(cloudShadowMap, (wsXz + origin - place.zw) * place.y).rg;
}

// The share of the sun's light the clouds let through to wsPos: 1 in the open, near 0 under a thick cloud.
float cloudShadow(vec3 wsPos) {
    if (cloudShadowBlock.cloudShadowStrength.x == 0.0) {
        return 1.0; // no clouds (the stand-in block of zeros, or the layer)
    }
    vec3 toSun = sunDir();
    float rise = max(cloudShadowBlock.cloudShadowPlace.x - wsPos.y, 0.0) / max(toSun.y, CLOUD_SHADOW_MIN_SINE);
    float through = cloudShadowAt(wsPos.xz + toSun.xz * rise).r;
    return mix(1.0, through, cloudShadowBlock.cloudShadowStrength.x);
}

// Optical depth of the cloud overhead at which the snow falls in full: 3, where the sun's disc is gone (5 % of its
// light through), an overcast sky.
const float SNOWFALL_DEPTH = 3.0;

// The share of the snowfall that falls at wsPos: snow falls from the cloud above, so none under a clear sky, in
// full under an overcast (the column's optical depth from 0 to SNOWFALL_DEPTH); the drift of a flake's half-hour
// fall from the cloud base is not followed. 1 without volumetric clouds (the layer has no depth to tell).
float snowfallShare(vec3 wsPos) {
    if (cloudShadowBlock.cloudShadowStrength.x == 0.0) {
        return 1.0;
    }
    float column = -log(max(cloudShadowAt(wsPos.xz).g, 1e-6));
    return clamp(column / SNOWFALL_DEPTH, 0.0, 1.0);
}

// The point in cascade i's map: xy texture coordinates, z its depth less the biases.
vec3 shadowCoords(int i, vec3 wsPos, vec3 wsNormal, float cosSun) {
    float texel = shadow.cascadeTexel[i];
    float sinSun = sqrt(max(1.0 - cosSun * cosSun, 0.0));
    vec3 offsetPos = wsPos + wsNormal * (shadow.biasParams.x * texel * sinSun);
    vec4 clip = shadow.lightViewProjection[i] * vec4(offsetPos, 1.0);
    vec3 coords = clip.xyz * 0.5 + 0.5;
    float reach = 1.0 + 0.5 * (shadow.shadowParams.y - 1.0);
    float tanSun = min(sinSun / max(cosSun, 1e-3), 10.0);
    float slope = shadow.biasParams.y * texel * tanSun * reach / shadow.cascadeDepth[i];
    coords.z -= shadow.shadowParams.z + slope;
    return coords;
}

// Metres between caster and ground beyond which the penumbra is wider than cascade i's filter of N texels, times
// 1.5: the middle of the range over which it grows to twice the filter's width.
float penumbraReach(int i, int n) {
    return 1.5 * float(n) * shadow.cascadeTexel[i] / max(shadow.viewerPos.w, 1e-6);
}

// The paper's percentage-closer filter: the mean of N x N depth tests around the point, a texel apart, or two
// texels apart where the caster lies beyond penumbraReach: one more test at the centre, against a depth that much
// nearer the sun, tells (1 - its result, so a point in the open or under a near caster keeps the narrow filter).
// Two texels is as far as the taps spread before the edge shows them as separate steps: the blur grows with the
// distance to the caster as far as the kernel allows, not to the sun's full penumbra.
float percentageCloser(int i, vec3 coords) {
    int n = int(shadow.shadowParams.y);
    float farCaster = 1.0 - texture(shadowMap, vec4(coords.xy, float(i),
                                                   coords.z - penumbraReach(i, n) / shadow.cascadeDepth[i]));
    float step = (1.0 + farCaster) / float(textureSize(shadowMap, 0).x);
    vec2 origin = coords.xy - 0.5 * float(n - 1) * step;
    float lit = 0.0;
    for (int y = 0; y < n; y++) {
        for (int x = 0; x < n; x++) {
            lit += texture(shadowMap, vec4(origin + vec2(x, y) * step, float(i), coords.z));
        }
    }
    return lit / float(n * n);
}

// How far inside cascade i's map the coordinates lie, as a fraction of its side (negative: outside).
float insideness(vec3 coords) {
    vec2 edge = min(coords.xy, 1.0 - coords.xy);
    return coords.z > 1.0 ? -1.0 : min(edge.x, edge.y);
}

#ifdef SUN_UNSHADOWED
// The variant for a pass with no shadow map bound (engine: RenderContext.shares): everything is lit, and no
// lookup is compiled in. With a map that shadows nothing (cascade count 0) the picture is the same, but a software
// rasteriser runs a loop's body at least once, masked, whatever its count: the cascade loop and its filter cost a
// fifth of the terrain's pixel time on llvmpipe, for no shadow.
float sunVisibility(vec3 wsPos, vec3 wsNormal) {
    return cloudShadow(wsPos);
}
#else
// The shadow maps' part of sunVisibility: the relief, the trees and everything else that casts a depth shadow.
float terrainShadow(vec3 wsPos, vec3 wsNormal) {
    int count = int(shadow.shadowParams.x);
    float distance = length(wsPos - shadow.viewerPos.xyz);
    float far = shadow.biasParams.w;
    if (count == 0 || (far > 0.0 && distance >= far)) {
        return 1.0;
    }
    float cosSun = clamp(dot(wsNormal, sunDir()), 0.0, 1.0);
    float band = shadow.shadowParams.w;
    // In a border band the finer cascade's result waits for the next trip, which filters the next cascade and blends
    // the two: a second filter in the loop's next trip rather than under an if, because a CPU rasteriser (llvmpipe)
    // runs both sides of an if for a whole group of pixels, but ends a loop once every pixel of the group is done.
    float finer = -1.0;    // the finer cascade's result while blending, else -1
    float weight = 0.0;    // its weight in the blend
    for (int i = 0; i < count; i++) {
        vec3 coords = shadowCoords(i, wsPos, wsNormal, cosSun);
        float inside = insideness(coords);
        if (finer < 0.0 && inside < 0.0) {
            continue;
        }
        float lit = percentageCloser(i, coords);
        if (finer >= 0.0) {
            lit = mix(lit, finer, weight);
        } else if (inside < band && i + 1 < count) {
            finer = lit;
            weight = inside / band;
            continue;
        }
        return far > 0.0 ? mix(lit, 1.0, smoothstep(shadow.biasParams.z, far, distance)) : lit;
    }
    return 1.0;
}

float sunVisibility(vec3 wsPos, vec3 wsNormal) {
    return cloudShadow(wsPos) * terrainShadow(wsPos, wsNormal);
}
#endif
