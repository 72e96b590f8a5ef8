#version 330 core
// The clouds' shadow map (engine: org.openworld.engine.clouds.CloudVolumeSystem; read by common/shadow.glsl's
// cloudShadow): per texel of one tile of the field, the transmittance of the sun's ray from the cloud base up through
// the layer, over the base shape, the layer taken flat (over the 12 km of a tile it drops by 11 m); and the
// transmittance of the column straight up from there through the layer, the cloud overhead (where snow falls from:
// common/shadow.glsl's snowfallShare). Texel (s, t) is the field's point (s, t) at the base, in the tile copy nearest
// the eye.
#include "clouds/volume.glsl"

out vec4 transmittance; // r: along the sun's ray; g: straight up

uniform vec2 uSize;   // the map's size, texels
uniform vec3 uEye;    // the viewer's eye, world space (m): the tile copy nearest it is marched
uniform vec3 uSunDir; // unit vector towards the sun (drawn in the update, before any pass's frame block)

// Steps along the sun's ray through the layer.
const int STEPS = 12;
// Longest stretch of the sun's ray that is marched, metres: with the sun 8.5 degrees up a 1500 m layer is crossed
// over 10 km; lower suns shadow as if it were that.
const float MAX_PATH = 10000.0;

void main() {
    vec2 st = gl_FragCoord.xy / uSize;
    vec2 wsXz = st * uLayer.z + uMotion.xy;
    wsXz += uLayer.z * floor((uEye.xz - wsXz) / uLayer.z + 0.5);
    float baseAltitude = uLayer.x - EARTH_RADIUS;
    float thickness = uLayer.y - uLayer.x;
    vec3 p = vec3(wsXz.x, baseAltitude, wsXz.y);
    float path = min(thickness / max(uSunDir.y, 1e-3), MAX_PATH);
    float ds = path / float(STEPS);
    float dh = thickness / float(STEPS);
    float depth = 0.0;
    float column = 0.0;
    for (int i = 0; i < STEPS; i++) {
        vec3 q = p + uSunDir * ((float(i) + 0.5) * ds);
        depth += cloudShape(q, (q.y - baseAltitude) / thickness) * ds;
        float h = (float(i) + 0.5) / float(STEPS);
        column += cloudShape(p + vec3(0.0, h * thickness, 0.0), h) * dh;
    }
    transmittance = vec4(exp(-depth * EXTINCTION), exp(-column * EXTINCTION), 0.0, 1.0);
}
