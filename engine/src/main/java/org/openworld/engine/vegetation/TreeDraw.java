package org.openworld.engine.vegetation;

import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_DRAW;

import java.nio.FloatBuffer;
import org.joml.Vector3fc;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.culling.Visibility;
import org.openworld.engine.culling.Visibility.Containment;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.origin.RenderOrigin;

/**
 * The plants' GL side: the records on the GPU, the two shapes of each kind, the two programs, the impostors
 * ({@link ImpostorDraw}) and the instanced draws of one pass. Which representation a plant gets is decided by its
 * distance from the viewer:
 *
 * <ul>
 *   <li>{@link Pass#MAIN}: the full shape within {@code vegetation.lod-distance}, the simplified one up to
 *       {@code vegetation.impostor-distance}, the impostor beyond; each switch cross-faded by an ordered dither over
 *       ±{@link #BAND} of its distance (each pixel of a plant in the band is drawn by one of the two, the share of
 *       the farther one rising linearly across it), so nothing pops.</li>
 *   <li>{@link Pass#SHADOW}: the same switches, hard (a dither in the shadow maps would speckle the shadows), so the
 *       far cascades, which hold the far plants, draw cards; and no bushes beyond the first switch: their shadows
 *       there are a few pixels under their own crowns.</li>
 *   <li>{@link Pass#REFLECTION}: the impostors alone: the mirror's picture is rippled and dimmed by the water.</li>
 * </ul>
 * A tile (its box) wholly on one side of a band draws only that side's representation; a tile across it draws both,
 * and the vertex shaders fold away the plants that are wholly on the other side.
 */
final class TreeDraw {

    /** A cross-fade's half width, a share of its switch distance: 15 m either side of the default 150 m. */
    static final float BAND = 0.1f;
    /** Where the plants start to shrink away, as a share of the view distance. */
    static final float FADE_START = 0.8f;
    /**
     * Radians per metre east and south of a crown's swing phase: neighbours a few metres apart swing out of step, a
     * gust's crest rolls across the stand (a wave 10 m long).
     */
    static final double SWAY_WAVE_X = 0.37;
    static final double SWAY_WAVE_Z = 0.51;
    /** Vertex attribute locations: the shape's (position, normal, part), then each plant's record. */
    private static final int POSITION = 0;
    private static final int NORMAL = 1;
    private static final int PART = 2;
    private static final int FOOT_HEIGHT = 3;
    private static final int TURN_TINT = 4;
    /** The barks' seed: every world's trees wear the same bark. */
    private static final long BARK_SEED = 1;

    private final ShaderProgram program;
    private final ShaderProgram depthProgram;
    private final Uniforms lit;
    private final Uniforms depth;
    /** [kind][0 full, 1 simplified]. */
    private final Mesh[][] shapes = new Mesh[TreePlacement.KINDS][2];
    private final GpuBuffer records;
    private final ImpostorDraw impostors;
    private final PlantMaps maps;

    /** The lit program's kind: its colours (the depth-only program has none). */
    private final Uniform.Int kind;

    /** The uniforms both programs have. */
    private record Uniforms(Uniform.Vec2 fade, Uniform.Vec3 lod, Uniform.Vec2 impostor, Uniform.Vec2 wind,
                            Uniform.Vec2 placed, Uniform.Vec3 sway) {

        static Uniforms of(ShaderProgram p) {
            return new Uniforms(p.vec2("uFade"), p.vec3("uLod"), p.vec2("uImpostor"), p.vec2("uWind"),
                    p.vec2("uPlaced"), p.vec3("uSway"));
        }
    }

