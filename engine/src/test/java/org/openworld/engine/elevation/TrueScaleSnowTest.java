package org.openworld.engine.elevation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.DataBuffer;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.terrain.TerrainData;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.material.SnowMap;

/**
 * A map at true scale gets its snow by altitude in metres, not over its own range: the same hills (the test relief,
 * about a kilometre from lowest to highest) lifted to lie wholly below the default snow line are bare, lifted above it
 * are white.
 */
class TrueScaleSnowTest {

    private static final int W = 301;
    private static final int H = 217;

    @TempDir
    Path dir;

    @Test
    void hillsBelowTheSnowLineInMetresAreBareAndAboveItWhite() throws IOException {
        TerrainSettings defaults = TerrainSettings.DEFAULTS;
        double snowStarts = defaults.snowBase() * ElevationImport.TRUE_SCALE_RELIEF;   // 1750 m
        double snowCertain = defaults.snowFull() * ElevationImport.TRUE_SCALE_RELIEF;  // 3000 m
        float[] relief = ElevationFiles.reliefGrid(W, H);
        float[] range = range(relief);
        // Lifted so the highest sample is 100 m below where snow may start: the chance is 0 everywhere, exactly.
        double low = snowStarts - 100 - range[1];
        // Lifted so the lowest sample is 100 m above where snow is certain: the chance is 1 everywhere.
        double high = snowCertain + 100 - range[0];

        assertEquals(0, snow(map("low.tif", relief, low)).fraction(), "below the snow line, no snow");
        assertEquals(1, snow(map("high.tif", relief, high)).fraction(), "above the snow line, all snow");
        // The snow line counts from the file's 0 m, not from the water: flooding to just under the lowest sample
        // leaves every sample a few metres above the water, and still above the snow line in metres.
        assertEquals(1, snow(map("flooded.tif", relief, high), "terrain.sea-level=" + (high + range[0] - 10))
                .fraction(), "the snow line is the file's metres, whatever the sea level");
    }

    @Test
    void theMaterialsReadTheSameMetresAsTheSnow() throws IOException {
        float[] relief = ElevationFiles.reliefGrid(W, H);
        TerrainData data = data(map("dem.tif", relief, 0), "terrain.sea-level=300");
        // normalised 0 is the file's 0 m, 300 m below the water; 1 is TRUE_SCALE_RELIEF above it
        assertEquals(-300, data.lowest(), 1e-9);
        assertEquals(ElevationImport.TRUE_SCALE_RELIEF - 300, data.highest(), 1e-9);
    }

    private static float[] range(float[] a) {
        float lo = Float.POSITIVE_INFINITY;
        float hi = Float.NEGATIVE_INFINITY;
        for (float v : a) {
            lo = Math.min(lo, v);
            hi = Math.max(hi, v);
        }
        return new float[] {lo, hi};
    }

    /** A projected GeoTIFF in metres of the relief lifted by {@code lift} metres, 30 m between samples. */
    private Path map(String name, float[] relief, double lift) throws IOException {
        float[] lifted = new float[relief.length];
        for (int i = 0; i < relief.length; i++) {
            lifted[i] = (float) (relief[i] + lift);
        }
        return ElevationFiles.geoTiff(dir.resolve(name), W, H, lifted, DataBuffer.TYPE_FLOAT,
                new double[] {30, 30, 0}, new double[] {0, 0, 0, 500_000, 4_000_000, 0},
                ElevationFiles.PROJECTED_METRES, null);
    }

    private static SnowMap snow(Path file, String... more) {
        return data(file, more).snow();
    }

    private static TerrainData data(Path file, String... more) {
        String[] assignments = new String[more.length + 2];
        assignments[0] = "terrain.import-file=" + file;
        assignments[1] = "terrain.import-detail=false";
        System.arraycopy(more, 0, assignments, 2, more.length);
        return TerrainData.create(ElevationImportTest.settings(assignments), 1, new StageTimes(stage -> { }));
    }
}
