package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

class CameraPathWriterTest {

    /** Half of the last printed decimal: the most a value may move through write and parse. */
    private static final double PRINT_PRECISION = 0.5e-3 + 1e-12;

    @Test
    void roundTripsWithinPrintPrecision() throws CameraPathFormatException {
        Random random = new Random(7);
        List<Keyframe> keys = new ArrayList<>();
        double time = random.nextDouble();
        for (int i = 0; i < 50; i++) {
            time += 0.01 + random.nextDouble();
            keys.add(new Keyframe(time, random.nextGaussian() * 1000, random.nextDouble() * 800,
                    random.nextGaussian() * 1000, random.nextDouble() * 720 - 360, random.nextDouble() * 178 - 89,
                    2 + random.nextDouble() * 170));
        }
        for (HeightReference heights : HeightReference.values()) {
            CameraPath path = new CameraPath(heights, keys);
            String text = CameraPathWriter.format(path);
            CameraPath back = CameraPathParser.parse("written.path", text);
            assertEquals(heights, back.heights());
            assertEquals(keys.size(), back.keys().size());
            for (int i = 0; i < keys.size(); i++) {
                Keyframe a = keys.get(i);
                Keyframe b = back.keys().get(i);
                assertEquals(a.time(), b.time(), PRINT_PRECISION);
                assertEquals(a.x(), b.x(), PRINT_PRECISION);
                assertEquals(a.y(), b.y(), PRINT_PRECISION);
                assertEquals(a.z(), b.z(), PRINT_PRECISION);
                assertEquals(a.yaw(), b.yaw(), PRINT_PRECISION);
                assertEquals(a.pitch(), b.pitch(), PRINT_PRECISION);
                assertEquals(a.fov(), b.fov(), PRINT_PRECISION);
            }
        }
    }

    @Test
    void writesAHeaderAndPlainNumbers() {
        CameraPath path = new CameraPath(HeightReference.GROUND, List.of(
                new Keyframe(0, 1, 1.7, -2.5, 90, 0, 60), new Keyframe(12.25, 3.0004, 1.7, -2.5, 90, -5, 60)));
        String text = CameraPathWriter.format(path);
        assertTrue(text.startsWith("# OpenWorld camera path"), text);
        assertTrue(text.contains("\nheights ground\n"), text);
        assertTrue(text.contains("\n0         1          1.7       -2.5       90       0        60\n"), text);
        assertTrue(text.contains("\n12.25     3          1.7       -2.5       90       -5       60\n"), text);
    }

    @Test
    void refusesKeysThatWouldPrintAtTheSameTime() {
        CameraPath path = new CameraPath(HeightReference.SEA, List.of(
                new Keyframe(1, 0, 0, 0, 0, 0, 60), new Keyframe(1.0001, 0, 0, 0, 0, 0, 60)));
        assertThrows(IllegalArgumentException.class, () -> CameraPathWriter.format(path));
    }
}
