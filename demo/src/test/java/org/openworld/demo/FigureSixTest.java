package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.colour.Lab;
import org.openworld.engine.gl.Image;

/**
 * Figure 6 as the catalogue makes it, at a small size: the ground below the horizon shows only the colours of the
 * levels, with nothing darker than the level colouring's floor in it (a plant, a crack, a NaN: each a dark dot).
 */
@Tag("gl")
class FigureSixTest {

    /**
     * The levels colouring (shaders/terrain/terrain.frag) draws a level's colour times (0.25 + 1.5 lightness), the
     * lightness 0 in the deepest shadow and at most 1: the darkest ground is 0.25 / 1.75 = 1/7 of the brightest of
     * its level. The colours' brightest channels lie between 0.80 and 0.95, so against the brightest pixel of any
     * level, 1/7 times 0.80 / 0.95. The display transform compresses bright light more than dim, so it only raises
     * this ratio; the air over the near ground (the lower half: within 1.5 km at this pose) dims each pixel alike to
     * within a few per cent, which the factor of two on the floor covers.
     */
    private static final double FLOOR = 0.5 * (0.25 / 1.75) * (0.80 / 0.95);

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @Test
    void theLevelsPictureShowsNoPixelDarkerThanTheLevelColouringsFloor() throws Exception {
        Figure figure = FigureCatalogue.all().stream().filter(f -> f.id().equals("6b")).findFirst().orElseThrow();
        Path out = dir.resolve("6b.png");
        List<String> args = new ArrayList<>(List.of("shot", "--out", out.toString()));
        args.addAll(figure.arguments());
        // small and fast; the lake is not level-coloured (it is water, drawn dark blue), so it is left out here
        args.addAll(List.of("--size", "320x180", "--set", "terrain.size=512", "--set", "system.water=off"));
        assertEquals(0, Main.execute(args.toArray(String[]::new)), console.stderr());

        Image image = Image.read(out);
        int top = image.height() / 2; // the pose looks 22 degrees down: the lower half is ground
        double brightest = 0;
        for (int y = top; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                brightest = Math.max(brightest, brightestChannel(image, x, y));
            }
        }
        int dark = 0;
        for (int y = top; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                if (brightestChannel(image, x, y) < FLOOR * brightest) {
                    dark++;
                }
            }
        }
        assertEquals(0, dark, "pixels of the ground darker than " + FLOOR + " of its brightest, " + brightest);
        assertTrue(brightest > 0.1, "the ground is lit: " + brightest);
    }

    /** The brightest of a pixel's three channels, in linear light. */
    private static double brightestChannel(Image image, int x, int y) {
        double max = 0;
        for (int c = 0; c < 3; c++) {
            max = Math.max(max, Lab.linear(image.channel(x, y, c)));
        }
        return max;
    }
}
