#version 330 core
// The far field (engine: org.openworld.engine.terrain.FarField): one ring of ground around the eye, from under the
// edge of the drawn patches out past the horizon, coloured by terrain.frag's far program (TERRAIN_FARFIELD). Its
// heights are the coarsest level's, read bilinearly; where that level may not hold the world (beyond a quarter of
// the unbounded world's window from the eye) and towards the ring's outer edge, the relief fades into level ground
// at the world's mean height. The ground falls away with the planet's curvature, d² / 2R, so the horizon is where
// a real one is, at sqrt(2 R h) for an eye h above the ground. Drawn at its true distance within the camera's depth
// range, and pulled along its line of sight into the range's last metres beyond that (the picture does not change,
// only the depth).
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/environment.glsl"
#ifdef TERRAIN_CLIPMAP
#include "terrain/stream/clipmap.glsl"
#endif

layout(location = 0) in vec2 ringPos;  // x: azimuth, 0..1 of a turn; y: 0 on the inner edge, 1 on the outer

uniform vec3 uRing;          // metres from the eye: inner radius, outer radius, where the curvature starts
uniform vec3 uSquare;        // the drawn patches' square: centre x, z and half its side, metres
uniform vec2 uDepthRoom;     // metres: drawn as is nearer than x; beyond, squeezed between x and y
uniform float uMeanHeight;   // the level ground's height, metres
uniform float uPlanetRadius; // metres
uniform float uSampleSpacing; // metres between the far level's samples
uniform float uOrigin;       // where the far level's sample 0 lies on either axis, metres
uniform int uFarLevel;       // the level read: the coarsest streamed level, or the tile's pyramid level
uniform float uMatSkyOcclusion; // material.glsl's switch (materials.sky-occlusion)
#ifdef TERRAIN_CLIPMAP
uniform sampler2DArray heights;
uniform sampler2DArray slopes;
uniform sampler2DArray snowMap; // g: the share of the sky seen
uniform int clipSize;          // samples per side of every level's window, a power of two
uniform float clipExtent;      // metres across level 0's window
out float farRelief;           // 1 on the streamed relief, 0 on the level ground (terrain.frag)
#else
uniform sampler2D heights;     // the tile's pyramid, periodic
uniform sampler2D farSlope;    // ba: the ground's (dh/dx, dh/dz) over the tile (FarMaterial)
uniform sampler2D snowMap;     // g: the share of the sky seen
uniform float extent;          // metres per tile
#endif

out vec3 wsPos;
out vec4 air;
flat out int lodLevel;
out vec3 skySharp;
out vec3 skyRough;
out vec3 skyLight;

const float TAU = 6.28318531;
// Metres over which the streamed relief fades out before the part of the window that always holds the world.
const float WINDOW_FADE = 8000.0;
// How steeply the ring goes down under the drawn patches, metres per metre inside their square: steeper than any
// slope the coarse level smooths away, so it stays under the patches' own ground.
const float SKIRT_SLOPE = 4.0;

float sampleAt(ivec2 i) {
#ifdef TERRAIN_CLIPMAP
    return texelFetch(heights, ivec3(i & (clipSize - 1), uFarLevel), 0).r;
#else
    return texelFetch(heights, i & (textureSize(heights, uFarLevel) - 1), uFarLevel).r;
#endif
}

// The air to a point d metres away, also beyond the aerial perspective table's last slice (AERIAL_MAX_DISTANCE):
// the air past it taken as alike to the table's own, a homogeneous layer, so its transmittance is the table's
// raised to d / AERIAL_MAX_DISTANCE and its light tends to the table's in-scattering over its own absorption, the
// colour of an endless layer of that air: far ground fades into it as into the horizon's sky.
vec4 airFar(vec3 wsSeen, float d) {
    vec4 table = airTo(wsSeen);
    float layers = d / AERIAL_MAX_DISTANCE;
    if (layers <= 1.0) {
        return table;
    }
    float transmittance = pow(table.a, layers);
    return vec4(table.rgb * (1.0 - transmittance) / max(1.0 - table.a, 1e-4), transmittance);
}

