// The forests beyond the plants' reach (engine: org.openworld.engine.environment.ForestCover, written by the
// vegetation): how much of the ground the canopy hides, and its colour, for the far ground's material to mix in
// where the plants themselves have shrunk away, so forests stay visible to the horizon. Needs common/frame.glsl.
layout(std140) uniform ForestCoverBlock {
    vec4 forestPlace;     // x: 1 / the map's period (1/m); y: the period (m); z: the reach from the viewer the map
                          // holds (m); w: 1 with forests, 0 without (the stand-in)
    vec4 forestFade;      // xy: metres from the viewer where the cover starts to show and where it is full
    vec4 forestColour[3]; // rgb: each kind's canopy albedo, linear, in the order of the map's channels
} forestCoverBlock;

uniform sampler2D forestCoverMap; // rgb each kind's share of the canopy, a the share of the ground it hides

// The canopy's albedo (rgb) and the share of the ground it hides at wsPos, as seen from the viewer (a).
vec4 forestCover(vec3 wsPos) {
    vec4 place = forestCoverBlock.forestPlace;
    if (place.w == 0.0) {
        return vec4(0.0);
    }
    // the render origin's share of the position modulo the period: whole steps, exact (the period and the step are
    // powers of two, so one divides the other)
    float steps = place.y / frame.origin.w;
    vec2 shift = steps >= 1.0 ? mod(frame.origin.xz, steps) * frame.origin.w : vec2(0.0);
    vec4 cover = texture(forestCoverMap, (wsPos.xz + shift) * place.x);
    // measured as the plants measure their fade: from the viewer's eye, in three dimensions
    float d = distance(wsPos, viewerPos());
    float share = cover.a * smoothstep(forestCoverBlock.forestFade.x, forestCoverBlock.forestFade.y, d)
            * (1.0 - smoothstep(0.8 * place.z, place.z, d));
    vec3 albedo = (cover.r * forestCoverBlock.forestColour[0].rgb + cover.g * forestCoverBlock.forestColour[1].rgb
            + cover.b * forestCoverBlock.forestColour[2].rgb) / max(cover.r + cover.g + cover.b, 1e-3);
    return vec4(albedo, share);
}
