package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.colour.DeltaE;
import org.openworld.engine.colour.Lab;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.gl.Image;

/** {@code openworld diff} on small PNGs with known edits: what it prints, the difference image, and the errors. */
class DiffCommandTest {

    private static final int W = 8;
    private static final int H = 6;

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    /** A mid-grey opaque picture, written as a PNG, with the given pixels set to {x, y, r, g, b}. */
    private Path png(String name, int[]... pixels) throws Exception {
        byte[] rgba = new byte[W * H * 4];
        for (int i = 0; i < W * H; i++) {
            rgba[i * 4] = rgba[i * 4 + 1] = rgba[i * 4 + 2] = (byte) 100;
            rgba[i * 4 + 3] = (byte) 255;
        }
        for (int[] p : pixels) {
            int i = (p[1] * W + p[0]) * 4;
            rgba[i] = (byte) p[2];
            rgba[i + 1] = (byte) p[3];
            rgba[i + 2] = (byte) p[4];
        }
        Path file = dir.resolve(name);
        new Image(W, H, rgba).writePng(file);
        return file;
    }

    @Test
    void identicalPicturesHaveNoChangedPixel() throws Exception {
        Path a = png("a.png");
        assertEquals(0, Main.execute("diff", a.toString(), png("b.png").toString()), console.stderr());
        String text = console.stdout();
        assertTrue(text.contains(": 8x6, identical"), text);
        assertTrue(text.contains("changed:     0 of 48 pixels (0.000 %)"), text);
        assertTrue(text.contains("max ΔE00:    0.0000"), text);
    }

    @Test
    void aKnownEditIsCountedMeasuredLocatedAndDrawn() throws Exception {
        Path a = png("a.png");
        Path b = png("b.png", new int[] {5, 3, 255, 255, 255}, new int[] {2, 4, 100, 100, 101});
        Path d = dir.resolve("d.png");
        assertEquals(0, Main.execute("diff", a.toString(), b.toString(), "--out", d.toString()), console.stderr());

        double toWhite = DeltaE.ciede2000(Lab.fromSrgb(100, 100, 100), Lab.fromSrgb(255, 255, 255));
        double toBluish = DeltaE.ciede2000(Lab.fromSrgb(100, 100, 100), Lab.fromSrgb(100, 100, 101));
        // ΔE00 1, the diff command's default threshold: a just-noticeable difference
        assertTrue(toBluish < 1 && toWhite > 1, "one edit below the default threshold, one above");
        String text = console.stdout();
        assertTrue(text.contains(": 8x6, they differ"), text);
        assertTrue(text.contains("changed:     2 of 48 pixels (4.167 %)"), text);
        assertTrue(text.contains("noticeable:  1 pixels (2.083 %), ΔE00 above 1.0"), text);
        assertTrue(text.contains(String.format(Locale.ROOT, "mean ΔE00:   %.4f", (toWhite + toBluish) / 48)), text);
        assertTrue(text.contains(String.format(Locale.ROOT, "max ΔE00:    %.4f at (5, 3)", toWhite)), text);

        Image picture = Image.read(d);
        assertEquals(List.of(255, 255, 0), rgb(picture, 5, 3), "the largest difference is yellow");
        int grey = (int) Math.round(0.5 * 100);
        assertEquals(List.of(grey + 96, grey / 2, grey / 2), rgb(picture, 2, 4),
                "a change below the threshold is a faint red cast over the grey");
        assertEquals(List.of(grey, grey, grey), rgb(picture, 0, 0), "unchanged: the picture in grey, halved");
    }

    @Test
    void theThresholdDecidesWhatIsNoticeable() throws Exception {
        Path a = png("a.png");
        Path b = png("b.png", new int[] {5, 3, 255, 255, 255}, new int[] {2, 4, 100, 100, 101});
        assertEquals(0, Main.execute("diff", a.toString(), b.toString(), "--threshold", "0"));
        assertTrue(console.stdout().contains("noticeable:  2 pixels (4.167 %), ΔE00 above 0.0"), console.stdout());
    }

    @Test
    void differentSizesAreAUserErrorNamingBoth() throws Exception {
        Path a = png("a.png");
        Path small = dir.resolve("small.png");
        new Image(4, 2, new byte[4 * 2 * 4]).writePng(small);
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("diff", a.toString(), small.toString()));
        assertEquals("openworld: the pictures differ in size: " + a + " is 8x6, " + small + " is 4x2",
                console.stderr().strip());
    }

    @Test
    void aMissingOrUnreadableFileIsAUserErrorSayingWhy() throws Exception {
        Path a = png("a.png");
        Path missing = dir.resolve("missing.png");
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("diff", a.toString(), missing.toString()));
        assertEquals("openworld: " + missing + ": no such file", console.stderr().strip());

        Path text = dir.resolve("text.png");
        Files.writeString(text, "not a picture\n");
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("diff", text.toString(), a.toString()));
        String error = console.stderr().lines().reduce((first, second) -> second).orElse("");
        assertTrue(error.startsWith("openworld: " + text + ": not a readable image: ") && error.length() > 60
                && !error.contains("Exception"), "stb's reason follows the file: " + error);
    }

    @Test
    void aNegativeThresholdIsAUserError() throws Exception {
        Path a = png("a.png");
        assertEquals(ExitCode.USER_MISTAKE.code(),
                Main.execute("diff", a.toString(), a.toString(), "--threshold", "-1"));
        assertTrue(console.stderr().contains("--threshold -1.0"), console.stderr());
        assertFalse(console.stdout().contains("changed"), "no comparison printed: " + console.stdout());
    }

    /** A pixel's red, green and blue, so a failure shows all three. */
    private static List<Integer> rgb(Image image, int x, int y) {
        return List.of(image.channel(x, y, 0), image.channel(x, y, 1), image.channel(x, y, 2));
    }
}
