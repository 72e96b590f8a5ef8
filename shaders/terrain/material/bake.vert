#version 330 core
// One triangle over the whole target (or viewport): the far material's bake (terrain/material/bake.frag) and the
// unbounded world's sky visibility per block (terrain/stream/sky.frag) and the tile's (terrain/material/tilesky.frag).
layout(location = 0) in vec2 position;

void main() {
    gl_Position = vec4(position, 0.0, 1.0);
}
