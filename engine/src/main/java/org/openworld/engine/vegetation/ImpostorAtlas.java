package org.openworld.engine.vegetation;

import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glClearColor;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glViewport;

import org.joml.Vector3f;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Labelled;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.OffscreenState;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;

/**
 * The impostors' atlas, baked once at start from the plants' full shapes: for each {@link TreeKind}, the shape seen
 * orthographically from {@link #FRAMES} × {@link #FRAMES} directions over the upper hemisphere, laid out
 * hemi-octahedrally ({@code shaders/vegetation/octahedron.glsl}: the hemisphere folded onto an octahedron and that
 * onto a square, so the views are spread evenly in angle and neighbours in the grid are neighbours on the sphere).
 * Each frame is {@link #FRAME_PIXELS} square and its bounding sphere fills it. Two halves side by side: the albedo and
 * the coverage (foliage, bark, nothing), and the shading normal (in the plant's own space) and the depth towards the
 * viewer ({@code shaders/vegetation/bake.frag}); one row of both per kind.
 *
 * <p>Cost: {@code 3 · 2 · 81} = 486 draws of at most 268 triangles at start, and one RGBA8 colour and
 * one depth attachment of {@code 2 · 9 · 64 × 3 · 9 · 64} = 1152 × 1728 texels, 15.2 MiB together, for as long as
 * the system lives. A card blends the three frames nearest the eye's direction
 * ({@code shaders/vegetation/impostor-sample.glsl}). Limits: the patterns are made at each kind's mean height at the
 * default settings; the normals are the still plant's, so a swaying card's shading does not bend.
 */
final class ImpostorAtlas implements Labelled {

    /** Frames per side of a kind's grid: odd, so the view straight down is one; 9 views 11° apart on the horizon. */
    static final int FRAMES = 9;
    /** Texels per side of a frame: a 16 m tree at the switch distance is 55 px tall at 1080p, drawn from 64. */
    static final int FRAME_PIXELS = 64;
    /** The widest a plant is drawn, as a share of its shape's width (tree.vert's WIDTH_LOW + WIDTH_SPREAD). */
    static final double WIDEST = 1.15;

    private final Framebuffer target;
    /** Per kind: the bounding sphere's centre height and radius, units of the plant's height. */
    private final float[][] spheres = new float[TreePlacement.KINDS][];
    /** Per kind: the mean albedo over the covered texels of every frame, linear, and the top view's covered area. */
    private final Vector3f[] meanAlbedo = new Vector3f[TreePlacement.KINDS];
    private final double[] topArea = new double[TreePlacement.KINDS];

