package org.openworld.engine.temporal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.TreeSet;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.ViewCamera;

/** The jitter's offsets and what they do to a projected point. */
class JitterTest {

    @Test
    void aRunStartsAtThePixelCentreAndTheCycleCoversThePixel() {
        assertEquals(0, Jitter.offset(0, 0));
        assertEquals(0, Jitter.offset(0, 1));
        TreeSet<Double> xs = new TreeSet<>();
        for (int n = 0; n < Jitter.CYCLE; n++) {
            for (int axis = 0; axis < 2; axis++) {
                double o = Jitter.offset(n, axis);
                assertTrue(o >= -0.5 && o < 0.5, "offset " + o + " of frame " + n + " within the pixel");
            }
            xs.add(Jitter.offset(n, 0));
        }
        // Halton base 2, points 1 to 32: 1/2, 1/4, 3/4, ... 31/32 and 1/64, one in each 32nd of the pixel (the
        // first, at x = 1/2, is the centre that frame 0 takes): every x offset distinct
        assertEquals(Jitter.CYCLE, xs.size());
        assertEquals(Jitter.offset(0, 0), Jitter.offset(Jitter.CYCLE, 0), "the cycle repeats");
        assertEquals(1.0 / 3, Jitter.halton(1, 3), 1e-15);
        assertEquals(7.0 / 9, Jitter.halton(5, 3), 1e-15); // 5 = 12 in base 3, mirrored 0.21
    }

    @Test
    void aJitteredCameraMovesEveryPointByTheOffsetInPixels() {
        int width = 320;
        int height = 180;
        ViewCamera camera = ViewCamera.perspective(new CameraPose(10, 50, -20, 30, -5, 60), 16f / 9, 0.5f, 40_000f);
        for (long n = 1; n < 4; n++) {
            ViewCamera jittered = Jitter.apply(camera, n, width, height);
            for (float[] p : new float[][] {{100, 20, -300}, {-50, 0, -2000}}) {
                Vector4f plain = camera.viewProjection().transform(new Vector4f(p[0], p[1], p[2], 1));
                Vector4f moved = jittered.viewProjection().transform(new Vector4f(p[0], p[1], p[2], 1));
                // pixels = NDC / 2 * size; a few float roundings of clip coordinates near 1e3 allowed
                assertEquals(Jitter.offset(n, 0), (moved.x / moved.w - plain.x / plain.w) / 2 * width, 1e-3);
                assertEquals(Jitter.offset(n, 1), (moved.y / moved.w - plain.y / plain.w) / 2 * height, 1e-3);
                assertEquals(plain.z / plain.w, moved.z / moved.w, 1e-6, "depth unchanged");
            }
        }
    }
}
