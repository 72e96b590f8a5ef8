package org.openworld.engine.terrain;

import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.NodeHeights;
import org.openworld.engine.core.Pass;
import org.openworld.engine.terrain.heights.HeightSource;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.lod.Residency;
import org.openworld.engine.terrain.lod.TerrainQuadtree;
import org.openworld.engine.terrain.mesh.PatchLayout;

/**
 * The ground the terrain system draws: a height source with the way its levels reach the GPU, its layout for the
 * programs and its shading. The system asks the same questions of every kind ({@link TileGround}: a generated or
 * imported tile, its whole pyramid on the GPU, drawn as copies around the camera; {@link StreamedGround}: the
 * unbounded world's levels streamed around the camera), so that it holds no branch on the kind it draws; the
 * setting {@code terrain.world} picks the kind once. The level-of-detail scheme ({@code lod.mode}) is a separate
 * choice, which asks only the ground's {@link Residency}.
 */
public interface Ground {

    /** The heights, the world's {@link org.openworld.engine.core.HeightField}. */
    HeightSource heights();

    /** The quadtree the cut walks: its roots one tile, or one root of the streamed lattice. */
    TerrainQuadtree tree();

    /** Which nodes are on the GPU, and the heights they span. */
    Residency residency();

    /** The heights the culling tests each node with. */
    NodeHeights cullHeights();

    /** Where the shaders find the heights. */
    PatchLayout layout();

    /** The near and far materials, made for this ground. */
    TerrainShading shading();

    /** Binds the heights, the gradients (slopes) and the snow map to their texture units. */
    void bind(int unitHeights, int unitGradients, int unitSnow);

    /**
     * Once per simulation step, after the camera moved.
     *
     * @return whether copies (roots) follow the camera; false for a ground that stays where it is
     */
    boolean follow(CameraPose pose, double step);

    /** Copies (roots) drawn on each side of the camera's. */
    int copyRadius();

    /** Before a pass other than the sun's shades these patches: what they read that is not ready yet. */
    void prepare(PatchList patches, float[] copyOffsets, Pass pass);

    /** The ground from the copies' edge to the horizon, or null where the ground ends at its edge. */
    FarField farField(EngineContext context, int unitHeights);
}
