#version 330 core
// A fixed, saturated display colour: a debug overlay that must stand out against sky, terrain and water, so it
// bypasses lighting, fog and tone mapping.

out vec4 fragColor;

const vec3 OUTLINE_COLOR = vec3(1.0, 0.1, 0.85); // magenta, display (sRGB) values

void main() {
    fragColor = vec4(OUTLINE_COLOR, 1.0);
}
