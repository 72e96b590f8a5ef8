// Clouds on the sky dome (paper 2.3, figure 5 a-d). The density field is a 3D DFT over two axes of space and one
// of time (engine: org.openworld.engine.sky.CloudField); the uniforms are packed by CloudSettings.cloudParams and
// CloudSettings.cloudMotion. In two steps: cloudAlong() per direction reads the field and lights the cloud (the sky
// panorama stores what it returns), and cloudOpacity() draws the cloud's edge from the density (per pixel, from the
// panorama's interpolated density, so the edge is as smooth as the field's and not the panorama's texel grid):
//   float alpha = cloudOpacity(cloud.excess, cloud.transmittance);
//   sky = mix(sky, cloud.color, alpha)
#include "common/conventions.glsl"

uniform sampler3D cloudField; // density, mean 0 and standard deviation 1; s, t: one tile; r: one period. R16F, repeat
uniform vec4 cloudParams;     // x: density threshold (standard deviations); y: layer altitude above the eye (m);
                              // z: tile size on the layer (m); w: fog e-folding distance along the layer (m)
uniform vec4 cloudMotion;     // xy: wind offset (m, world x and z, wrapped by the tile); z: time phase in [0, 1);
                              // w: mapping, CloudSettings.Mapping's ordinal: 0 SPHERICAL, 1 SPHERICAL_FOG,
                              //    2 PERSPECTIVE, 3 PERSPECTIVE_FOG

// Density above the threshold (standard deviations) over which opacity ramps from 0 to 1: a soft rim about a
// fifth of a puff wide. Kept below 1 so that the threshold for cover 1 (the minimum less 1) makes every texel opaque.
const float CLOUD_EDGE = 0.6;
// Density above the threshold (standard deviations) at which a cloud counts as thick: its core is shaded and
// its rim no longer glows.
const float CLOUD_THICK = 2.0;
// Lowest elevation sine used to meet the layer: 0.06 degrees, keeps the distance (altitude / sine) finite.
const float CLOUD_MIN_SINE = 1e-3;
// Sky light on a cloud relative to ambientColor (light on an upward surface): a cloud base sees the whole lower
// hemisphere as well (bright ground, haze), so it gets more than an upward surface.
const float CLOUD_AMBIENT = 1.5;
// Share of direct sunlight that a cloud's base scatters towards the eye after passing through it.
const float CLOUD_SUN = 0.7;
// Fraction of CLOUD_SUN left in a thick core: the light crossed more cloud.
const float CLOUD_CORE_SHADE = 0.45;
// Silver lining: forward scattering in thin rims seen near the sun, strength and angular sharpness of the lobe
// pow(cos(angle to the sun), CLOUD_SILVER_EXPONENT) (8: half strength 24 degrees from the sun).
const float CLOUD_SILVER = 1.5;
const float CLOUD_SILVER_EXPONENT = 8.0;

// Distance along the layer from the point above the eye to where the ray meets it, metres: the fog's argument in
// both fog mappings. dir.y must be positive.
float cloudLayerDistance(vec3 wsDir) {
    float up = max(wsDir.y, CLOUD_MIN_SINE);
    return cloudParams.y * length(wsDir.xz) / up;
}

// Texture coordinates s, t of the field for a view direction, per mapping (figure 5).
vec2 cloudCoordinates(vec3 wsDir, int mapping) {
    vec2 wind = cloudMotion.xy / cloudParams.z; // tiles the wind has carried the field
    if (mapping <= 1) {
        // spherical: azimuth clockwise from north (-Z) over a full turn, elevation over a quarter turn; the
        // whole hemisphere holds one tile, squeezed flat at the horizon and pinched at the zenith (figure 5a)
        float azimuth = atan(wsDir.x, -wsDir.z);
        float elevation = asin(clamp(wsDir.y, 0.0, 1.0));
        return vec2(azimuth / (2.0 * PI), elevation / (0.5 * PI)) - wind;
    }
    // perspective: where the ray meets the plane at the layer's altitude, in tiles (figure 5c)
    float up = max(wsDir.y, CLOUD_MIN_SINE);
    vec2 wsOnLayer = wsDir.xz * (cloudParams.y / up);
    return (wsOnLayer - cloudMotion.xy) / cloudParams.z;
}

// The cloud layer along the unit view direction wsDir (world space, Y up), all but the edge: excess is the density
// above the threshold (standard deviations; negative where there is no cloud), color the cloud's linear colour and
// transmittance what the horizon fog leaves of it (1 without fog; 0 at and below the horizon, where there are no
// clouds). sunDir is the unit vector towards the sun, sunColor the direct sunlight, ambientColor the sky light on an
// upward surface and horizonColor the sky's colour at the horizon, into which the fog mappings fade the far clouds.
//
// Light: CLOUD_AMBIENT * ambient, plus the sun through the cloud, dimmer in thick cores, plus a silver lining in thin
// rims towards the sun. Fog (mappings 1 and 3): with T the transmittance exp(-distance along the layer / fog
// distance), the colour goes to the horizon colour and the opacity to 0 as T does, so the farthest clouds dissolve
// into whatever sky lies behind them.
struct Cloud {
    float excess;
    vec3 color;
    float transmittance;
};

Cloud cloudAlong(vec3 wsDir, vec3 sunDir, vec3 sunColor, vec3 ambientColor, vec3 horizonColor) {
    if (wsDir.y <= 0.0) {
        return Cloud(-1.0, vec3(0.0), 0.0);
    }
    int mapping = int(cloudMotion.w + 0.5);

    // 1. density at the mapped point and time: the frames' texel centres sit at (i + 0.5) / frames, and linear
    //    filtering between neighbouring frames (wrapping from the last to the first) animates the field smoothly
    float frames = float(textureSize(cloudField, 0).z);
    vec3 str = vec3(cloudCoordinates(wsDir, mapping), cloudMotion.z + 0.5 / frames);
    float excess = texture(cloudField, str).r - cloudParams.x;

    // 2. thickness from the density above the threshold
    float thick = smoothstep(0.0, CLOUD_THICK, excess);

    // 3. light
    float towardSun = max(dot(wsDir, sunDir), 0.0);
    float sun = CLOUD_SUN * mix(1.0, CLOUD_CORE_SHADE, thick)
            + CLOUD_SILVER * pow(towardSun, CLOUD_SILVER_EXPONENT) * (1.0 - thick);
    vec3 color = CLOUD_AMBIENT * ambientColor + sun * sunColor;

    // 4. horizon fog for the fog mappings
    float transmittance = 1.0;
    if (mapping == 1 || mapping == 3) {
        transmittance = exp(-cloudLayerDistance(wsDir) / cloudParams.w);
        color = mix(horizonColor, color, transmittance);
    }
    return Cloud(excess, color, transmittance);
}

// The cloud's opacity: a smoothstep from the threshold to CLOUD_EDGE above it, so the fraction of the field with any
// cloud is the cover the threshold was made for; times what the fog leaves.
float cloudOpacity(float excess, float transmittance) {
    return smoothstep(0.0, CLOUD_EDGE, excess) * transmittance;
}
