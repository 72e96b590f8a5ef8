#version 330 core
// The sky (paper 2.3 and 3.1) read from the panorama (sky/panorama.frag) with one lookup per pixel. Drawn twice: on
// the camera's far plane after the opaque systems, depth-tested, so only the pixels no surface covers are shaded
// (exposed and tone-mapped, with the sun's and the moon's discs); and into the six faces of the environment map
// (linear, no discs: glossy surfaces add the sun's highlight themselves, and a disc smaller than a texel would only
// flicker). Engine: org.openworld.engine.sky.SkySystem.
#include "common/frame.glsl"
#include "common/color.glsl"
#include "sky/night.glsl"

in vec3 wsRay;
out vec4 fragColor;

uniform int uCubeFace;             // 0: the camera's view; 1: a face of the environment map (sky.vert)
uniform float uSunDisc;            // 1: draw the sun's disc; 0 in the water's reflection, whose shader adds the sun's
                                   // glitter on the ripples itself (the disc's mirror image would count it twice)
uniform sampler2D cloudVolume;     // the volumetric clouds' panorama (clouds/panorama.frag): rgb their light after
                                   // the air in front, display units; a: the transmittance
uniform float uCloudVolume;        // 1: the environment map takes the volumetric clouds over the sky; 0: none

// The sun's angular radius, radians (0.2666 degrees, seen from Earth).
const float SUN_RADIUS = 0.004654;
// Limb darkening, linear law I(mu) = I(1) (1 - u (1 - mu)), u for visible light (Cox, Allen's Astrophysical
// Quantities); the mean over the disc is 1 - u/3, which the disc's radiance is divided by so its total light is
// the sun's.
const float LIMB_U = 0.6;

// The disc's radiance in display units: the sunlight at the eye (irradiance, frame.sunColor) spread over the
// disc's solid angle pi R^2, times pi for display units: sunColor / R^2, shaped by the limb darkening. Computed per
// pixel, not read from the panorama, so its edge stays as sharp as the screen. The angle to the sun is the chord
// |wsDir - sunDir| (2 sin(angle / 2), off by a millionth within the disc), which needs no acos.
vec3 sunDisc(vec3 wsDir) {
    float angle = length(wsDir - sunDir());
    float r = min(angle / SUN_RADIUS, 1.0);
    float mu = sqrt(1.0 - r * r);
    float limb = (1.0 - LIMB_U * (1.0 - mu)) / (1.0 - LIMB_U / 3.0);
    return step(angle, SUN_RADIUS) * frame.sunColor.rgb * limb / (SUN_RADIUS * SUN_RADIUS);
}

void main() {
    vec3 wsDir = normalize(wsRay);
    float alpha;
    vec3 radiance = skyBehind(wsDir, alpha);
    if (uCubeFace == 1) {
        if (uCloudVolume > 0.5) {
            vec4 cloud = textureLod(cloudVolume, panoramaUv(wsDir, vec2(textureSize(cloudVolume, 0))), 0.0);
            radiance = radiance * cloud.a + cloud.rgb;
        }
        fragColor = vec4(radiance, 1.0);
        return;
    }
    // the discs behind the clouds, and none below the horizon (the distant ground)
    radiance += (1.0 - alpha) * (uSunDisc * step(0.0, wsDir.y) * sunDisc(wsDir) + moonDisc(wsDir));
    fragColor = vec4(displayColor(radiance), 1.0);
}
