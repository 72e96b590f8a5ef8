package org.openworld.engine.terrain;

import static org.lwjgl.opengl.GL11C.*;

import java.util.List;
import java.util.function.Consumer;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.NodeHeights;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.culling.Visibility;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * The mountains: generates (or imports) the height field with its pyramid and snow map, publishes it as the world's
 * {@link HeightField} and where its snow lies as the world's {@link SnowLine} (metres, {@link SnowLines}), and draws it as geomipmapped patches chosen by a {@link PatchSelection} among those the
 * culling system left visible.
 *
 * <p>Frame by frame: {@link #update} keeps the copies of a periodic tile centred on the camera (so the world has no
 * edge) and refreshes the {@link Cullable}; the culling system tests it against the pass camera; {@link #render}
 * chooses the cut and draws it with one instanced call per index pattern.
 *
 * <p>Order: the {@link Cullable} and the {@link HeightField} are attached at init and the copy offsets are refreshed in
 * update, which always precedes every pass's render, so neither needs an order edge; the terrain declares that it
 * reads the {@link Visibility} the culling writes in each pass, the {@link Camera} it follows and the viewer's
 * {@link PassView} the engine publishes each frame (the shadow casters follow it), and that it writes
 * the {@link SnowLine}: at init and again each update, as {@code materials.snow-mode} may change while it runs.
 */
public final class TerrainSystem implements EngineSystem {

    /**
     * How far from the camera's tile copies of a periodic tile are drawn, metres: where the ground's detail has
     * faded into the air; beyond them the {@link FarField} carries the ground on to the horizon.
     */
    static final double COPY_DISTANCE = 12_000;
    /** The tile's pyramid level the far field reads: 256 m apart at 2 m, as the unbounded world's coarsest. */
    static final int FAR_LEVEL = 7;
    /** The most copies drawn on each side of the camera's tile (a small tile is cheap far away, but not free). */
    static final int MAX_COPY_RADIUS = 3;
    /** Texture units: the terrain's maps first (heights, gradients, snow), then the materials (TerrainShading). */
    private static final int UNIT_HEIGHTS = 0;
    private static final int UNIT_GRADIENTS = 1;
    private static final int UNIT_SNOW = 2;

    private final Consumer<String> progress;
    /** The tile's heights, pyramid, snow map and sky view; null for the unbounded world. */
    private TerrainData data;
    /** The unbounded world, streamed around the camera; null for a tile. */
    private UnboundedWorld unbounded;
    private PatchLayout layout;
    private TerrainQuadtree tree;
    private PatchSelection selection;
    /** Which nodes are on the GPU and the heights they span: all of a tile's, the streamed world's as it streams. */
    private Residency residency = Residency.ALL;
    /** The heights the culling tests each node with: the boxes' own for a tile, the streamed cells' otherwise. */
    private NodeHeights heights = NodeHeights.NONE;
    private final PatchList patches = new PatchList();
    private PatchPatterns patterns;
    private final PatchOrder order = new PatchOrder();
    /** The tile's maps on the GPU; null for the unbounded world, whose clipmap holds its own. */
    private TerrainMaps maps;
    private TerrainShading shading;
    private PatchRenderer renderer;
    /** The same patches for the sun's shadow pass: the vertex stage alone, writing depth. */
    private ShaderProgram depthProgram;
    private int entity;
    private float[] copyOffsets;
    private long copyCentreX = Long.MIN_VALUE;
    private long copyCentreZ = Long.MIN_VALUE;
    /** Copies (roots) drawn on each side of the camera's. */
    private int copyRadius;
    /** Ground from the copies' edge to the horizon; null for an imported map, which has an edge by design. */
    private FarField farField;
    /** The lowest and highest heights drawn, metres. */
    private double lowest;
    private double highest;
    /** Where levels are chosen from while {@code terrain-debug.freeze-lod} is on; null while it is off. */
    private Vector3f frozenEye;

    /** A terrain that reports nothing while it generates. */
    public TerrainSystem() {
        this(message -> { });
    }

    /** @param progress receives one line per generation stage with its time, e.g. for the console */
    public TerrainSystem(Consumer<String> progress) {
        this.progress = progress;
    }

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("terrain").reads(Settings.class, Camera.class, PassView.class, Visibility.class)
                .writes(SnowLine.class).draws(Pass.SHADOW, Pass.REFLECTION, Pass.MAIN);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(TerrainSettings.SETTINGS, LodSettings.SETTINGS, MaterialSettings.SETTINGS,
                TerrainDebugSettings.SETTINGS);
    }

    @Override
    public void init(EngineContext context) {
        Settings settings = context.settings();
        int seed = settings.get(EngineSettings.class).seed();
        TerrainSettings terrain = settings.get(TerrainSettings.class);
        StageTimes times = new StageTimes(stage -> progress.accept(
                String.format(java.util.Locale.ROOT, "terrain: %-10s %7.0f ms", stage.name(), stage.ms())));
        int cells = settings.get(LodSettings.class).patchVertices() - 1;
        patterns = new PatchPatterns(cells);
        renderer = context.own(new PatchRenderer(context, patterns));
        if (terrain.world() == TerrainSettings.World.UNBOUNDED) {
            initUnbounded(context, terrain, seed, cells, times);
        } else {
            initTile(context, terrain, seed, cells, times);
        }
        entity = context.world().spawn();
        // the render origin steps by a tile (a root's side): a whole number of samples of every level
        context.world().setResource(new RenderOrigin(tree.extent()));
        copyOffsets = new float[] {0, 0};
        context.world().add(entity, new Cullable(tree.bounds(), copyOffsets, heights));
        depthProgram = context.own("depth", context.shaders().program(layout.defines(), "terrain/terrain.vert",
                "terrain/depth.frag"));
        layout.apply(depthProgram, UNIT_HEIGHTS);
        publishSnowLine(context.world(), settings);
        farField = farField(context);
    }

    /**
     * The far field, reading the coarsest streamed level or the tile's pyramid level of the same spacing (its
     * periodic copies go on for ever); none for an imported map.
     */
    private FarField farField(EngineContext context) {
        if (unbounded != null) {
            StreamedWorld stream = unbounded.stream();
            int level = stream.levels() - 1;
            lowest = stream.heights().lowest();
            highest = stream.heights().highest();
            double mean = (lowest + highest) / 2; // the bands' bounds lie symmetric about the mean
            ShaderProgram program = shading.farField(context, UNIT_HEIGHTS);
            program.float1("uFarSnow").set((float) unbounded.snowCoverageAt(mean));
            return new FarField(context, program,
                    new FarField.Source(level, stream.heights().spacing(level), 0, mean));
        }
        HeightMap base = data.pyramid().base();
        lowest = base.min();
        highest = base.max();
        if (!base.periodic()) {
            return null;
        }
        int top = data.pyramid().levelCount() - 1;
        int level = Math.min(top, FAR_LEVEL);
        return new FarField(context, shading.farField(context, UNIT_HEIGHTS), new FarField.Source(level,
                Math.scalb(base.spacing(), level), -base.extent() / 2, data.pyramid().level(top).sample(0, 0)));
    }

    /** The tile: its data off the GPU, its quadtree, its maps, then the programs and materials (which bake on them). */
    private void initTile(EngineContext context, TerrainSettings terrain, int seed, int cells, StageTimes times) {
        progress.accept("terrain: " + (terrain.imports() ? "importing " + terrain.importFile()
                : "generating " + terrain.size() + "² samples, seed " + seed));
        data = TerrainData.create(terrain, seed, times);
        HeightMap base = data.pyramid().base();
        context.world().setResource(HeightField.class, base::heightAt);
        tree = times.time("quadtree", () -> new TerrainQuadtree(data.pyramid(), cells));
        selection = new PatchSelection(tree);
        layout = PatchLayout.tile(base, cells);
        maps = new TerrainMaps(context, data.pyramid(), data.snow(), data.sky());
        shading = new TerrainShading(context, layout, base, seed, UNIT_HEIGHTS, times);
        bindMaps();
        shading.bake(context.settings().get(MaterialSettings.class));
    }

    /** The unbounded world: bands, streamed around where the camera starts, and the programs that read them. */
    private void initUnbounded(EngineContext context, TerrainSettings terrain, int seed, int cells,
                               StageTimes times) {
        progress.accept("terrain: the unbounded world, seed " + seed);
        unbounded = context.own(new UnboundedWorld(context, terrain, seed, cells, UNIT_HEIGHTS, times, progress));
        StreamedWorld stream = unbounded.stream();
        context.world().setResource(HeightField.class, stream.heights());
        tree = stream.tree();
        residency = stream;
        heights = stream.cullHeights();
        selection = new PatchSelection(tree, stream);
        layout = PatchLayout.clipmap(tree, stream.clipSize(), terrain);
        shading = new TerrainShading(context, layout, null, seed, UNIT_HEIGHTS, times);
    }

    /** Binds the heights, then the gradients (slopes) and the snow map, to their units. */
    private void bindMaps() {
        if (unbounded != null) {
            unbounded.heightTexture.bind(UNIT_HEIGHTS);
            unbounded.slopeTexture.bind(UNIT_GRADIENTS);
            unbounded.snowTexture.bind(UNIT_SNOW);
        } else {
            maps.heights.bind(UNIT_HEIGHTS);
            maps.gradients.bind(UNIT_GRADIENTS);
            maps.snow.bind(UNIT_SNOW);
        }
    }

    /** The snow line in metres of the snow rule in use (the snow map's, or the altitude bands') over the heights. */
    private void publishSnowLine(World world, Settings settings) {
        world.setResource(SnowLines.of(layout.lowest(), layout.highest(),
                settings.get(MaterialSettings.class).snowMode(), settings.get(TerrainSettings.class)));
    }

    @Override
    public void update(World world, double step) {
        publishSnowLine(world, world.resource(Settings.class));
        CameraPose pose = world.resource(Camera.class).pose();
        if (unbounded != null) {
            unbounded.follow(pose, step);
        } else if (!data.pyramid().base().periodic()) {
            return;
        }
        // Copies of the periodic tile (roots of the unbounded world) on a square around the one under the camera:
        // a world without an edge.
        double extent = tree.extent();
        long cx = Math.round(pose.x() / extent);
        long cz = Math.round(pose.z() / extent);
        if (cx == copyCentreX && cz == copyCentreZ) {
            return;
        }
        copyCentreX = cx;
        copyCentreZ = cz;
        copyRadius = unbounded != null ? unbounded.stream().rootRadius()
                : (int) Math.min(MAX_COPY_RADIUS, Math.ceil(COPY_DISTANCE / extent - 0.5));
        copyOffsets = copies(cx, cz, copyRadius, extent);
        world.add(entity, new Cullable(tree.bounds(), copyOffsets, heights));
    }

    /**
     * The offsets, metres, of the copies (roots) on a square of {@code radius} around copy (cx, cz), each
     * {@code extent} a side: x, z pairs, row by row from the north-west.
     */
    static float[] copies(long cx, long cz, int radius, double extent) {
        int side = 2 * radius + 1;
        float[] offsets = new float[2 * side * side];
        int c = 0;
        for (int dz = -radius; dz <= radius; dz++) {
            for (int dx = -radius; dx <= radius; dx++) {
                offsets[c++] = (float) ((cx + dx) * extent);
                offsets[c++] = (float) ((cz + dz) * extent);
            }
        }
        return offsets;
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        World world = context.world();
        Settings settings = world.resource(Settings.class);
        LodSettings lod = settings.get(LodSettings.class);
        TerrainDebugSettings debug = settings.get(TerrainDebugSettings.class);
        // 1. the cut: the level rule over the quadtree (or its flat grid), visible patches only
        Visibility visibility = world.get(entity, Visibility.class)
                .filter(v -> v.copies() * 2 == copyOffsets.length).orElse(null);
        // levels follow the pass's camera: its projection and pixels bound the screen error; distances are from its
        // eye. The sun's pass (a light box has no eye) cuts its casters from the viewer's eye and, under the screen
        // error, by the viewer's own limit: they are then the very ground the viewer sees, and no caster finer than
        // its receiver shadows it where it lies below, nor a coarser one where it stands above (acne)
        PassView view = pass == Pass.SHADOW && lod.rule() == LodRule.SCREEN_ERROR ? world.resource(PassView.class)
                : new PassView(context.camera(), context.target());
        DetailLimit limit = lod.limit(pass, view.camera(), view.target().width(), view.target().height());
        Vector3fc eye = pass == Pass.SHADOW ? viewerEye(world) : context.camera().position();
        if (debug.freezeLod()) {
            frozenEye = frozenEye != null ? frozenEye : new Vector3f(eye);
            eye = frozenEye;
        } else {
            frozenEye = null;
        }
        long t0 = System.nanoTime();
        selection.select(eye, copyOffsets, limit, lod.mode(), visibility, patches);
        if (!lod.morph()) {
            patches.withoutMorph();
        }
        double selectMs = (System.nanoTime() - t0) / 1e6;
        if (unbounded != null && pass != Pass.SHADOW) {
            // the share of the sky seen where the shading reads it, and a few blocks more with the picture
            unbounded.shadeFor(patches, copyOffsets, pass == Pass.MAIN ? StreamedWorld.UPLOADS_PER_FRAME : 0);
        }
        Counters counters = world.resource(Counters.class);
        String prefix = "terrain." + pass.label() + ".";
        counters.add(prefix + "patches", patches.size());
        counters.add(prefix + "culled", selection.culledPatches());
        counters.add(prefix + "select-ms", selectMs);
        // 2. nearest first, so near ground hides far ground before it is shaded
        order.sort(patches, tree.bounds(), residency, copyOffsets, eye);
        // 3. the maps, then the patches, front faces only: in the sun's pass with the heights alone, else with the
        // materials near and far and the view options; the copies placed from the render origin
        RenderOrigin origin = world.resource(RenderOrigin.class);
        float[] drawnOffsets = origin.relativePairs(copyOffsets);
        shading.origin(origin.x(), origin.z());
        bindMaps();
        long triangles = context.stats().triangles();
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
        glEnable(GL_CULL_FACE);
        if (pass == Pass.SHADOW) {
            depthProgram.use();
            renderer.draw(patches, order.order(), 0, order.size(), drawnOffsets, context.stats());
        } else {
            if (debug.wireframe()) {
                glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            }
            int near = shading.draw(patches, order, drawnOffsets, settings.get(MaterialSettings.class),
                    debug.colouring(), context.sunShadowed(), renderer, context.stats());
            counters.add(prefix + "near", near);
            if (farField != null && pass == Pass.MAIN
                    && debug.colouring() == TerrainDebugSettings.Colouring.SHADED) {
                // 4. beyond the patches, the far field to the horizon
                shading.bindFarField(settings.get(MaterialSettings.class));
                double extent = tree.extent();
                farField.draw(context.camera().positionFrom(origin.x(), origin.z()),
                        copyCentreX * extent - origin.x(), copyCentreZ * extent - origin.z(),
                        (copyRadius + 0.5) * extent, lowest, highest, context.stats());
            }
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        }
        glDisable(GL_CULL_FACE);
        context.world().resource(Counters.class).add(prefix + "triangles", context.stats().triangles() - triangles);
    }

    private static Vector3f viewerEye(World world) {
        var pose = world.resource(Camera.class).pose();
        return new Vector3f((float) pose.x(), (float) pose.y(), (float) pose.z());
    }

    /**
     * The generated or imported tile, once initialised (tests and tools read the heights the terrain draws); null
     * for the unbounded world, which has no map.
     */
    public TerrainData data() {
        return data;
    }

    /** The unbounded world, once initialised (tests read its textures); null for a tile. */
    UnboundedWorld unbounded() {
        return unbounded;
    }
}
