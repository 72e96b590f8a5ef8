#version 330 core
// One texel of an impostor's frame (engine: org.openworld.engine.vegetation.ImpostorAtlas): the plant's surface made
// as the meshes make it (vegetation/surface.glsl) at the mean tint, 0.5, unlit, in one of two halves of the atlas:
//   uOutput 0: rgb the albedo's square root (8 bits keep 4-5 % steps of these dark albedos, against 8-15 % stored
//              linear), a the coverage: 1 foliage, 0.5 bark, 0 nothing
//   uOutput 1: rgb the shading normal in the plant's own space, * 0.5 + 0.5; a the depth towards the viewer, units
//              of the bounding sphere's radius, * 0.5 + 0.5
#include "vegetation/surface.glsl"

in vec3 bakeNormal;
in vec3 msShape;
in float bakeDepth;
flat in float vPart;
out vec4 fragColor;

uniform int uKind;
uniform int uOutput;

void main() {
    PlantSurface p = plantSurface(normalize(bakeNormal), msShape, vPart > 0.5, 0.5, uKind);
    fragColor = uOutput == 0 ? vec4(sqrt(p.albedo), p.foliage ? 1.0 : 0.5)
            : vec4(p.normal * 0.5 + 0.5, bakeDepth * 0.5 + 0.5);
}
