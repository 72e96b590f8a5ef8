// The per-pass frame block (engine: org.openworld.engine.gl.FrameUniforms). Every member is a vec4, a mat4 or an
// array of vec4s, so the std140 layout is simply their order. Conventions: shaders/common/conventions.glsl.
//
// Two eyes, not to be mixed up:
//   cameraPos()  the PASS camera's eye: the viewer's in MAIN and OVERLAY, the mirrored eye under the water in
//                REFLECTION, and in SHADOW the sun's camera (a point on the light box's sunward face). Use it for
//                what depends on the picture being drawn: the view ray, the air in front of a surface, a highlight.
//   viewerPos()  the VIEWER's eye (the MAIN camera's), the same in every pass. Use it for what must agree between
//                the passes: a level of detail, a fade or a cut-off with distance. Faded by cameraPos(), an object
//                would leave the shadow maps (the sun's camera is far away) and the reflection at other distances
//                than it leaves the picture.
#include "common/conventions.glsl"

layout(std140) uniform FrameBlock {
    mat4 view;            // world -> view
    mat4 projection;      // view -> clip
    mat4 viewProjection;  // world -> clip
    mat4 invViewProjection;
    vec4 cameraPosNear;   // xyz: the pass camera's eye, world space (m); w: near plane (m)
    vec4 sunDirFar;       // xyz: unit vector towards the sun, world space; w: far plane (m)
    vec4 sunColor;        // rgb: direct sunlight at the eye, display units (1 = the sun above the atmosphere)
    vec4 ambientColor;    // rgb: sky light on an upward surface, display units
    vec4 exposure;        // x: scene (display units, 1 = white under the sun above the air) -> tone mapper input;
                          // y: the rods' share of vision, 0 by day .. 1 at night (the Purkinje shift); zw: 0
    vec4 timeInfo;        // x: simulation time (s); y: time of day (h); z: frame index; w: 0
    vec4 viewport;        // xy: size (px); zw: 1 / size
    vec4 viewerPos;       // xyz: the viewer's eye, world space (m), the same in every pass; w: 0
    vec4 origin;          // xz: the render origin in steps, whole numbers; y: 0; w: the step (m) (engine:
                          // origin.RenderOrigin). "World space" on the GPU is measured from it: every position
                          // above and in the vertex data is p - origin, so a float keeps its millimetres.
    vec4 sky[10];         // rgb: [0..8] the sky's and the ground's irradiance as factors of order-2 spherical
                          // harmonics, [9] the light of the terrain where it hides the sky (engine:
                          // environment.SkyIrradiance), read by skyIrradiance
} frame;

vec3 cameraPos() { return frame.cameraPosNear.xyz; }
vec3 viewerPos() { return frame.viewerPos.xyz; }
vec3 sunDir() { return frame.sunDirFar.xyz; }

// The light of the sky and of the sunlit ground around on a surface of unit normal n, display units: the irradiance
// convolution of Ramamoorthi and Hanrahan (2001) with its factors folded in on the CPU, so 9 multiply-adds and no
// texture read. Facing up it is ambientColor within a few per cent; facing down, the ground's bounce light.
vec3 skyIrradiance(vec3 n) {
    return frame.sky[0].rgb + frame.sky[1].rgb * n.y + frame.sky[2].rgb * n.z + frame.sky[3].rgb * n.x
        + frame.sky[4].rgb * (n.x * n.y) + frame.sky[5].rgb * (n.y * n.z)
        + frame.sky[6].rgb * (3.0 * n.y * n.y - 1.0) + frame.sky[7].rgb * (n.x * n.z)
        + frame.sky[8].rgb * (n.x * n.x - n.z * n.z);
}

// The same where the relief hides part of the sky and leaves `visible` of it (engine: HorizonSearch): the
// hidden share sees the terrain instead, lit as the sky system reckons (sky.SkyLight#irradiance).
vec3 skyIrradiance(vec3 n, float visible) {
    return mix(frame.sky[9].rgb, skyIrradiance(n), visible);
}

// The world-space direction of the view ray through a point of the screen (ndc.xy in -1..1), unnormalised. Built
// from the view's rotation and the projection's x and y scales, not by unprojecting a depth: that stays right for a
// mirrored view and for the water's oblique projection, whose near and far planes are tilted.
vec3 viewRay(vec2 ndc) {
    vec3 vsDir = vec3((ndc.x + frame.projection[2][0]) / frame.projection[0][0],
                      (ndc.y + frame.projection[2][1]) / frame.projection[1][1], -1.0);
    return transpose(mat3(frame.view)) * vsDir;
}
