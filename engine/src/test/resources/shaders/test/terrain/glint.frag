#version 330 core
// A glossy surface seen where it mirrors the sun (engine test: org.openworld.engine.terrain.material.SpecularAntialiasTest):
// every pixel shows the same ground point, the mirror point of the sun for the camera, under the same light, with
// the gloss of a polished texel (1). The left half is smooth; on the right half the detail normal tilts by uTilt
// (tangent-space slope along x) on every other pixel, in a checkerboard: bumps smaller than a pixel, as far ground
// shows them. The albedo is the material's own (so material.glsl's textures stay bound and read).
#include "terrain/material/material.glsl"
uniform float uSkyVisibility; // the share of the sky the relief leaves (set to 1: open ground)
#include "common/color.glsl"

out vec4 fragColor;

const float TILT = 0.15; // tangent-space slope of the tilted texels: 8.5 degrees

void main() {
    vec3 eye = cameraPos();
    vec3 toSun = sunDir();
    TerrainSurface s;
    s.wsPos = vec3(eye.xz + toSun.xz * (eye.y / toSun.y), 0.0).xzy;
    s.wsNormal = vec3(0.0, 1.0, 0.0);
    s.wsTangent = vec3(1.0, 0.0, 0.0);
    s.wsBitangent = vec3(0.0, 0.0, 1.0);
    s.height01 = 0.1;
    s.snow = 0.0;
    s.skyVisibility = uSkyVisibility;
    s.sediment = 0.0; // no erosion
    s.bare = 0.0;
    MatTexel m = terrainMaterial(s, 0.5, matMacroTint(s.wsPos.xz)); // one ground point: one macro value
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    bool bumpy = gl_FragCoord.x > 0.5 * frame.viewport.x;
    bool tilted = bumpy && (pixel.x + pixel.y) % 2 == 1;
    m.slope = vec2(tilted ? TILT : 0.0, 0.0);
    m.gloss = 1.0;
    fragColor = vec4(displayColor(lightTerrain(s, m)), 1.0);
}
