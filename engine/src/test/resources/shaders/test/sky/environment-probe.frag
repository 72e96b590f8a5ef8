#version 330 core
// The environment map read back in four directions, one per 8-pixel column, linear, times 4 so a blue sky's
// radiance (about 0.05-0.2 display units) uses the 8-bit range (engine test: org.openworld.engine.sky.EnvironmentMapTest).
#include "common/environment.glsl"

out vec4 fragColor;

void main() {
    int column = min(int(gl_FragCoord.x) / 8, 3);
    vec3 directions[4] = vec3[4](
        vec3(0.0, 1.0, 0.0),                                 // zenith
        vec3(cos(radians(20.0)), sin(radians(20.0)), 0.0),   // east, 20 deg up
        vec3(0.0, sin(radians(45.0)), -cos(radians(45.0))),  // north, 45 deg up
        vec3(-cos(radians(10.0)), sin(radians(10.0)), 0.0)); // west, 10 deg up
    fragColor = vec4(environmentRadiance(directions[column], 0.0) * 4.0, 1.0);
}