    TreeDraw(EngineContext context) {
        program = context.own("program", context.shaders().program("vegetation/tree.vert", "vegetation/tree.frag"));
        depthProgram = context.own("depth", context.shaders().program("vegetation/tree.vert",
                "vegetation/depth.frag"));
        lit = Uniforms.of(program);
        maps = new PlantMaps(context, BarkTextures.generate(BARK_SEED));
        PlantMaps.samplers(program);
        kind = program.int1("uKind");
        depth = Uniforms.of(depthProgram);
        records = context.own("records", new GpuBuffer(context.gl(), GL_ARRAY_BUFFER));
        for (TreeKind kind : TreeKind.values()) {
            for (int far = 0; far < 2; far++) {
                TreeShape.Geometry shape = TreeShape.of(kind, far == 1);
                Mesh mesh = context.own(kind.name().toLowerCase() + (far == 1 ? "-far" : "-near"),
                        new Mesh(context.gl(), shape.vertices(), shape.triangles(), new Mesh.Attribute(POSITION, 3),
                                new Mesh.Attribute(NORMAL, 3), new Mesh.Attribute(PART, 1)));
                mesh.instances(records, TreePlacement.FLOATS, new Mesh.Attribute(FOOT_HEIGHT, 4),
                        new Mesh.Attribute(TURN_TINT, 2));
                shapes[kind.ordinal()][far] = mesh;
            }
        }
        impostors = new ImpostorDraw(context, records, FOOT_HEIGHT, TURN_TINT, maps);
    }

    ImpostorAtlas atlas() {
        return impostors.atlas();
    }

    void upload(TreePlacement.Layout layout) {
        FloatBuffer data = MemoryUtil.memAllocFloat(layout.records().length).put(layout.records()).flip();
        try {
            records.upload(data, GL_DYNAMIC_DRAW);
        } finally {
            MemoryUtil.memFree(data);
        }
    }

    /**
     * Draws the layout's plants that the pass camera sees (all of them where {@code visibility} is null).
     *
     * @param viewer     the viewer's eye from the layout's centre, metres
     * @param groundWind m/s of the wind among the plants, x (east) and z (south)
     * @return the plants drawn, every representation of a plant in a cross-fade counted
     */
    int draw(Pass pass, RenderContext context, TreePlacement.Layout layout, Visibility visibility,
             VegetationSettings s, Vector3fc viewer, float[] groundWind) {
        // 1. the bands: MAIN cross-fades full to simplified at the LOD distance and simplified to impostors at theirs;
        //    the shadow maps switch hard at both; the reflection draws the impostors alone, from the viewer on
        Bands b = Bands.of(pass, s);
        float end = (float) s.viewDistance();
        float[] fade = {FADE_START * end, end};
        // the feet are measured from the layout's centre: placed from the render origin in double, as is the swing's
        // phase there (reduced modulo a turn), so the GPU adds small numbers to small numbers 10 000 km out
        RenderOrigin origin = context.world().resource(RenderOrigin.class);
        float[] placed = {origin.relativeX(layout.centreX()), origin.relativeZ(layout.centreZ())};
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
        Containment root = visibility == null ? Containment.INSIDE : visibility.root(0);
        float[] boxes = layout.bounds().boxes();
        int drawn = 0;
        float[] sway = {(float) SWAY_WAVE_X, (float) SWAY_WAVE_Z, (float) RenderOrigin.reduce(
                SWAY_WAVE_X * layout.centreX() + SWAY_WAVE_Z * layout.centreZ(), 2 * Math.PI)};
        // 2. the meshes: depth alone for the sun's maps, lit otherwise; every distance is measured from the VIEWER
        //    (viewerPos), so a plant leaves the shadow maps and the reflection where it leaves the picture
        if (pass != Pass.REFLECTION) {
            Uniforms u = pass == Pass.SHADOW ? depth : lit;
            (pass == Pass.SHADOW ? depthProgram : program).use();
            u.fade().set(fade[0], fade[1]);
            u.wind().set(groundWind[0], groundWind[1]);
            u.placed().set(placed[0], placed[1]);
            u.sway().set(sway[0], sway[1], sway[2]);
            maps.bind(); // the bark's units, which the impostors' atlas took since the last pass
            u.impostor().set(b.impostorFrom(), b.impostorTo());
            glEnable(GL_CULL_FACE);
            for (TreeKind kind : TreeKind.values()) {
                if (pass != Pass.SHADOW) {
                    this.kind.set(kind.ordinal());
                }
                u.lod().set(b.lodFrom(), b.lodTo(), 0);
                drawn += drawRuns(context, layout, kind.ordinal(), shapes[kind.ordinal()][0], visibility, root,
                        boxes, viewer, 0, b.lodTo());
                // the far bushes' shadows are a few pixels under their own crowns: left out
                if (pass != Pass.SHADOW || kind != TreeKind.BUSH) {
                    u.lod().set(b.lodFrom(), b.lodTo(), 1);
                    drawn += drawRuns(context, layout, kind.ordinal(), shapes[kind.ordinal()][1], visibility, root,
                            boxes, viewer, b.lodFrom(), b.impostorTo());
                }
            }
            glDisable(GL_CULL_FACE);
        }
        // 3. the impostors: cards, seen from either side, swaying as the meshes do
        impostors.begin(pass, fade, new float[] {b.impostorFrom(), b.impostorTo()}, placed, groundWind, sway);
        for (TreeKind kind : TreeKind.values()) {
            if (pass != Pass.SHADOW || kind != TreeKind.BUSH) {
                drawn += drawRuns(context, layout, kind.ordinal(), impostors.card(pass, kind), visibility, root,
                        boxes, viewer, b.impostorFrom(), Float.POSITIVE_INFINITY);
            }
        }
        return drawn;
    }

