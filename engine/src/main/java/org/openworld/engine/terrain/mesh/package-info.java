/**
 * The terrain's third stage: patches to triangles. In: a {@link org.openworld.engine.terrain.lod.PatchList}.
 * Out: draw calls: one element buffer of stitching patterns shared by every patch, one instanced call per pattern
 * in use ({@link org.openworld.engine.terrain.mesh.PatchRenderer}), patches ordered nearest first
 * ({@link org.openworld.engine.terrain.mesh.PatchOrder}), and the uniforms that tell the shaders where the heights
 * lie ({@link org.openworld.engine.terrain.mesh.PatchLayout}).
 *
 * <p><b>Stitching.</b> Where a patch meets a coarser neighbour, its edge strip uses only every 2^k-th vertex
 * (a fan from each outer vertex, {@link org.openworld.engine.terrain.mesh.PatchPatterns}), so no vertex lies in the middle
 * of the neighbour's edge (no T-junction); and the vertices on that edge read the neighbour's pyramid level, the
 * corners the coarsest level meeting there, so both sides compute the same height (no crack). Differences of up to
 * log2 N levels are stitched; a cut that would need more is split until it does not. The patterns are shared: one
 * element buffer holds them all, and {@link org.openworld.engine.terrain.mesh.PatchRenderer} draws each pattern in use
 * with one instanced call, so draw calls do not grow with the visible patches.
 */
package org.openworld.engine.terrain.mesh;
