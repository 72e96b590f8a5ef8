#version 330 core
// A plant's impostor, one instance per record (engine: org.openworld.engine.vegetation.ImpostorAtlas): a card through
// the centre of the plant's bounding sphere, square to the direction from the plant to the eye (in the sun's shadow
// pass: to the sun), showing a blend of the three atlas frames whose directions are nearest that one
// (vegetation/impostor-sample.glsl), so the plant turns smoothly as the eye goes round it. The card is turned,
// widened and scaled with the plant's record as its mesh would be, sways in the wind as the mesh does
// (vegetation/sway.glsl), and shrinks into the ground over the last fifth of the view distance as the meshes do.
#include "common/frame.glsl"
#include "vegetation/octahedron.glsl"
#include "vegetation/sway.glsl"

layout(location = 0) in vec2 corner;     // the card's corner, (+-1, +-1)
layout(location = 3) in vec4 footHeight; // xyz: the foot, x and z from uPlaced (m); w: height (m)
layout(location = 4) in vec2 turnTint;   // x: turn about the vertical (radians); y: tint 0..1

uniform vec2 uFade;     // x: distance from the viewer where plants start to shrink (m); y: where they are gone (m)
uniform vec2 uImpostor; // the cross-fade from the simplified shape to the impostor (m); equal ends: a hard switch
uniform vec2 uPlaced;   // where the feet's x and z are measured from: the layout's centre from the render origin (m)
uniform float uFrames;  // cells per side of the frames' grid
uniform vec2 uSphere;   // the bounding sphere: x its centre's height, y its radius (units of the plant's height)
uniform int uTowardsSun; // 1: the card faces the sun (the shadow pass), 0: the pass's camera

out vec3 vCard;            // the card's point in the plant's own space, radii of its sphere from the centre, swayed
flat out vec3 vView;       // the direction towards the eye in the plant's own space
flat out vec2 vCells[3];   // the three nearest frames' cells in the grid
flat out vec3 vWeight;     // their barycentric weights on the grid, summing to 1
flat out vec2 vLean;       // the sway at the top of the stem in the plant's own space, plant heights
flat out vec4 vFootHeight; // the foot from the render origin (m), the height as drawn (m)
flat out float vShare;     // the impostor's share at this plant, 0..1 (the cross-fade)
flat out float vTint;
flat out vec3 vTurn;       // cos and sin of the plant's turn, its width

const float WIDTH_LOW = 0.85;   // as tree.vert
const float WIDTH_SPREAD = 0.3;

void main() {
    vec3 foot = footHeight.xyz + vec3(uPlaced.x, 0.0, uPlaced.y);
    float d = distance(foot, viewerPos());
    float height = footHeight.w * (1.0 - smoothstep(uFade.x, uFade.y, d));
    vShare = clamp((d - uImpostor.x) / max(uImpostor.y - uImpostor.x, 1e-3), 0.0, 1.0);
    float c = cos(turnTint.x);
    float s = sin(turnTint.x);
    mat2 turn = mat2(c, s, -s, c);
    float width = WIDTH_LOW + WIDTH_SPREAD * turnTint.y;
    vec3 centre = foot + vec3(0.0, uSphere.x * height, 0.0);
    vec3 toEye = uTowardsSun == 1 ? sunDir() : cameraPos() - centre;
    // 1. the direction in the plant's own space: turned back and narrowed back
    vec2 across = transpose(turn) * toEye.xz / width;
    vec3 v = normalize(vec3(across.x, toEye.y, across.y));
    // 2. the three nearest views: the grid's cell holding the direction, cut along its diagonal into two
    //    triangles; the corners of the one it falls in, weighted barycentrically (linear across the triangle, so the
    //    weights, and the picture, change continuously as the eye moves, and one view's weight is 1 on its own)
    vec2 g = hemiOctEncode(v) * (uFrames - 1.0);
    vec2 base = clamp(floor(g), 0.0, uFrames - 2.0);
    vec2 t = clamp(g - base, 0.0, 1.0);
    if (t.x + t.y < 1.0) {
        vCells = vec2[3](base, base + vec2(1.0, 0.0), base + vec2(0.0, 1.0));
        vWeight = vec3(1.0 - t.x - t.y, t.x, t.y);
    } else {
        vCells = vec2[3](base + vec2(1.0), base + vec2(0.0, 1.0), base + vec2(1.0, 0.0));
        vWeight = vec3(t.x + t.y - 1.0, 1.0 - t.x, 1.0 - t.y);
    }
    vView = v;
    // 3. the card, square to the eye, grown by the sway's reach so the swayed crown stays on it; its corners swayed
    //    as the mesh's points at their heights, the fragments take the sway back out per pixel
    vec3 right;
    vec3 up;
    frameBasis(v, right, up);
    vLean = transpose(turn) * plantLean(footHeight.xz) / width;
    vec3 q = (right * corner.x + up * corner.y) * (1.0 + length(vLean) / uSphere.y);
    float y = max(q.y * uSphere.y + uSphere.x, 0.0);
    q.xz += vLean * (y * y / uSphere.y);
    vCard = q;
    vec3 p = q * uSphere.y + vec3(0.0, uSphere.x, 0.0);
    vec3 wsCard = foot + vec3(turn * p.xz * width, p.y).xzy * height;
    vFootHeight = vec4(foot, height);
    vTint = turnTint.y;
    vTurn = vec3(c, s, width);
    // a plant short of the impostors' band: folded away before the rasteriser
    gl_Position = vShare <= 0.0 ? vec4(0.0, 0.0, 2.0, 1.0) : frame.viewProjection * vec4(wsCard, 1.0);
}
