package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.gl.Image;

/** {@code openworld heightmap} as a user runs it: files, printed stages, the generation benchmark, errors. */
class HeightmapCommandTest {

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @Test
    void writesSixteenBitHeightsSnowAndSpectrumAndPrintsEachStage() throws Exception {
        Path folder = dir.resolve("maps");
        assertEquals(0, Main.execute("heightmap", "--out", folder.toString(), "--seed", "3",
                "--set", "terrain.size=256", "--set", "terrain.beta=2"), console.stderr());
        BufferedImage height = ImageIO.read(folder.resolve(HeightmapCommand.HEIGHT_PNG).toFile());
        assertEquals(256, height.getWidth());
        assertEquals(256, height.getHeight());
        assertEquals(16, height.getColorModel().getComponentSize(0), "16 bits per height sample");
        Image snow = Image.read(folder.resolve(HeightmapCommand.SNOW_PNG));
        assertEquals(256, snow.width());
        Image spectrum = Image.read(folder.resolve(HeightmapCommand.SPECTRUM_PNG));
        assertTrue(spectrum.width() > 400);
        for (String line : new String[] {"synthesis", "pyramid", "snow map", "peak heap", "expected -2 beta = -4.00"}) {
            assertTrue(console.stdout().contains(line), "missing '" + line + "' in\n" + console.stdout());
        }
        String slope = console.stdout().replaceAll("(?s).*spectrum slope: (-?[0-9.]+).*", "$1");
        assertEquals(-4.0, Double.parseDouble(slope), 0.15, console.stdout());
    }

    @Test
    void itsHeightPngImportsAgain() throws Exception {
        Path first = dir.resolve("first");
        assertEquals(0, Main.execute("heightmap", "--out", first.toString(), "--set", "terrain.size=256"), console.stderr());
        Path again = dir.resolve("again");
        String png = first.resolve(HeightmapCommand.HEIGHT_PNG).toString();
        assertEquals(0, Main.execute("heightmap", "--out", again.toString(), "--set", "terrain.import-file=" + png),
                console.stderr());
        assertTrue(console.stdout().contains("import "), console.stdout());
        // lowest sample 0 and highest 65535 both times, so the exported heights come back to within rounding
        var a = ImageIO.read(first.resolve(HeightmapCommand.HEIGHT_PNG).toFile()).getRaster();
        var b = ImageIO.read(again.resolve(HeightmapCommand.HEIGHT_PNG).toFile()).getRaster();
        assertEquals(a.getWidth(), b.getWidth());
        int worst = 0;
        for (int z = 0; z < a.getHeight(); z++) {
            for (int x = 0; x < a.getWidth(); x++) {
                worst = Math.max(worst, Math.abs(a.getSample(x, z, 0) - b.getSample(x, z, 0)));
            }
        }
        // one 16-bit step: the heights go through float and back, so a sample may round to its neighbouring step
        assertTrue(worst <= 1, "largest difference in 16-bit steps: " + worst);
    }

    /**
     * {@code --stats} on a small eroded tile (512² at 8 m, routed at level 0): the measures are printed and the
     * drainage picture written; erosion gives the concavity of real channels (0.3–0.6, docs/terrain.md section 6).
     */
    @Test
    void statsMeasureTheDrainageAndDrawIt() throws Exception {
        assertEquals(0, Main.execute("heightmap", "--stats", "--stats-level", "0", "--out", dir.toString(),
                "--set", "terrain.world=tile", "--set", "terrain.size=512", "--set", "terrain.spacing=8",
                "--set", "terrain.min-wavelength=16", "--set", "terrain.erosion=on"), console.stderr());
        for (String line : new String[] {"erosion", "concavity theta", "Hack exponent h", "hypsometric integral",
                "slope percentiles", "drainage density"}) {
            assertTrue(console.stdout().contains(line), "missing '" + line + "' in\n" + console.stdout());
        }
        double theta = Double.parseDouble(console.stdout().replaceAll("(?s).*concavity theta\\s+(-?[0-9.]+).*", "$1"));
        // the concavity of real channels, 0.3–0.6 (see the Javadoc and DrainageStatsTest)
        assertTrue(theta > 0.3 && theta < 0.6, console.stdout());
        Image picture = Image.read(dir.resolve(DrainageReport.DRAINAGE_PNG));
        assertEquals(512, picture.width());
    }

