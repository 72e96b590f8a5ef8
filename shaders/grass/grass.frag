#version 330 core
// A blade's light (engine: org.openworld.engine.grass.GrassDraw): the terrain's own light, so the blades sit in the
// ground they grow from: the sun (wrapped Lambert, where the shadow cascades see it: common/shadow.glsl), the sky's
// hemisphere light, the light through the blade seen against the sun, then the air in front of it (common/fog.glsl)
// and the display transform (common/color.glsl).
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"

in vec3 wsPos;
in vec3 wsFace;
in float vAlong;
flat in float vTint;
out vec4 fragColor;

// Albedos, linear: the root the dark and light blades of the ground's grass texture (terrain.material's
// MaterialRecipes), so a meadow's far blades melt into the ground; the tips lighter and yellower, towards the
// texture's dry patches, as grass tips in the sun.
const vec3 ROOT_DARK = vec3(0.030, 0.075, 0.012);
const vec3 ROOT_LIGHT = vec3(0.085, 0.165, 0.030);
const vec3 TIP_DARK = vec3(0.060, 0.130, 0.020);
const vec3 TIP_LIGHT = vec3(0.160, 0.190, 0.045);
// A meadow is a layer, not a surface of its own: the normal leans this far towards the sky, so the blades light like
// the ground under them and not each by its own turn.
const float UP_BLEND = 1.5;
// Lambert wrapped by this share of the hemisphere: light reaches round a thin blade.
const float WRAP = 0.4;
// A blade lets through about as much light as it reflects, greener.
const vec3 TRANSMIT = vec3(0.7, 1.1, 0.4);
// The tuft's root in the shade of its own blades: the light at the root, a share of the tip's.
const float ROOT_SHADE = 0.6;

void main() {
    vec3 face = gl_FrontFacing ? wsFace : -wsFace;
    vec3 n = normalize(face + vec3(0.0, UP_BLEND, 0.0));
    vec3 l = sunDir();
    vec3 albedo = mix(mix(ROOT_DARK, ROOT_LIGHT, vTint), mix(TIP_DARK, TIP_LIGHT, vTint), vAlong);
    float nl = max((dot(n, l) + WRAP) / (1.0 + WRAP), 0.0);
    float visible = sunVisibility(wsPos, n);
    float shade = mix(ROOT_SHADE, 1.0, vAlong);
    vec3 color = albedo * (frame.sunColor.rgb * nl * visible + skyIrradiance(n)) * shade;
    vec3 v = normalize(wsPos - cameraPos());
    color += TRANSMIT * albedo * frame.sunColor.rgb * pow(max(dot(v, l), 0.0), 4.0) * visible * vAlong;
    fragColor = vec4(displayColor(applyFog(color, wsPos)), 1.0);
}
