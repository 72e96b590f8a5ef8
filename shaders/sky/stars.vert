#version 330 core
// The stars (engine: org.openworld.engine.sky.StarField): one point of one pixel per star, on the far plane. The catalogue's equatorial directions turned to the world by the sky of the moment; a direction is a point
// at infinity (w = 0), so the camera's position does not move it.
#include "common/frame.glsl"

layout(location = 0) in vec4 star;       // xyz: unit direction, equatorial axes; w: light against the sun's

uniform mat3 uEquatorialToWorld;

out vec3 wsRay;
flat out float starRadiance;             // pi x the radiance over one pixel, display units

void main() {
    wsRay = uEquatorialToWorld * star.xyz;
    vec4 clip = frame.viewProjection * vec4(wsRay, 0.0);
    // below the horizon the sky is the distant ground: no star (a point outside the clip volume draws nothing)
    gl_Position = wsRay.y < 0.0 ? vec4(2.0, 2.0, 2.0, 1.0) : clip.xyww;
    gl_PointSize = 1.0; // one pixel, should a program point size be switched on
    // the pixel's solid angle at the centre of the picture, (2 / (P00 W)) (2 / (P11 H)) steradians
    float pixel = 4.0 * frame.viewport.z * frame.viewport.w / (frame.projection[0][0] * frame.projection[1][1]);
    starRadiance = 3.14159265 * star.w / pixel;
}
