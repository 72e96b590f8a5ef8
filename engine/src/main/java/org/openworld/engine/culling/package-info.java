/**
 * Visual surface detection by frustum culling (paper section 2.4): what lies wholly outside a pass camera's view is
 * not sent to the GPU.
 *
 * <p><b>Technique.</b> A {@link org.openworld.engine.culling.Frustum} holds the camera's six planes, extracted from the
 * view-projection matrix (Gribb and Hartmann); the water's reflection camera has its near plane in the water
 * surface (an oblique projection), so the same six planes cull what lies under the water. A box is rejected only when all eight of
 * its corners lie outside one plane: with {@code p⁺} the corner furthest along the plane normal {@code n},
 * {@code n · p⁺ + d < 0}. That is the paper's conservative test: a box outside the frustum may pass (near its
 * corners), a box inside never fails.
 *
 * <p><b>Hierarchy.</b> The {@link org.openworld.engine.culling.CullingSystem} walks each
 * {@link org.openworld.engine.core.Cullable}'s {@link org.openworld.engine.core.BoundsTree} (the terrain's
 * quadtree, with each node's box spanning its min and max heights) from the root: a node wholly outside or wholly
 * inside settles its whole subtree, so a pass tests a few hundred boxes of a tree of tens of thousands. A cullable
 * may know its nodes' heights more tightly than its boxes ({@link org.openworld.engine.core.NodeHeights}): the
 * unbounded world builds one tree for all its roots before any height has arrived, so its boxes span the whole
 * world's heights, and it gives each node the range of the streamed cells it reads (its levels L .. L + log2 N,
 * 8-sample cells, widened by its level's error); a node whose range is unknown keeps its parent's, and one whose
 * children the level choice cannot draw yet (their heights have not arrived) is kept whole rather than descended
 * into. It runs in
 * every pass that draws (main, light, mirror) with that pass's camera, before the drawers, and leaves a
 * {@link org.openworld.engine.culling.Visibility} for them to read top-down.
 *
 * <p><b>Cost.</b> At most 12 dot products per box tested; about 26 µs per pass for a 5461-node tree in 9 copies on the
 * 2-core reference machine. The unbounded world's heights cost more per node than the box test: a few dozen cell
 * look-ups for its range and the residency of its four children, about 1 µs on that machine (loaded), but they are
 * what lets its walk settle subtrees at all. Along {@code crossing.path} its reflection pass (the near plane in the
 * water, which every world-high box straddles) tested about 153 000 of its 25 roots' 546 000 nodes and found none
 * inside, 3.2 ms a frame on llvmpipe; with the streamed ranges it tests about 350, 0.4 ms, and the culling of all
 * passes fell from 3.9 to 1.7 ms a frame, though the main pass and the cascades, testing 10 to 25 times fewer
 * nodes, each cost a little more than before (0.3 – 0.5 ms). Per-pass counters {@code culling.<pass>.tested/outside/inside/kept} appear in {@code bench}.
 *
 * <p><b>Debug.</b> {@code culling.freeze=on} keeps each pass's frustum where it was; the frozen main frustum is drawn as
 * a magenta outline, so one can fly out and see what was culled.
 *
 * <p><b>Limits.</b> Only the frustum: nothing hidden behind a mountain is culled (no occlusion culling), and a box
 * near a frustum corner can survive although it is outside.
 */
package org.openworld.engine.culling;
