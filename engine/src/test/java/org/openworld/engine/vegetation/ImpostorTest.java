package org.openworld.engine.vegetation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.ImageComparison;
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
     * along the mesh's outline. The impostor's frame is the nearest of views about 11° apart (so up to 8° off the eye's
     * direction) and its texels are finer than the picture's pixels here, so its outline may be off by a pixel at
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
}