    /**
     * Metres from the viewer where the full shapes give way to the simplified ones (from, to) and those to the
     * impostors: cross-fades over ±{@link #BAND} of each distance in the picture, hard switches in the shadow maps,
     * and the impostors from the viewer on in the reflection (the mirror's picture is rippled and dimmed).
     */
    record Bands(float lodFrom, float lodTo, float impostorFrom, float impostorTo) {

        static Bands of(Pass pass, VegetationSettings s) {
            float lod = (float) s.lodDistance();
            float impostor = (float) s.impostorFrom();
            return switch (pass) {
                case MAIN -> new Bands((1 - BAND) * lod, (1 + BAND) * lod, (1 - BAND) * impostor,
                        (1 + BAND) * impostor);
                case REFLECTION -> new Bands(0, 0, 0, 0);
                default -> new Bands(lod, lod, impostor, impostor);
            };
        }
    }

    /**
     * The visible tiles whose boxes reach into [nearest, farthest] metres from the viewer (horizontally), one
     * instanced call per run of neighbouring such tiles: a kind's plants follow one another tile by tile.
     */
    private static int drawRuns(RenderContext context, TreePlacement.Layout layout, int kind, Mesh mesh,
                                Visibility visibility, Containment root, float[] boxes, Vector3fc viewer,
                                float nearest, float farthest) {
        int drawn = 0;
        int runFirst = 0;
        int runCount = 0;
        for (int t = 0; t < layout.tiles(); t++) {
            int b = 6 * (t + 1);
            double dx0 = Math.max(0, Math.max(boxes[b] - viewer.x(), viewer.x() - boxes[b + 3]));
            double dz0 = Math.max(0, Math.max(boxes[b + 2] - viewer.z(), viewer.z() - boxes[b + 5]));
            double dx1 = Math.max(Math.abs(boxes[b] - viewer.x()), Math.abs(boxes[b + 3] - viewer.x()));
            double dz1 = Math.max(Math.abs(boxes[b + 2] - viewer.z()), Math.abs(boxes[b + 5] - viewer.z()));
            boolean inReach = Math.hypot(dx0, dz0) <= farthest && Math.hypot(dx1, dz1) >= nearest;
            boolean seen = visibility == null || visibility.of(0, t + 1, root) != Containment.OUTSIDE;
            int count = layout.tileCount()[kind][t];
            if (inReach && seen) {
                if (runCount == 0) {
                    runFirst = layout.tileFirst()[kind][t];
                }
                runCount += count;
                continue;
            }
            mesh.drawInstances(runFirst, runCount, context.stats());
            drawn += runCount;
            runCount = 0;
        }
        mesh.drawInstances(runFirst, runCount, context.stats());
        return drawn + runCount;
    }
}
