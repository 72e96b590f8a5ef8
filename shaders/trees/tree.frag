#version 330 core
// A conifer's light (engine: org.openworld.engine.trees.TreeSystem): the terrain's own light, so trees and ground
// sit in one picture: the sun (Lambert, where the shadow maps see it: common/shadow.glsl), the sky's hemisphere
// light, then the air in front of it (common/fog.glsl) and the display transform (common/color.glsl).
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"

in vec3 wsPos;
in vec3 wsNormal;
flat in float vPart;
flat in float vTint;
out vec4 fragColor;

// Albedos, linear: spruce needles reflect 3-8% of visible light (dark, bluish green); bark a little more, brown.
const vec3 NEEDLES_DARK = vec3(0.028, 0.055, 0.030);
const vec3 NEEDLES_LIGHT = vec3(0.055, 0.085, 0.035);
const vec3 BARK = vec3(0.10, 0.065, 0.040);
// A crown is not a closed surface: light reaches a little round its edge. Lambert "wrapped" by this share of the
// hemisphere, cos' = (cos + WRAP) / (1 + WRAP), so the cones' shaded sides are not black under a low sun.
const float WRAP = 0.3;

void main() {
    vec3 n = normalize(wsNormal);
    vec3 l = sunDir();
    bool needles = vPart > 0.5;
    vec3 albedo = needles ? mix(NEEDLES_DARK, NEEDLES_LIGHT, vTint) : BARK;
    float wrap = needles ? WRAP : 0.0;
    float nl = max((dot(n, l) + wrap) / (1.0 + wrap), 0.0);
    float sun = nl * sunVisibility(wsPos, n);
    vec3 sky = skyIrradiance(n);
    vec3 color = albedo * (frame.sunColor.rgb * sun + sky);
    fragColor = vec4(displayColor(applyFog(color, wsPos)), 1.0);
}
