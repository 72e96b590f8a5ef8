package org.openworld.engine.elevation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.DataBuffer;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.terrain.heights.HeightImportException;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * Real elevation models of a non-square, non-power-of-two size (301 × 217) from GeoTIFF (float32, int16, uint16),
 * 16-bit PNG and raw float32 with sidecars: heights within 1 m of the file's, spacing from the tags, and one line for each
 * kind of bad file.
 */
class ElevationImportTest {

    /** The requirement: an imported height lies within 1 m of the file's. */
    private static final double HEIGHT_TOLERANCE = 1.0;
    private static final int W = 301;
    private static final int H = 217;

    @TempDir
    Path dir;

    static TerrainSettings settings(String... assignments) {
        Settings settings = new Settings(List.of(TerrainSettings.SETTINGS));
        for (String a : assignments) {
            settings.apply(a);
        }
        return settings.get(TerrainSettings.class);
    }

    private final TerrainSettings plain = settings("terrain.import-detail=false");

    @Test
    void float32GeoTiffKeepsMetresAndTheTagsSpacing() throws IOException {
        Path file = ElevationFiles.geoTiff(dir.resolve("dem.tif"), W, H, ElevationFiles.reliefGrid(W, H),
                DataBuffer.TYPE_FLOAT, new double[] {30, 30, 0}, new double[] {0, 0, 0, 500_000, 4_000_000, 0},
                ElevationFiles.PROJECTED_METRES, null);
        ElevationGrid grid = ElevationImport.grid(file, plain);
        assertEquals(30, grid.spacingX(), 1e-12);
        assertEquals(30, grid.spacingZ(), 1e-12);
        assertMatches(grid, 0, 1);
        // The tile: the model's samples fall on the tile's (same spacing, odd sides centred): heightAt gives them back
        assertTileMatches(ElevationImport.read(file, plain, 1), grid, 0);
    }

    @Test
    void int16GeographicDegreesBecomeMetresAtTheLatitudeAndNoDataIsFilled() throws IOException {
        float[] values = ElevationFiles.reliefGrid(W, H);
        for (int z = 100; z < 105; z++) {
            for (int x = 200; x < 205; x++) {
                values[z * W + x] = Short.MIN_VALUE;
            }
        }
        double pixel = 1.0 / 1200; // 3 arc-seconds, SRTM's
        double north = 45 + H / 2.0 * pixel; // the map's centre at 45° N
        Path file = ElevationFiles.geoTiff(dir.resolve("srtm.tif"), W, H, values, DataBuffer.TYPE_SHORT,
                new double[] {pixel, pixel, 0}, new double[] {0, 0, 0, 7.0, north, 0}, ElevationFiles.GEOGRAPHIC,
                "-32768");
        ElevationGrid grid = ElevationImport.grid(file, plain);
        // WGS 84 at 45°: a degree of latitude is 111 132.95 m, of longitude 78 846.8 m (published to 0.1 m; the
        // comparison is to 1 mm a sample, far inside that)
        assertEquals(111_132.95 * pixel, grid.spacingZ(), 1e-3);
        assertEquals(78_846.8 * pixel, grid.spacingX(), 1e-3);
        assertEquals(45, grid.latitude(), 1e-9);
        float[] rim = {Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY};
        for (int z = 99; z <= 105; z++) {
            for (int x = 199; x <= 205; x++) {
                if (z == 99 || z == 105 || x == 199 || x == 205) {
                    rim[0] = Math.min(rim[0], grid.at(x, z));
                    rim[1] = Math.max(rim[1], grid.at(x, z));
                }
            }
        }
        for (int z = 0; z < H; z++) {
            for (int x = 0; x < W; x++) {
                boolean hole = z >= 100 && z < 105 && x >= 200 && x < 205;
                float h = grid.at(x, z);
                if (hole) {
                    // filled with means of means of the rim: within the rim's range
                    assertTrue(h >= rim[0] && h <= rim[1], "filled " + h + " outside the rim's " + rim[0] + " .. "
                            + rim[1]);
                } else {
                    assertEquals(ElevationFiles.relief(x, z), h, 0.5, "int16 rounding is at most half a metre");
                }
            }
        }
    }

    @Test
    void uint16InFeetAndASeaLevel() throws IOException {
        float[] values = ElevationFiles.reliefGrid(W, H);
        for (int i = 0; i < values.length; i++) {
            values[i] += 600; // uint16 holds no negative heights
        }
        Path file = ElevationFiles.geoTiff(dir.resolve("feet.tif"), W, H, values, DataBuffer.TYPE_USHORT,
                new double[] {10, 10, 0}, new double[] {0, 0, 0, 0, 0, 0}, ElevationFiles.PROJECTED_FEET, null);
        TerrainSettings s = settings("terrain.import-detail=false", "terrain.sea-level=600");
        ElevationGrid grid = ElevationImport.grid(file, s);
        assertEquals(3.048, grid.spacingX(), 1e-12, "10 international feet");
        // heights are relief + 600 rounded, then 600 m of sea level taken off
        assertTileMatches(ElevationImport.read(file, s, 1), grid, 600);
    }

