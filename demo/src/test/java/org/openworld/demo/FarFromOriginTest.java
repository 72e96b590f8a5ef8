package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * The world far from its origin is the world near it: positions reach the GPU from the render origin
 * (org.openworld.engine.origin), so neither the relief nor its materials turn to blocks, specks or holes thousands of
 * kilometres out. The whole demo scene (sky, terrain, trees, shadows) through {@code openworld shot}, small.
 */
@Tag("gl")
class FarFromOriginTest {

    /** Small pictures: a shot is a few seconds on llvmpipe. */
    static final String SIZE = "240x135";
    /** The default tile's period, metres: it repeats every size × spacing (4096 m). */
    static final double PERIOD = TerrainSettings.DEFAULTS.size() * TerrainSettings.DEFAULTS.spacing();
    /** Periods out: 10 000 km, where a float's neighbours are 1 m apart. */
    static final long PERIODS = 2442;
    /**
     * Mean ΔE00 between the tile at home and the tile 2442 periods out. The relief, its maps and its detail textures
     * repeat with the tile, but the materials' macro tint (120 m value noise) and their coarse tiles (17 m, turned)
     * do not, so even exact arithmetic leaves the two pictures a little apart: one period out they measure 0.025
     * (480 × 270, 1 % of the pixels above ΔE00 1, on the tints' edges), 2442 periods out 0.036 here. A float's
     * error adds to it: the code before the render origin measured 1.55 in this very test (35 % of the pixels
     * above 1, the ground's detail in blocks). 0.1 is three times the tint's share, fifteen times below the failure.
     * The plants are left out: they do not repeat with the tile (each is drawn from a hash of the world's cell, the
     * forests from noise over the plane), so 2442 periods out another stand grows (here a clearing: 0.38 with them);
     * how their feet keep their centimetres there is {@code TreePlacementTest}'s.
     */
    static final double MOST_MEAN_DELTA_E = 0.1;
    /**
     * The share of the far unbounded world's pixels whose colour the picture at the origin lacks (no pixel of it
     * within one 16-level bin on each channel). The unbounded world never repeats, so the far picture is another
     * relief, but one of the same ground, rock, snow, water and sky; the float garbage it showed before was a colour
     * of none of them (cyan, green and yellow specks in the valleys): 0.42 % of the pixels at 1000 km in this very
     * test on the code before the render origin, none with it, at 1000 km and at 10 000 km. 0.1 % (32 pixels)
     * leaves room for a rare shade of a relief the origin's picture lacks.
     */
    static final double MOST_FOREIGN = 0.001;
    /**
     * The plants' pixels (ΔE00 above 1 against the same view without them) 2442 periods out, as a share of those at
     * home. The tile's ground repeats, the forests' noise does not, so the two views grow other stands of the same
     * density field: a share near 1, not 1 (2553 pixels far out against 1322 at home here, 1.9 times). Half is far
     * below it and far above the failure: feet kept as world floats put every plant 10 000 km from the viewer, and
     * the fade left none standing (0 pixels in this very view on the code before).
     */
    static final double LEAST_PLANT_SHARE = 0.5;
    /** Channel levels per colour bin. */
    static final int BIN = 16;

    /** The shots made, by name: the tests share the tile's views (a shot is seconds). */
    private static final Map<String, Image> SHOTS = new HashMap<>();

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @Test
    void theTileTwoThousandFourHundredFortyTwoPeriodsOutIsTheTileAtHome() throws IOException {
        Image home = tile(1000);
        Image far = tile(1000 + PERIODS * PERIOD);
        ImageComparison comparison = ImageComparison.of(home, far);
        System.out.println("tile " + PERIODS + " periods out: mean dE00 " + comparison.meanDeltaE() + ", "
                + comparison.pixelsAbove(1) + " of " + comparison.pixels() + " pixels above 1");
        assertTrue(comparison.meanDeltaE() < MOST_MEAN_DELTA_E, "the tile " + PERIODS + " periods ("
                + PERIODS * PERIOD / 1000 + " km) out against home: mean dE00 " + comparison.meanDeltaE() + ", "
                + comparison.pixelsAbove(1) + " pixels above 1");
    }

