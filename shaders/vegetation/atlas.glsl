// The impostors' atlas (engine: org.openworld.engine.vegetation.ImpostorAtlas): one row per kind of plant, each row
// two squares of uFrames x uFrames frames: the albedo and coverage (half 0), the normal and depth (half 1).
uniform sampler2D uAtlas;
uniform int uKind; // 0 conifer, 1 broadleaf, 2 bush

const float KINDS = 3.0;
// The coverage codes: nothing 0, bark 0.5, foliage 1 (bake.frag); thresholds halfway between.
const float COVERED = 0.25;
const float FOLIAGE = 0.75;

vec2 atlasUv(vec2 frameUv, int side) {
    return vec2((frameUv.x + float(side)) * 0.5, (frameUv.y + float(uKind)) / KINDS);
}