    /**
     * Bakes the atlas, the plants wearing the synthesised {@code maps} as the meshes do; the bake's program and
     * meshes are freed before it returns.
     */
    ImpostorAtlas(EngineContext context, PlantMaps maps) {
        int side = FRAMES * FRAME_PIXELS;
        target = new Framebuffer(context.gl(), 2 * side, TreePlacement.KINDS * side, Format.RGBA8,
                Format.DEPTH24_STENCIL8, Sampling.NEAREST_CLAMP);
        try (ShaderProgram bake = context.shaders().program("vegetation/bake.vert", "vegetation/bake.frag");
             OffscreenState state = OffscreenState.enter()) {
            target.bind();
            glClearColor(0, 0, 0, 0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glEnable(GL_DEPTH_TEST);
            bake.use();
            PlantMaps.samplers(bake);
            maps.bind();
            bake.float1("uFrames").set(FRAMES);
            DrawStats stats = new DrawStats();
            for (TreeKind kind : TreeKind.values()) {
                TreeShape.Geometry shape = TreeShape.of(kind, false);
                float[] sphere = sphere(shape);
                spheres[kind.ordinal()] = sphere;
                VegetationSettings d = VegetationSettings.DEFAULTS;
                bake.vec2("uSphere").set(sphere[0], sphere[1]);
                bake.float1("uHeight").set((float) (kind.scale * 0.5 * (d.minHeight() + d.maxHeight())));
                bake.int1("uKind").set(kind.ordinal());
                try (Mesh mesh = new Mesh(context.gl(), shape.vertices(), shape.triangles(),
                        new Mesh.Attribute(0, 3), new Mesh.Attribute(1, 3), new Mesh.Attribute(2, 1))) {
                    for (int output = 0; output < 2; output++) {
                        bake.int1("uOutput").set(output);
                        for (int j = 0; j < FRAMES; j++) {
                            for (int i = 0; i < FRAMES; i++) {
                                glViewport(output * side + i * FRAME_PIXELS,
                                        kind.ordinal() * side + j * FRAME_PIXELS, FRAME_PIXELS, FRAME_PIXELS);
                                bake.vec2("uFrame").set(i, j);
                                mesh.draw(stats);
                            }
                        }
                    }
                }
            }
        } catch (RuntimeException e) {
            target.close();
            throw e;
        }
        measure(target.read());
    }

    /**
     * The sphere round a shape of width {@link #WIDEST}: centre halfway up its height, radius to its farthest point
     * and a texel more, so no outline touches its frame's edge.
     */
    static float[] sphere(TreeShape.Geometry shape) {
        float[] v = shape.vertices();
        double low = Double.MAX_VALUE;
        double high = -Double.MAX_VALUE;
        for (int o = 0; o < v.length; o += TreeShape.FLOATS) {
            low = Math.min(low, v[o + 1]);
            high = Math.max(high, v[o + 1]);
        }
        double centre = 0.5 * (low + high);
        double radius = 0;
        for (int o = 0; o < v.length; o += TreeShape.FLOATS) {
            radius = Math.max(radius, Math.hypot(WIDEST * Math.hypot(v[o], v[o + 2]), v[o + 1] - centre));
        }
        return new float[] {(float) centre, (float) (radius * (1 + 2.0 / FRAME_PIXELS))};
    }

    /** The mean albedo of each kind's frames and its covered area seen from straight above. */
    private void measure(Image atlas) {
        int side = FRAMES * FRAME_PIXELS;
        for (int k = 0; k < TreePlacement.KINDS; k++) {
            Vector3f sum = new Vector3f();
            int covered = 0;
            int top = 0;
            int topFrame = FRAMES / 2;
            for (int y = 0; y < side; y++) {
                for (int x = 0; x < side; x++) {
                    // the image's top row first: the atlas's row k starts k sides up from its bottom
                    int row = atlas.height() - 1 - (k * side + y);
                    if (atlas.channel(x, row, 3) < 64) { // under the coverage codes' threshold, 0.25 of 255
                        continue;
                    }
                    covered++;
                    for (int c = 0; c < 3; c++) {
                        double stored = atlas.channel(x, row, c) / 255.0;
                        sum.setComponent(c, sum.get(c) + (float) (stored * stored)); // stored as the square root
                    }
                    if (x / FRAME_PIXELS == topFrame && y / FRAME_PIXELS == topFrame) {
                        top++;
                    }
                }
            }
            meanAlbedo[k] = sum.div(Math.max(1, covered));
            double frameSide = 2 * spheres[k][1]; // units of the plant's height
            topArea[k] = top / (double) (FRAME_PIXELS * FRAME_PIXELS) * frameSide * frameSide;
        }
    }

    /** The atlas: albedo and coverage left, normal and depth right, one row per kind. */
    Texture2D texture() {
        return target.color();
    }

    /** The atlas read back (tests), top row first. */
    Image read() {
        return target.read();
    }

    /** The kind's bounding sphere: centre height and radius, units of the plant's height. */
    float[] sphere(TreeKind kind) {
        return spheres[kind.ordinal()];
    }

    /** The kind's mean albedo over its frames, linear RGB, at the mean tint. */
    Vector3f meanAlbedo(TreeKind kind) {
        return new Vector3f(meanAlbedo[kind.ordinal()]);
    }

    /** The ground a plant of the kind hides seen from straight above, in units of its height squared (width 1). */
    double topArea(TreeKind kind) {
        return topArea[kind.ordinal()];
    }

    @Override
    public void label(String name) {
        target.label(name);
    }

    @Override
    public void close() {
        target.close();
    }
}
