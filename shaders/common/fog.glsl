// Aerial perspective: what the air between the eye and a surface adds and takes away, the same in every pass
// (paper section 1's distance fog, made physical). The sky system fills the table for the eye's altitude and the
// sun of the moment (engine: org.openworld.engine.sky.AerialPerspective): per view direction and distance, the
// light scattered into the ray (display units) and the mean transmittance. Seen colour:
//   c' = c * transmittance + inScattered
// With atmosphere.fog=simple the table holds the paper's distance fog instead, transmittance exp(-d/D) and the
// horizon's colour times 1 - exp(-d/D): the same lookup and blend.
// Without a sky system the engine binds a neutral table (nothing added, everything transmitted).
#include "common/frame.glsl"
#include "sky/atmosphere.glsl"

uniform sampler3D aerialPerspective; // bound by the engine (gl.SharedTexture.AERIAL_PERSPECTIVE)

// The air over distance metres along the unit direction dir from the eye (the table's eye: its altitude): rgb the
// light it scatters towards the eye, a its transmittance.
vec4 airAlong(vec3 dir, float distance) {
    vec4 table = texture(aerialPerspective, aerialPerspectiveUvw(dir, sunDir(), distance));
    return mix(vec4(0.0, 0.0, 0.0, 1.0), table, aerialPerspectiveWeight(distance));
}

// The air between the eye and wsPos: rgb the light it scatters towards the eye, a its transmittance.
vec4 airTo(vec3 wsPos) {
    vec3 toPoint = wsPos - cameraPos();
    float distance = length(toPoint);
    return airAlong(toPoint / max(distance, 1e-3), distance);
}

// The colour seen at wsPos after the air between it and the eye.
vec3 applyFog(vec3 linearColor, vec3 wsPos) {
    vec4 air = airTo(wsPos);
    return linearColor * air.a + air.rgb;
}
