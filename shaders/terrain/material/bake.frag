#version 330 core
// The far material, baked once at start (and when the snow mode, the tile size or the tiling changes; engine:
// FarMaterial; materials.tiling=stochastic compiles it with MAT_STOCHASTIC):
// steps 1-3 of material.glsl on every texel of a texture laid over the map tile like the gradient map, as a far
// viewer sees them: the coarse tile at its far weight, each material texture at the mip level of one baked texel
// (this pass's own derivatives choose it), the macro variation made periodic over a repeating tile.
// Far terrain then reads albedo, gloss, the detail slope and the ground's gradient with two lookups (terrain.frag,
// TERRAIN_FAR).
#include "terrain/material/material.glsl"

uniform sampler2D heights;     // the height pyramid; level bakeLevel is read
uniform sampler2D gradients;   // (dh/dx, dh/dz) of the finest level, filtered
uniform sampler2D snowMap;     // snow coverage 0..1
uniform int mapSize;           // level-0 samples per side
uniform float spacing;         // metres between level-0 samples
uniform int periodic;          // 1: the map wraps (generated), 0: it clamps (imported)
uniform float extent;          // metres per map tile
uniform vec2 heightRange;      // lowest height, 1 / (highest - lowest), metres
uniform int bakeLevel;         // the pyramid level whose samples are as far apart as the baked texels
uniform vec2 bakeSize;         // texels of the far material

layout(location = 0) out vec4 farColour; // rgb albedo (written to sRGB storage), a gloss
layout(location = 1) out vec4 farSlope;  // rg the detail slope, encoded s * 0.5 + 0.5; ba the ground's gradient

// Metres over which the macro variation of one tile edge fades into that of the opposite edge (two of its longest
// wavelengths): a generated tile repeats, and its baked variation must meet itself without a seam.
const float MACRO_WRAP_BAND = 2.0 * MAT_MACRO_SCALE;

float heightSample(ivec2 index) {
    int n = mapSize >> bakeLevel;
    index = periodic == 1 ? (index & (n - 1)) : clamp(index, ivec2(0), ivec2(n - 1));
    return texelFetch(heights, index, bakeLevel).r;
}

// The height at wsXZ, bilinear between the samples of level bakeLevel (what the patches' triangles show).
float heightAt(vec2 wsXZ) {
    vec2 f = (wsXZ / spacing + 0.5 * float(mapSize)) / float(1 << bakeLevel);
    ivec2 i = ivec2(floor(f));
    vec2 t = f - floor(f);
    float a = mix(heightSample(i), heightSample(i + ivec2(1, 0)), t.x);
    float b = mix(heightSample(i + ivec2(0, 1)), heightSample(i + ivec2(1, 1)), t.x);
    return mix(a, b, t.y);
}

// matMacroTint, periodic over the tile when the tile repeats: near the +x (+z) edge it fades into the variation one
// tile back, so the last texel meets the first.
vec2 macroTint(vec2 wsXZ) {
    if (periodic == 0) {
        return matMacroTint(wsXZ);
    }
    vec2 w = smoothstep(0.5 * extent - MACRO_WRAP_BAND, 0.5 * extent, wsXZ);
    vec2 a = mix(matMacroTint(wsXZ), matMacroTint(wsXZ - vec2(extent, 0.0)), w.x);
    vec2 b = mix(matMacroTint(wsXZ - vec2(0.0, extent)), matMacroTint(wsXZ - vec2(extent)), w.x);
    return mix(a, b, w.y);
}

void main() {
    vec2 uv = gl_FragCoord.xy / bakeSize;
    vec2 wsXZ = (uv - 0.5) * extent;
    vec2 slope = texture(gradients, uv).xy;
    TerrainSurface s;
    s.wsPos = vec3(wsXZ.x, heightAt(wsXZ), wsXZ.y);
    s.wsTangent = normalize(vec3(1.0, slope.x, 0.0));
    s.wsBitangent = normalize(vec3(0.0, slope.y, 1.0));
    s.wsNormal = normalize(vec3(-slope.x, 1.0, -slope.y));
    s.height01 = clamp((s.wsPos.y - heightRange.x) * heightRange.y, 0.0, 1.0);
    vec4 maps = texture(snowMap, uv);
    s.snow = maps.r;
    s.sediment = maps.b;
    s.bare = 1.0 - maps.a;
    MatTexel m = terrainMaterial(s, matCoarseWeight(MAT_COARSE_FAR), macroTint(wsXZ));
    farColour = vec4(m.albedo, m.gloss);
    // the gradient too, so the far program reads the ground's slope from this texel instead of a third texture
    farSlope = vec4(m.slope * 0.5 + 0.5, slope);
}
