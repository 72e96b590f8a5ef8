package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_SCISSOR_TEST;
import static org.lwjgl.opengl.GL11C.GL_VIEWPORT;
import static org.lwjgl.opengl.GL11C.glClear;
import static org.lwjgl.opengl.GL11C.glClearColor;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL11C.glGetIntegerv;
import static org.lwjgl.opengl.GL11C.glScissor;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.gl.GlObjects;
import org.openworld.engine.gl.Image;

/**
 * {@code engine.render-scale} on real GL: the viewer's passes draw into a smaller target, the picture keeps the
 * requested size and is that smaller picture stretched with linear filtering; at 2 they draw into a larger one and
 * each picture pixel is the mean of its 2 × 2 samples; what draws over the picture draws at
 * its full size; a change of the scale between frames re-makes the targets.
 */
@GlTest
class RenderScaleTest {

    static final int SIZE = 64;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    final List<EngineTest.Call> calls = new ArrayList<>();

    /** Green everywhere, then red over the lower-left quarter: one hard vertical and one hard horizontal edge. */
    private Engine engine(int size, String... settings) {
        List<String> log = new ArrayList<>();
        EngineTest.Drawing ground = new EngineTest.Drawing(SystemSpec.named("ground").draws(Pass.MAIN), log, calls,
                GlTestSupport::fullScreenTriangle, 0, 1, 0);
        EngineTest.Drawing quarter = new EngineTest.Drawing(SystemSpec.named("quarter").after("ground")
                .draws(Pass.MAIN), log, calls, GlTestSupport::quarterQuad, 1, 0, 0);
        return GlTestSupport.engine(GL.context(), size, size, List.of(settings), ground, quarter);
    }

