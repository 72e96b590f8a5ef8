package org.openworld.engine.vegetation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.joml.Vector3f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.Engine;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.GlTest;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.environment.Wind;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;

/**
 * The impostors on real GL, over {@link TreeRenderTest}'s shore world: the atlas baked at start holds every kind from
 * every direction, a card draws the outline its mesh draws, and at the switch distance the simplified shapes and the
 * impostors look alike.
 */
@GlTest
class ImpostorTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @TempDir
    static Path dir;

    @BeforeAll
    static void writeWorld() throws IOException {
        TreeRenderTest.shore = TreeRenderTest.writeShore(dir);
    }

    /** A pixel is a plant's where it is noticeably unlike the bare ground: a ΔE00 over the just noticeable 2.3. */
    static final double NOTICED = 2.3;

    /** Where the ground is drawn without (bare) and with plants, and which pixels the plants took. */
    static boolean[] plantPixels(Image bare, Image plants) {
        ImageComparison c = ImageComparison.of(plants, bare);
        boolean[] mask = new boolean[bare.width() * bare.height()];
        for (int y = 0; y < bare.height(); y++) {
            for (int x = 0; x < bare.width(); x++) {
                mask[y * bare.width() + x] = c.deltaE(x, y) > NOTICED;
            }
        }
        return mask;
    }

    static Image draw(Engine engine, double lod, double impostor) {
        engine.settings().set("vegetation.lod-distance", String.valueOf(lod));
        engine.settings().set("vegetation.impostor-distance", String.valueOf(impostor));
        return TreeRenderTest.frame(engine, "vegetation", true);
    }

    @Test
    void theAtlasHoldsEveryKindFromEveryDirection() {
        VegetationSystem plants = new VegetationSystem();
        try (Engine engine = TreeRenderTest.engine(GL.context(), plants, new CameraPose(-60, 40, 0, 270, -12, 60),
                List.of())) {
            engine.update();
            Image atlas = plants.atlas().read();
            int side = ImpostorAtlas.FRAMES * ImpostorAtlas.FRAME_PIXELS;
            assertEquals(2 * side, atlas.width());
            assertEquals(TreePlacement.KINDS * side, atlas.height());
            for (TreeKind kind : TreeKind.values()) {
                float[] sphere = plants.atlas().sphere(kind);
                for (int j = 0; j < ImpostorAtlas.FRAMES; j++) {
                    for (int i = 0; i < ImpostorAtlas.FRAMES; i++) {
                        int covered = 0;
                        int touchesEdge = 0;
                        for (int y = 0; y < ImpostorAtlas.FRAME_PIXELS; y++) {
                            for (int x = 0; x < ImpostorAtlas.FRAME_PIXELS; x++) {
                                int px = i * ImpostorAtlas.FRAME_PIXELS + x;
                                int py = atlas.height() - 1 - (kind.ordinal() * side
                                        + j * ImpostorAtlas.FRAME_PIXELS + y);
                                if (atlas.channel(px, py, 3) >= 64) {
                                    covered++;
                                    boolean edge = x == 0 || y == 0 || x == ImpostorAtlas.FRAME_PIXELS - 1
                                            || y == ImpostorAtlas.FRAME_PIXELS - 1;
                                    touchesEdge += edge ? 1 : 0;
                                }
                            }
                        }
                        // the shape seen from anywhere covers at least a tenth of its sphere's square: a plant is as
                        // tall as the sphere is wide less its reach, and at least 0.3 of its height across; and the
                        // sphere holds it all, so nothing is cut at the frame's edge
                        double share = covered / (double) (ImpostorAtlas.FRAME_PIXELS * ImpostorAtlas.FRAME_PIXELS);
                        assertTrue(share > 0.1, kind + " frame (" + i + ", " + j + ") covers " + share
                                + " of its square (sphere " + sphere[1] + " heights)");
                        assertEquals(0, touchesEdge, kind + " frame (" + i + ", " + j + ") is cut at its edge");
                    }
                }
            }
        }
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }

    /**
     * Close up, every plant drawn as its full mesh and then as its impostor: the outlines agree to within one pixel
     * along the mesh's outline. The impostor blends the three nearest of views about 11° apart (each up to 11° off the
     * eye's direction) and its texels are finer than the picture's pixels here, so its outline may be off by a pixel at
     * the edge, no more; a wrong frame, a card turned or placed wrong, or an outline cut off differs by whole crowns.
     */
    @Test
    void anImpostorDrawsTheOutlineOfItsMesh() {
        VegetationSystem plants = new VegetationSystem();
        // 40 m up over the land, looking west and a little down: plants 20 to 140 m away, 12 m tall, 15 to 100 px
        try (Engine engine = TreeRenderTest.engine(GL.context(), plants, new CameraPose(-60, 40, 0, 270, -12, 60),
                List.of())) {
            Image bare = TreeRenderTest.frame(engine, "vegetation", false);
            boolean[] mesh = plantPixels(bare, draw(engine, 5000, 5000));
            boolean[] card = plantPixels(bare, draw(engine, 10, 10));
            int w = bare.width();
            int meshPixels = 0;
            int outline = 0;
            int disagree = 0;
            for (int i = 0; i < mesh.length; i++) {
                meshPixels += mesh[i] ? 1 : 0;
                int x = i % w;
                int y = i / w;
                boolean edge = mesh[i] && (x == 0 || y == 0 || x == w - 1 || i + w >= mesh.length || !mesh[i - 1]
                        || !mesh[i + 1] || !mesh[i - w] || !mesh[i + w]);
                outline += edge ? 1 : 0;
                disagree += mesh[i] != card[i] ? 1 : 0;
            }
            assertTrue(meshPixels > 2000, "plant pixels: " + meshPixels);
            assertTrue(disagree <= outline, "pixels where the mesh and the impostor disagree: " + disagree
                    + ", the meshes' outline: " + outline + " of " + meshPixels);
        }
    }

    /** The default switch distance to the impostors, metres: the camera stands this far from the nearest plant. */
    static final double SWITCH = VegetationSettings.DEFAULTS.impostorDistance();
    /** The ordered dither's cell, pixels: the cross-fade interleaves the two representations within each such block. */
    static final int DITHER = 4;

    /** The picture's means over blocks of n × n pixels (of the stored values, alpha opaque). */
    static Image blocks(Image image, int n) {
        int w = image.width() / n;
        int h = image.height() / n;
        byte[] rgba = new byte[w * h * 4];
        for (int by = 0; by < h; by++) {
            for (int bx = 0; bx < w; bx++) {
                for (int c = 0; c < 3; c++) {
                    int sum = 0;
                    for (int y = 0; y < n; y++) {
                        for (int x = 0; x < n; x++) {
                            sum += image.channel(bx * n + x, by * n + y, c);
                        }
                    }
                    rgba[(by * w + bx) * 4 + c] = (byte) Math.round(sum / (float) (n * n));
                }
                rgba[(by * w + bx) * 4 + 3] = (byte) 255;
            }
        }
        return new Image(w, h, rgba);
    }

    /**
     * The simplified shapes and the impostors seen at the distance where one gives way to the other, as
     * {@link TreeRenderTest#theFullAndTheSimplifiedShapesLookAlikeAtTheSwitchDistance} sees the first switch: from
     * above the lake 400 m east of the shore, through a 20° lens so that a 12 m plant there is 15 pixels tall, every
     * plant simplified and then every plant an impostor, compared where either picture has a plant, with the same
     * bound ({@link TreeRenderTest#MEAN_BOUND}: twice the just noticeable difference, as the dithered cross-fade never
     * shows both representations of a plant side by side). Compared over the dither's 4 × 4 blocks: at this distance
     * a leaf clump is smaller than a pixel, so each representation's pixels are a different sample of the same
     * pattern, and across the switch the dither interleaves the two within each block; what changes for the eye is
     * the block's mean.
     */
    @Test
    void theSimplifiedShapesAndTheImpostorsLookAlikeAtTheSwitchDistance() {
        VegetationSystem plants = new VegetationSystem();
        List<String> more = List.of("vegetation.density=150", "vegetation.view-distance=1000");
        try (Engine engine = TreeRenderTest.engine(GL.context(), plants, new CameraPose(SWITCH, 12, 0, 270, -1, 20),
                more, new SkySystem())) {
            // in a gale: the simplified shapes and the cards sway alike
            engine.world().setResource(GALE);
            Image bare = blocks(TreeRenderTest.frame(engine, "vegetation", false), DITHER);
            Image simple = blocks(draw(engine, 10, 5000), DITHER);
            Image cards = blocks(draw(engine, 10, 10), DITHER);
            ImageComparison between = ImageComparison.of(simple, cards);
            boolean[] simpleMask = plantPixels(bare, simple);
            boolean[] cardMask = plantPixels(bare, cards);
            double sum = 0;
            int pixels = 0;
            for (int i = 0; i < simpleMask.length; i++) {
                if (simpleMask[i] || cardMask[i]) {
                    sum += between.deltaE(i % bare.width(), i / bare.width());
                    pixels++;
                }
            }
            assertTrue(pixels > 100, "blocks with plants: " + pixels);
            double mean = sum / pixels;
            assertTrue(mean < TreeRenderTest.MEAN_BOUND, "mean ΔE00 between the simplified shapes and the impostors at "
                    + SWITCH + " m, over " + pixels + " blocks of plants: " + mean);
        }
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }

    /**
     * The plant the orbit looks at: of the trees (not bushes) within 15 m of the shore, the one farthest from any other
     * plant, as {x, y, z, height}. Seen from the land towards the lake, nothing stands behind it.
     */
    static float[] aShoreTree(VegetationSystem plants) {
        float[] placed = plants.placed();
        float[] best = null;
        double bestGap = 0;
        for (int i = 0; i < placed.length; i += TreePlacement.FLOATS) {
            if (placed[i] < -15 || Math.abs(placed[i + 2]) > 80
                    || TreePlacementTest.kindOf(plants.layout(), i / TreePlacement.FLOATS) == TreeKind.BUSH) {
                continue;
            }
            double gap = Double.POSITIVE_INFINITY;
            for (int j = 0; j < placed.length; j += TreePlacement.FLOATS) {
                if (j != i) {
                    gap = Math.min(gap, Math.hypot(placed[j] - placed[i], placed[j + 2] - placed[i + 2]));
                }
            }
            if (gap > bestGap) {
                bestGap = gap;
                best = Arrays.copyOfRange(placed, i, i + 4);
            }
        }
        assertTrue(best != null && bestGap > 10, "no lone tree by the shore: " + bestGap + " m to the nearest");
        return best;
    }

    /** The camera {@code range} m from the tree's middle, {@code bearing}° round it, 20° above it, looking at it. */
    static CameraPose orbit(float[] tree, double range, double bearing, double fov) {
        double elevation = Math.toRadians(20);
        double yaw = Math.toRadians(bearing);
        double across = range * Math.cos(elevation);
        return new CameraPose(tree[0] - across * Math.sin(yaw), tree[1] + 0.5 * tree[3]
                + range * Math.sin(elevation), tree[2] + across * Math.cos(yaw), bearing, -20, fov);
    }

    /** Metres from the eye to the tree's middle, and the lens, degrees: the 12 m tree is 110 pixels tall. */
    static final double RANGE = 30;
    static final double LENS = 36;
    /** Degrees between the orbit's steps, and the steps: round two and a bit of the views' 11° spacing. */
    static final double ORBIT_STEP = 0.5;
    static final int ORBIT_STEPS = 50;

    /**
     * Orbiting a lone tree drawn as an impostor by half a degree a step (from the land, so only the lake bed lies
     * behind it), the picture of the tree changes by about as much at every step: no step stands out. With the
     * nearest frame alone, the card holds one picture for the 11° between two views and then swaps it whole, so the
     * step across a view's boundary carries the change of 22 steps at once; blended, the three nearest frames'
     * weights move linearly with the direction and spread that change over the 22. The largest step may be twice the
     * median (the blend's rate of change differs from one triangle of the grid to the next by up to 2 ×), an
     * eleventh of the whole swap. Measured over the pixels of the middle third of the picture's width, where the tree
     * stands, that are plant in the later picture.
     */
    @Test
    void anImpostorTurnsSmoothlyAsTheEyeGoesRoundIt() {
        VegetationSystem plants = new VegetationSystem();
        try (Engine engine = TreeRenderTest.engine(GL.context(), plants, new CameraPose(-60, 40, 0, 270, -12, 60),
                List.of())) {
            engine.update();
            float[] tree = aShoreTree(plants);
            double[] steps = new double[ORBIT_STEPS];
            Image last = null;
            for (int k = 0; k <= ORBIT_STEPS; k++) {
                engine.world().resource(Camera.class).setPose(orbit(tree, RANGE, 75 + k * ORBIT_STEP, LENS));
                Image bare = TreeRenderTest.frame(engine, "vegetation", false);
                Image cards = draw(engine, 10, 10);
                if (last != null) {
                    steps[k - 1] = plantChange(last, cards, bare);
                }
                last = cards;
            }
            double[] sorted = steps.clone();
            Arrays.sort(sorted);
            double median = sorted[ORBIT_STEPS / 2];
            double largest = sorted[ORBIT_STEPS - 1];
            assertTrue(median > 0, "the picture does not change as the eye goes round: " + Arrays.toString(steps));
            assertTrue(largest < 2 * median, "the largest step's change " + largest + " against the median's "
                    + median + ": " + Arrays.toString(steps));
        }
    }

    /**
     * The mean ΔE00 between two pictures over the pixels of the middle third of the width where the second differs
     * noticeably from the bare one.
     */
    static double plantChange(Image before, Image after, Image bare) {
        ImageComparison between = ImageComparison.of(before, after);
        boolean[] plant = plantPixels(bare, after);
        int w = bare.width();
        double sum = 0;
        int pixels = 0;
        for (int i = 0; i < plant.length; i++) {
            if (plant[i] && Math.abs(i % w - w / 2) < w / 6) {
                sum += between.deltaE(i % w, i / w);
                pixels++;
            }
        }
        assertTrue(pixels > 500, "pixels of the tree: " + pixels);
        return sum / pixels;
    }

    /**
     * A wind from the north at which the crowns lean their most (sway.glsl's cap, 0.06 heights, from 15 m/s among
     * the plants): across the view of a camera looking east.
     */
    static final Wind GALE = new Wind(new Vector3f(0, 0, 40));

    /** The pixels that differ noticeably (ΔE00 over {@link #NOTICED}) between two pictures. */
    static int changed(Image a, Image b) {
        ImageComparison c = ImageComparison.of(a, b);
        int n = 0;
        for (int y = 0; y < a.height(); y++) {
            for (int x = 0; x < a.width(); x++) {
                n += c.deltaE(x, y) > NOTICED ? 1 : 0;
            }
        }
        return n;
    }

    /** The mean x, pixels, of the plant's pixels in the upper half of the picture's middle third: the crown's top. */
    static double crownX(Image bare, Image plants) {
        boolean[] plant = plantPixels(bare, plants);
        int w = bare.width();
        double sum = 0;
        int pixels = 0;
        for (int i = 0; i < plant.length / 2; i++) {
            if (plant[i] && Math.abs(i % w - w / 2) < w / 6) {
                sum += i % w;
                pixels++;
            }
        }
        assertTrue(pixels > 200, "pixels of the crown: " + pixels);
        return sum / pixels;
    }

    /**
     * How far the crown's top moves between now and half a swing (0.3 Hz) later, pixels, drawn as meshes ([0]) and
     * as cards ([1]) at each of the two times; [2]: how many pixels of the cards changed noticeably.
     */
    static double[] swayed(Engine engine, Image bare) {
        Image mesh = draw(engine, 5000, 5000);
        Image card = draw(engine, 10, 10);
        double half = 0.5 / 0.3;
        double step = engine.settings().get(EngineSettings.class).step();
        for (int i = 0; i < Math.round(half / step); i++) {
            engine.update();
        }
        Image meshLater = draw(engine, 5000, 5000);
        Image cardLater = draw(engine, 10, 10);
        return new double[] {crownX(bare, meshLater) - crownX(bare, mesh), crownX(bare, cardLater)
                - crownX(bare, card), changed(card, cardLater)};
    }

    /**
     * The cards sway in the wind as the meshes do, and stand still in calm air: the lone tree by the shore 30 m away
     * through a 36° lens, drawn now and half a swing later. In a gale the crown's top swings by two thirds of its
     * 0.06-height lean, 0.5 m of a 12 m tree, 5 pixels here; the upper half of the crown, whose mean it is, by about
     * a third of that. The card's crown must move the mesh's way by as much to within a pixel (their outlines differ
     * by a pixel, see above), and in calm air not one pixel of the card may change.
     */
    @Test
    void anImpostorSwaysInTheWindAsItsMeshDoes() {
        VegetationSystem plants = new VegetationSystem();
        try (Engine engine = TreeRenderTest.engine(GL.context(), plants, new CameraPose(-60, 40, 0, 270, -12, 60),
                List.of())) {
            engine.update();
            engine.world().resource(Camera.class).setPose(orbit(aShoreTree(plants), RANGE, 90, LENS));
            Image bare = TreeRenderTest.frame(engine, "vegetation", false);
            double[] calm = swayed(engine, bare);
            engine.world().setResource(GALE);
            double[] gale = swayed(engine, bare);
            assertTrue(Math.abs(gale[0]) > 1, "the meshes' crowns moved by " + gale[0] + " px");
            assertTrue(Math.abs(gale[1] - gale[0]) < 1, "the cards' crowns moved by " + gale[1]
                    + " px, the meshes' by " + gale[0]);
            assertEquals(0, calm[2], "pixels of the cards changed in calm air");
        }
    }
}
