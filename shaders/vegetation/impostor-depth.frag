#version 330 core
// A plant's impostor in the sun's shadow pass: depth only, where its frame is covered.
#include "vegetation/atlas.glsl"

in vec2 frameUv;

void main() {
    if (texture(uAtlas, atlasUv(frameUv, 0)).a < COVERED) {
        discard;
    }
}
