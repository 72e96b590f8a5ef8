#version 330 core
// A snowflake as a billboard (paper section 4; engine: org.openworld.engine.particles.ParticleSystem): one instance
// per flake, a square of two triangles (four corners) that faces the camera. The flake's light is worked
// out here, once per corner, and handed on flat: all four corners share the flake's centre.
//
// Size and brightness follow distance: a flake is drawn at its true size until that is under uFlake.y pixels of
// radius; farther away it stays that big and fades with the square of the ratio, so it gives the picture the light
// it would cover, not more. Towards the cube's edge it fades out, so flakes wrapping round never pop in.
#include "common/frame.glsl"
#include "common/color.glsl"
#include "common/fog.glsl"
#include "common/shadow.glsl"

layout(location = 0) in vec3 position;   // the flake's centre, world space (m): per instance
layout(location = 1) in vec2 unitCorner; // the square's corner, 0 or 1 on each axis: per vertex

uniform vec4 uFlake; // x: radius (m); y: smallest drawn radius (px); z: the cube's side (m); w: albedo

out vec2 corner;     // -1..1 across the billboard
flat out vec4 flake; // rgb: display colour; a: opacity at the centre

void main() {
    corner = unitCorner * 2.0 - 1.0;
    float halfSide = 0.5 * uFlake.z;
    vec3 vsCentre = (frame.view * vec4(position, 1.0)).xyz;
    float depth = -vsCentre.z;
    float near = frame.cameraPosNear.w;
    float distance = length(vsCentre);
    // radius in pixels: metres / depth, times the projection's scale, times half the picture's height
    float pixels = uFlake.x * frame.projection[1][1] * 0.5 * frame.viewport.y / max(depth, near);
    float drawn = max(pixels, uFlake.y);
    float opacity = (pixels / drawn) * (pixels / drawn)
            * (1.0 - smoothstep(0.6 * halfSide, halfSide, distance)) // the cube's inscribed sphere, faded at its rim
            * smoothstep(near, 2.0 * near, depth)                    // not cut by the near plane
            * snowfallShare(position);                               // only under the cloud it falls from
    // Most flakes are behind the eye or beside the view: skip them before the light, the costly part (the shadow
    // maps' filter and the air's table), keeping those whose disc reaches into the picture.
    vec4 clipCentre = frame.projection * vec4(vsCentre, 1.0);
    vec2 reach = 2.0 * drawn * frame.viewport.zw; // the drawn radius, in normalised device units
    bool outside = any(greaterThan(abs(clipCentre.xy / clipCentre.w), 1.0 + reach));
    if (opacity < 1.0 / 512.0 || outside) {
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume: nothing is rasterised
        flake = vec4(0.0);
        return;
    }
    // A thin translucent plate at a random angle catches on average half the sun's light (the mean |cos|) and the
    // whole sky's on an upward surface, and scatters it to both sides.
    vec3 toSun = sunDir();
    vec3 lit = uFlake.w * (0.5 * frame.sunColor.rgb * sunVisibility(position, toSun) + frame.ambientColor.rgb);
    flake = vec4(displayColor(applyFog(lit, position)), opacity);
    vec3 vsCorner = vsCentre + vec3(corner * uFlake.x * drawn / pixels, 0.0);
    gl_Position = frame.projection * vec4(vsCorner, 1.0);
}
