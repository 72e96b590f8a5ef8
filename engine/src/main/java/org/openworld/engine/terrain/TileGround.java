package org.openworld.engine.terrain;

import java.nio.file.Path;
import java.util.function.Consumer;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.NodeHeights;
import org.openworld.engine.core.Pass;
import org.openworld.engine.drainage.Wetness;
import org.openworld.engine.elevation.ElevationImport;
import org.openworld.engine.erosion.TileErosion;
import org.openworld.engine.erosion.hydraulic.GpuPipeErosion;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightSource;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.lod.CopyLattice;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.lod.Residency;
import org.openworld.engine.terrain.lod.TerrainQuadtree;
import org.openworld.engine.terrain.material.MaterialSettings;
import org.openworld.engine.terrain.material.TerrainMaps;
import org.openworld.engine.terrain.mesh.PatchLayout;

/**
 * A tile of heights, generated or imported: its pyramid and snow map made at start ({@link TerrainData}), all on
 * the GPU with the sky view baked there ({@link TerrainMaps}), its quadtree's boxes exact. A periodic tile is drawn
 * as copies around the camera's up to {@link CopyLattice#COPY_DISTANCE}, then the far field; an imported map once,
 * with its edge.
 */
public final class TileGround implements Ground {

    /** The tile's pyramid level the far field reads: 256 m apart at 2 m, as the unbounded world's coarsest. */
    static final int FAR_LEVEL = 7;
    /** The most copies drawn on each side of the camera's tile (a small tile is cheap far away, but not free). */
    static final int MAX_COPY_RADIUS = 3;

    private final TerrainData data;
    private final TerrainQuadtree tree;
    private final PatchLayout layout;
    private final TerrainMaps maps;
    private final TerrainShading shading;

    /**
     * A generated or imported tile, made by {@code tiles}, and how wet each place is ({@link Wetness}, published
     * to the world) where it repeats; its maps bound to these units as it bakes.
     */
    static TileGround make(EngineContext context, TerrainData.Maker tiles, TerrainSettings terrain, int seed,
                           int cells, int unitHeights, int unitGradients, int unitSnow, StageTimes times,
                           Consumer<String> progress) {
        Path file = Path.of(terrain.importFile());
        progress.accept("terrain: " + (terrain.imports() ? "importing " + terrain.importFile()
                + (ElevationImport.handles(file) ? ": " + ElevationImport.describe(file, terrain, seed) : "")
                : "generating " + terrain.size() + "² samples, seed " + seed));
        TerrainData data = tiles.make(terrain, seed, times, new GpuPipeErosion(context.gl(), context.shaders()));
        HeightMap base = data.pyramid().base();
        if (base.periodic()) {
            // how wet each place is, from the water that drains through it (drainage.Wetness)
            HeightMap routed = data.pyramid().level(TileErosion.routingLevel(base));
            context.world().setResource(times.time("wetness",
                    () -> Wetness.ofTile(routed.heights(), routed.size(), routed.spacing())));
        }
        return new TileGround(context, data, seed, cells, unitHeights, unitGradients, unitSnow, times);
    }

    /** The tile's data off the GPU, its quadtree, its maps, then the materials (which bake on them). */
    TileGround(EngineContext context, TerrainData data, int seed, int cells, int unitHeights, int unitGradients,
               int unitSnow, StageTimes times) {
        this.data = data;
        HeightMap base = data.pyramid().base();
        tree = times.time("quadtree", () -> new TerrainQuadtree(data.pyramid(), cells));
        layout = PatchLayout.tile(base, cells, data.lowest(), data.highest());
        maps = new TerrainMaps(context, data.pyramid(), data.snow(), data.sediment(), unitHeights, times);
        shading = TerrainShading.baked(context, layout, base, seed, unitHeights, times);
        bind(unitHeights, unitGradients, unitSnow);
        shading.bake(context.settings().get(MaterialSettings.class));
    }

    /** The tile's heights, pyramid and snow map. */
    public TerrainData data() {
        return data;
    }

    @Override
    public HeightSource heights() {
        return data.pyramid();
    }

    @Override
    public TerrainQuadtree tree() {
        return tree;
    }

    @Override
    public Residency residency() {
        return Residency.ALL;
    }

    @Override
    public NodeHeights cullHeights() {
        return NodeHeights.NONE;
    }

    @Override
    public PatchLayout layout() {
        return layout;
    }

    @Override
    public TerrainShading shading() {
        return shading;
    }

    @Override
    public void bind(int unitHeights, int unitGradients, int unitSnow) {
        maps.heights.bind(unitHeights);
        maps.gradients.bind(unitGradients);
        maps.snow.bind(unitSnow);
    }

    @Override
    public boolean follow(CameraPose pose, double step) {
        return data.pyramid().base().periodic();
    }

    @Override
    public int copyRadius() {
        return (int) Math.min(MAX_COPY_RADIUS, Math.ceil(CopyLattice.COPY_DISTANCE / tree.extent() - 0.5));
    }

    @Override
    public void prepare(PatchList patches, float[] copyOffsets, Pass pass) {
        // the tile's sky view was baked with its maps at start
    }

    /** Reads the pyramid level of the streamed world's coarsest spacing: its periodic copies go on for ever. */
    @Override
    public FarField farField(EngineContext context, int unitHeights) {
        HeightMap base = data.pyramid().base();
        if (!base.periodic()) {
            return null;
        }
        int top = data.pyramid().levelCount() - 1;
        int level = Math.min(top, FAR_LEVEL);
        return new FarField(context, shading.farField(context, unitHeights), new FarField.Source(level,
                Math.scalb(base.spacing(), level), -base.extent() / 2, data.pyramid().level(top).sample(0, 0)));
    }
}
