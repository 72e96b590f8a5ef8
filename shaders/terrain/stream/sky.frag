#version 330 core
// The unbounded world's share of the sky seen (StreamedSky): the horizon search (terrain/material/horizon.glsl) for the
// texels of one streamed block of level L, marched over the clipmap's own levels, written into the g channel of the
// snow map's layer L (the caller masks r, the snow, off).

uniform sampler2DArray heights; // layer k: level k's window, world sample i at texel i & (clipSize - 1)
uniform sampler2DArray slopes;  // layer L: (dh/dx, dh/dz) of level L, as the heights
uniform isampler2DArray held;   // layer k, one texel a slot: the block (x, z) whose heights the slot's texels hold
uniform int clipSize;           // samples per side of every window, a power of two
uniform int blockShift;         // log2 of a block's side
uniform int originX;            // level-L sample index of the block's first sample, along x
uniform int originZ;            // and along z

out vec4 visibility;

// Whether the slot of level k's sample i holds the block i lies in: its texels are that place's heights, not the
// NaN they start as nor a place the window left.
bool holds(int k, ivec2 i) {
    ivec2 b = i >> blockShift; // >> on a negative int keeps the sign (floor division)
    return texelFetch(held, ivec3(b & ((clipSize >> blockShift) - 1), k), 0).xy == b;
}

// Level k's height at sample coordinates base + offset (base an index, offset a few samples at most, so that a
// float keeps its fraction far from the origin), bilinearly; false when a sample it needs is not held.
bool heightOf(int k, ivec2 base, vec2 offset, out float h) {
    vec2 f = floor(offset);
    vec2 t = offset - f;
    ivec2 i0 = base + ivec2(f);
    ivec2 i1 = i0 + 1;
    h = 0.0;
    if (!(holds(k, i0) && holds(k, i1) && holds(k, ivec2(i1.x, i0.y)) && holds(k, ivec2(i0.x, i1.y)))) {
        return false;
    }
    int mask = clipSize - 1;
    float h00 = texelFetch(heights, ivec3(i0 & mask, k), 0).r;
    float h10 = texelFetch(heights, ivec3(ivec2(i1.x, i0.y) & mask, k), 0).r;
    float h01 = texelFetch(heights, ivec3(ivec2(i0.x, i1.y) & mask, k), 0).r;
    float h11 = texelFetch(heights, ivec3(i1 & mask, k), 0).r;
    h = mix(mix(h00, h10, t.x), mix(h01, h11, t.x), t.y);
    return true;
}

#include "terrain/material/horizon.glsl"

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    ivec2 origin = ivec2(originX, originZ);
    ivec2 p = origin + texel - (origin & (clipSize - 1)); // level-L sample index: the block lies in one slot
    float h0 = texelFetch(heights, ivec3(texel, level), 0).r;
    vec2 slope = texelFetch(slopes, ivec3(texel, level), 0).rg;
    visibility = vec4(0.0, skyVisible(p, h0, slope), 0.0, 0.0);
}
