#version 330 core
// The stand-in sky cube map read back in six directions, one per 8-pixel column, linear and unscaled by the
// display curve (engine test: org.openworld.engine.terrain.MaterialRenderTest, which knows the same directions).
// Columns 6 and on shade a meadow, which keeps every uniform of material.glsl in use.
#include "terrain/material.glsl"

out vec4 fragColor;

void main() {
    int column = int(gl_FragCoord.x) / 8;
    vec3 directions[6] = vec3[6](
        vec3(0.0, 1.0, 0.0),                          // zenith
        vec3(0.0, -1.0, 0.0),                         // nadir
        vec3(cos(radians(30.0)), sin(radians(30.0)), 0.0),  // east, 30 deg up
        vec3(0.0, sin(radians(30.0)), -cos(radians(30.0))), // north, 30 deg up
        vec3(0.0, -sin(radians(30.0)), cos(radians(30.0))), // south, 30 deg down
        vec3(-cos(radians(10.0)), sin(radians(10.0)), 0.0)); // west, 10 deg up
    if (column < 6) {
        fragColor = vec4(skyReflection(directions[column], 0.0), 1.0);
    } else {
        TerrainSurface s;
        s.wsPos = vec3(gl_FragCoord.x, 0.0, gl_FragCoord.y);
        s.wsNormal = vec3(0.0, 1.0, 0.0);
        s.wsTangent = vec3(1.0, 0.0, 0.0);
        s.wsBitangent = vec3(0.0, 0.0, 1.0);
        s.height01 = 0.1;
        s.snow = 0.0;
        fragColor = vec4(shadeTerrain(s), 1.0);
    }
}
