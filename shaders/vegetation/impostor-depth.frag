#version 330 core
// A plant's impostor in the sun's shadow pass: depth only, where its three blended frames cover it.
#include "vegetation/surface.glsl"
#include "vegetation/atlas.glsl"
#include "vegetation/octahedron.glsl"
#include "vegetation/impostor-sample.glsl"

void main() {
    if (!impostorTexel(bayer(ivec2(gl_FragCoord.xy))).covered) {
        discard;
    }
}
