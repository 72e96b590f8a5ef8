#version 330 core
// A full-screen triangle: the water is found per pixel by intersecting the view ray with its plane, so it reaches
// the horizon in every direction with no mesh to run out (engine: org.openworld.engine.water.WaterSystem).
// Above the water its corners carry the plane's own depth, an affine function of the screen position
// (PlaneOnScreen), and a clip distance cuts it at the horizon: the rasteriser gives every pixel the plane's depth, so
// the depth test rejects the water under the terrain before its fragment shader runs. Under the water (and for the
// stencil method's full-screen quad) the clip distance is not enabled and the fragment shader writes the depth.
layout(location = 0) in vec2 csCorner;
out vec2 ndc;

uniform vec3 uDepthPlane; // NDC depth of the water: dot(uDepthPlane, vec3(x, y, 1))
uniform vec3 uHorizon;    // the water's side of the horizon: dot(uHorizon, vec3(x, y, 1)) >= 0

void main() {
    ndc = csCorner;
    gl_Position = vec4(csCorner, dot(uDepthPlane, vec3(csCorner, 1.0)), 1.0);
    gl_ClipDistance[0] = dot(uHorizon, vec3(csCorner, 1.0));
}
