package org.openworld.engine.terrain;

import java.util.function.Consumer;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.NodeHeights;
import org.openworld.engine.core.Pass;
import org.openworld.engine.erosion.ErodedWorld;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.terrain.heights.HeightSource;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.lod.Residency;
import org.openworld.engine.terrain.lod.TerrainQuadtree;
import org.openworld.engine.terrain.mesh.PatchLayout;
import org.openworld.engine.terrain.stream.StreamedWorld;
import org.openworld.engine.terrain.stream.UnboundedWorld;

/**
 * The unbounded world: its levels streamed into a clipmap around the camera ({@link UnboundedWorld}), a node drawn
 * only once its level has arrived, roots on a lattice around the camera's.
 */
public final class StreamedGround implements Ground {

    private final UnboundedWorld world;
    private final StreamedWorld stream;
    private final PatchLayout layout;
    private final TerrainShading shading;

    /** The bands, streamed around where the camera starts, and the programs that read them. */
    static StreamedGround make(EngineContext context, TerrainSettings terrain, int seed, int cells, int unitHeights,
                               StageTimes times, Consumer<String> progress) {
        progress.accept("terrain: the unbounded world, seed " + seed);
        UnboundedWorld world = context.own(new UnboundedWorld(context, terrain, seed, cells, unitHeights, times,
                progress));
        if (world.stream().heights() instanceof ErodedWorld eroded) { // how wet each place is (drainage.Wetness)
            context.world().setResource(eroded.wetness());
        }
        return new StreamedGround(world, context, seed, unitHeights, times);
    }

    StreamedGround(UnboundedWorld world, EngineContext context, int seed, int unitHeights,
                   StageTimes times) {
        this.world = world;
        this.stream = world.stream();
        layout = PatchLayout.clipmap(stream.tree(), stream.clipSize(), context.settings()
                .get(TerrainSettings.class));
        shading = TerrainShading.coarse(context, layout, seed, unitHeights, times);
    }

    /** The world's streams and textures (tests read them). */
    public UnboundedWorld world() {
        return world;
    }

    @Override
    public HeightSource heights() {
        return stream.heights();
    }

    @Override
    public TerrainQuadtree tree() {
        return stream.tree();
    }

    @Override
    public Residency residency() {
        return stream;
    }

    @Override
    public NodeHeights cullHeights() {
        return stream.cullHeights();
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
        world.heightTexture.bind(unitHeights);
        world.slopeTexture.bind(unitGradients);
        world.snowTexture.bind(unitSnow);
    }

    @Override
    public boolean follow(CameraPose pose, double step) {
        world.follow(pose, step);
        return true;
    }

    @Override
    public int copyRadius() {
        return stream.rootRadius();
    }

    /** The share of the sky seen where the shading reads it, and a budget's worth more with the picture. */
    @Override
    public void prepare(PatchList patches, float[] copyOffsets, Pass pass) {
        world.shadeFor(patches, copyOffsets, pass == Pass.MAIN);
    }

    /** Reads the coarsest streamed level, its snow the coverage at the mean height. */
    @Override
    public FarField farField(EngineContext context, int unitHeights) {
        int level = stream.levels() - 1;
        double mean = (heights().lowest() + heights().highest()) / 2; // the bands' bounds lie symmetric about it
        ShaderProgram program = shading.farField(context, unitHeights);
        program.float1("uFarSnow").set((float) world.snowCoverageAt(mean));
        return new FarField(context, program, new FarField.Source(level, stream.heights().spacing(level), 0, mean));
    }
}
