// A plant's light (engine: org.openworld.engine.vegetation): the terrain's own light, so plants and ground sit in one
// picture: the sun (wrapped Lambert, where the shadow maps see it: common/shadow.glsl), the sky's hemisphere light,
// the light through the leaves against the sun, then the air in front of it (common/fog.glsl) and the display
// transform (common/color.glsl). Shared by the meshes (tree.frag) and the impostors (impostor.frag), so a plant is
// lit alike in either representation. Needs common/frame, fog, color and shadow, and vegetation/surface.glsl.

// A crown is not a closed surface: light reaches a little round its edge. Lambert "wrapped" by this share of the
// hemisphere, cos' = (cos + WRAP) / (1 + WRAP), so the shaded side is not black under a low sun.
const float WRAP = 0.3;
// Leaves let through about as much light as they reflect, greener (a factor on the albedo): seen against the sun, a
// crown glows at its edges.
const vec3 TRANSMIT = vec3(0.8, 1.2, 0.5);

// The displayed colour of a plant's surface at wsPos.
vec3 plantLight(PlantSurface p, vec3 wsPos) {
    vec3 l = sunDir();
    float wrap = p.foliage ? WRAP : 0.0;
    float nl = max((dot(p.normal, l) + wrap) / (1.0 + wrap), 0.0);
    float visible = sunVisibility(wsPos, p.normal);
    vec3 color = p.albedo * (frame.sunColor.rgb * nl * visible + skyIrradiance(p.normal));
    if (p.foliage) {
        // through the leaves: strongest looking straight at the sun behind them (v from the eye, l towards the sun)
        vec3 v = normalize(wsPos - cameraPos());
        color += TRANSMIT * p.albedo * frame.sunColor.rgb * pow(max(dot(v, l), 0.0), 4.0) * visible;
    }
    return displayColor(applyFog(color, wsPos));
}
