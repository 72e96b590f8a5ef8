#version 330 core
// A blade's light (engine: org.openworld.engine.grass.GrassDraw): the terrain's own light, so the blades sit in the
// ground they grow from: the sun (wrapped Lambert, where the shadow cascades see it: common/shadow.glsl), the sky's
// hemisphere light, the light through the blade seen against the sun, then the air in front of it (common/fog.glsl)
// and the display transform (common/color.glsl).
#include "common/frame.glsl"
#include "common/fog.glsl"
#include "common/color.glsl"
#include "common/shadow.glsl"
#include "common/environment.glsl"

in vec3 wsPos;
in vec3 wsFace;
in float vAlong;
flat in float vTint;
flat in float vOwn;
flat in vec3 vGround;
flat in float vContact;
out vec4 fragColor;

uniform vec4 uGround;     // the ground's grass from afar (terrain.material's GrassAlbedo): linear albedo, sheen

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
// The ground's reflectance at normal incidence (terrain/material/material.glsl's MAT_F0: leaves, IOR ~1.3-1.5).
const float GROUND_F0 = 0.04;

void main() {
    vec3 face = gl_FrontFacing ? wsFace : -wsFace;
    vec3 n = normalize(face + vec3(0.0, UP_BLEND, 0.0));
    vec3 l = sunDir();
    vec3 albedo = mix(mix(ROOT_DARK, ROOT_LIGHT, vTint), mix(TIP_DARK, TIP_LIGHT, vTint), vAlong);
    float nl = max((dot(n, l) + WRAP) / (1.0 + WRAP), 0.0);
    float visible = sunVisibility(wsPos, n);
    // the contact shadow: the meadow's own blades hide the sky and the sun from a root, less up the blade
    float shade = 1.0 - vContact * (1.0 - vAlong);
    vec3 color = albedo * (frame.sunColor.rgb * nl * visible + skyIrradiance(n)) * shade;
    vec3 v = normalize(wsPos - cameraPos());
    color += TRANSMIT * albedo * frame.sunColor.rgb * pow(max(dot(v, l), 0.0), 4.0) * visible * vAlong;
    // far off the blade takes on the look of the ground it stands on (its grass from afar, lit on its normal as the
    // terrain lights it), so the blades that thin away are the ground's colour and leave no change of tone
    if (vOwn < 1.0) {
        vec3 ground = uGround.rgb * (frame.sunColor.rgb * max(dot(vGround, l), 0.0) * visible
                + skyIrradiance(vGround));
        // and its sheen: the sky it reflects, strong at a grazing look (the terrain's Schlick Fresnel, F0 = 0.04),
        // blurred as grass's low gloss blurs it
        float m = 1.0 - max(dot(vGround, -v), 0.0);
        float fresnel = GROUND_F0 + (1.0 - GROUND_F0) * m * m * m * m * m;
        ground += environmentRadiance(reflect(v, vGround), ENVIRONMENT_ROUGH_LOD) * fresnel * uGround.a;
        color = mix(ground, color, vOwn);
    }
    fragColor = vec4(displayColor(applyFog(color, wsPos)), 1.0);
}
