#version 330 core
// The minimap's square: corners (0, 0) to (1, 1), placed in the picture by uSquare.
#include "common/frame.glsl"

layout(location = 0) in vec2 corner;  // 0..1 across the square

uniform vec3 uSquare;  // xy: the square's lower-left corner (px, from the picture's lower left); z: its side (px)

out vec2 mapUv;  // 0..1 across the map: x east, y north

void main() {
    mapUv = corner;
    vec2 px = uSquare.xy + corner * uSquare.z;
    gl_Position = vec4(px * frame.viewport.zw * 2.0 - 1.0, 0.0, 1.0);
}