    @Test
    void png16WithSidecar() throws IOException {
        int[] stored = new int[W * H];
        for (int z = 0; z < H; z++) {
            for (int x = 0; x < W; x++) {
                stored[z * W + x] = Math.round((ElevationFiles.relief(x, z) + 600) * 10);
            }
        }
        Path file = ElevationFiles.png16(dir.resolve("dem.png"), W, H, stored);
        ElevationFiles.sidecar(file, "spacing", "25", "verticalScale", "0.1", "verticalOffset", "-600");
        ElevationGrid grid = ElevationImport.grid(file, plain);
        assertEquals(25, grid.spacingX(), 1e-12);
        assertMatches(grid, 0, 0.05 + 1e-3); // a 0.1 m step rounds by at most half of it (float32's error below)
        assertTileMatches(ElevationImport.read(file, plain, 1), grid, 0);
    }

    @Test
    void rawFloat32WithSidecarAndUnequalSpacing() throws IOException {
        Path file = ElevationFiles.raw(dir.resolve("dem.raw"), ElevationFiles.reliefGrid(W, H));
        ElevationFiles.sidecar(file, "width", "301", "height", "217", "spacingX", "20", "spacingZ", "40");
        ElevationGrid grid = ElevationImport.grid(file, plain);
        assertEquals(20, grid.spacingX(), 1e-12);
        assertEquals(40, grid.spacingZ(), 1e-12);
        assertMatches(grid, 0, 1e-3);
        // resampled at 20 m both ways: every model sample is on the tile's grid, rows at every second tile row
        assertTileMatches(ElevationImport.read(file, plain, 1), grid, 0);
    }

    @Test
    void aTiffWithoutGeoreferenceIsRefusedAtTrueScaleAndNormalisedOtherwise() throws IOException {
        Path file = ElevationFiles.geoTiff(dir.resolve("plain.tif"), W, H, ElevationFiles.reliefGrid(W, H),
                DataBuffer.TYPE_FLOAT, null, null, null, null);
        assertOneLine(file, plain, "has no georeference");
        TerrainSettings normalised = settings("terrain.import-scale=false", "terrain.relief=1000",
                "terrain.sea-fraction=0.2", "terrain.spacing=5");
        HeightMap map = ElevationImport.read(file, normalised, 1);
        assertEquals(5, map.spacing());
        assertEquals(-200, map.min(), 1e-3);
        assertEquals(800, map.max(), 1e-3);
    }

    @Test
    void aCorruptTiffGetsOneLine() throws IOException {
        Path file = dir.resolve("broken.tif");
        Files.write(file, new byte[] {'I', 'I', 42, 0, 8, 0, 0, 0, (byte) 0xFF, (byte) 0xFF, 1, 2, 3});
        assertOneLine(file, plain, "not a readable TIFF");
    }

    @Test
    void eightBitSamplesAreAnUnsupportedFormat() throws IOException {
        Path file = ElevationFiles.geoTiff(dir.resolve("byte.tif"), W, H, new float[W * H], DataBuffer.TYPE_BYTE,
                new double[] {30, 30, 0}, new double[] {0, 0, 0, 0, 0, 0}, ElevationFiles.PROJECTED_METRES, null);
        assertOneLine(file, plain, "8-bit samples; an elevation model needs one band of float32, int16 or uint16");
    }

    @Test
    void aModelLargerThanTheHeapSaysWhatItWouldNeed() throws IOException {
        Path file = ElevationFiles.raw(dir.resolve("huge.raw"), new float[4]);
        ElevationFiles.sidecar(file, "width", "100000", "height", "100000", "spacing", "1");
        String message = assertOneLine(file, plain, "needs about 74.5 GiB (100000×100000 samples 8 bytes each");
        assertTrue(message.contains("the heap has"), message);
    }

    private static void assertMatches(ElevationGrid grid, double offset, double tolerance) {
        for (int z = 0; z < grid.height(); z++) {
            for (int x = 0; x < grid.width(); x++) {
                assertEquals(ElevationFiles.relief(x, z) + offset, grid.at(x, z), tolerance, x + ", " + z);
            }
        }
    }

    /** The tile's height at each model sample's place is the file's, less the sea level, within 1 m. */
    private static void assertTileMatches(HeightMap map, ElevationGrid grid, double seaLevel) {
        for (int z = 0; z < grid.height(); z++) {
            for (int x = 0; x < grid.width(); x++) {
                double wx = x * grid.spacingX() - grid.extentX() / 2;
                double wz = z * grid.spacingZ() - grid.extentZ() / 2;
                assertEquals(grid.at(x, z) - seaLevel, map.heightAt(wx, wz), HEIGHT_TOLERANCE, x + ", " + z);
            }
        }
    }

    private static String assertOneLine(Path file, TerrainSettings s, String expected) {
        String message = assertThrows(HeightImportException.class, () -> ElevationImport.read(file, s, 1))
                .getMessage();
        assertTrue(message.startsWith(file.toString()) && message.contains(expected), message);
        assertFalse(message.contains("\n"), message);
        return message;
    }
}