    /** A level the map does not have is one clear line and the user's exit code. */
    @Test
    void statsRefuseALevelTheMapLacks() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--stats", "--stats-level", "20",
                "--out", dir.toString(), "--set", "terrain.world=tile", "--set", "terrain.size=256"));
        assertTrue(console.stderr().contains("--stats-level 20"), console.stderr());
    }

    @Test
    void repeatPrintsTheMedianOfEachStage() {
        assertEquals(0, Main.execute("heightmap", "--out", dir.toString(), "--set", "terrain.size=256",
                "--repeat", "3"), console.stderr());
        assertTrue(console.stdout().contains("run 3/3: snow map"), console.stdout());
        assertTrue(console.stdout().contains("median of 3 runs:"), console.stdout());
        assertTrue(console.stdout().matches("(?s).*median of 3 runs:\\s+synthesis\\s+\\d+ ms\\s+pyramid\\s+\\d+ ms"
                + "\\s+snow map\\s+\\d+ ms\\s+total\\s+\\d+ ms.*"), console.stdout());
    }

    @Test
    void aBandNarrowerThanTwoRingsIsFittedOverAllRings() {
        // the paper preset's band, 512-2048 m, on a 1 km map: one ring of its spectrum lies in it
        assertEquals(0, Main.execute("heightmap", "--out", dir.toString(), "--set", "terrain.size=512",
                "--set", "terrain.beta=1", "--set", "terrain.min-wavelength=512"), console.stderr());
        assertTrue(console.stdout().contains("over all rings: the band of 512-2048 m holds fewer than two rings"),
                console.stdout());
    }

    @Test
    void outThatIsAFileIsAUserError() throws Exception {
        Path file = Files.writeString(dir.resolve("taken"), "x");
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--out", file.toString()));
        assertEquals("openworld: --out " + file + ": is a file, not a folder; give a folder (it is created if missing)",
                console.stderr().strip());
        assertFalse(console.stderr().contains("Exception"), console.stderr());
    }

    @Test
    void badImportFileIsAUserErrorNamingTheFile() throws Exception {
        Path file = Files.write(dir.resolve("heights.raw"), new byte[1000]);
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--out", dir.resolve("o").toString(),
                "--set", "terrain.import-file=" + file));
        assertTrue(console.stderr().contains(file.toString()) && console.stderr().contains("250 float32 samples"), console.stderr());
        assertFalse(console.stderr().contains("Exception"), console.stderr());
    }

    @Test
    void aMapWhosePowerLiesInNoTwoRingsHasNoSlopeInsteadOfAnInternalError() throws Exception {
        // a checkerboard of ±1e30 m (finite float32, 1e60 apart): its power lies at one frequency, past the rings
        int side = 257;
        ByteBuffer raw = ByteBuffer.allocate(side * side * Float.BYTES).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < side * side; i++) {
            raw.putFloat((i % side + i / side) % 2 == 0 ? 1e30f : -1e30f);
        }
        Path file = Files.write(dir.resolve("checkerboard.raw"), raw.array());
        Path out = dir.resolve("maps");
        assertEquals(0, Main.execute("heightmap", "--out", out.toString(), "--set", "terrain.import-file=" + file),
                console.stderr());
        assertTrue(console.stdout().contains("spectrum slope: none"), console.stdout());
        assertTrue(Image.read(out.resolve(HeightmapCommand.SPECTRUM_PNG)).width() > 0, "the spectrum chart is written");
        var heights = ImageIO.read(out.resolve(HeightmapCommand.HEIGHT_PNG).toFile()).getRaster();
        assertEquals(0, heights.getSample(1, 0, 0), "the low squares are black");
        assertEquals(65535, heights.getSample(0, 0, 0), "the high squares are white");
    }

    @Test
    void repeatMustBePositive() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--out", dir.toString(), "--repeat", "0"));
        assertTrue(console.stderr().contains("--repeat"), console.stderr());
    }

    @Test
    void overviewWritesTheUnboundedWorldsHeightsAndReliefWithProgress() throws Exception {
        Path folder = dir.resolve("overview");
        assertEquals(0, Main.execute("heightmap", "--overview", "--out", folder.toString()), console.stderr());
        BufferedImage height = ImageIO.read(folder.resolve(HeightmapCommand.HEIGHT_PNG).toFile());
        assertEquals(WorldOverview.SAMPLES, height.getWidth());
        assertEquals(WorldOverview.SAMPLES, height.getHeight());
        assertEquals(16, height.getColorModel().getComponentSize(0), "16 bits per height sample");
        Image relief = Image.read(folder.resolve(WorldOverview.RELIEF_PNG));
        assertEquals(WorldOverview.SAMPLES, relief.width());
        // shaded: along the diagonal the brightness spans far more than a flat tint would
        double darkest = 255;
        double brightest = 0;
        for (int i = 0; i < relief.width(); i += 7) {
            darkest = Math.min(darkest, relief.luma(i, i));
            brightest = Math.max(brightest, relief.luma(i, i));
        }
        // 80 levels: a hillshade spans sunlit and shaded slopes, a flat tint a few levels
        assertTrue(brightest - darkest > 80, "luma along the diagonal: " + darkest + " .. " + brightest);
        for (String line : new String[] {"pyramid level 4", "64 km across", "( 50 %)", "(100 %)", "peak heap"}) {
            assertTrue(console.stdout().contains(line), "missing '" + line + "' in\n" + console.stdout());
        }
        String slope = console.stdout().replaceAll("(?s).*spectrum slope of the central 1024²: (-?[0-9.]+).*", "$1");
        assertEquals(-4.4, Double.parseDouble(slope), 0.15, console.stdout());
    }

    @Test
    void overviewRefusesWhatItCannotPicture() {
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--overview", "--out", dir.toString(),
                "--set", "terrain.spacing=3"));
        assertTrue(console.stderr().contains("--overview") && console.stderr().contains("3.0 m"), console.stderr());
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--overview", "--out", dir.toString(),
                "--repeat", "2"));
        assertTrue(console.stderr().contains("--repeat"), console.stderr());
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--overview", "--out", dir.toString(),
                "--set", "terrain.import-file=" + dir.resolve("map.png")));
        assertTrue(console.stderr().contains("terrain.import-file"), console.stderr());
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--overview", "--out", dir.toString(),
                "--set", "terrain.world=tile"));
        assertTrue(console.stderr().contains("not terrain.world=tile"), console.stderr());
        assertFalse(console.stderr().contains("Exception"), console.stderr());
    }

    /** The shipped real place: the model's own size and heights (344 rows of 403 int16 samples, 236 .. 1076 m). */
    @Test
    void aRealPlacePrintsItsExtentSpacingAndRange() {
        assertEquals(0, Main.execute("heightmap", "--out", dir.toString(), "--set",
                "terrain.import-file=../assets/elevation/jacksboro-fault.tif", "--set", "terrain.import-detail=false"));
        for (String line : new String[] {"403×344 samples", " m apart", " km, heights 236.0 .. 1076.0 m",
            "(geographic, spacing at 36.5", "tile: 512² samples"}) {
            assertTrue(console.stdout().contains(line), "missing '" + line + "' in\n" + console.stdout());
        }
    }

    @Test
    void aCorruptTiffIsOneLineAndExit2() throws java.io.IOException {
        Path broken = Files.write(dir.resolve("broken.tif"), new byte[] {'I', 'I', 42, 0, 8, 0, 0, 0, 1, 2, 3});
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("heightmap", "--out", dir.resolve("out").toString(),
                "--set", "terrain.import-file=" + broken));
        assertTrue(console.stderr().strip().lines().count() == 1 && console.stderr().contains("not a readable TIFF"),
                console.stderr());
    }
}
