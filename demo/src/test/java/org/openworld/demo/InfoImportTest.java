package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code openworld info --set terrain.import-file=FILE} says what the imported map holds before the frame order: its
 * samples, spacing, extent and height range, from a raw float32 model with a sidecar written here, so every figure
 * expected follows from the file. {@code --frame} keeps it free of OpenGL.
 */
class InfoImportTest {

    private static final int W = 120;
    private static final int H = 70;
    private static final double SPACING = 25;
    /** The model rises west to east from LOW to HIGH metres. */
    private static final float LOW = 120;
    private static final float HIGH = 480;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @TempDir
    Path dir;

    @Test
    void infoPrintsTheImportedMapsExtentSpacingAndRange() throws Exception {
        ByteBuffer raw = ByteBuffer.allocate(W * H * Float.BYTES).order(ByteOrder.LITTLE_ENDIAN);
        for (int z = 0; z < H; z++) {
            for (int x = 0; x < W; x++) {
                raw.putFloat(LOW + (HIGH - LOW) * x / (W - 1));
            }
        }
        Path file = Files.write(dir.resolve("ramp.raw"), raw.array());
        Files.writeString(dir.resolve("ramp.json"), String.format(Locale.ROOT,
                "{\"width\": %d, \"height\": %d, \"spacing\": %s}", W, H, SPACING));

        assertEquals(0, Main.execute("info", "--frame", "--set", "terrain.import-file=" + file), console.stderr());
        String out = console.stdout();
        String first = out.lines().findFirst().orElse("");
        assertTrue(first.startsWith("terrain:   " + file), out);
        for (String expected : new String[] {
                W + "×" + H + " samples",
                String.format(Locale.ROOT, "%.2f × %.2f m apart", SPACING, SPACING),
                // from the first sample's centre to the last's
                String.format(Locale.ROOT, "%.2f × %.2f km", (W - 1) * SPACING / 1000, (H - 1) * SPACING / 1000),
                String.format(Locale.ROOT, "heights %.1f .. %.1f m", LOW, HIGH),
                "true scale"}) {
            assertTrue(first.contains(expected), "'" + expected + "' in: " + first);
        }
        assertTrue(out.contains("Frame order"), "the frame order follows: " + out);
    }

    @Test
    void withoutAnImportInfoSaysNothingOfAMap() throws Exception {
        assertEquals(0, Main.execute("info", "--frame"), console.stderr());
        assertFalse(console.stdout().contains("terrain:"), console.stdout());
    }
}
