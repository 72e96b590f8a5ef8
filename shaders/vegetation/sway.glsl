// A plant's sway in the wind (engine: org.openworld.engine.vegetation.TreeDraw): shared by the meshes (tree.vert) and
// the impostors (impostor.vert, impostor-sample.glsl), so a plant sways alike in either representation and the switch
// to the cards does not freeze it. Needs common/frame.glsl.
//
// A crown bends downwind by this share of its height per m/s, as the square of the height up the stem (a
// cantilever's bend), capped at MAX_LEAN; it swings by a third of that about the mean at 0.3 Hz (a grown tree's first
// mode) with a phase from its place, so neighbours do not swing in step. A point of the plant y heights up its stem
// moves plantLean(...) * y^2 plant heights across.
uniform vec2 uWind; // the wind among the plants, m/s, x east and z south
uniform vec3 uSway; // xy: the swing's phase per metre east and south (rad/m); z: its phase at uPlaced (rad)

const float LEAN_PER_MS = 0.004;
const float MAX_LEAN = 0.06;
const float SWING_HZ = 0.3;

// The lean at the top of the stem, world x and z, plant heights, for the foot at `foot` (metres from uPlaced).
vec2 plantLean(vec2 foot) {
    float speed = length(uWind);
    float phase = dot(foot, uSway.xy) + uSway.z;
    float swing = 1.0 + 0.33 * sin(6.2831853 * SWING_HZ * frame.timeInfo.x + phase);
    return speed > 0.0 ? uWind / speed * min(MAX_LEAN, LEAN_PER_MS * speed) * swing : vec2(0.0);
}