void main() {
    float azimuth = ringPos.x * TAU;
    float r = uRing.x * pow(uRing.y / uRing.x, ringPos.y); // rings a constant ratio apart
    vec2 xz = cameraPos().xz + r * vec2(sin(azimuth), -cos(azimuth));
    // 1. the far level, bilinear
    vec2 p = (xz - uOrigin) / uSampleSpacing;
#ifdef TERRAIN_CLIPMAP
    p += clipmapOrigin(uFarLevel, clipExtent, clipSize); // xz is from the render origin (the tile needs no shift: it
#endif                                                    // repeats every step)
    ivec2 i = ivec2(floor(p));
    vec2 f = p - floor(p);
    float level = mix(mix(sampleAt(i), sampleAt(i + ivec2(1, 0)), f.x),
                      mix(sampleAt(i + ivec2(0, 1)), sampleAt(i + ivec2(1, 1)), f.x), f.y);
    // 2. its relief, faded into level ground towards the outer edge and, streamed, before the window ends
    float relief = 1.0 - smoothstep(0.5 * uRing.y, uRing.y, r);
#ifdef TERRAIN_CLIPMAP
    // a window keeps the camera at least a quarter of its side inside (HeightClipmap), so the square of that half
    // side around the eye (less a sample, for the bilinear read) holds the world whatever the flight was
    vec2 fromEye = abs(xz - cameraPos().xz);
    float reach = (0.25 * float(clipSize) - 1.0) * uSampleSpacing;
    relief *= 1.0 - smoothstep(reach - WINDOW_FADE, reach, max(fromEye.x, fromEye.y));
    farRelief = relief;
#endif
    // (a texel never written holds NaN, UnboundedWorld, and NaN times a zero weight is still NaN: a hole)
    float y = relief > 0.0 && !isnan(level) ? mix(uMeanHeight, level, relief) : uMeanHeight;
    // 3. under the drawn patches the ring goes down out of their way
    float inside = uSquare.z - max(abs(xz.x - uSquare.x), abs(xz.y - uSquare.y));
    y -= SKIRT_SLOPE * max(inside, 0.0);
    wsPos = vec3(xz.x, y, xz.y);
    lodLevel = uFarLevel;
    // 4. the slope and the sky per vertex, as terrain.vert's far program reads them
#ifdef TERRAIN_CLIPMAP
    vec3 clipUv = clipmapCoordinates(xz, uFarLevel, clipExtent, clipSize);
    vec2 slope = relief * textureLod(slopes, clipUv, 0.0).xy;
    float visible = mix(1.0, textureLod(snowMap, clipUv, 0.0).g, relief);
#else
    vec2 uv = xz / extent + 0.5;
    float texels = uSampleSpacing / extent * float(textureSize(farSlope, 0).x);
    vec2 slope = relief * textureLod(farSlope, uv, log2(texels)).ba;
    float snowTexels = uSampleSpacing / extent * float(textureSize(snowMap, 0).x);
    float visible = mix(1.0, textureLod(snowMap, uv, log2(snowTexels)).g, relief);
#endif
    vec3 normal = normalize(vec3(-slope.x, 1.0, -slope.y));
    vec3 mirror = reflect(normalize(wsPos - cameraPos()), normal);
    skySharp = environmentRadiance(mirror, ENVIRONMENT_SHARP_LOD);
    skyRough = environmentRadiance(mirror, ENVIRONMENT_ROUGH_LOD);
    skyLight = skyIrradiance(normal, mix(1.0, visible, uMatSkyOcclusion));
    // 5. the planet's curvature: level ground r metres away lies r² / 2R below the eye's tangent plane (counted from
    // where the flat patches end, so the two meet); the air is that to the point where it is seen
    vec3 seen = wsPos - vec3(0.0, max(r * r - uRing.z * uRing.z, 0.0) / (2.0 * uPlanetRadius), 0.0);
    vec3 toPoint = seen - cameraPos();
    float d = length(toPoint);
    air = airFar(seen, d);
    // 6. along its line of sight into the depth range: order kept, picture unchanged
    float room = uDepthRoom.y - uDepthRoom.x;
    float drawn = d <= uDepthRoom.x ? d : uDepthRoom.x + room * (1.0 - exp(-(d - uDepthRoom.x) / room));
    gl_Position = frame.viewProjection * vec4(cameraPos() + toPoint * (drawn / max(d, 1e-3)), 1.0);
}
