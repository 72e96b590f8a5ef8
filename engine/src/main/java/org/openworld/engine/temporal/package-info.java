/**
 * Temporal anti-aliasing (TAA; Brian Karis, "High-quality temporal supersampling", SIGGRAPH 2014 course "Advances in
 * Real-Time Rendering"): supersampling spread over frames. Each frame is drawn with the projection moved by a
 * fraction of a pixel ({@link org.openworld.engine.temporal.Jitter}), so over {@code antialias.samples} frames a
 * pixel is sampled at that many places, and one pass ({@link org.openworld.engine.temporal.TemporalAntialias},
 * {@code shaders/temporal/taa.frag}) blends each frame into the mean of the frames before. Chosen with
 * {@code antialias.method=taa} (the default). Page: {@code docs/design.md}, "Anti-aliasing".
 *
 * <p><b>Why.</b> FXAA finds edges in one frame; it cannot tell a texel that flickers from one that does not, and its
 * threshold itself flickers. Supersampling can, but costs its samples every frame; TAA pays one sample a pixel a frame
 * and gets the mean of many from the frames before, which in a still or slow picture is what supersampling gives. In
 * motion it is the steadier picture ({@code openworld stability}, docs/benchmarks.md, "Temporal stability").
 *
 * <p><b>Method.</b> Per pixel p of frame n, with c the frame's colour, z its depth and h the last output:
 * <pre>
 *   x      = (uv_p · 2 − 1, z · 2 − 1, 1)                       the pixel's point, normalised device coordinates
 *   x'     = VP_{n−1} · VP_n⁻¹ · x                               reprojected (both without jitter): no motion vectors
 *   m      = |x' − x| in pixels                                  the pixel's motion since the last frame
 *   h'     = mix(h(x'), clamp(h(x'), min₃ₓ₃ c, max₃ₓ₃ c), min(2m, 1))   clamped to the neighbourhood's colours
 *   out_n  = h' + w · (c − h'),   w = max(blend, 1 / (k + 1))      k frames in the run so far
 * </pre>
 * The world is static to the camera but for the snow, so the camera's two matrices and the depth give every pixel's
 * motion. The clamp is what keeps history from ghosting: a colour that no pixel of the 3×3 neighbourhood shows this
 * frame (a surface uncovered, the sky behind a ridge that moved) is pulled to the nearest that one does. It is needed
 * only where the view moves: where it is still (m = 0) the history at the pixel is the same surface, and a clamp to
 * one jittered frame's box would cut what that frame's samples happen to miss (a sub-pixel trunk, a ridge's thin
 * edge, a glint), which the next frames add back, so a still picture would never settle to the mean of its samples
 * and two stills a little apart would differ by that noise. The clamp's share therefore grows with the motion, whole
 * from half a pixel a frame (m = ½). The weight
 * 1 / (k + 1) makes the first {@code 1 / blend} frames an exact mean; {@code antialias.blend} then keeps an
 * exponential mean over about {@code 2 / blend − 1} frames. A run starts when the pass was not drawn the frame
 * before (or the size changed); its first frame has no jitter and no history, so a single frame is the plain
 * picture, and {@code shot} renders one cycle ({@code AntialiasSettings.framesToSettle}) to settle.
 *
 * <p><b>Data path.</b> The engine asks for the viewer's camera jittered before the passes; the systems draw the scene
 * target with it as usual (the shadow and reflection cameras derive from it). After the last pass one full-screen
 * triangle reads the scene's colour and depth ({@code texelFetch}) and the other of two RGBA16F histories (bilinear:
 * a reprojected point falls between texels), and writes the blend through two outputs at once: into one history and
 * into the anti-aliased RGBA8 target of the scene's size (no copy of the history after the pass). Float histories:
 * with 8-bit ones a blend weight of 0.1 could not move a pixel by less than five levels, and the history would
 * stick.
 *
 * <p><b>Cost.</b> Ten colour fetches (the 3×3 box and the centre once more: fetching it once, through a loop that
 * skips it or a table of the eight offsets, measured no faster) and one depth fetch for the clamp and the point, one
 * bilinear history fetch, a matrix product, the motion's length and one more mix for the clamp's share (a few
 * arithmetic operations beside the twelve fetches, not measurable on the loaded machine), and two writes a pixel
 * (RGBA16F and RGBA8). On a software
 * rasteriser the fetches are the pass: it costs about what the terrain's material does per pixel. Writing the
 * picture as a second output spares the full-screen copy of the history that followed the pass, a saving within the
 * loaded machine's noise (docs/benchmarks.md, "The terrain's main pass"). Measured as
 * the span {@code antialias.engine} on llvmpipe (the peer comparison's terrain view, 1280 × 720, profiled, one
 * sitting on a loaded machine): 28 % of the frame against FXAA's 23 %, 1.1 times FXAA's span (docs/benchmarks.md, "Temporal stability"). Memory: two RGBA16F
 * targets of the scene's size (14 MiB at 1280 × 720). A still picture settles in one cycle of frames.
 *
 * <p><b>Limits.</b> In motion the history is read between texels, a slight blur that the next frames sharpen again;
 * a thing that moves on its own (the falling snow) has no motion vector and is kept only within the clamp, so it
 * may leave a faint trail (not measured), and under a still view, where nothing is clamped, a plant's sway or a
 * cloud's drift is averaged over the history's half second; in motion, a thin feature that the neighbourhood of one
 * frame misses entirely is clamped away. The clamp's box of colours lets a pixel keep what its neighbours show, so
 * a flicker smaller than the local contrast (in a textured region) survives; a larger one is cut. A layer drawn
 * without writing depth (the falling snow) is reprojected by the depth beneath it.
 */
package org.openworld.engine.temporal;
