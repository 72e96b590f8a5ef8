#version 330 core
// A plant's mesh, full or simplified (engine: org.openworld.engine.vegetation.TreeDraw): its surface
// (vegetation/surface.glsl) lit as the terrain is (vegetation/light.glsl), drawn where the cross-fades give this
// shape the pixel: the full shape before the LOD band, the simplified one between it and the impostors' band.
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"
#include "vegetation/surface.glsl"
#include "vegetation/light.glsl"

in vec3 wsPos;
in vec3 wsNormal;
in vec3 msShape;
flat in float vPart;
flat in float vTint;
flat in float vFar;
flat in float vImpostor;
out vec4 fragColor;

uniform vec3 uLod;  // z: 0 the full shape, 1 the simplified one
uniform int uKind;  // 0 conifer, 1 broadleaf, 2 bush

void main() {
    float threshold = bayer(ivec2(gl_FragCoord.xy));
    if (uLod.z < 0.5 ? vFar > threshold : vFar <= threshold || vImpostor > threshold) {
        discard;
    }
    PlantSurface p = plantSurface(normalize(wsNormal), msShape, vPart > 0.5, vTint, uKind);
    fragColor = vec4(plantLight(p, wsPos), 1.0);
}
