#version 330 core
// Eight material cases side by side, each a cell of ground seen from above (engine test:
// org.openworld.engine.terrain.material.MaterialRenderTest, which knows the same layout). Top row, left to right:
//   0 a flat low meadow, 1 a flat high snowfield, 2 a 55-degree slope at low height, 3 a flat high bare peak;
// bottom row:
//   4 height rising 0 -> 1 left to right with a snow map rising above 0.55, 5 slope rising 0 -> 65 degrees at low
//   height, 6 slope rising 0 -> 70 degrees under full snow-map cover, 7 flat rock at mid height.
// Slopes fall towards the east (+X), facing the morning sun.
// Every cell covers CELL_METRES of ground around uCentre, where the sun's mirror image is seen from the camera.
#include "terrain/material/material.glsl"
uniform float uSkyVisibility; // the share of the sky the relief leaves (set to 1: open ground)
#include "common/color.glsl"

uniform vec3 uCentre;          // world point at each cell's centre, on the ground (y = 0)
uniform float uSediment;       // the erosion's sediment cover on every cell (0: none)
uniform float uBare;           // the bed the erosion bared on every cell (0: none)
out vec4 fragColor;

const float CELL_METRES = 2.5; // width of ground one cell shows

TerrainSurface ground(vec2 wsXZ, float gradientX, float height01, float snow) {
    TerrainSurface s;
    s.wsPos = vec3(wsXZ.x, gradientX * (wsXZ.x - uCentre.x), wsXZ.y);
    s.wsNormal = normalize(vec3(-gradientX, 1.0, 0.0));
    s.wsTangent = normalize(vec3(1.0, gradientX, 0.0));
    s.wsBitangent = vec3(0.0, 0.0, 1.0);
    s.height01 = height01;
    s.snow = snow;
    s.skyVisibility = uSkyVisibility;
    s.sediment = uSediment;
    s.bare = uBare;
    return s;
}

void main() {
    vec2 cellSize = frame.viewport.xy / vec2(4.0, 2.0);
    ivec2 cell = ivec2(gl_FragCoord.xy / cellSize);
    int index = (1 - cell.y) * 4 + cell.x;                // row 0 at the top of the image
    vec2 local = (gl_FragCoord.xy - (vec2(cell) + 0.5) * cellSize) / cellSize.x; // -0.5..0.5 across the cell
    float u = local.x + 0.5;                               // 0 at the cell's left edge, 1 at its right
    vec2 wsXZ = uCentre.xz + vec2(local.x, -local.y) * CELL_METRES; // image up is north (-Z)
    TerrainSurface s;
    if (index == 0) {
        s = ground(wsXZ, 0.0, 0.1, 0.0);
    } else if (index == 1) {
        s = ground(wsXZ, 0.0, 0.9, 1.0);
    } else if (index == 2) {
        s = ground(wsXZ, -tan(radians(55.0)), 0.15, 0.0);
    } else if (index == 3) {
        s = ground(wsXZ, 0.0, 0.9, 0.0);
    } else if (index == 4) {
        s = ground(wsXZ, 0.0, u, smoothstep(0.55, 0.85, u));
    } else if (index == 5) {
        s = ground(wsXZ, -tan(radians(65.0 * u)), 0.15, 0.0);
    } else if (index == 6) {
        s = ground(wsXZ, -tan(radians(70.0 * u)), 0.8, 1.0);
    } else {
        s = ground(wsXZ, 0.0, 0.6, 0.0);
    }
    fragColor = vec4(displayColor(shadeTerrain(s)), 1.0);
}
