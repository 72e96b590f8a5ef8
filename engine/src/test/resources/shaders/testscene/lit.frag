#version 330 core
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"

in vec3 wsPos;
in vec3 wsNormal;
out vec4 fragColor;

const float GRID_SPACING = 50.0; // metres between grid lines
const float LINE_WIDTH = 1.5;    // pixels

// Anti-aliased grid lines: distance to the nearest line in pixels, from the screen-space derivative.
float gridLine(vec2 wsXZ) {
    vec2 cell = wsXZ / GRID_SPACING;
    vec2 pixels = abs(fract(cell - 0.5) - 0.5) / fwidth(cell);
    return 1.0 - clamp(min(pixels.x, pixels.y) / LINE_WIDTH, 0.0, 1.0);
}

void main() {
    vec3 n = normalize(wsNormal);
    bool isGround = n.y > 0.99 && wsPos.y < 0.01;
    vec3 albedo = isGround ? mix(vec3(0.30, 0.34, 0.26), vec3(0.85), gridLine(wsPos.xz)) : vec3(0.70, 0.45, 0.30);
    float diffuse = max(dot(n, sunDir()), 0.0) * sunVisibility(wsPos, n);
    vec3 light = frame.sunColor.rgb * diffuse + frame.ambientColor.rgb * (0.5 + 0.5 * n.y);
    vec3 color = applyFog(albedo * light, wsPos);
    fragColor = vec4(displayColor(color), 1.0);
}
