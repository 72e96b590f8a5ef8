#version 330 core
// The clouds' temporal resolve (engine: org.openworld.engine.clouds.CloudVolumeSystem), on the quarter grid: the
// texels marched this frame are taken as they are; every other texel is reprojected, its point (along its ray at the
// cloud distance its marched neighbour found) carried into the previous frame's picture and the history read there,
// then clamped to the range of this frame's marched texels around it, so what moved or appeared cannot leave a
// ghost. Where the previous picture did not see the point the marched neighbour stands in.
#include "clouds/screen.glsl"

layout(location = 0) out vec4 cloudLight; // as march.frag's
layout(location = 1) out vec4 cloudDepth; // x: the cloud's distance (m); y: the scene's distance at this texel (m)

uniform sampler2D freshLight;   // this frame's march: one texel per 2 x 2 block (or every texel)
uniform sampler2D freshDepth;
uniform sampler2D historyLight; // the last frame's resolve, the quarter grid
uniform mat4 uPreviousViewProjection;
uniform vec4 uGrid;             // xy: the quarter grid's size (texels); zw: this frame's slot in each 2 x 2 block
uniform float uEveryTexel;      // 1: every texel was marched this frame (no history)

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec2 uv = (vec2(texel) + 0.5) / uGrid.xy;
    float surface = min(sceneDistance(uv, viewRay(2.0 * uv - 1.0)), NO_SURFACE);
    if (uEveryTexel > 0.5) {
        cloudLight = texelFetch(freshLight, texel, 0);
        cloudDepth = vec4(texelFetch(freshDepth, texel, 0).x, surface, 0.0, 0.0);
        return;
    }
    ivec2 block = texel / 2;
    ivec2 blocks = ivec2(ceil(uGrid.xy * 0.5));
    vec4 light = texelFetch(freshLight, block, 0);
    float distance = texelFetch(freshDepth, block, 0).x;
    cloudDepth = vec4(distance, surface, 0.0, 0.0);
    if (texel - 2 * block == ivec2(uGrid.zw)) {
        cloudLight = light;
        return;
    }
    // 1. the point this texel sees, in the previous frame's picture
    vec3 wsPoint = cameraPos() + normalize(viewRay(2.0 * uv - 1.0)) * distance;
    vec4 clip = uPreviousViewProjection * vec4(wsPoint, 1.0);
    vec2 previous = clip.xy / max(clip.w, 1e-6) * 0.5 + 0.5;
    if (clip.w <= 0.0 || any(lessThan(previous, vec2(0.0))) || any(greaterThan(previous, vec2(1.0)))) {
        cloudLight = light;
        return;
    }
    // 2. the history there, clamped to this frame's marched neighbours (3 x 3 blocks)
    vec4 low = light;
    vec4 high = light;
    for (int y = -1; y <= 1; y++) {
        for (int x = -1; x <= 1; x++) {
            vec4 near = texelFetch(freshLight, clamp(block + ivec2(x, y), ivec2(0), blocks - 1), 0);
            low = min(low, near);
            high = max(high, near);
        }
    }
    cloudLight = clamp(texture(historyLight, previous), low, high);
}
