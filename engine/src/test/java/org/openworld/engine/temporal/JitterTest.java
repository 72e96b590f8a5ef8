package org.openworld.engine.temporal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.TreeSet;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.ViewCamera;

/** The jitter's offsets and what they do to a projected point. */
class JitterTest {

    @ParameterizedTest
    @ValueSource(ints = {16, 32, 64, 128})
    void aRunStartsAtThePixelCentreAndTheCycleCoversThePixel(int cycle) {
        assertEquals(0, Jitter.offset(0, 0, cycle));
        assertEquals(0, Jitter.offset(0, 1, cycle));
        TreeSet<Integer> columns = new TreeSet<>();
        for (int n = 0; n < cycle; n++) {
            for (int axis = 0; axis < 2; axis++) {
                double o = Jitter.offset(n, axis, cycle);
                assertTrue(o >= -0.5 && o < 0.5, "offset " + o + " of frame " + n + " within the pixel");
            }
            columns.add((int) Math.floor((Jitter.offset(n, 0, cycle) + 0.5) * cycle));
        }
        // Halton base 2, points 1 to N for N a power of two: 1/2, 1/4, 3/4, ... (N−1)/N and 1/(2N), one in each
        // N-th of the pixel along x (the first, at x = 1/2, is the centre that frame 0 takes): a longer cycle
        // samples the pixel more finely, every N-th holds one offset
        assertEquals(cycle, columns.size(), "one x offset in each " + cycle + "th of the pixel");
        assertEquals(Jitter.offset(1, 0, cycle), Jitter.offset(cycle + 1, 0, cycle), "the cycle repeats");
        assertEquals(Jitter.offset(1, 1, cycle), Jitter.offset(cycle + 1, 1, cycle), "the cycle repeats");
    }

    @Test
    void aLongerCycleExtendsTheShorterOne() {
        // the same Halton points: a cycle of 128 begins with the 32 of the default's, so it only adds samples
        for (int n = 0; n < 32; n++) {
            for (int axis = 0; axis < 2; axis++) {
                assertEquals(Jitter.offset(n, axis, 32), Jitter.offset(n, axis, 128));
            }
        }
        assertTrue(Jitter.offset(32, 0, 32) == 0 && Jitter.offset(32, 0, 128) != 0,
                "frame 32 starts the short cycle again and is a new offset of the long one");
        assertEquals(1.0 / 3, Jitter.halton(1, 3), 1e-15);
        assertEquals(7.0 / 9, Jitter.halton(5, 3), 1e-15); // 5 = 12 in base 3, mirrored 0.21
    }

    @Test
    void aJitteredCameraMovesEveryPointByTheOffsetInPixels() {
        int width = 320;
        int height = 180;
        ViewCamera camera = ViewCamera.perspective(new CameraPose(10, 50, -20, 30, -5, 60), 16f / 9, 0.5f, 40_000f);
        for (long n = 1; n < 4; n++) {
            ViewCamera jittered = Jitter.apply(camera, n, 32, width, height);
            for (float[] p : new float[][] {{100, 20, -300}, {-50, 0, -2000}}) {
                Vector4f plain = camera.viewProjection().transform(new Vector4f(p[0], p[1], p[2], 1));
                Vector4f moved = jittered.viewProjection().transform(new Vector4f(p[0], p[1], p[2], 1));
                // pixels = NDC / 2 * size; a few float roundings of clip coordinates near 1e3 allowed
                assertEquals(Jitter.offset(n, 0, 32), (moved.x / moved.w - plain.x / plain.w) / 2 * width, 1e-3);
                assertEquals(Jitter.offset(n, 1, 32), (moved.y / moved.w - plain.y / plain.w) / 2 * height, 1e-3);
                assertEquals(plain.z / plain.w, moved.z / moved.w, 1e-6, "depth unchanged");
            }
        }
    }
}
