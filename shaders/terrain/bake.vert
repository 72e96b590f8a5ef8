#version 330 core
// The far material's bake (terrain/bake.frag): one triangle over the whole target.
layout(location = 0) in vec2 position;

void main() {
    gl_Position = vec4(position, 0.0, 1.0);
}
