#version 330 core
// The minimap: the relief around the camera, north up, moved so the camera's exact position is at the centre, with
// a marker at the camera pointing where it looks, inside a thin border. An overlay: its colours are display (sRGB)
// values, drawn as they are, without light, fog or tone mapping. Engine: org.openworld.engine.minimap.
#include "common/conventions.glsl"

in vec2 mapUv;  // 0..1 across the map: x east, y north

uniform sampler2D relief;  // the ReliefMap: s east, t south; display colours
uniform vec3 uSquare;      // z: the square's side (px)
uniform vec3 uCamera;      // xy: the camera's (s, t) on the relief; z: the share of the relief shown across the map
uniform vec2 uHeading;     // sin(yaw), cos(yaw): the view direction, x east, y north
uniform vec2 uMarker;      // x: the marker's length from the camera to its tip (px); y: the border's width (px)

out vec4 fragColor;

const vec3 BORDER_COLOR = vec3(0.10, 0.10, 0.12);  // near black: parts the map from sky and snow alike
const vec3 MARKER_COLOR = vec3(0.90, 0.10, 0.05);  // signal red: no land or water on the map is red
const vec3 RIM_COLOR = vec3(1.0);                  // white, so the marker shows on dark slopes too
const float RIM_PX = 1.5;                          // the rim's width (px)

// Signed distance (px) from a point to the marker, negative inside: a dart pointing along +y, its tip at length L
// from the camera, its barbs 0.6 L behind and beside it and a notch between them 0.25 L behind, so it reads as an
// arrow and not as a triangle that might point either way. For a convex shape the largest signed distance to its
// edges' lines is exact inside and near the edges, which is all the rim needs; the dart is the triangle of tip and
// barbs less the triangle of barbs and notch.
float edgeDistance(vec2 p, vec2 a, vec2 b) {
    vec2 e = normalize(b - a);
    return e.y * (p.x - a.x) - e.x * (p.y - a.y);  // positive right of a -> b: outside, the corners going round anticlockwise
}

float triangle(vec2 p, vec2 a, vec2 b, vec2 c) {
    return max(max(edgeDistance(p, a, b), edgeDistance(p, b, c)), edgeDistance(p, c, a));
}

float dart(vec2 p, float L) {
    vec2 tip = vec2(0.0, L);
    vec2 left = vec2(-0.6 * L, -0.6 * L);
    vec2 right = vec2(0.6 * L, -0.6 * L);
    vec2 notch = vec2(0.0, -0.25 * L);
    return max(triangle(p, tip, left, right), -triangle(p, left, right, notch));
}

void main() {
    float side = uSquare.z;
    vec2 px = mapUv * side;  // pixels from the map's lower-left corner
    // 1. the border
    float fromEdge = min(min(px.x, px.y), min(side - px.x, side - px.y));
    if (fromEdge < uMarker.y) {
        fragColor = vec4(BORDER_COLOR, 1.0);
        return;
    }
    // 2. the relief: the centre of the map is the camera; north (+y on the map) is towards t = 0 on the relief
    vec2 st = uCamera.xy + vec2(mapUv.x - 0.5, 0.5 - mapUv.y) * uCamera.z;
    vec3 color = texture(relief, st).rgb;
    // 3. the marker, turned to the yaw: p in (right, forward) of the view direction, pixels from the centre
    vec2 p = px - 0.5 * side;
    vec2 local = vec2(p.x * uHeading.y - p.y * uHeading.x, dot(p, uHeading));
    float d = dart(local, uMarker.x);
    color = mix(color, RIM_COLOR, clamp(RIM_PX + 0.5 - d, 0.0, 1.0));  // a pixel's worth of anti-aliasing
    color = mix(color, MARKER_COLOR, clamp(0.5 - d, 0.0, 1.0));
    fragColor = vec4(color, 1.0);
}
