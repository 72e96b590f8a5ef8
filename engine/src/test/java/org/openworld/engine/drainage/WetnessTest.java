package org.openworld.engine.drainage;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class WetnessTest {

    /**
     * A periodic valley: 64² cells 8 m apart, the ground rising at 30 % both ways from the axis x = 0 to a crest
     * halfway round, and falling 1 % along the axis to the sea at the axis's first cell. The valley floor gathers the
     * flanks (a large catchment on a gentle slope: wet), the crest only itself on a steep one (dry).
     */
    @Test
    void valleyFloorsAreWetAndCrestsDry() {
        int n = 64;
        double spacing = 8;
        float[] h = new float[n * n];
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                h[z * n + x] = (float) (0.3 * spacing * Math.min(x, n - x) + 0.01 * spacing * z + 1);
            }
        }
        h[0] = 0; // the sea
        Wetness wet = Wetness.ofTile(h, n, spacing);
        double extent = n * spacing;
        // world position of cell (x, z): the tile is centred on the origin
        double floorX = -extent / 2 + 0.5 * spacing;
        double crestX = floorX + n / 2 * spacing;
        double z = -extent / 2 + (n / 2 + 0.5) * spacing;
        // wetness runs 0 (a crest: area of one cell) to 1 (the tile's largest area); 0.8 and 0.2 keep the floor and
        // crest well apart from the middle, where a mis-routed tile would land
        assertTrue(wet.wetness(floorX, z) > 0.8, "valley floor " + wet.wetness(floorX, z));
        assertTrue(wet.wetness(crestX, z) < 0.2, "crest " + wet.wetness(crestX, z));
        // every cell of the tile drains to the sea cell: its area is the whole tile
        // 1e-6 m² on an exact sum of n² cell areas (integers in m², exact in double)
        assertEquals(n * n * spacing * spacing, wet.drainageArea(floorX, -extent / 2 + 0.5 * spacing), 1e-6);
    }
}
