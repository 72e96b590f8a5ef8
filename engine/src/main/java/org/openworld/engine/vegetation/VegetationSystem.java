package org.openworld.engine.vegetation;

import java.nio.ByteBuffer;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.function.Supplier;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryUtil;
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
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.Workers;
import org.openworld.engine.core.World;
import org.openworld.engine.culling.Visibility;
import org.openworld.engine.environment.ForestCover;
import org.openworld.engine.environment.Moisture;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.environment.Wind;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.SharedBlock;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Trees and bushes on the ground around the viewer, drawn instanced in the picture, the sun's shadow maps and the
 * water's reflection. See the package documentation for the technique.
 *
 * <p>Frame by frame: {@link #update} has the plants within reach of the viewer placed again when the viewer has moved
 * {@link #REBUILD_SHARE} of the view distance, on a worker thread ({@link TreePlacer}, which places only the tiles
 * the move brings in), and takes the result when it is ready: it uploads the records and hands the tiles' boxes to
 * the culling system as a {@link Cullable}. Only the first placement, and one after the world or the settings
 * changed, is made at once on the render thread: there is nothing to show until then. {@link #render} reads the
 * culling's {@link Visibility} for the pass camera and has {@link TreeDraw} draw the visible tiles' plants.
 */
public final class VegetationSystem implements EngineSystem {
    /** The counters: placing's CPU time (ms, when plants were placed), the plants, those drawn per pass. */
    private static final Counter PLACE_MS = Counter.of("vegetation", "place-ms");
    private static final Counter COUNT = Counter.of("vegetation", "count");
    private static final Counter DRAWN = Counter.of("vegetation", "drawn");

    /** The share of the view distance the viewer may move before the plants are placed again. */
    static final double REBUILD_SHARE = 0.25;
    /**
     * The wind among the plants as a share of the cloud layer's: near the ground the air is slowed by it (a
     * logarithmic profile gives 30-50 % at 10 m of what blows a kilometre up).
     */
    static final float GROUND_WIND = 0.4f;

    private final ExecutorService worker = Workers.single("vegetation-placement");
    private TreeDraw draw;
    private int entity;
    private TreePlacement.Layout layout;
    private TreePlacer placer;
    /** Where the viewer was for the layout drawn now, and for the one being placed. */
    private double placedX;
    private double placedZ;
    private CompletableFuture<Placed> placing;
    private int placements;
    /** The far forests: the shared map, its window under way, where the viewer was for the one shown. */
    private ForestCover cover;
    private CompletableFuture<FarForest.Window> covering;
    private double coveredX;
    private double coveredZ;
    /** Each kind's crown from above, units of its height squared, from the impostors' bake. */
    private final double[] topArea = new double[TreePlacement.KINDS];
    /** Each kind's outline from the side over that from above ({@link FarForest#sideOverTop}). */
    private final float[] sideOverTop = new float[TreePlacement.KINDS];

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("vegetation")
                .reads(Settings.class, Camera.class, HeightField.class, WaterLevel.class, SnowLine.class,
                        Moisture.class, Wind.class, Visibility.class)
                .publishes(PlacementField.class, ForestCover.class)
                .draws(Pass.SHADOW, Pass.REFLECTION, Pass.MAIN);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(VegetationSettings.SETTINGS);
    }

    @Override
    public void init(EngineContext context) {
        draw = new TreeDraw(context);
        entity = context.world().spawn();
        Settings settings = context.settings();
        cover = context.own("forestCover", new ForestCover(Texture2D.empty(context.gl(), FarForest.SIZE,
                FarForest.SIZE, Format.RGBA8, Sampling.LINEAR_REPEAT), SharedBlock.FOREST_COVER.standIn(context.gl()),
                () -> settings.systemEnabled(spec().name())));
        context.world().setResource(cover);
        for (TreeKind kind : TreeKind.values()) {
            topArea[kind.ordinal()] = draw.atlas().topArea(kind);
            sideOverTop[kind.ordinal()] = (float) FarForest.sideOverTop(kind);
        }
    }

    @Override
    public void update(World world, double step) {
        VegetationSettings s = world.resource(Settings.class).get(VegetationSettings.class);
        CameraPose pose = world.resource(Camera.class).pose();
        TreePlacer.World now = new TreePlacer.World(world.findResource(HeightField.class).orElse(HeightField.FLAT),
                world.findResource(Moisture.class).orElse(null), s, limits(world, s),
                world.resource(Settings.class).get(EngineSettings.class).seed());
        double radius = (1 + REBUILD_SHARE) * s.viewDistance();
        if (placer == null || !placer.world().equals(now)) {
            // a new world or new settings: placed at once, whatever was under way is dropped
            if (placing != null) {
                placing.cancel(false);
                placing = null;
            }
            placer = new TreePlacer(now);
            world.setResource(placer.field());
            place(world, () -> placer.around(pose.x(), pose.z(), radius), pose, true);
            if (covering != null) {
                covering.cancel(false);
                covering = null;
            }
            takeCover(FarForest.around(now, placer.field(), topArea, pose.x(), pose.z()), s);
        } else if (placing != null && placing.isDone()) {
            take(world, placing.join());
            placing = null;
        } else if (placing == null && Math.hypot(pose.x() - placedX, pose.z() - placedZ) > REBUILD_SHARE
                * s.viewDistance()) {
            TreePlacer p = placer;
            place(world, () -> p.around(pose.x(), pose.z(), radius), pose, false);
        }
        // the forests past the plants' reach: made again on the worker once the viewer has moved an eighth of them
        if (covering != null && covering.isDone()) {
            takeCover(covering.join(), s);
            covering = null;
        } else if (covering == null && Math.hypot(pose.x() - coveredX, pose.z() - coveredZ) > FarForest.RECENTRE) {
            TreePlacer p = placer;
            coveredX = pose.x();
            coveredZ = pose.z();
            covering = CompletableFuture.supplyAsync(() -> FarForest.around(p.world(), p.field(), topArea, pose.x(),
                    pose.z()), worker);
        }
    }

    /** A window of far forests on the GPU, with the fade where the plants shrink away. */
    private void takeCover(FarForest.Window window, VegetationSettings s) {
        coveredX = window.x();
        coveredZ = window.z();
        ByteBuffer data = MemoryUtil.memAlloc(window.rgba().length).put(window.rgba()).flip();
        try {
            cover.map().upload(0, 0, FarForest.SIZE, data);
        } finally {
            MemoryUtil.memFree(data);
        }
        Vector3f[] colours = new Vector3f[TreePlacement.KINDS];
        for (TreeKind kind : TreeKind.values()) {
            colours[kind.ordinal()] = draw.atlas().meanAlbedo(kind);
        }
        cover.write(FarForest.EXTENT, FarForest.REACH, new float[] {(float) (TreeDraw.FADE_START * s.viewDistance()),
            (float) s.viewDistance()}, colours, sideOverTop);
    }

    /** A placement and the milliseconds of CPU it took (on whichever thread made it). */
    private record Placed(TreePlacement.Layout layout, double ms) {
    }

    /** Places the plants around the pose, at once or on the worker. */
    private void place(World world, Supplier<TreePlacement.Layout> job, CameraPose pose, boolean atOnce) {
        placedX = pose.x();
        placedZ = pose.z();
        placements++;
        Supplier<Placed> timed = () -> {
            long t0 = System.nanoTime();
            TreePlacement.Layout l = job.get();
            return new Placed(l, (System.nanoTime() - t0) / 1e6);
        };
        if (atOnce) {
            take(world, timed.get());
        } else {
            placing = CompletableFuture.supplyAsync(timed, worker);
        }
    }

    /** The new layout on the GPU and its boxes with the culling. */
    private void take(World world, Placed placed) {
        world.resource(Counters.class).put(PLACE_MS, placed.ms());
        layout = placed.layout();
        draw.upload(layout);
        if (layout.bounds() != null) {
            // the boxes are measured from the layout's centre: the culling's one copy stands there
            world.add(entity, new Cullable(layout.bounds(),
                    new float[] {(float) layout.centreX(), (float) layout.centreZ()}));
        } else {
            world.remove(entity, Cullable.class);
        }
    }

    /** The rules from the world: above the water (if any) by the shore margin, below the tree line the snow sets. */
    static TreePlacement.Limits limits(World world, VegetationSettings s) {
        double lowest = world.findResource(WaterLevel.class).map(w -> w.height() + s.shoreMargin())
                .orElse(Double.NEGATIVE_INFINITY);
        return new TreePlacement.Limits(lowest, world.findResource(SnowLine.class).orElse(null), s.maxGradient());
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        if (layout == null || layout.count() == 0) {
            return;
        }
        World world = context.world();
        VegetationSettings s = world.resource(Settings.class).get(VegetationSettings.class);
        // the tiles the culling left visible to this pass's camera (all of them without culling)
        Visibility visibility = world.get(entity, Visibility.class)
                .filter(v -> v.nodeCount() == layout.tiles() + 1 && v.copies() == 1).orElse(null);
        CameraPose pose = world.resource(Camera.class).pose();
        Vector3f wind = new Vector3f(world.findResource(Wind.class).orElse(Wind.CALM).velocity()).mul(GROUND_WIND);
        int drawn = draw.draw(pass, context, layout, visibility, s,
                new Vector3f((float) (pose.x() - layout.centreX()), (float) pose.y(),
                        (float) (pose.z() - layout.centreZ())), new float[] {wind.x, wind.z});
        Counters counters = world.resource(Counters.class);
        counters.put(COUNT, layout.count());
        counters.add(DRAWN.in(pass), drawn);
    }

    @Override
    public void close() {
        worker.shutdownNow();
    }

    /**
     * The plants placed now (tests and tools): {@link TreePlacement#FLOATS} floats per plant, kind by kind, feet in
     * world x, z.
     */
    float[] placed() {
        return layout == null ? new float[0] : layout.worldRecords();
    }

    /** The impostors' atlas (tests). */
    ImpostorAtlas atlas() {
        return draw.atlas();
    }

    /** The layout drawn now (tests). */
    TreePlacement.Layout layout() {
        return layout;
    }

    /** How often a placement began. */
    int placements() {
        return placements;
    }

    /** Waits for a placement under way and takes it (tests: the next frame shows it). */
    void settle(World world) {
        if (placing != null) {
            take(world, placing.join());
            placing = null;
        }
    }
}
