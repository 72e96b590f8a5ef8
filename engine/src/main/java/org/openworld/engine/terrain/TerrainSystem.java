package org.openworld.engine.terrain;

import static org.lwjgl.opengl.GL11C.*;

import java.util.List;
import java.util.function.Consumer;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.culling.Visibility;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.lod.CopyLattice;
import org.openworld.engine.terrain.lod.DetailLimit;
import org.openworld.engine.terrain.lod.LodRule;
import org.openworld.engine.terrain.lod.LodSettings;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.lod.PatchSelection;
import org.openworld.engine.terrain.lod.TerrainQuadtree;
import org.openworld.engine.terrain.material.MaterialSettings;
import org.openworld.engine.terrain.material.SnowLines;
import org.openworld.engine.terrain.mesh.PatchLayout;
import org.openworld.engine.terrain.mesh.PatchOrder;
import org.openworld.engine.terrain.mesh.PatchPatterns;
import org.openworld.engine.terrain.mesh.PatchRenderer;

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
    /** The counters, per pass: patches drawn and culled, selection's CPU time (ms), near patches, triangles. */
    private static final Counter PATCHES = Counter.of("terrain", "patches");
    private static final Counter CULLED = Counter.of("terrain", "culled");
    private static final Counter SELECT_MS = Counter.of("terrain", "select-ms");
    private static final Counter NEAR = Counter.of("terrain", "near");
    private static final Counter TRIANGLES = Counter.of("terrain", "triangles");

    /** Texture units: the terrain's maps first (heights, gradients, snow, in this order), then the materials. */
    private static final TextureUnits UNITS = new TextureUnits();
    private static final int UNIT_HEIGHTS = UNITS.add("heights").unit();
    private static final int UNIT_GRADIENTS = UNITS.add("gradients").unit();
    private static final int UNIT_SNOW = UNITS.add("snowMap").unit();

    private final Consumer<String> progress;
    /** Makes a tile's heights, pyramid and snow map: generated or imported unless told otherwise. */
    private final TerrainData.Maker tiles;
    /** The heights and how their levels reach the GPU: a tile, or the unbounded world streamed. */
    private Ground ground;
    private PatchLayout layout;
    private TerrainQuadtree tree;
    private PatchSelection selection;
    private final PatchList patches = new PatchList();
    private PatchPatterns patterns;
    private final PatchOrder order = new PatchOrder();
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
    /** Where levels are chosen from while {@code terrain-debug.freeze-lod} is on; null while it is off. */
    private Vector3f frozenEye;

    /** A terrain that reports nothing while it generates. */
    public TerrainSystem() {
        this(message -> { });
    }

    /** @param progress receives one line per generation stage with its time, e.g. for the console */
    public TerrainSystem(Consumer<String> progress) {
        this(progress, TerrainData::create);
    }

    /**
     * @param progress receives one line per generation stage with its time
     * @param tiles    makes the tile drawn when {@code terrain.world=tile}, e.g. from a height source of one's own
     *                 ({@link TerrainData#of})
     */
    public TerrainSystem(Consumer<String> progress, TerrainData.Maker tiles) {
        this.progress = progress;
        this.tiles = tiles;
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
        ground = switch (terrain.world()) {
            case TILE -> TileGround.make(context, tiles, terrain, seed, cells, UNIT_HEIGHTS, UNIT_GRADIENTS, UNIT_SNOW,
                    times, progress);
            case UNBOUNDED -> StreamedGround.make(context, terrain, seed, cells, UNIT_HEIGHTS, times, progress);
        };
        context.world().setResource(HeightField.class, ground.heights());
        tree = ground.tree();
        selection = new PatchSelection(tree, ground.residency());
        layout = ground.layout();
        shading = ground.shading();
        entity = context.world().spawn();
        // the render origin steps by a tile (a root's side): a whole number of samples of every level
        context.world().setResource(new RenderOrigin(tree.extent()));
        copyOffsets = new float[] {0, 0};
        context.world().add(entity, new Cullable(tree.bounds(), copyOffsets, ground.cullHeights()));
        depthProgram = shading.depth(context, UNIT_HEIGHTS);
        publishSnowLine(context.world(), settings);
        farField = ground.farField(context, UNIT_HEIGHTS);
    }

    /** The snow line in metres of the snow rule in use (the snow map's, or the altitude bands') over the heights. */
    private void publishSnowLine(World world, Settings settings) {
        world.setResource(SnowLines.of(layout.lowest(), layout.highest(),
                settings.get(MaterialSettings.class).snowMode(), settings.get(TerrainSettings.class)));
    }

    @Override
    public void update(World world, double step) {
        publishSnowLine(world, world.resource(Settings.class));
        world.setResource(shading.grass(world.resource(Settings.class).get(MaterialSettings.class)));
        CameraPose pose = world.resource(Camera.class).pose();
        if (!ground.follow(pose, step)) {
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
        copyRadius = ground.copyRadius();
        copyOffsets = CopyLattice.copies(cx, cz, copyRadius, extent);
        world.add(entity, new Cullable(tree.bounds(), copyOffsets, ground.cullHeights()));
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
        if (pass != Pass.SHADOW) {
            ground.prepare(patches, copyOffsets, pass); // what the shading reads
        }
        Counters counters = world.resource(Counters.class);
        counters.add(PATCHES.in(pass), patches.size());
        counters.add(CULLED.in(pass), selection.culledPatches());
        counters.add(SELECT_MS.in(pass), selectMs);
        // 2. nearest first, so near ground hides far ground before it is shaded
        order.sort(patches, tree.bounds(), ground.residency(), copyOffsets, eye);
        // 3. the maps, then the patches, front faces only: in the sun's pass with the heights alone, else with the
        // materials near and far and the view options; the copies placed from the render origin
        RenderOrigin origin = world.resource(RenderOrigin.class);
        float[] drawnOffsets = origin.relativePairs(copyOffsets);
        shading.origin(origin.x(), origin.z());
        ground.bind(UNIT_HEIGHTS, UNIT_GRADIENTS, UNIT_SNOW);
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
                    debug.colouring(), context.shares(SunShadow.class), renderer, context.stats());
            counters.add(NEAR.in(pass), near);
            if (farField != null && pass == Pass.MAIN
                    && debug.colouring() == TerrainDebugSettings.Colouring.SHADED) {
                // 4. beyond the patches, the far field to the horizon
                shading.bindFarField(settings.get(MaterialSettings.class));
                double extent = tree.extent();
                farField.draw(context.camera().positionFrom(origin.x(), origin.z()),
                        copyCentreX * extent - origin.x(), copyCentreZ * extent - origin.z(),
                        (copyRadius + 0.5) * extent, ground.heights().lowest(), ground.heights().highest(),
                        context.stats());
            }
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        }
        glDisable(GL_CULL_FACE);
        context.world().resource(Counters.class).add(TRIANGLES.in(pass), context.stats().triangles() - triangles);
    }

    private static Vector3f viewerEye(World world) {
        var pose = world.resource(Camera.class).pose();
        return new Vector3f((float) pose.x(), (float) pose.y(), (float) pose.z());
    }

    /**
     * The ground, once initialised: a {@link TileGround} or a {@link StreamedGround} (tests and tools read the
     * heights the terrain draws).
     */
    public Ground ground() {
        return ground;
    }
}
