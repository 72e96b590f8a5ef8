package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CameraPathParserTest {

    private static final String SOURCE = "assets/paths/x.path";

    @Test
    void parsesAValidFile() throws CameraPathFormatException {
        CameraPath path = CameraPathParser.parse(SOURCE, """
                # a walk
                heights ground   # eye height above the terrain

                # time x y z yaw pitch fov
                0     10   1.7  -20   90   -5
                2.5   13  +1.7  -20.5 95.5 -4.5  55   # trailing comment
                \t4e0  .5   1.7  -21   100  0
                """);
        assertEquals(HeightReference.GROUND, path.heights());
        assertEquals(3, path.keys().size());
        assertEquals(new Keyframe(0, 10, 1.7, -20, 90, -5, CameraPose.DEFAULT_FOV), path.keys().get(0));
        assertEquals(new Keyframe(2.5, 13, 1.7, -20.5, 95.5, -4.5, 55), path.keys().get(1));
        assertEquals(new Keyframe(4, 0.5, 1.7, -21, 100, 0, CameraPose.DEFAULT_FOV), path.keys().get(2));
        assertEquals(4, path.duration());
    }

    @Test
    void refusesAPositionBeyondTheRenderersReach() throws CameraPathFormatException {
        assertError("0 0 0 0 0 0\n1 0 100 -2e7 0 0\n", "2:9: expected z within -16777216 .. 16777216 m (2^24 m, the "
                + "renderer's reach), found '-2e7'");
        assertError("0 1e9 400 1e9 45 -10\n1 0 0 0 0 0\n", "1:3: expected x within -16777216 .. 16777216 m (2^24 m, "
                + "the renderer's reach), found '1e9'");
        double edge = CameraPose.MAX_COORDINATE_M;
        assertEquals(edge, CameraPathParser.parse(SOURCE, "0 " + edge + " 0 0 0 0\n1 0 0 0 0 0\n").keys().get(0).x(),
                "the limit itself is drawable");
    }

    @Test
    void heightsDefaultToSeaLevel() throws CameraPathFormatException {
        assertEquals(HeightReference.SEA, CameraPathParser.parse(SOURCE, "0 0 0 0 0 0\n1 0 0 0 0 0\n").heights());
    }

    @Test
    void reportsABadNumber() {
        assertError("0 0 0 0 0 0\n\n\n\n\n#\n1.5  0 0 0 0 abc\n", "7:14: expected a number for pitch, found 'abc'");
        assertError("0 0 0 0 0 0\n1 NaN 0 0 0 0\n", "2:3: expected a number for x, found 'NaN'");
        assertError("0 0 0 0 0 0\n1 0 1e999 0 0 0\n", "2:5: expected a finite number for y, found '1e999'");
    }

    /** Found by the fuzz test: finite but huge numbers overflowed the curve, and the path sampled as NaN. */
    @Test
    void reportsANumberTooLargeForThePathArithmetic() throws CameraPathFormatException {
        assertError("0 0 0 0 0 0\n1 -1e308 0 0 0 0\n", "2:3: expected a number within ±1e9 for x, found '-1e308'");
        assertError("0 0 0 0 0 0\n1e10 0 0 0 0 0\n", "2:1: expected a number within ±1e9 for time, found '1e10'");
        // times and yaws at the arithmetic's bound, positions at the renderer's reach
        CameraPath widest = CameraPathParser.parse(SOURCE, "-1e9 -1e6 1e6 -1e6 -1e9 0\n1e9 1e6 -1e6 1e6 1e9 0\n");
        CameraPose middle = widest.sample(0, (x, z) -> 0);
        assertTrue(Double.isFinite(middle.x()) && Double.isFinite(middle.y()) && Double.isFinite(middle.yaw()),
                middle.toString());
    }

    @Test
    void reportsTooFewAndTooManyFields() {
        assertError("0 0 0 0 0 0\n1  2 3 4 5\n", "2:11: expected a number for pitch, found end of line");
        assertError("0 0 0 0 0 0 60 7\n1 0 0 0 0 0\n", "1:16: expected end of line after fov, found '7'");
    }

    @Test
    void reportsATimeThatDoesNotIncrease() {
        assertError("0 0 0 0 0 0\n2.5 0 0 0 0 0\n  2 0 0 0 0 0\n",
                "3:3: expected a time at least 0.001 s after the previous key's 2.5, found '2'");
        assertError("0 0 0 0 0 0\n0 1 0 0 0 0\n",
                "2:1: expected a time at least 0.001 s after the previous key's 0, found '0'");
    }

    /** Keys closer than the format's 1 ms: 1e-320 s apart, a pitch turn's slope overflowed and sampled as NaN. */
    @Test
    void reportsKeysCloserThanAMillisecond() {
        assertError("0 0 0 0 0 -89\n1e-320 0 0 0 0 89\n",
                "2:1: expected a time at least 0.001 s after the previous key's 0, found '1e-320'");
        assertError("5 0 0 0 0 0\n5.0009 0 0 0 0 0\n",
                "2:1: expected a time at least 0.001 s after the previous key's 5, found '5.0009'");
    }

    /** Keys 1 ms apart as the writer prints them read back, though their difference rounds a hair below 0.001. */
    @Test
    void readsKeysOneMillisecondApart() throws CameraPathFormatException {
        CameraPath path = CameraPathParser.parse("x.path", "100.001 0 0 0 0 -89\n100.002 0 0 0 0 89\n");
        assertTrue(100.002 - 100.001 < 0.001);
        CameraPose middle = path.sample(100.0015, (x, z) -> 0);
        // midway between -89° and 89°: times near 100 s round at 1.4e-14 s, a 1e-11 share of the 1 ms step, so 1e-6° is
        // loose
        assertEquals(0, middle.pitch(), 1e-6);
    }

    @Test
    void reportsAnglesOutOfRange() {
        assertError("0 0 0 0 0 0\n1 0 0 0 0 -90\n", "2:11: expected pitch within [-89, 89] degrees, found '-90'");
        assertError("0 0 0 0 0 0 179\n1 0 0 0 0 0\n", "1:13: expected fov within (1, 179) degrees, found '179'");
    }

    @Test
    void reportsBadDirectives() {
        assertError("speed 3\n", "1:1: expected a keyframe or the directive 'heights', found 'speed'");
        assertError("heights water\n", "1:9: expected 'sea' or 'ground' after heights, found 'water'");
        assertError("heights\n", "1:8: expected 'sea' or 'ground' after heights, found end of line");
        assertError("heights sea now\n", "1:13: expected end of line after heights sea, found 'now'");
        assertError("heights sea\nheights ground\n", "2:1: expected a single heights directive, found a second one");
        assertError("0 0 0 0 0 0\n  heights sea\n",
                "2:3: expected the heights directive before the first keyframe, found it after a keyframe");
    }

    @Test
    void reportsTooFewKeyframes() {
        assertError("# one key\n\n0 0 0 0 0 0\n", "3:1: expected at least 2 keyframes, found 1");
        assertError("", "1:1: expected at least 2 keyframes, found none");
        assertError("heights sea\n# nothing else\n", "2:1: expected at least 2 keyframes, found none");
    }

    @Test
    void reportsAMissingFile(@TempDir Path dir) {
        Path missing = dir.resolve("missing.path");
        CameraPathFormatException e = assertThrows(CameraPathFormatException.class,
                () -> CameraPathParser.parse(missing));
        assertEquals(missing + ":1:1: expected a readable camera path file, found no such file", e.getMessage());
    }

    @Test
    void reportsAnUnreadableFile(@TempDir Path dir) throws Exception {
        Path directory = Files.createDirectory(dir.resolve("a-directory.path"));
        CameraPathFormatException e = assertThrows(CameraPathFormatException.class,
                () -> CameraPathParser.parse(directory));
        // the reason in brackets is the operating system's, e.g. "Is a directory" on Linux
        assertTrue(e.getMessage().startsWith(
                directory + ":1:1: expected a readable camera path file, found an unreadable file ("), e.getMessage());
    }

    @Test
    void reportsAMissingResource() {
        CameraPathFormatException e = assertThrows(CameraPathFormatException.class,
                () -> CameraPathParser.parseResource("assets/paths/none.path"));
        assertEquals("assets/paths/none.path:1:1: expected a readable camera path file, "
                + "found no such resource on the classpath", e.getMessage());
    }

    @Test
    void readsAFileFromDisk(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("ok.path"), "0 0 0 0 0 0\r\n1 2 0 0 0 0\r\n");
        assertEquals(2, CameraPathParser.parse(file).keys().get(1).x());
    }

    private static void assertError(String text, String expected) {
        CameraPathFormatException e = assertThrows(CameraPathFormatException.class,
                () -> CameraPathParser.parse(SOURCE, text));
        assertEquals(SOURCE + ":" + expected, e.getMessage());
    }
}
