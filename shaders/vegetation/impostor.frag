#version 330 core
// A plant's impostor (engine: org.openworld.engine.vegetation.ImpostorAtlas): the baked frame's albedo, normal and
// depth, lit per pixel as the meshes are (vegetation/light.glsl) at the point the depth puts back behind or before the
// card, so the sun, the shadow maps and the air see the plant where its mesh would stand.
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"
#include "vegetation/surface.glsl"
#include "vegetation/light.glsl"
#include "vegetation/atlas.glsl"

in vec2 frameUv;
in vec3 wsCard;
flat in float vShare;
flat in float vTint;
flat in vec3 vTurn;
flat in vec3 vDepthAxis;
out vec4 fragColor;

void main() {
    if (vShare <= bayer(ivec2(gl_FragCoord.xy))) {
        discard;
    }
    vec4 albedo = texture(uAtlas, atlasUv(frameUv, 0));
    if (albedo.a < COVERED) {
        discard;
    }
    vec4 normalDepth = texture(uAtlas, atlasUv(frameUv, 1));
    PlantSurface p;
    p.foliage = albedo.a > FOLIAGE;
    // the albedo baked at the mean tint, 0.5; the plant's own as surface.glsl adds it, linear in the tint
    p.albedo = albedo.rgb * albedo.rgb
            + (p.foliage ? 0.5 * (vTint - 0.5) * (FOLIAGE_LIGHT[uKind] - FOLIAGE_DARK[uKind]) : vec3(0.0));
    vec3 n = normalDepth.xyz * 2.0 - 1.0;
    // into the world: turned, and squeezed across by the width (the inverse transpose of the widening)
    p.normal = normalize(vec3(mat2(vTurn.x, vTurn.y, -vTurn.y, vTurn.x) * n.xz / vTurn.z, n.y).xzy);
    vec3 wsPos = wsCard + vDepthAxis * (normalDepth.a * 2.0 - 1.0);
    fragColor = vec4(plantLight(p, wsPos), 1.0);
}
