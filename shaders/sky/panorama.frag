#version 330 core
// The sky panorama (paper 2.3 and 3.1): for the direction of each texel (sky/panorama.glsl), into two targets at
// once: the sky (the dome's radiance from the SkyView table, and the ground far below the horizon seen through the
// air) with the cloud's density above the threshold; and the cloud layer's colour with what the horizon fog leaves
// of it (sky/clouds.glsl, cloudAlong). Linear display units. The sky pass draws the cloud's edge from the density per
// pixel (cloudOpacity). Drawn by SkySystem's update when the sun or the clouds moved: its inputs are uniforms, not
// the pass's frame block, as no pass is being drawn.
#include "sky/atmosphere.glsl"
#include "sky/clouds.glsl"
#include "sky/panorama.glsl"

layout(location = 0) out vec4 skyExcess;         // rgb: the sky behind the clouds; a: the cloud's density excess
layout(location = 1) out vec4 cloudTransmittance; // rgb: the cloud's colour; a: what the horizon fog leaves of it

uniform sampler2D skyView;     // radiance per dome direction, display units (SkyView)
uniform sampler3D airTable;    // in-scattering and transmittance per direction and distance (AerialPerspective)
uniform vec2 uSize;            // the panorama's size, texels (2N x N)
uniform vec3 uSunDir;          // unit vector towards the sun
uniform vec3 uSunColor;        // direct sunlight at the eye, display units
uniform vec3 uAmbientColor;    // sky light on an upward surface, display units
uniform float uAltitude;       // the eye's altitude the tables were made for, metres
uniform float uGroundAlbedo;   // the ground seen below the horizon (AtmosphereSettings.groundAlbedo)
uniform float uScale;          // the colours are stored times this, 1 / the ground's light (SkyPanorama.draw): the
                               // night's radiance is below a half float's normal range, the night's sky relative to
                               // its light is not

// Below the horizon, beyond all terrain: level ground at sea level lit by the sun and the sky, seen through the air
// (the SkyView table already holds the light scattered in on the way; this adds the ground's own, transmitted).
vec3 distantGround(vec3 wsDir) {
    float altitude = max(uAltitude, 1.0);
    float distance = altitude / max(-wsDir.y, 1e-4);
    float transmittance = texture(airTable, aerialPerspectiveUvw(wsDir, uSunDir, distance)).a;
    vec3 lit = uGroundAlbedo * (uSunColor * max(uSunDir.y, 0.0) + uAmbientColor);
    return lit * transmittance;
}

void main() {
    vec3 wsDir = panoramaDirection(gl_FragCoord.xy, uSize);
    vec3 sky = texture(skyView, skyViewUv(wsDir, uSunDir)).rgb;
    if (wsDir.y < 0.0) {
        sky += distantGround(wsDir);
    }
    vec3 level = normalize(vec3(wsDir.x, 0.0, wsDir.z) + vec3(1e-6, 0.0, 0.0));
    vec3 horizon = texture(skyView, skyViewUv(level, uSunDir)).rgb;
    Cloud cloud = cloudAlong(wsDir, uSunDir, uSunColor, uAmbientColor, horizon);
    skyExcess = vec4(sky * uScale, cloud.excess);
    cloudTransmittance = vec4(cloud.color * uScale, cloud.transmittance);
}
