#version 330 core
// A full-screen triangle at the far plane (z = w, so depth 1: drawn only where nothing nearer is), with the world
// direction of each corner: a view ray is linear across the screen, so the rasteriser interpolates it exactly and
// the fragment shader need not rebuild it. uCubeFace 1 takes the direction through a face of the environment map
// instead. The sky panorama draws with it too, and reads neither.
#include "common/frame.glsl"

layout(location = 0) in vec2 csCorner;
out vec3 wsRay;

uniform int uCubeFace;             // 0: the camera's view; 1: a face of the environment map, through uFaceAxes
uniform mat3 uFaceAxes;            // the face's s, t and outward axes (CubeMapTexture.faceAxes)

void main() {
    wsRay = uCubeFace == 1 ? uFaceAxes * vec3(csCorner, 1.0) : viewRay(csCorner);
    gl_Position = vec4(csCorner, 1.0, 1.0);
}
