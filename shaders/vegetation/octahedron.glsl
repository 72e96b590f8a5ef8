// The impostors' views (engine: org.openworld.engine.vegetation.ImpostorAtlas): a hemi-octahedral grid of
// uFrames x uFrames directions over the upper half of the sphere, the grid's cell (i, j) the direction
// hemiOctDecode((i, j) / (uFrames - 1)). The upper hemisphere is folded onto the octahedron |x| + |y| + |z| = 1 and
// that square, turned 45 degrees, onto [0, 1]^2: the views are spread evenly in angle, and a view's neighbours in
// the grid are its neighbours on the sphere. Shared by the bake (bake.vert) and the draw (impostor.vert), so each
// frame is read from where it was drawn from.

// The direction, y up and x, z across, for a point of [0, 1]^2.
vec3 hemiOctDecode(vec2 uv) {
    vec2 g = uv * 2.0 - 1.0;
    vec2 p = vec2(g.x + g.y, g.x - g.y) * 0.5;
    return normalize(vec3(p.x, 1.0 - abs(p.x) - abs(p.y), p.y));
}

// The point of [0, 1]^2 for a direction (below the horizon: its horizontal part).
vec2 hemiOctEncode(vec3 d) {
    d.y = max(d.y, 0.0);
    vec2 p = d.xz / (abs(d.x) + d.y + abs(d.z));
    return vec2(p.x + p.y, p.x - p.y) * 0.5 + 0.5;
}

// A view's screen axes, f pointing from the plant to the viewer: right and up, up in the vertical plane through f
// (for the view straight down, north, -z, is up).
void frameBasis(vec3 f, out vec3 right, out vec3 up) {
    vec3 ref = f.y > 0.999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
    right = normalize(cross(ref, f));
    up = cross(f, right);
}
