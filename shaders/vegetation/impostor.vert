#version 330 core
// A plant's impostor, one instance per record (engine: org.openworld.engine.vegetation.ImpostorAtlas): a card through
// the centre of the plant's bounding sphere, square to the atlas frame whose view direction is nearest the one from
// the plant to the eye (in the sun's shadow pass: to the sun), so the card shows the plant from about where it is
// seen. The card is turned, widened and scaled with the plant's record as its mesh would be, and shrinks into the
// ground over the last fifth of the view distance as the meshes do.
#include "common/frame.glsl"
#include "vegetation/octahedron.glsl"

layout(location = 0) in vec2 corner;     // the card's corner, (+-1, +-1)
layout(location = 3) in vec4 footHeight; // xyz: the foot, x and z from uPlaced (m); w: height (m)
layout(location = 4) in vec2 turnTint;   // x: turn about the vertical (radians); y: tint 0..1

uniform vec2 uFade;     // x: distance from the viewer where plants start to shrink (m); y: where they are gone (m)
uniform vec2 uImpostor; // the cross-fade from the simplified shape to the impostor (m); equal ends: a hard switch
uniform vec2 uPlaced;   // where the feet's x and z are measured from: the layout's centre from the render origin (m)
uniform float uFrames;  // cells per side of the frames' grid
uniform vec2 uSphere;   // the bounding sphere: x its centre's height, y its radius (units of the plant's height)
uniform int uTowardsSun; // 1: the card faces the sun (the shadow pass), 0: the pass's camera

out vec2 frameUv;         // the point of the frame, 0..1 across the whole grid
out vec3 wsCard;          // the card's point
flat out float vShare;    // the impostor's share at this plant, 0..1 (the cross-fade)
flat out float vTint;
flat out vec3 vTurn;      // cos and sin of the plant's turn, its width
flat out vec3 vDepthAxis; // metres in the world per unit of the baked depth

const float WIDTH_LOW = 0.85;   // as tree.vert
const float WIDTH_SPREAD = 0.3;

// A point or a direction of the plant's own space (units of its height) into the world's, without the foot.
vec3 toWorld(vec3 p, mat2 turn, float width, float height) {
    return vec3(turn * p.xz * width, p.y).xzy * height;
}

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
    // the direction in the plant's own space: turned back and narrowed back
    vec2 across = transpose(turn) * toEye.xz / width;
    vec3 local = normalize(vec3(across.x, toEye.y, across.y));
    vec2 cell = clamp(floor(hemiOctEncode(local) * (uFrames - 1.0) + 0.5), 0.0, uFrames - 1.0);
    vec3 f = hemiOctDecode(cell / (uFrames - 1.0));
    vec3 right;
    vec3 up;
    frameBasis(f, right, up);
    vec3 p = (right * corner.x + up * corner.y) * uSphere.y + vec3(0.0, uSphere.x, 0.0);
    wsCard = foot + toWorld(p, turn, width, height);
    frameUv = (cell + corner * 0.5 + 0.5) / uFrames;
    vTint = turnTint.y;
    vTurn = vec3(c, s, width);
    vDepthAxis = toWorld(f, turn, width, height) * uSphere.y;
    // a plant short of the impostors' band: folded away before the rasteriser
    gl_Position = vShare <= 0.0 ? vec4(0.0, 0.0, 2.0, 1.0) : frame.viewProjection * vec4(wsCard, 1.0);
}
