#version 330 core
// A tuft of grass blades, made here from nothing but its instance and vertex index (engine:
// org.openworld.engine.grass.GrassDraw). Instance i of a run is the world's cell (uCellX + i mod uWide,
// uCellZ + i div uWide); a hash of that cell and the seed jitters the tuft in its cell and gives each blade its place
// in the tuft, turn, height, tint and the threshold at which it thins away. The cell is the world's, never the
// viewer's, so a blade stands still as the viewer moves. The ground's height and the land's share of grass come
// from the field texture (GrassField), 1 m a sample.
//
// Thinning, not blending: a blade is drawn while its hash is under share × fade, so with distance (and where the land
// grows less) whole blades drop out one by one, the same ones every frame. Nothing is transparent, so the depth
// buffer and the temporal anti-aliasing's reprojection stay exact.
#include "common/frame.glsl"

uniform sampler2D uField; // per sample: the ground's height (m), the share of grass 0..1
uniform vec3 uFieldAt;    // xy: the field's first sample from the render origin (m); z: samples a side (1 m apart)
uniform int uCellX;       // the run's first cell on the world's grid (the hash's input)
uniform int uCellZ;
uniform int uWide;        // cells in a row of the run
uniform int uSeed;        // engine.seed
uniform vec3 uRunAt;      // xy: the run's first cell's corner from the render origin (m); z: the cell's side (m)
uniform vec3 uBlade;      // x: the tallest blade (m); y: distance where blades start thinning (m); z: where none is left
uniform vec2 uWind;       // the wind among the blades, m/s, x east and z south
uniform vec3 uSway;       // xy: the swing's phase per metre east and south (rad/m); z: its phase at the run's corner
uniform float uDensity;   // grass.density: blades per square metre where the share is 1

out vec3 wsPos;
out vec3 wsFace;          // the blade's face normal, before it is turned to the eye
out float vAlong;         // 0 at the root, 1 at the tip
flat out float vTint;
flat out float vOwn;      // how much of the blade's own look is left: 1 near, 0 where the blades start thinning
flat out vec3 vGround;    // the ground's normal at the root
flat out float vContact;  // the share of the light the meadow's blades take from a root (the contact shadow)

// One blade: the lower half a quad (two triangles), the tip one triangle; x across the blade (-1..1), y along it.
const vec2 SHAPE[9] = vec2[](vec2(-1.0, 0.0), vec2(1.0, 0.0), vec2(1.0, 0.5),
                             vec2(-1.0, 0.0), vec2(1.0, 0.5), vec2(-1.0, 0.5),
                             vec2(-1.0, 0.5), vec2(1.0, 0.5), vec2(0.0, 1.0));
// Metres: a blade's width at the root, the narrowest and the spread (each blade stands for a clump of real ones,
// a few millimetres each); it narrows to a point at the tip.
const float WIDTH_LOW = 0.04;
const float WIDTH_SPREAD = 0.04;
// The blades of a tuft stand within this share of the cell around its jittered centre.
const float TUFT_SPREAD = 0.6;
// A blade leans out along its face by 20 to 50 % of its height at the tip (its own weight), more in the wind: this
// share of its height per m/s, at most MAX_LEAN, swinging by a third about the mean at 1 Hz (a grass stem's sway).
const float REST_LEAN_LOW = 0.2;
const float REST_LEAN_SPREAD = 0.3;
const float LEAN_PER_MS = 0.08;
const float MAX_LEAN = 0.8;
const float SWING_HZ = 1.0;
// Metres the root reaches below the ground: the field's bilinear ground and the terrain's triangles differ by a few
// centimetres on bends.
const float SINK = 0.05;
// The contact shadow: a root among rho blades per m² sees the sky past them as exp(-rho / CONTACT_DENSITY) (a
// Poisson field of blades hides a share of the hemisphere growing with their number), at most CONTACT_MAX of it
// taken: the default meadow (24 blades/m²) darkens its roots by 0.55 × (1 - exp(-1)) = 35 %, as dark as the 0.6 of
// the light a tuft's root had before; the dry soil between the blades stays lit a little by the light they scatter.
const float CONTACT_DENSITY = 24.0;
const float CONTACT_MAX = 0.55;