    @Test
    void thePlantsStandTwoThousandFourHundredFortyTwoPeriodsOutAsAtHome() throws IOException {
        int home = ImageComparison.of(tile(1000), tile(1000, "on")).pixelsAbove(1);
        double farX = 1000 + PERIODS * PERIOD;
        int far = ImageComparison.of(tile(farX), tile(farX, "on")).pixelsAbove(1);
        System.out.println("plant pixels at home " + home + ", " + PERIODS + " periods out " + far);
        assertTrue(home > 0, "the view at home shows plants");
        assertTrue(far >= LEAST_PLANT_SHARE * home, PERIODS + " periods out the plants cover " + far
                + " pixels, at home " + home);
    }

    @Test
    void theUnboundedWorldFarOutShowsNoColourTheOriginLacks() throws IOException {
        Image home = unbounded(0);
        boolean[][][] palette = palette(home);
        for (double out : new double[] {1e6, 1e7}) {
            Image far = unbounded(out);
            double foreign = foreignShare(far, palette);
            System.out.println("unbounded world at " + out / 1000 + " km: " + foreign + " of the pixels foreign");
            assertTrue(foreign < MOST_FOREIGN, "the unbounded world at " + out / 1000 + " km has " + foreign
                    + " of its pixels in colours the picture at the origin lacks (garbage)");
        }
    }

    private Image tile(double x) throws IOException {
        return tile(x, "off");
    }

    /** The tile's view from x, the plants on or off. */
    private Image tile(double x, String vegetation) throws IOException {
        return shot("tile-" + (long) x + "-vegetation-" + vegetation, "--time", "12:00", "--camera",
                x + ",600,1000,45,-60", "--set", "terrain.world=tile", "--set", "system.water=off", "--set",
                "system.vegetation=" + vegetation);
    }

    private Image unbounded(double at) throws IOException {
        return shot("unbounded-" + (long) at, "--time", "15:00", "--camera", at + ",1500," + at + ",300,-6");
    }

    private Image shot(String name, String... options) throws IOException {
        Image made = SHOTS.get(name);
        if (made != null) {
            return made;
        }
        Path out = dir.resolve(name + ".png");
        String[] args = new String[options.length + 5];
        args[0] = "shot";
        args[1] = "--out";
        args[2] = out.toString();
        args[3] = "--size";
        args[4] = SIZE;
        System.arraycopy(options, 0, args, 5, options.length);
        assertEquals(0, Main.execute(args), console.stderr());
        Path kept = Path.of("target/test-images/far-" + name + ".png");
        Files.createDirectories(kept.getParent());
        Files.copy(out, kept, StandardCopyOption.REPLACE_EXISTING);
        made = Image.read(out);
        SHOTS.put(name, made);
        return made;
    }

    /** The colour bins the picture fills. */
    private static boolean[][][] palette(Image image) {
        int n = 256 / BIN;
        boolean[][][] filled = new boolean[n][n][n];
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                filled[image.channel(x, y, 0) / BIN][image.channel(x, y, 1) / BIN][image.channel(x, y, 2) / BIN] = true;
            }
        }
        return filled;
    }

    /** The share of the pixels whose bin and its neighbours (one bin each way on each channel) are all empty. */
    private static double foreignShare(Image image, boolean[][][] palette) {
        int n = palette.length;
        int foreign = 0;
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                int r = image.channel(x, y, 0) / BIN;
                int g = image.channel(x, y, 1) / BIN;
                int b = image.channel(x, y, 2) / BIN;
                boolean known = false;
                for (int i = Math.max(r - 1, 0); i <= Math.min(r + 1, n - 1) && !known; i++) {
                    for (int j = Math.max(g - 1, 0); j <= Math.min(g + 1, n - 1) && !known; j++) {
                        for (int k = Math.max(b - 1, 0); k <= Math.min(b + 1, n - 1) && !known; k++) {
                            known = palette[i][j][k];
                        }
                    }
                }
                foreign += known ? 0 : 1;
            }
        }
        return (double) foreign / (image.width() * image.height());
    }
}
