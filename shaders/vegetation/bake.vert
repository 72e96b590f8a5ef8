#version 330 core
// An impostor's view of a plant (engine: org.openworld.engine.vegetation.ImpostorAtlas): the full shape (1 unit tall
// on its foot) seen along one of the hemi-octahedral directions, orthographic, its bounding sphere filling the
// viewport (one frame of the atlas).
#include "vegetation/octahedron.glsl"

layout(location = 0) in vec3 msPos;
layout(location = 1) in vec3 msNormal;
layout(location = 2) in float part;

uniform vec2 uFrame;   // the frame's cell in the grid, (i, j)
uniform float uFrames; // cells per side of the grid
uniform vec2 uSphere;  // the bounding sphere: x its centre's height, y its radius (units of the plant's height)
uniform float uHeight; // metres: the height the patterns are made at (the kind's mean)

out vec3 bakeNormal;
out vec3 msShape;
out float bakeDepth;
flat out float vPart;

void main() {
    vec3 f = hemiOctDecode(uFrame / (uFrames - 1.0));
    vec3 right;
    vec3 up;
    frameBasis(f, right, up);
    vec3 p = (msPos - vec3(0.0, uSphere.x, 0.0)) / uSphere.y;
    bakeDepth = dot(p, f); // -1 at the back of the sphere, 1 at its front
    bakeNormal = msNormal;
    msShape = msPos * uHeight;
    vPart = part;
    gl_Position = vec4(dot(p, right), dot(p, up), -bakeDepth, 1.0);
}