// A 32-bit integer hash (Chris Wellons' "lowbias32"): every input bit moves about half the output bits.
uint hash(uint x) {
    x ^= x >> 16; x *= 0x7feb352du;
    x ^= x >> 15; x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
float unit(uint h) { return float(h >> 8) * (1.0 / 16777216.0); }

void main() {
    ivec2 local = ivec2(gl_InstanceID % uWide, gl_InstanceID / uWide);
    uint tuft = hash(uint(uCellX + local.x) ^ hash(uint(uCellZ + local.y) ^ hash(uint(uSeed))));
    int index = gl_VertexID / 9;
    vec2 shape = SHAPE[gl_VertexID % 9];
    uint b = hash(tuft + uint(index) * 0x9e3779b9u);
    // 1. the blade's root: the tuft jittered in its cell, the blade spread around it
    vec2 centre = vec2(unit(tuft), unit(hash(tuft ^ 0x1u)));
    vec2 spread = (vec2(unit(b), unit(hash(b ^ 0x2u))) - 0.5) * TUFT_SPREAD;
    vec2 inRun = (vec2(local) + clamp(centre + spread, 0.0, 1.0)) * uRunAt.z;
    vec2 root = uRunAt.xy + inRun;
    // 2. the ground and the land's share there (the samples' centres are at the texels' centres)
    vec2 uv = ((root - uFieldAt.xy) + 0.5) / uFieldAt.z;
    vec2 ground = texture(uField, uv).xy;
    bool inside = all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0)));
    float d = distance(vec3(root.x, ground.x, root.y), viewerPos());
    float fade = 1.0 - smoothstep(uBlade.y, uBlade.z, d);
    bool drawn = inside && unit(hash(b ^ 0x3u)) < ground.y * fade;
    if (!drawn) {
        // a blade the land or the distance leaves out: folded away before the rasteriser, and the rest of its
        // work skipped (on a software rasteriser the vertices are the grass's main cost)
        wsPos = vec3(0.0);
        wsFace = vec3(0.0, 1.0, 0.0);
        vAlong = 0.0;
        vTint = 0.0;
        vOwn = 0.0;
        vGround = vec3(0.0, 1.0, 0.0);
        vContact = 0.0;
        gl_Position = vec4(0.0, 0.0, 2.0, 1.0);
        return;
    }
    // 3. the blade: turned, sized by the land's share, shrinking a little as it thins away, leaning and swinging
    float turn = 6.2831853 * unit(hash(b ^ 0x4u));
    vec2 face = vec2(cos(turn), sin(turn));
    vec2 across = vec2(-face.y, face.x);
    float height = uBlade.x * (0.5 + 0.5 * ground.y) * (0.7 + 0.6 * unit(hash(b ^ 0x5u))) * mix(0.6, 1.0, fade);
    float speed = length(uWind);
    float phase = dot(inRun, uSway.xy) + uSway.z;
    float swing = 1.0 + 0.33 * sin(6.2831853 * SWING_HZ * frame.timeInfo.x + phase);
    vec2 windLean = speed > 0.0 ? uWind / speed * min(MAX_LEAN, LEAN_PER_MS * speed) * swing : vec2(0.0);
    vec2 lean = face * (REST_LEAN_LOW + REST_LEAN_SPREAD * unit(hash(b ^ 0x6u))) + windLean;
    float t = shape.y;
    float width = (WIDTH_LOW + WIDTH_SPREAD * unit(hash(b ^ 0x7u))) * (1.0 - t);
    // the blade's spine bends as the square of the way up: the point, and its tangent (d/dt)
    vec3 spine = vec3(lean.x * t * t, t, lean.y * t * t) * height;
    vec3 tangent = vec3(2.0 * lean.x * t, 1.0, 2.0 * lean.y * t);
    vec3 side = vec3(across.x, 0.0, across.y);
    wsPos = vec3(root.x, ground.x - SINK * (1.0 - t), root.y) + spine + side * (0.5 * width * shape.x);
    wsFace = normalize(cross(side, tangent));
    vAlong = t;
    vTint = unit(hash(b ^ 0x8u));
    // the blade takes on the ground's look over a ring as wide as the thinning's, just before it: where the blades
    // thin away they already look like the ground they leave
    vOwn = 1.0 - smoothstep(2.0 * uBlade.y - uBlade.z, uBlade.y, d);
    // the ground's normal from the next samples east and south (1 m apart)
    float east = texture(uField, uv + vec2(1.0 / uFieldAt.z, 0.0)).x;
    float south = texture(uField, uv + vec2(0.0, 1.0 / uFieldAt.z)).x;
    vGround = normalize(vec3(ground.x - east, 1.0, ground.x - south));
    // the blades around the root: the land's and the distance's share of the density
    vContact = CONTACT_MAX * (1.0 - exp(-uDensity * ground.y * fade / CONTACT_DENSITY));
    gl_Position = frame.viewProjection * vec4(wsPos, 1.0);
}
