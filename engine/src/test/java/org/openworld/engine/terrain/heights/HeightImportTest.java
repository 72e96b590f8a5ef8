package org.openworld.engine.terrain.heights;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Importing 16-bit PNG and float32 raw height maps, and the messages for files that cannot be used. */
class HeightImportTest {

    @TempDir
    Path dir;

    private final TerrainSettings settings = TestTerrain.settings("terrain.relief=1000", "terrain.sea-fraction=0.1",
            "terrain.spacing=5");

    /** A test pattern with distinct values, min 0 and max 65535 (x, z over a side of {@code side}). */
    private static int pattern(int x, int z, int side) {
        if (x == 0 && z == 0) {
            return 0;
        }
        if (x == side - 1 && z == side - 1) {
            return 65535;
        }
        return 1000 + (x * 37 + z * 101) % 60000;
    }

    /** The height the normalisation should give a sample v of a map ranging 0 .. 65535. */
    private double expected(double v) {
        return settings.relief() * (v / 65535.0 - settings.seaFraction());
    }

    private Path png16(String name, int width, int height) throws IOException {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_USHORT_GRAY);
        for (int z = 0; z < height; z++) {
            for (int x = 0; x < width; x++) {
                image.getRaster().setSample(x, z, 0, pattern(x, z, width));
            }
        }
        Path file = dir.resolve(name);
        ImageIO.write(image, "png", file.toFile());
        return file;
    }

    private Path raw(String name, int side) throws IOException {
        ByteBuffer bytes = ByteBuffer.allocate(side * side * 4).order(ByteOrder.LITTLE_ENDIAN);
        for (int z = 0; z < side; z++) {
            for (int x = 0; x < side; x++) {
                bytes.putFloat(pattern(x, z, side) / 65535f * 3000f - 200f); // metres, any range
            }
        }
        Path file = dir.resolve(name);
        Files.write(file, bytes.array());
        return file;
    }

    @Test
    void sixteenBitPngRoundTrip() throws IOException {
        HeightMap map = HeightImport.read(png16("h.png", 256, 256), settings);
        assertEquals(256, map.size());
        assertEquals(5, map.spacing());
        assertFalse(map.periodic());
        for (int[] p : new int[][] {{0, 0}, {255, 255}, {17, 3}, {200, 111}, {5, 250}}) {
            assertEquals(expected(pattern(p[0], p[1], 256)), map.sample(p[0], p[1]), 1e-3,
                    "sample " + p[0] + "," + p[1] + " (row 0 of the PNG is z = 0, the north edge)");
        }
    }

    @Test
    void rawFloatRoundTripDropsTheLastRowAndColumnOfA2PowNPlus1Map() throws IOException {
        HeightMap map = HeightImport.read(raw("h.r32", 257), settings);
        assertEquals(256, map.size(), "257 samples per side lose their last row and column");
        // the kept part no longer holds the maximum (it was at 256, 256), so it normalises to its own range
        double lo = pattern(0, 0, 257);
        double hi = 0;
        for (int z = 0; z < 256; z++) {
            for (int x = 0; x < 256; x++) {
                hi = Math.max(hi, pattern(x, z, 257));
            }
        }
        for (int[] p : new int[][] {{0, 0}, {17, 3}, {200, 111}, {255, 255}}) {
            double n = (pattern(p[0], p[1], 257) - lo) / (hi - lo);
            assertEquals(settings.relief() * (n - settings.seaFraction()), map.sample(p[0], p[1]), 1e-2,
                    "sample " + p[0] + "," + p[1]);
        }
        // heights in float metres (24-bit mantissa, 6e-5 m at 900 m): 1e-3 m for exact ends, 1e-2 m for samples
        // rescaled from 16-bit integers through float
        assertEquals(-100, map.min(), 1e-3);
        assertEquals(900, map.max(), 1e-3);
    }

    @Test
    void rawOfPowerOfTwoSideIsReadWhole() throws IOException {
        HeightMap map = HeightImport.read(raw("h.raw", 256), settings);
        assertEquals(256, map.size());
        // float metres rescaled from 16-bit samples: 1e-2 m, well under the 1000 m / 65 535 ≈ 1.5 cm of one input step
        assertEquals(expected(pattern(100, 42, 256)), map.sample(100, 42), 1e-2);
    }

    private String failure(Path file) {
        return assertThrows(HeightImportException.class, () -> HeightImport.read(file, settings)).getMessage();
    }

    @Test
    void missingFile() {
        Path file = dir.resolve("nothing.png");
        String message = failure(file);
        assertTrue(message.contains(file.toString()) && message.contains("no such file"), message);
    }

    @Test
    void eightBitPngIsRefused() throws IOException {
        BufferedImage image = new BufferedImage(256, 256, BufferedImage.TYPE_BYTE_GRAY);
        Path file = dir.resolve("eight.png");
        ImageIO.write(image, "png", file.toFile());
        String message = failure(file);
        assertTrue(message.contains(file.toString()) && message.contains("8-bit") && message.contains("16-bit"),
                message);
    }

    @Test
    void notSquare() throws IOException {
        Path file = png16("wide.png", 512, 256);
        String message = failure(file);
        assertTrue(message.contains(file.toString()) && message.contains("512×256") && message.contains("square"),
                message);
    }

    @Test
    void wrongPngSideNamesTheNearestValidSides() throws IOException {
        Path file = png16("odd.png", 300, 300);
        String message = failure(file);
        assertTrue(message.contains(file.toString()) && message.contains("257×257 or 512×512"), message);
    }

    @Test
    void wrongRawSampleCountNamesTheNearestValidSizes() throws IOException {
        Path file = dir.resolve("short.f32");
        Files.write(file, new byte[4 * (256 * 256 + 10)]);
        String message = failure(file);
        assertTrue(message.contains(file.toString()) && message.contains("65546 float32 samples")
                && message.contains("65536 (256²) or 66049 (257²)"), message);
    }

    @Test
    void unknownExtension() throws IOException {
        Path file = dir.resolve("heights.tif");
        Files.write(file, new byte[16]);
        String message = failure(file);
        assertTrue(message.contains(file.toString()) && message.contains("'.tif'") && message.contains(".png"),
                message);
    }

    @Test
    void flatMapCannotBeNormalised() throws IOException {
        Path file = dir.resolve("flat.raw");
        Files.write(file, new byte[4 * 256 * 256]);
        String message = failure(file);
        assertTrue(message.contains(file.toString()) && message.contains("flat"), message);
    }
}
