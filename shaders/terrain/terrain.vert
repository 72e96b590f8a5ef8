#version 330 core
// Geomipmapped terrain patches (engine: org.openworld.engine.terrain.mesh.PatchRenderer). Every patch is the same grid
// of (N+1)² vertices; the instance says where it lies, how far apart its vertices are and which pyramid level each
// of its vertices reads. Heights come from the R32F pyramid texture, level L = pyramid level L, read exactly; with
// TERRAIN_CLIPMAP (terrain.world=unbounded) from layer L of the streamed clipmap (HeightClipmap), whose window
// around the camera holds world sample i of level L at texel i mod clipSize.
#include "common/frame.glsl"
#include "common/fog.glsl"
#ifdef TERRAIN_FAR
#include "common/environment.glsl"
#endif
#ifdef TERRAIN_CLIPMAP
#include "terrain/stream/clipmap.glsl"
#endif

layout(location = 0) in vec2 gridPos;         // column, row in 0..N
layout(location = 1) in ivec4 patchInfo;      // origin sample x, origin sample z, samples per grid step, level
layout(location = 2) in ivec4 sideLevels;     // north, east, south, west
layout(location = 3) in ivec4 cornerLevels;   // north-west, north-east, south-east, south-west
layout(location = 4) in vec2 copyOffset;      // metres from the render origin (frame.glsl)
layout(location = 5) in float patchMorph;     // k: how far the patch has morphed towards its parent's surface
layout(location = 6) in vec4 sideMorph;       // north, east, south, west neighbour's k when it samples the side's level
layout(location = 7) in vec4 cornerMorph;     // north-west, north-east, south-east, south-west diagonal's k, likewise

uniform int mapSize;        // level-0 samples per side of the tile (of a root of the unbounded world)
uniform float spacing;      // metres between level-0 samples
uniform int cells;          // N, grid cells per patch side
#ifdef TERRAIN_CLIPMAP
uniform sampler2DArray heights;
uniform int clipSize;       // samples per side of every level's window, a power of two
ivec2 worldOrigin;          // world sample index of this instance's root's north-west corner, set by main
#else
uniform sampler2D heights;
uniform int periodic;       // 1: the map wraps (generated), 0: it clamps (imported)
#endif
#ifdef TERRAIN_FAR
  #ifdef TERRAIN_CLIPMAP
uniform sampler2DArray slopes;  // (dh/dx, dh/dz) of each level's window, as in terrain.frag
uniform sampler2DArray snowMap; // g: the share of the sky seen (StreamedSky), as in terrain.frag
uniform float clipExtent;       // metres across level 0's window
  #else
uniform sampler2D farSlope; // ba: the ground's (dh/dx, dh/dz) over the tile (FarMaterial), as in terrain.frag
uniform sampler2D snowMap;  // g: the share of the sky the relief leaves (HorizonSearch), as in terrain.frag
uniform float extent;       // metres per map tile
  #endif
uniform float uMatSkyOcclusion; // material.glsl's switch (materials.sky-occlusion)
#endif

out vec3 wsPos;
out vec4 air;                 // the air between the eye and this vertex (common/fog.glsl), see main
flat out int lodLevel;
#ifdef TERRAIN_FAR
out vec3 skySharp;            // the environment mirrored by the ground, at its sharp and rough levels (see main)
out vec3 skyRough;
out vec3 skyLight;            // the sky's and the ground's irradiance for the ground's normal (frame.glsl)
#endif

// The level a vertex reads: a stitched side reads its coarser neighbour's level, a corner the coarsest of the
// patches that meet there, so every patch computes the same height for a shared vertex (no cracks).
int vertexLevel(ivec2 g) {
    bool north = g.y == 0, south = g.y == cells, west = g.x == 0, east = g.x == cells;
    if (north && west) return cornerLevels.x;
    if (north && east) return cornerLevels.y;
    if (south && east) return cornerLevels.z;
    if (south && west) return cornerLevels.w;
    if (north) return sideLevels.x;
    if (east) return sideLevels.y;
    if (south) return sideLevels.z;
    if (west) return sideLevels.w;
    return patchInfo.w;
}

float heightAt(ivec2 sampleIndex, int level) {
#ifdef TERRAIN_CLIPMAP
    // >> on a negative int keeps the sign (floor division), & the power-of-two modulo of two's complement
    return texelFetch(heights, ivec3(((sampleIndex + worldOrigin) >> level) & (clipSize - 1), level), 0).r;
#else
    int n = mapSize >> level;
    ivec2 texel = sampleIndex >> level;
    texel = periodic == 1 ? (texel & (n - 1)) : clamp(texel, ivec2(0), ivec2(n - 1));
    return texelFetch(heights, texel, level).r;
#endif
}

// Geomorphing (QuadtreeLod explains it): k of a side's patches that sample this level, the neighbour's (given only
// when it samples the side's level)
float sideK(int side, int level) {
    return sideLevels[side] == level ? sideMorph[side] : 0.0;
}

