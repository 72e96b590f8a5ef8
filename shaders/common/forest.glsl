// The forests beyond the plants' reach (engine: org.openworld.engine.environment.ForestCover, written by the
// vegetation): how much of the ground the canopy hides, and its colour, for the far ground's material to mix in
// where the plants themselves have shrunk away, so forests stay visible to the horizon. Needs common/frame.glsl.
layout(std140) uniform ForestCoverBlock {
    vec4 forestPlace;     // x: 1 / the map's period (1/m); y: the period (m); z: the reach from the viewer the map
                          // holds (m); w: 1 with forests, 0 without (the stand-in)
    vec4 forestFade;      // xy: metres from the viewer where the cover starts to show and where it is full
    vec4 forestColour[3]; // rgb: each kind's canopy albedo, linear, in the order of the map's channels; w: its
                          // outline from the side over its outline from above
} forestCoverBlock;

uniform sampler2D forestCoverMap; // rgb each kind's share of the canopy, a the share of the ground it hides

// What the drawn forest looks like from afar: a geometric-optical canopy (after Li and Strahler 1992) of crowns
// standing at random, each hiding `top` of the ground seen from above and `side` seen from the side (forestColour's w
// is side / top), lit as the plants' own shader lights them (vegetation/light.glsl). tau, the crowns' area from
// above per square metre of ground, comes back from the map's share hidden, a = 1 - exp(-tau); seen at zenith angle
// theta (cosine mu) a crown hides top cos + side sin, so it covers tau F(mu), F = 1 + side / top tan theta. So:
//   crowns seen      c = 1 - exp(-tau_v),  tau_v = tau F(mu_v)
//   gaps seen, lit   exp(-tau_v - t),  t = tau F(mu_s) (1 - hot): the sun's way through the crowns to the ground
//   a crown's sun    the sphere's disc mean of the wrapped Lambert (n.l + WRAP) / (1 + WRAP) at the phase angle A
//                    between eye and sun, ((sin A + (pi - A) cos A) 2 / (3 pi) + WRAP (1 + cos A) / 2) / (1 + WRAP)
//                    (the Lambert sphere's phase law plus the wrap over the lit half of the disc), times the chance
//                    the sun reaches the crown points the eye sees: those lie at an optical depth x along the view,
//                    weighted exp(-x), so x / tau_v down the canopy, where the sun's depth is r x, r = t / tau_v:
//                    (1 - exp(-(1 + r) tau_v)) / ((1 + r)(1 - exp(-tau_v))). At a grazing angle the eye sees only
//                    the canopy's lit top (r small); from above it sees deeper, into the crowns' shadows
//   a crown's sky    the sky's light for the visible face's mean normal, 2/3 v (the plants take it unoccluded)
// hot = exp(-A / HOT_SPOT): looking down the sun's rays the eye sees the lit sides and hides the shadows behind the
// crowns that cast them. The gaps stay ground: their albedo is scaled by their light over the bare ground's (the
// shadowed share keeps the sky alone), and the terrain lights them; the crowns are lit here, as the plants are,
// and mixed over the lit ground by c. Returns the ground's albedo with the gaps' shade in it; `crownLight` the
// crowns' colour (linear, before the air), `shown` their share of the picture (c times the fade).
const float FOREST_PI = 3.14159265;
// The plants' wrapped Lambert's share of the hemisphere (vegetation/light.glsl, WRAP).
const float FOREST_WRAP = 0.3;
// Radians: the hot spot's half width, a crown's radius over its height (TreeKind.reach, about 0.45): the angle within
// which a crown hides its own shadow from the eye.
const float HOT_SPOT = 0.45;
// The lowest zenith cosine used, 0.05 (87 degrees): below it the ground is hidden by the crowns anyway.
const float FOREST_MIN_MU = 0.05;

// F(mu) above: the ground a crown covers along a direction of zenith cosine mu, in units of its area from above.
float forestFootprint(float mu, float sideOverTop) {
    return 1.0 + sideOverTop * sqrt(1.0 - mu * mu) / mu;
}

