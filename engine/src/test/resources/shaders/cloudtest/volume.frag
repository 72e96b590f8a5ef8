#version 330 core
// Reads a single-channel 3D texture back (engine test: org.openworld.engine.gl.Texture3DTest): pixel (x, y) samples
// texel column x, row y of the volume at depth coordinate r, shifted by whole or partial tiles, and writes the
// value to red.
uniform sampler3D volume;
uniform vec4 lookup; // xy: offset added to the texel centre's s, t (tiles); z: the r coordinate; w: unused
out vec4 fragColor;

void main() {
    vec3 size = vec3(textureSize(volume, 0));
    vec2 st = gl_FragCoord.xy / size.xy + lookup.xy;
    fragColor = vec4(texture(volume, vec3(st, lookup.z)).r, 0.0, 0.0, 1.0);
}