// How far a vertex sampling `level` has morphed: the largest k of the patches that sample that level there, so that
// every patch sharing the vertex computes the same k.
float morphFactor(ivec2 g, int level) {
    bool north = g.y == 0, south = g.y == cells, west = g.x == 0, east = g.x == cells;
    float k = level == patchInfo.w ? patchMorph : 0.0;
    if (north && west) return max(k, max(max(sideK(0, level), sideK(3, level)), cornerMorph.x));
    if (north && east) return max(k, max(max(sideK(0, level), sideK(1, level)), cornerMorph.y));
    if (south && east) return max(k, max(max(sideK(2, level), sideK(1, level)), cornerMorph.z));
    if (south && west) return max(k, max(max(sideK(2, level), sideK(3, level)), cornerMorph.w));
    if (north) return max(k, sideK(0, level));
    if (east) return max(k, sideK(1, level));
    if (south) return max(k, sideK(2, level));
    if (west) return max(k, sideK(3, level));
    return k;
}

// The next coarser level's surface at a vertex of `level`: its own height there when the vertex is on the coarser
// grid (even), else the mean of its two even neighbours along its odd axis, or along the cell's diagonal (from
// (−,−) to (+,+), as PatchPatterns cuts every cell) when odd in both.
float coarserHeight(ivec2 sampleIndex, int level) {
    ivec2 toEven = ((sampleIndex >> level) & 1) << level;
    return 0.5 * (heightAt(sampleIndex - toEven, level + 1) + heightAt(sampleIndex + toEven, level + 1));
}

void main() {
#ifdef TERRAIN_CLIPMAP
    // roots lie on a lattice of their own side, so their offset in samples is an integer exactly; the copy's offset
    // is from the render origin, whose own whole steps (a root's side each) come in int
    worldOrigin = ivec2(round(copyOffset / spacing)) + ivec2(frame.origin.xz) * mapSize - ivec2(mapSize / 2);
#endif
    ivec2 g = ivec2(gridPos);
    ivec2 sampleIndex = patchInfo.xy + g * patchInfo.z;
    vec2 xz = (vec2(sampleIndex) - 0.5 * float(mapSize)) * spacing + copyOffset;
    int level = vertexLevel(g);
    wsPos = vec3(xz.x, heightAt(sampleIndex, level), xz.y);
    float k = morphFactor(g, level);
    if (k > 0.0) {
        wsPos.y = mix(wsPos.y, coarserHeight(sampleIndex, level), k);
    }
    lodLevel = patchInfo.w;
    // Aerial perspective per vertex, interpolated: the table varies slowly across a triangle (the level rule keeps
    // a triangle's side a small share of its distance), and per pixel it cost a fifth of the terrain's pixel time
    // on a software rasteriser (an asin, an atan and a 3D lookup a pixel).
    air = airTo(wsPos);
#ifdef TERRAIN_FAR
    // The sky's reflection per vertex too, at two levels the pixels blend by their gloss (material.glsl): on the
    // far ground its cube map lookup per pixel was a sixth of the terrain's pixel time on a software rasteriser. The
    // normal is the ground's, read at the level whose texels are as far apart as this patch's vertices.
  #ifdef TERRAIN_CLIPMAP
    vec3 clipUv = clipmapCoordinates(wsPos.xz, patchInfo.w, clipExtent, clipSize);
    vec2 slope = textureLod(slopes, clipUv, 0.0).xy;
    float visible = textureLod(snowMap, clipUv, 0.0).g;
  #else
    vec2 uv = wsPos.xz / extent + 0.5;
    float samplesPerStep = float(patchInfo.z) / float(mapSize);
    vec2 slope = textureLod(farSlope, uv, max(log2(samplesPerStep * float(textureSize(farSlope, 0).x)), 0.0)).ba;
    float visible = textureLod(snowMap, uv, max(log2(samplesPerStep * float(textureSize(snowMap, 0).x)), 0.0)).g;
  #endif
    vec3 normal = normalize(vec3(-slope.x, 1.0, -slope.y));
    vec3 mirror = reflect(normalize(wsPos - cameraPos()), normal);
    skySharp = environmentRadiance(mirror, ENVIRONMENT_SHARP_LOD);
    skyRough = environmentRadiance(mirror, ENVIRONMENT_ROUGH_LOD);
    // and the sky light on it: per pixel, its nine factors read from the frame block cost the far ground a sixth
    // of its time on llvmpipe, and it varies as slowly over a far triangle as the reflection does; where the relief
    // hides part of the sky, the sunlit ground's light stands in for it (as material.glsl's matSkyLight)
    skyLight = skyIrradiance(normal, mix(1.0, visible, uMatSkyOcclusion));
#endif
    gl_Position = frame.viewProjection * vec4(wsPos, 1.0);
}
