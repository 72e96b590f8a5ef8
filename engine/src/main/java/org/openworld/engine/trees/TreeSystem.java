package org.openworld.engine.trees;

import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_DRAW;

import java.nio.FloatBuffer;
import java.util.List;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.culling.Visibility;
import org.openworld.engine.culling.Visibility.Containment;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Conifers on the ground around the viewer, drawn instanced in the picture, the sun's shadow maps and the water's
 * reflection. See the package documentation for the technique.
 *
 * <p>Frame by frame: {@link #update} places the trees within reach of the viewer again when the viewer has moved
 * {@link #REBUILD_SHARE} of the view distance, or what decides them changed ({@link TreePlacement}); it uploads their
 * records and hands the tiles' boxes to the culling system as a {@link Cullable}. {@link #render} reads the culling's
 * {@link Visibility} for the pass camera and draws the visible tiles' trees, one instanced call per run of
 * neighbouring tiles: with the lit program in {@link Pass#MAIN} and {@link Pass#REFLECTION} (the engine gives the
 * mirrored camera, its clip plane and its flipped winding), with the depth-only program in each of the sun's
 * cascades ({@link Pass#SHADOW}).
 */
public final class TreeSystem implements EngineSystem {
    /** The counters: placing's CPU time (ms, when the trees were placed again), the trees, those drawn per pass. */
    private static final Counter PLACE_MS = Counter.of("trees", "place-ms");
    private static final Counter COUNT = Counter.of("trees", "count");
    private static final Counter DRAWN = Counter.of("trees", "drawn");

    /** The share of the view distance the viewer may move before the trees are placed again. */
    static final double REBUILD_SHARE = 0.25;
    /** Where the trees start to shrink away, as a share of the view distance. */
    static final float FADE_START = 0.8f;
    /** Vertex attribute locations: the shape's (position, normal, part), then each tree's record. */
    private static final int POSITION = 0;
    private static final int NORMAL = 1;
    private static final int PART = 2;
    private static final int FOOT_HEIGHT = 3;
    private static final int TURN_TINT = 4;

    private ShaderProgram program;
    private ShaderProgram depthProgram;
    private Uniform.Vec2 fade;
    private Uniform.Vec2 depthFade;
    private Mesh tree;
    private GpuBuffer records;
    private int entity;
    private TreePlacement.Layout layout;
    /** What the layout was placed from; a new one places the trees again. */
    private Inputs placedFrom;
    private int placements;

    /** Everything the placement depends on but the viewer's small moves. */
    private record Inputs(HeightField field, TreeSettings settings, TreePlacement.Limits limits, int seed,
                          double x, double z) {

        boolean serves(Inputs now, double reach) {
            return field == now.field && settings.equals(now.settings) && limits.equals(now.limits)
                    && seed == now.seed && Math.hypot(x - now.x, z - now.z) <= reach;
        }
    }

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("trees")
                .reads(Settings.class, Camera.class, HeightField.class, WaterLevel.class, SnowLine.class,
                        Visibility.class)
                .draws(Pass.SHADOW, Pass.REFLECTION, Pass.MAIN)
                .offByDefault(); // today's pictures and benchmarks unchanged: --set system.trees=on
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(TreeSettings.SETTINGS);
    }

    @Override
    public void init(EngineContext context) {
        program = context.own("program", context.shaders().program("trees/tree.vert", "trees/tree.frag"));
        fade = program.vec2("uFade");
        depthProgram = context.own("depth", context.shaders().program("trees/tree.vert", "trees/depth.frag"));
        depthFade = depthProgram.vec2("uFade");
        TreeShape.Geometry shape = TreeShape.coneStack();
        tree = context.own("tree", new Mesh(context.gl(), shape.vertices(), shape.triangles(),
                new Mesh.Attribute(POSITION, 3), new Mesh.Attribute(NORMAL, 3), new Mesh.Attribute(PART, 1)));
        records = context.own("records", new GpuBuffer(context.gl(), GL_ARRAY_BUFFER));
        tree.instances(records, TreePlacement.FLOATS, new Mesh.Attribute(FOOT_HEIGHT, 4),
                new Mesh.Attribute(TURN_TINT, 2));
        entity = context.world().spawn();
    }

    @Override
    public void update(World world, double step) {
        TreeSettings s = world.resource(Settings.class).get(TreeSettings.class);
        CameraPose pose = world.resource(Camera.class).pose();
        Inputs now = new Inputs(world.findResource(HeightField.class).orElse(HeightField.FLAT), s, limits(world, s),
                world.resource(Settings.class).get(EngineSettings.class).seed(), pose.x(), pose.z());
        if (placedFrom != null && placedFrom.serves(now, REBUILD_SHARE * s.viewDistance())) {
            return;
        }
        // the disc reaches past the view distance by the move allowed before the next placement
        long t0 = System.nanoTime();
        layout = TreePlacement.around(now.field(), now.x(), now.z(), (1 + REBUILD_SHARE) * s.viewDistance(), s,
                now.limits(), now.seed());
        world.resource(Counters.class).put(PLACE_MS, (System.nanoTime() - t0) / 1e6);
        placedFrom = now;
        placements++;
        FloatBuffer data = MemoryUtil.memAllocFloat(layout.records().length).put(layout.records()).flip();
        try {
            records.upload(data, GL_DYNAMIC_DRAW);
        } finally {
            MemoryUtil.memFree(data);
        }
        if (layout.bounds() != null) {
            world.add(entity, new Cullable(layout.bounds(), new float[] {0, 0}));
        } else {
            world.remove(entity, Cullable.class);
        }
    }

    /** The rules from the world: above the water (if any) by the shore margin, below the snow (if any). */
    static TreePlacement.Limits limits(World world, TreeSettings s) {
        double lowest = world.findResource(WaterLevel.class).map(w -> w.height() + s.shoreMargin())
                .orElse(Double.NEGATIVE_INFINITY);
        double highest = world.findResource(SnowLine.class).map(SnowLine::start).orElse(Double.POSITIVE_INFINITY);
        return new TreePlacement.Limits(lowest, highest, s.maxGradient());
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        if (layout == null || layout.count() == 0) {
            return;
        }
        World world = context.world();
        TreeSettings s = world.resource(Settings.class).get(TreeSettings.class);
        // 1. the program: depth alone for the sun's maps, lit otherwise; both shrink the trees by the VIEWER's
        //    distance (viewerPos), so a tree leaves the shadow maps and the reflection where it leaves the picture
        float end = (float) s.viewDistance();
        if (pass == Pass.SHADOW) {
            depthProgram.use();
            depthFade.set(FADE_START * end, end);
        } else {
            program.use();
            fade.set(FADE_START * end, end);
        }
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
        glEnable(GL_CULL_FACE);
        // 2. the tiles the culling left visible to this pass's camera (all of them without culling); the tiles'
        //    trees follow one another in the records, so neighbouring visible tiles are drawn as one run
        Visibility visibility = world.get(entity, Visibility.class)
                .filter(v -> v.nodeCount() == layout.tiles() + 1 && v.copies() == 1).orElse(null);
        Containment root = visibility == null ? Containment.INSIDE : visibility.root(0);
        int drawn = 0;
        int runFirst = 0;
        int runCount = 0;
        for (int t = 0; t < layout.tiles(); t++) {
            if (visibility == null || visibility.of(0, t + 1, root) != Containment.OUTSIDE) {
                runCount += layout.tileCount()[t];
                continue;
            }
            tree.drawInstances(runFirst, runCount, context.stats());
            drawn += runCount;
            runFirst = layout.tileFirst()[t] + layout.tileCount()[t];
            runCount = 0;
        }
        tree.drawInstances(runFirst, runCount, context.stats());
        drawn += runCount;
        glDisable(GL_CULL_FACE);
        Counters counters = world.resource(Counters.class);
        counters.put(COUNT, layout.count());
        counters.add(DRAWN.in(pass), drawn);
    }

    /** The trees placed now (tests and tools): {@link TreePlacement#FLOATS} floats per tree. */
    float[] placed() {
        return layout == null ? new float[0] : layout.records();
    }

    /** How often the trees were placed. */
    int placements() {
        return placements;
    }
}
