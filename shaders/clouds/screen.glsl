// The scene's depth for the clouds' screen passes (engine: org.openworld.engine.clouds.CloudVolumeSystem): the depth
// buffer copied after the opaque systems, read as a distance along the view ray.
#include "common/frame.glsl"

uniform sampler2D sceneDepth; // the scene's depth buffer, full resolution, nearest

// Distance standing for "no surface" (the sky), metres: beyond every cloud, within a full float's range.
const float NO_SURFACE = 1e7;

// Distance along the ray wsRay (viewRay's, unnormalised: 1 deep in view space) to the surface the depth buffer holds
// at uv, or NO_SURFACE where it holds the sky: the depth unprojected by the projection's z row.
float sceneDistance(vec2 uv, vec3 wsRay) {
    float depth = texture(sceneDepth, uv).r;
    if (depth >= 1.0) {
        return NO_SURFACE;
    }
    float vsDepth = frame.projection[3][2] / (2.0 * depth - 1.0 + frame.projection[2][2]);
    return vsDepth * length(wsRay);
}