vec3 forestGround(vec3 groundAlbedo, vec3 wsPos, vec3 wsNormal, out vec3 crownLight, out float shown) {
    shown = 0.0;
    crownLight = vec3(0.0);
    vec4 place = forestCoverBlock.forestPlace;
    if (place.w == 0.0) {
        return groundAlbedo;
    }
    // the render origin's share of the position modulo the period: whole steps, exact (the period and the step are
    // powers of two, so one divides the other)
    float steps = place.y / frame.origin.w;
    vec2 shift = steps >= 1.0 ? mod(frame.origin.xz, steps) * frame.origin.w : vec2(0.0);
    vec4 cover = texture(forestCoverMap, (wsPos.xz + shift) * place.x);
    // measured as the plants measure their fade: from the viewer's eye, in three dimensions
    float d = distance(wsPos, viewerPos());
    float fade = smoothstep(forestCoverBlock.forestFade.x, forestCoverBlock.forestFade.y, d)
            * (1.0 - smoothstep(0.8 * place.z, place.z, d));
    if (cover.a == 0.0 || fade == 0.0) {
        return groundAlbedo;
    }
    float kinds = max(cover.r + cover.g + cover.b, 1e-3);
    vec3 crownAlbedo = (cover.r * forestCoverBlock.forestColour[0].rgb + cover.g * forestCoverBlock.forestColour[1].rgb
            + cover.b * forestCoverBlock.forestColour[2].rgb) / kinds;
    float sideOverTop = (cover.r * forestCoverBlock.forestColour[0].w + cover.g * forestCoverBlock.forestColour[1].w
            + cover.b * forestCoverBlock.forestColour[2].w) / kinds;
    float tau = -log(1.0 - min(cover.a, 0.995));
    vec3 v = normalize(cameraPos() - wsPos);
    vec3 l = sunDir();
    float phase = acos(clamp(dot(v, l), -1.0, 1.0));
    float hot = exp(-phase / HOT_SPOT);
    float tauV = tau * forestFootprint(max(v.y, FOREST_MIN_MU), sideOverTop);
    float tauS = tau * forestFootprint(max(l.y, FOREST_MIN_MU), sideOverTop) * (1.0 - hot);
    float crowns = 1.0 - exp(-tauV);
    float r = tauS / tauV;
    float sunThrough = (1.0 - exp(-(1.0 + r) * tauV)) / ((1.0 + r) * max(crowns, 1e-4));
    // the crowns' faces the eye sees: at a grazing angle the crowns in front hide the lower halves, and the eye sees
    // their tops, as if from above; the visible face's mean normal is turned up by the share c of the view they fill
    vec3 seen = normalize(v + crowns * (1.0 - v.y) * vec3(0.0, 1.0, 0.0));
    float lit = acos(clamp(dot(seen, l), -1.0, 1.0));
    float crownSun = ((sin(lit) + (FOREST_PI - lit) * cos(lit)) * 2.0 / (3.0 * FOREST_PI)
            + FOREST_WRAP * 0.5 * (1.0 + cos(lit))) / (1.0 + FOREST_WRAP) * sunThrough;
    vec3 sun = frame.sunColor.rgb * step(0.0, l.y) * sunVisibility(wsPos, wsNormal);
    crownLight = crownAlbedo * (sun * crownSun + skyIrradiance(2.0 / 3.0 * seen));
    // the gaps: the sun's share of the ground's light left where the crowns let it through
    float groundSun = max(dot(wsNormal, l), 0.0);
    vec3 bare = frame.sunColor.rgb * groundSun + skyIrradiance(wsNormal);
    vec3 gap = (frame.sunColor.rgb * groundSun * exp(-tauS) + skyIrradiance(wsNormal)) / max(bare, vec3(1e-4));
    shown = crowns * fade;
    return mix(groundAlbedo, groundAlbedo * gap, fade);
}
