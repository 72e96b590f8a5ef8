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
 * The plants' GL side: the records on the GPU, the two shapes of each kind, the two programs, and the instanced
 * draws of one pass. Which representation a plant gets is decided by its distance from the viewer:
 *
 * <ul>
 *   <li>{@link Pass#MAIN}: the full shape within {@code vegetation.lod-distance}, the simplified one beyond, the two
 *       cross-faded by an ordered dither over ±{@link #BAND} of the distance (each pixel of a plant in the band
 *       is drawn by one of the two, the share of the far one rising linearly across it), so nothing pops.</li>
 *   <li>{@link Pass#SHADOW}: the same switch, hard (a dither in the shadow maps would speckle the shadows), and no
 *       bushes beyond it: their shadows there are a few pixels under their own crowns.</li>
 *   <li>{@link Pass#REFLECTION}: the simplified shapes alone: the mirror's picture is rippled and dimmed by the
 *       water.</li>
 * </ul>
 * A tile (its box) wholly on one side of the band draws only that side's shape; a tile across it draws both, and the
 * vertex shader folds away the plants that are wholly on the other side.
 */
final class TreeDraw {

    /** The cross-fade's half width, a share of the switch distance: 15 m either side of the default 150 m. */
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

    private final ShaderProgram program;
    private final ShaderProgram depthProgram;
    private final Uniforms lit;
    private final Uniforms depth;
    /** [kind][0 full, 1 simplified]. */
    private final Mesh[][] shapes = new Mesh[TreePlacement.KINDS][2];
    private final GpuBuffer records;

    /** The lit program's kind: its colours (the depth-only program has none). */
    private final Uniform.Int kind;

    /** The uniforms both programs have. */
    private record Uniforms(Uniform.Vec2 fade, Uniform.Vec3 lod, Uniform.Vec2 wind, Uniform.Vec2 placed,
                            Uniform.Vec3 sway) {

        static Uniforms of(ShaderProgram p) {
            return new Uniforms(p.vec2("uFade"), p.vec3("uLod"), p.vec2("uWind"), p.vec2("uPlaced"),
                    p.vec3("uSway"));
        }
    }

    TreeDraw(EngineContext context) {
        program = context.own("program", context.shaders().program("vegetation/tree.vert", "vegetation/tree.frag"));
        depthProgram = context.own("depth", context.shaders().program("vegetation/tree.vert",
                "vegetation/depth.frag"));
        lit = Uniforms.of(program);
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
     * @return the plants drawn, both shapes of a plant in the cross-fade counted
     */
    int draw(Pass pass, RenderContext context, TreePlacement.Layout layout, Visibility visibility,
             VegetationSettings s, Vector3fc viewer, float[] groundWind) {
        // 1. the program: depth alone for the sun's maps, lit otherwise; both measure the fade and the switch from
        //    the VIEWER (viewerPos), so a plant leaves the shadow maps and the reflection where it leaves the picture
        Uniforms u = pass == Pass.SHADOW ? depth : lit;
        (pass == Pass.SHADOW ? depthProgram : program).use();
        float end = (float) s.viewDistance();
        u.fade().set(FADE_START * end, end);
        u.wind().set(groundWind[0], groundWind[1]);
        // the feet are measured from the layout's centre: placed from the render origin in double, as is the swing's
        // phase there (reduced modulo a turn), so the GPU adds small numbers to small numbers 10 000 km out
        RenderOrigin origin = context.world().resource(RenderOrigin.class);
        u.placed().set(origin.relativeX(layout.centreX()), origin.relativeZ(layout.centreZ()));
        u.sway().set((float) SWAY_WAVE_X, (float) SWAY_WAVE_Z, (float) RenderOrigin.reduce(
                SWAY_WAVE_X * layout.centreX() + SWAY_WAVE_Z * layout.centreZ(), 2 * Math.PI));
        float lod = (float) s.lodDistance();
        float band = pass == Pass.MAIN ? BAND * lod : 0;
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
        glEnable(GL_CULL_FACE);
        Containment root = visibility == null ? Containment.INSIDE : visibility.root(0);
        float[] boxes = layout.bounds().boxes();
        int drawn = 0;
        for (TreeKind kind : TreeKind.values()) {
            if (pass != Pass.SHADOW) {
                this.kind.set(kind.ordinal());
            }
            for (int far = 0; far < 2; far++) {
                boolean near = far == 0;
                if (pass == Pass.REFLECTION && near || pass == Pass.SHADOW && !near && kind == TreeKind.BUSH) {
                    continue;
                }
                // the reflection's far shapes reach to the viewer: the switch at 0
                float from = pass == Pass.REFLECTION ? 0 : lod - band;
                float to = pass == Pass.REFLECTION ? 0 : lod + band;
                u.lod().set(from, to, far);
                drawn += drawRuns(context, layout, kind.ordinal(), shapes[kind.ordinal()][far], visibility, root,
                        boxes, viewer, near ? 0 : from, near ? to : Float.POSITIVE_INFINITY);
            }
        }
        glDisable(GL_CULL_FACE);
        return drawn;
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