    @Test
    void theHalfScalePictureHasTheFullSizeAndIsTheHalfSizePictureStretchedLinearly() {
        Image scaled;
        Image small;
        try (Engine engine = engine(SIZE, "engine.render-scale=0.5")) {
            engine.render();
            scaled = engine.readImage();
            assertEquals(SIZE / 2, calls.get(0).target().width(), "the passes draw at half the size");
        }
        try (Engine engine = engine(SIZE / 2)) {
            engine.render();
            small = engine.readImage();
        }
        assertEquals(SIZE, scaled.width());
        assertEquals(SIZE, scaled.height());
        Image expected = stretched(small, SIZE, SIZE);
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                for (int c = 0; c < 3; c++) {
                    assertTrue(Math.abs(scaled.channel(x, y, c) - expected.channel(x, y, c)) <= 2,
                            "pixel " + x + "," + y + " channel " + c + ": " + scaled.channel(x, y, c) + " against "
                                    + expected.channel(x, y, c));
                }
            }
        }
        // the red quarter's right edge, between columns 31 and 32, is soft: a quarter of green, a quarter of red;
        // ± 2 of 255: the blend is rounded once into the 8-bit target, and the linear filter's weights are fixed
        // point (llvmpipe's are 8 bits), which may move it one level more
        int y = SIZE * 3 / 4;
        assertEquals(191, scaled.channel(SIZE / 2 - 1, y, 0), 2);
        assertEquals(64, scaled.channel(SIZE / 2, y, 0), 2);
    }

    /**
     * At 2 the passes draw at twice the picture's sides and each picture pixel is the mean of its 2 × 2 samples. The
     * picture is 63 pixels a side so that the red quarter's edges (at 63 of the 126 samples) cut pixel 31 in half:
     * supersampled, it is half red; drawn at the picture's size, or halved by a nearest blit, it would be all red or
     * all green.
     */
    @Test
    void atTwoEachPixelIsTheMeanOfItsTwoByTwoSamples() {
        int odd = SIZE - 1;
        Image supersampled;
        Image large;
        try (Engine engine = engine(odd, "engine.render-scale=2")) {
            engine.render();
            supersampled = engine.readImage();
            assertEquals(2 * odd, calls.get(0).target().width(), "the passes draw at twice the size");
        }
        try (Engine engine = engine(2 * odd)) {
            engine.render();
            large = engine.readImage();
        }
        assertEquals(odd, supersampled.width());
        Image expected = stretched(large, odd, odd);
        for (int y = 0; y < odd; y++) {
            for (int x = 0; x < odd; x++) {
                for (int c = 0; c < 3; c++) {
                    // ± 2 of 255, as above: one rounding into the 8-bit target, fixed-point filter weights
                    assertEquals(expected.channel(x, y, c), supersampled.channel(x, y, c), 2,
                            "pixel " + x + "," + y + " channel " + c);
                }
            }
        }
        int y = odd * 3 / 4; // a row through the red quarter (the image counts rows from the top)
        assertEquals(255, supersampled.channel(odd / 2 - 1, y, 0), 2, "all red left of the edge");
        assertEquals(128, supersampled.channel(odd / 2, y, 0), 2, "the pixel the edge halves: half red");
    }

    @Test
    void whatDrawsOverThePictureDrawsAtItsFullSize() {
        try (Engine engine = engine(SIZE, "engine.render-scale=0.5")) {
            engine.render();
            int[] viewport = new int[4];
            engine.drawOver(() -> {
                glGetIntegerv(GL_VIEWPORT, viewport);
                // one column of the picture's pixels, white: half a pixel of the scene target
                glEnable(GL_SCISSOR_TEST);
                glScissor(SIZE - 9, 0, 1, SIZE);
                glClearColor(1, 1, 1, 1);
                glClear(GL_COLOR_BUFFER_BIT);
                glDisable(GL_SCISSOR_TEST);
            });
            assertArrayEquals(new int[] {0, 0, SIZE, SIZE}, viewport);
            Image image = engine.readImage();
            int y = SIZE / 4;
            assertEquals(255, image.channel(SIZE - 9, y, 0), "the white column");
            assertEquals(0, image.channel(SIZE - 10, y, 0), "green beside it");
            assertEquals(0, image.channel(SIZE - 8, y, 0), "green beside it");
        }
    }

    @Test
    void aChangedScaleRemakesTheTargetsBeforeTheNextFrame() {
        try (Engine engine = engine(SIZE)) {
            engine.render();
            int textures = GL.context().objects().live(GlObjects.Kind.TEXTURE);
            int framebuffers = GL.context().objects().live(GlObjects.Kind.FRAMEBUFFER);
            engine.settings().set("engine.render-scale", "0.5");
            engine.render();
            assertEquals(SIZE / 2, calls.get(calls.size() - 1).target().width());
            assertEquals(SIZE, engine.readImage().width());
            engine.settings().set("engine.render-scale", "1");
            engine.render();
            assertEquals(SIZE, calls.get(calls.size() - 1).target().width());
            // the picture made for the smaller scale is closed, and the smaller target
            assertEquals(textures, GL.context().objects().live(GlObjects.Kind.TEXTURE));
            assertEquals(framebuffers, GL.context().objects().live(GlObjects.Kind.FRAMEBUFFER));
        }
    }

    @Test
    void aResizedWindowKeepsTheScale() {
        try (Engine engine = engine(SIZE, "engine.render-scale=0.5")) {
            engine.resize(2 * SIZE, SIZE);
            engine.render();
            assertEquals(SIZE, calls.get(calls.size() - 1).target().width());
            assertEquals(SIZE / 2, calls.get(calls.size() - 1).target().height());
            assertEquals(2 * SIZE, engine.readImage().width());
        }
    }

    /**
     * What a linearly filtered blit does: each picture pixel's centre, mapped into the small image, reads the four
     * nearest small pixels weighted by distance (edges clamped).
     */
    static Image stretched(Image small, int width, int height) {
        byte[] rgba = new byte[width * height * 4];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                double sx = (x + 0.5) * small.width() / width - 0.5;
                double sy = (y + 0.5) * small.height() / height - 0.5;
                int x0 = (int) Math.floor(sx);
                int y0 = (int) Math.floor(sy);
                double fx = sx - x0;
                double fy = sy - y0;
                for (int c = 0; c < 4; c++) {
                    double top = (1 - fx) * at(small, x0, y0, c) + fx * at(small, x0 + 1, y0, c);
                    double bottom = (1 - fx) * at(small, x0, y0 + 1, c) + fx * at(small, x0 + 1, y0 + 1, c);
                    rgba[(y * width + x) * 4 + c] = (byte) Math.round((1 - fy) * top + fy * bottom);
                }
            }
        }
        return new Image(width, height, rgba);
    }

    private static int at(Image image, int x, int y, int c) {
        return image.channel(Math.max(0, Math.min(image.width() - 1, x)), Math.max(0, Math.min(image.height() - 1, y)),
                c);
    }
}
