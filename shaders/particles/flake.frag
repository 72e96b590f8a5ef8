#version 330 core
// A snowflake's disc (paper section 4): round from the distance to the billboard's centre, with a soft rim.
// Premultiplied alpha, blended over the scene with (1, 1 - source alpha).
in vec2 corner;
flat in vec4 flake;

out vec4 fragColor;

void main() {
    float r = length(corner);
    if (r >= 1.0) {
        discard;
    }
    float alpha = flake.a * (1.0 - smoothstep(0.4, 1.0, r)); // opaque core, soft outer rim
    fragColor = vec4(flake.rgb * alpha, alpha);
}
