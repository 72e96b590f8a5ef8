// Height-dependent exponential fog, the same in every pass (engine: org.openworld.engine.environment.Fog).
// Optical depth along the ray eye -> p through density(h) = d0 * exp(-k h):
//   tau = d0 * |p - eye| * (exp(-k h0) - exp(-k h1)) / (k (h1 - h0))
#include "common/frame.glsl"

float fogOpticalDepth(vec3 wsEye, vec3 wsPos) {
    float d0 = frame.fogColorDensity.w;
    float k = frame.timeInfo.w;
    float dist = length(wsPos - wsEye);
    float h0 = wsEye.y;
    float h1 = wsPos.y;
    float dh = h1 - h0;
    // For a level ray the integral tends to exp(-k h0); the series form avoids dividing by ~0.
    float mean = abs(k * dh) < 1e-3 ? exp(-k * h0) * (1.0 - 0.5 * k * dh)
                                    : (exp(-k * h0) - exp(-k * h1)) / (k * dh);
    return d0 * dist * mean;
}

// The colour seen at wsPos after the fog between it and the eye.
vec3 applyFog(vec3 linearColor, vec3 wsPos) {
    float transmittance = exp(-fogOpticalDepth(cameraPos(), wsPos));
    return mix(frame.fogColorDensity.rgb, linearColor, transmittance);
}
