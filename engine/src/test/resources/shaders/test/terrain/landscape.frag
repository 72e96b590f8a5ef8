#version 330 core
// The stand-in landscape shaded by material.glsl, to judge the materials from afar (engine test:
// org.openworld.engine.terrain.material.MaterialRenderTest): the height field's normal gives the tangent frame, a made-up
// snow map puts snow likelier higher up; with uSky = 1 the environment map behind it.
#include "terrain/material/material.glsl"
uniform float uSkyVisibility; // the share of the sky the relief leaves (set to 1: open ground)
#include "common/fog.glsl"
#include "common/color.glsl"

in vec3 wsPos;
in vec3 wsNormal;
uniform int uSky;
uniform float uTop;   // metres: the highest point of the mesh, where height01 = 1
out vec4 fragColor;

void main() {
    if (uSky == 1) {
        vec2 ndc = gl_FragCoord.xy * frame.viewport.zw * 2.0 - 1.0;
        vec4 wsFar = frame.invViewProjection * vec4(ndc, 1.0, 1.0);
        vec3 dir = normalize(wsFar.xyz / wsFar.w - cameraPos());
        vec3 sky = environmentRadiance(dir, 0.0) + frame.sunColor.rgb * pow(max(dot(dir, sunDir()), 0.0), 400.0) * 4.0;
        fragColor = vec4(displayColor(sky), 1.0);
        return;
    }
    vec3 n = normalize(wsNormal);
    TerrainSurface s;
    s.wsPos = wsPos;
    s.wsNormal = n;
    s.wsTangent = normalize(vec3(n.y, -n.x, 0.0));    // (1, dh/dx, 0) with dh/dx = -n.x / n.y
    s.wsBitangent = normalize(vec3(0.0, -n.z, n.y));  // (0, dh/dz, 1)
    s.height01 = clamp(wsPos.y / uTop, 0.0, 1.0);
    float patchy = matValueNoise(wsPos.xz / 180.0, vec2(0.0)) + 0.5 * matValueNoise(wsPos.xz / 60.0, vec2(0.0));
    s.snow = smoothstep(0.5, 0.62, s.height01 + 0.2 * (patchy - 0.75));
    s.skyVisibility = uSkyVisibility;
    s.sediment = 0.0; // no erosion
    s.bare = 0.0;
    fragColor = vec4(displayColor(applyFog(shadeTerrain(s), wsPos)), 1.0);
}
