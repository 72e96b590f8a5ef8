package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Mesh;

/**
 * {@code antialias.method} on real GL: a red triangle over green with one shallow edge, drawn with and without FXAA.
 * Rasterised, every pixel is wholly red or wholly green, so the edge is a staircase; anti-aliased, the pixels along
 * it take intermediate colours, and nothing away from it changes.
 */
@GlTest
class AntialiasRenderTest {

    static final int SIZE = 64;
    /** The edge's rise across the picture, in clip units (2 = its height): a slope of 0.4 pixels per pixel. */
    static final float RISE = 0.8f;

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /** Red below the line from (-1, -0.4) to (1, 0.4) in clip space, green above it. */
    private static Image picture(String method) {
        List<String> log = new ArrayList<>();
        List<EngineTest.Call> calls = new ArrayList<>();
        EngineTest.Drawing ground = new EngineTest.Drawing(SystemSpec.named("ground").draws(Pass.MAIN), log, calls,
                GlTestSupport::fullScreenTriangle, 0, 1, 0);
        EngineTest.Drawing wedge = new EngineTest.Drawing(SystemSpec.named("wedge").after("ground")
                .draws(Pass.MAIN), log, calls, gl -> new Mesh(gl,
                new float[] {-1, -1, 1, -1, 1, RISE / 2, -1, -RISE / 2}, new int[] {0, 1, 2, 0, 2, 3},
                new Mesh.Attribute(0, 2)), 1, 0, 0);
        try (Engine engine = GlTestSupport.engine(GL.context(), SIZE, SIZE, List.of("antialias.method=" + method),
                ground, wedge)) {
            engine.render();
            return engine.readImage();
        }
    }

    /** Pixels whose red is neither the background's 0 nor the wedge's 255 (beyond one 8-bit level of rounding). */
    private static int intermediate(Image image, int x) {
        int count = 0;
        for (int y = 0; y < SIZE; y++) {
            int red = image.channel(x, y, 0);
            count += red > 1 && red < 254 ? 1 : 0;
        }
        return count;
    }

    @Test
    void withoutAntialiasingTheEdgeIsAStaircaseOfWholePixels() {
        Image off = picture("off");
        for (int x = 0; x < SIZE; x++) {
            assertEquals(0, intermediate(off, x), "column " + x);
        }
    }

    @Test
    void fxaaGivesTheEdgeIntermediateCoverageAndLeavesTheRestAlone() {
        Image off = picture("off");
        Image fxaa = picture("fxaa");
        // Each step of the staircase is 1 / 0.4 = 2.5 pixels long; FXAA ramps a step's pixels by 0.5 - d / L from
        // its nearer end, so only a pixel at a step's very middle (d = L / 2) keeps its colour: at most one column
        // in two. Columns at the picture's sides are left out, where the search along the edge meets the border.
        int columns = 0;
        int blended = 0;
        for (int x = 2; x < SIZE - 2; x++) {
            columns++;
            blended += intermediate(fxaa, x) > 0 ? 1 : 0;
        }
        assertTrue(blended >= columns / 2, blended + " of " + columns + " columns have a blended pixel");
        // away from the edge (more than two pixels, FXAA's 3x3 neighbourhood and the neighbour it blends with),
        // the picture is exactly what was drawn
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                // the edge's height at the column's centre, pixels from the top: clip y = RISE (x_clip) / 2
                double edgeY = SIZE / 2.0 * (1 - RISE / 2 * ((x + 0.5) / (SIZE / 2.0) - 1));
                if (Math.abs(y + 0.5 - edgeY) > 2) {
                    for (int c = 0; c < 3; c++) {
                        assertEquals(off.channel(x, y, c), fxaa.channel(x, y, c), "pixel " + x + "," + y);
                    }
                }
            }
        }
    }
}
