package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Image quilting's minimum-error boundary cut ({@link ImageQuilting}) against every path through a small strip. */
class ImageQuiltingTest {

    @Test
    void theCutIsTheLeastErrorPathThroughTheStrip() {
        // every path through a 4 × 6 strip, one texel per row moving at most one sideways, against the program's
        SplittableRandom random = new SplittableRandom(7);
        int width = 4;
        int length = 6;
        for (int trial = 0; trial < 20; trial++) {
            double[] e = random.doubles(width * length).toArray();
            int[] path = ImageQuilting.minimumPath(e, length, width);
            double best = Double.POSITIVE_INFINITY;
            for (int code = 0; code < Math.pow(width, length); code++) {
                double cost = 0;
                int previous = -1;
                boolean connected = true;
                for (int l = 0, c = code; l < length; l++, c /= width) {
                    int w = c % width;
                    connected &= previous < 0 || Math.abs(w - previous) <= 1;
                    previous = w;
                    cost += e[l * width + w];
                }
                if (connected) {
                    best = Math.min(best, cost);
                }
            }
            for (int l = 1; l < length; l++) {
                assertTrue(Math.abs(path[l] - path[l - 1]) <= 1, "the path moves one texel at most");
            }
            // doubles: the same sum of errors taken twice, equal to round-off
            assertEquals(best, ImageQuilting.cost(e, width, path), 1e-12);
        }
    }
}
