// What the sky shows behind the sun's disc: the panorama's sky and clouds (sky/panorama.frag), the night sky's glow
// behind the clouds, and the moon's disc. Read by the sky pass (sky/sky.frag) and the stars (sky/stars.frag), which
// draw the same sky with a star on it. Engine: org.openworld.engine.sky.NightLight, MoonPosition.
#include "common/frame.glsl"
#include "sky/clouds.glsl"
#include "sky/panorama.glsl"

uniform sampler2D skyPanorama;     // the sky behind the clouds, linear rgb; alpha: the cloud's density excess
uniform sampler2D cloudPanorama;   // the clouds' colour, linear rgb; alpha: what the horizon fog leaves of them
uniform float uCloudLayer;        // 1: the layer's clouds over the sky; 0: none (the volumetric clouds are drawn over
                                   // the picture by engine.clouds)
uniform float uPanoramaScale;      // both colours are stored times this (SkyPanorama.draw)
uniform vec3 uNightSky;            // pi x the radiance of the moonless night sky (airglow), display units
uniform vec3 uMoonDir;             // unit vector towards the moon, world space
uniform vec3 uMoonDisc;            // pi x the radiance of the moon's lit part, display units

// The moon's angular radius, radians (0.2590 degrees: MoonPosition.ANGULAR_RADIUS_DEG).
const float MOON_RADIUS = 0.004520;
// The least radius the moon is drawn with, pixels: its true disc is 2.3 pixels wide at 480 x 270 and 60 degrees,
// and a thin crescent would fall between the pixels. Its light is kept: the radiance falls as the disc grows.
const float MOON_MIN_PIXELS = 2.0;

// The sky and its clouds in the unit direction wsDir, display units; cloudAlpha: how much the clouds hide behind them.
vec3 skyBehind(vec3 wsDir, out float cloudAlpha) {
    // textureLod: the panorama has no mip levels, and an explicit level spares the rasteriser the derivatives
    vec2 uv = panoramaUv(wsDir, vec2(textureSize(skyPanorama, 0)));
    vec4 sky = textureLod(skyPanorama, uv, 0.0);
    vec4 cloud = textureLod(cloudPanorama, uv, 0.0);
    cloudAlpha = cloudOpacity(sky.a, cloud.a) * uCloudLayer;
    return mix(sky.rgb / uPanoramaScale + uNightSky * step(0.0, wsDir.y), cloud.rgb / uPanoramaScale, cloudAlpha);
}

// The moon's disc in the unit direction wsDir: lit where its sphere faces the sun. The point of the sphere seen there
// has the normal o - sqrt(1 - |o|^2) uMoonDir, o the offset from the disc's centre in its radii (the chord stands for
// the angle, as the sun's disc does), so the terminator is the true one for the sun and moon of the moment.
vec3 moonDisc(vec3 wsDir) {
    float pixel = 2.0 * frame.viewport.w / frame.projection[1][1]; // radians per pixel at the picture's centre
    float radius = max(MOON_RADIUS, MOON_MIN_PIXELS * pixel);
    vec3 o = (wsDir - uMoonDir) / radius;
    float r2 = dot(o, o);
    vec3 n = o - sqrt(max(1.0 - r2, 0.0)) * uMoonDir;
    float kept = MOON_RADIUS * MOON_RADIUS / (radius * radius);
    return step(r2, 1.0) * step(0.0, dot(n, sunDir())) * step(0.0, wsDir.y) * kept * uMoonDisc;
}
