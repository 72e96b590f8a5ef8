#version 330 core
// A plant's impostor (engine: org.openworld.engine.vegetation.ImpostorAtlas): the three nearest baked frames' albedo,
// normal and depth blended (vegetation/impostor-sample.glsl), lit per pixel as the meshes are (vegetation/light.glsl)
// at the point the depths put back behind or before the card, so the sun, the shadow maps and the air see the plant
// where its mesh would stand.
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"
#include "vegetation/surface.glsl"
#include "vegetation/light.glsl"
#include "vegetation/atlas.glsl"
#include "vegetation/octahedron.glsl"
#include "vegetation/impostor-sample.glsl"

flat in float vShare;
flat in float vTint;
out vec4 fragColor;

void main() {
    if (vShare <= bayer(ivec2(gl_FragCoord.xy))) {
        discard;
    }
    // the views' blend dithered by the 4 x 4 pattern turned a quarter and shifted, so it does not follow the
    // cross-fade's
    ImpostorTexel t = impostorTexel(bayer(ivec2(gl_FragCoord.yx) + ivec2(2, 1)));
    if (!t.covered) {
        discard;
    }
    PlantSurface p;
    p.foliage = t.foliage;
    // the albedo baked at the mean tint, 0.5; the plant's own as surface.glsl adds it, linear in the tint
    p.albedo = t.albedo + (p.foliage ? 0.5 * (vTint - 0.5) * (FOLIAGE_LIGHT[uKind] - FOLIAGE_DARK[uKind]) : vec3(0.0));
    // into the world: turned, and squeezed across by the width (the inverse transpose of the widening)
    p.normal = normalize(vec3(mat2(vTurn.x, vTurn.y, -vTurn.y, vTurn.x) * t.normal.xz / vTurn.z, t.normal.y).xzy);
    fragColor = vec4(plantLight(p, t.wsPos), 1.0);
}
