#version 330 core
// The sky (paper 2.3 and 3.1): the dome's radiance from the SkyView table, the ground far below the horizon seen
// through the air, the sun's disc with limb darkening, and the cloud layer. Drawn twice: on the camera's far plane
// (exposed and tone-mapped), and into the six faces of the environment map (linear, no sun disc: glossy surfaces
// add the sun's highlight themselves, and a disc smaller than a texel would only flicker).
// Engine: org.openworld.engine.sky.SkySystem.
#include "common/frame.glsl"
#include "common/color.glsl"
#include "sky/atmosphere.glsl"
#include "sky/clouds.glsl"

in vec2 ndc;
out vec4 fragColor;

uniform sampler2D skyView;         // radiance per dome direction, display units (SkyView)
uniform sampler3D aerialPerspective; // engine-bound: in-scattering and transmittance per direction and distance
uniform int uCubeFace;             // 0: the camera's view; 1: a face of the environment map, through uFaceAxes
uniform mat3 uFaceAxes;            // the face's s, t and outward axes (CubeMapTexture.faceAxes)
uniform float uGroundAlbedo;       // the ground seen below the horizon (AtmosphereSettings.groundAlbedo)
uniform int uSunDisc;              // 1: draw the sun's disc; 0 in the water's reflection, whose shader adds the sun's
                                   // glitter on the ripples itself (the disc's mirror image would count it twice)

// The sun's angular radius, radians (0.2666 degrees, seen from Earth).
const float SUN_RADIUS = 0.004654;
// Limb darkening, linear law I(mu) = I(1) (1 - u (1 - mu)), u for visible light (Cox, Allen's Astrophysical
// Quantities); the mean over the disc is 1 - u/3, which the disc's radiance is divided by so its total light is
// the sun's.
const float LIMB_U = 0.6;

// The disc's radiance in display units: the sunlight at the eye (irradiance, frame.sunColor) spread over the
// disc's solid angle pi R^2, times pi for display units: sunColor / R^2, shaped by the limb darkening.
vec3 sunDisc(vec3 wsDir) {
    float angle = acos(clamp(dot(wsDir, sunDir()), -1.0, 1.0));
    if (angle >= SUN_RADIUS) {
        return vec3(0.0);
    }
    float r = angle / SUN_RADIUS;
    float mu = sqrt(1.0 - r * r);
    float limb = (1.0 - LIMB_U * (1.0 - mu)) / (1.0 - LIMB_U / 3.0);
    return frame.sunColor.rgb * limb / (SUN_RADIUS * SUN_RADIUS);
}

// Below the horizon, beyond all terrain: level ground at sea level lit by the sun and the sky, seen through the air
// (the SkyView table already holds the light scattered in on the way; this adds the ground's own, transmitted).
vec3 distantGround(vec3 wsDir) {
    float altitude = max(cameraPos().y, 1.0);
    float distance = altitude / max(-wsDir.y, 1e-4);
    float transmittance = texture(aerialPerspective, aerialPerspectiveUvw(wsDir, sunDir(), distance)).a;
    vec3 lit = uGroundAlbedo * (frame.sunColor.rgb * max(sunDir().y, 0.0) + frame.ambientColor.rgb);
    return lit * transmittance;
}

void main() {
    vec3 wsDir;
    if (uCubeFace == 1) {
        wsDir = normalize(uFaceAxes * vec3(ndc, 1.0));
    } else {
        wsDir = normalize(viewRay(ndc));
    }
    vec3 sky = texture(skyView, skyViewUv(wsDir, sunDir())).rgb;
    if (wsDir.y < 0.0) {
        sky += distantGround(wsDir);
    } else if (uCubeFace == 0 && uSunDisc == 1) {
        sky += sunDisc(wsDir);
    }
    vec3 level = normalize(vec3(wsDir.x, 0.0, wsDir.z) + vec3(1e-6, 0.0, 0.0));
    vec3 horizon = texture(skyView, skyViewUv(level, sunDir())).rgb;
    vec4 clouds = cloudLayer(wsDir, sunDir(), frame.sunColor.rgb, frame.ambientColor.rgb, horizon);
    sky = sky * (1.0 - clouds.a) + clouds.rgb;
    fragColor = vec4(uCubeFace == 1 ? sky : displayColor(sky), 1.0);
}
