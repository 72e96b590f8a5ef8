#version 330 core
// The tile's share of the sky seen (TileSky): the horizon search (horizon.glsl) for the samples of pyramid
// level L, marched over the pyramid's levels (the height texture's mips), written into r of an R8 target of level L's
// size. The tile wraps (periodic) or repeats its edge samples (imported), as its heights do.

uniform sampler2D heights; // mip k: pyramid level k, read exactly with texelFetch
uniform int mapSize;       // level 0's samples per side, a power of two
uniform int periodic;      // 1: wrap, 0: clamp

out vec4 visibility;

// Level k's sample i, wrapped or clamped like the tile's heights.
float sampleOf(int k, ivec2 i) {
    int n = mapSize >> k;
    ivec2 at = periodic == 1 ? i & (n - 1) : clamp(i, ivec2(0), ivec2(n - 1));
    return texelFetch(heights, at, k).r;
}

// Level k's height at sample coordinates base + offset, bilinearly; every sample of the tile is there.
bool heightOf(int k, ivec2 base, vec2 offset, out float h) {
    vec2 f = floor(offset);
    vec2 t = offset - f;
    ivec2 i0 = base + ivec2(f);
    ivec2 i1 = i0 + 1;
    h = mix(mix(sampleOf(k, i0), sampleOf(k, ivec2(i1.x, i0.y)), t.x),
            mix(sampleOf(k, ivec2(i0.x, i1.y)), sampleOf(k, i1), t.x), t.y);
    return true;
}

#include "terrain/material/horizon.glsl"

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float d = spacing0 * float(1 << level);
    vec2 slope = vec2(sampleOf(level, p + ivec2(1, 0)) - sampleOf(level, p - ivec2(1, 0)),
                      sampleOf(level, p + ivec2(0, 1)) - sampleOf(level, p - ivec2(0, 1))) / (2.0 * d);
    visibility = vec4(skyVisible(p, sampleOf(level, p), slope), 0.0, 0.0, 1.0);
}
