#version 330 core
// linearToSrgb (common/color.glsl) over a ramp of linear values, one per column, squared so the dark end, where the
// curve is steepest, gets as many columns as the bright (engine test: SrgbEncodingTest).
#include "common/color.glsl"

uniform float width; // columns of the target
out vec4 fragColor;

void main() {
    float t = (gl_FragCoord.x - 0.5) / (width - 1.0);
    fragColor = vec4(linearToSrgb(vec3(t * t)), 1.0);
}
