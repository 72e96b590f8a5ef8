// An impostor's texel (engine: org.openworld.engine.vegetation.ImpostorAtlas): the blend of the three atlas frames
// nearest the eye's direction that impostor.vert chose, for the lit program (impostor.frag) and the shadow maps'
// (impostor-depth.frag). Needs vegetation/octahedron.glsl and vegetation/atlas.glsl.
//
// `threshold` is the pixel's dither threshold in (0, 1), uncorrelated with the cross-fade's. Per pixel, with q the
// card's point (the plant's own space, radii of its sphere from the centre) and v the direction to the eye:
//   1. the sway taken back out: q.xz -= lean * y^2, y the point's height up the stem (the sway is horizontal);
//   2. per frame k, of direction f_k: the eye's ray through q slid to the frame's plane through the centre,
//      s_k = q - v (q . f_k) / (v . f_k) (the parallax between the card and the frame), read at s_k's place in the
//      frame, and the surface's point put back there: s_k + f_k depth_k;
//   3. the frames that hold the plant there weighted barycentrically: covered where their weights pass an ordered
//      dither's threshold (so where the frames' outlines disagree, the pixels turn one by one as the weights move,
//      not all at once when one frame's weight passes a half), foliage or bark the same way, the albedo, the normal
//      (the plant's own space in every frame) and the point their weighted means, the point swayed again.
// Six texture reads a pixel against the nearest frame's two.
uniform float uFrames;
uniform vec2 uSphere;

in vec3 vCard;
flat in vec3 vView;
flat in vec2 vCells[3];
flat in vec3 vWeight;
flat in vec2 vLean;
flat in vec4 vFootHeight;
flat in vec3 vTurn;

struct ImpostorTexel {
    bool covered;
    bool foliage;
    vec3 albedo; // linear
    vec3 normal; // the plant's own space
    vec3 wsPos;  // the surface's point in the world, from the render origin
};

ImpostorTexel impostorTexel(float threshold) {
    // 1. the still plant's point under this pixel
    float y = max(vCard.y * uSphere.y + uSphere.x, 0.0);
    vec3 q = vCard - vec3(vLean.x, 0.0, vLean.y) * (y * y / uSphere.y);
    // 2. each frame, read where the eye's ray meets its plane
    float cover = 0.0;
    float foliage = 0.0;
    vec3 albedo = vec3(0.0);
    vec3 normal = vec3(0.0);
    vec3 point = vec3(0.0);
    for (int k = 0; k < 3; k++) {
        vec3 f = hemiOctDecode(vCells[k] / (uFrames - 1.0));
        vec3 right;
        vec3 up;
        frameBasis(f, right, up);
        // the frames lie within 16 degrees of the eye's direction (more only for a sun below the horizon)
        vec3 s = q - vView * (dot(q, f) / max(dot(vView, f), 0.25));
        vec2 uv = vec2(dot(s, right), dot(s, up));
        if (vWeight[k] <= 0.0 || max(abs(uv.x), abs(uv.y)) >= 1.0) {
            continue;
        }
        vec2 frameUv = (vCells[k] + uv * 0.5 + 0.5) / uFrames;
        vec4 a = texture(uAtlas, atlasUv(frameUv, 0));
        if (a.a < COVERED) {
            continue;
        }
        vec4 nd = texture(uAtlas, atlasUv(frameUv, 1));
        float w = vWeight[k];
        cover += w;
        foliage += a.a > FOLIAGE ? w : 0.0;
        albedo += w * a.rgb * a.rgb;
        normal += w * (nd.xyz * 2.0 - 1.0);
        point += w * (s + f * (nd.a * 2.0 - 1.0));
    }
    // 3. the weighted means, the point swayed again and into the world
    ImpostorTexel t;
    t.covered = cover > threshold;
    t.foliage = foliage > threshold * cover;
    float inv = 1.0 / max(cover, 1e-4);
    t.albedo = albedo * inv;
    t.normal = normalize(normal + vec3(0.0, 1e-6, 0.0));
    vec3 p = point * inv * uSphere.y + vec3(0.0, uSphere.x, 0.0);
    float py = max(p.y, 0.0);
    p.xz += vLean * py * py;
    t.wsPos = vFootHeight.xyz + vec3(mat2(vTurn.x, vTurn.y, -vTurn.y, vTurn.x) * p.xz * vTurn.z, p.y).xzy
            * vFootHeight.w;
    return t;
}
