package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.gl.Image;

/** {@code openworld figures} as a user runs it: real OpenGL (headless), a small world, real files and the gallery. */
@Tag("gl")
class FiguresCommandTest {

    /** A small render and world keep each shot to a few seconds on llvmpipe. */
    private static final String[] SMALL = {"--size", "320x180", "--set", "terrain.size=256"};
    private static final Pattern LINK = Pattern.compile("(?:href|src)=\"([^\"#]+)\"");
    private static final Pattern COMMAND = Pattern.compile("<code>(openworld shot --out 13b\\.png [^<]*)</code>");

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @Test
    void onlyMakesTheAskedFiguresWhoseGalleryLinksEveryFileAndWhoseCommandsRemakeThem() throws Exception {
        Path out = dir.resolve("gallery");
        assertEquals(0, Main.execute(concat(new String[] {"figures", "--out", out.toString(), "--only", "2",
            "--only", "13,8"}, SMALL)), console.stderr());

        // the pictures of figures 2 (maps), 8 (sky) and 13 (water), and nothing else
        List<Figure> asked = FigureCatalogue.all().stream().filter(f -> Set.of(2, 8, 13).contains(f.number())).toList();
        Set<String> expected = new HashSet<>();
        asked.forEach(f -> expected.addAll(f.files()));
        assertEquals(expected, pngsUnder(out));
        for (Figure figure : asked) {
            if (figure.tool() == Figure.Tool.SHOT) {
                Image image = Image.read(out.resolve(figure.output()));
                assertEquals(320, image.width(), figure.id());
                assertEquals(180, image.height(), figure.id());
                assertNotBlank(image, figure.id());
            }
        }
        BufferedImage height = ImageIO.read(out.resolve("2/height.png").toFile());
        assertEquals(256, height.getWidth(), "figure 2's maps at the overridden terrain.size");
        assertTrue(console.stdout().contains("figures: 1/" + asked.size() + " 2 ... "), console.stdout());
        assertTrue(console.stdout().contains("figures: " + asked.size() + "/" + asked.size() + " 13c ... "),
                console.stdout());

        // the gallery: every file written linked, every link a file, only the figures made
        String html = Files.readString(out.resolve(Gallery.INDEX));
        Set<String> links = links(html);
        assertEquals(expected, links);
        links.forEach(l -> assertTrue(Files.isRegularFile(out.resolve(l)), l));
        assertTrue(html.contains("id=\"figure-8\"") && !html.contains("id=\"figure-9\""), "only the figures made");
        assertTrue(html.contains("llvmpipe") || html.contains("OpenGL"), "the header names the renderer");

        // 13b's printed command, run on its own, makes the same picture
        Matcher command = COMMAND.matcher(html);
        assertTrue(command.find(), html);
        List<String> words = new ArrayList<>(Arrays.asList(command.group(1).split(" ")));
        assertEquals(List.of("openworld", "shot", "--out", "13b.png"), words.subList(0, 4));
        assertTrue(words.contains("--set") && words.contains("water.alpha=0.5") && words.contains("terrain.size=256"),
                words.toString());
        Path again = dir.resolve("again.png");
        words.set(3, again.toString());
        assertEquals(0, Main.execute(words.subList(1, words.size()).toArray(String[]::new)), console.stderr());
        Image made = Image.read(out.resolve("13b.png"));
        Image remade = Image.read(again);
        // same world, pose, time and settings through the same code: the very same pixels
        assertEquals(0, meanDifference(made, remade), "the printed command remakes the picture");
    }

    /**
     * Figure 3 shows what the gloss map does: its gloss panel differs noticeably (ΔE00 above 1) from the bare one in
     * a good share of the pixels, and the difference picture beside them is made from the two.
     */
    @Test
    void figureThreesGlossPanelDiffersFromTheBarePanelAndItsDifferenceIsDrawn() throws Exception {
        Path out = dir.resolve("three");
        assertEquals(0, Main.execute("figures", "--out", out.toString(), "--only", "3", "--size", "160x90"),
                console.stderr());
        Image bare = Image.read(out.resolve("3a.png"));
        Image gloss = Image.read(out.resolve("3c.png"));
        ImageComparison comparison = ImageComparison.of(bare, gloss);
        double share = (double) comparison.pixelsAbove(1) / comparison.pixels();
        // a tenth of the pixels beyond ΔE00 1 (a just-noticeable difference): the gloss shows over the lit ground, not
        // in a stray pixel
        assertTrue(share > 0.1, "gloss panel against the bare one: " + share);
        Image drawn = Image.read(out.resolve("3c-diff.png"));
        assertEquals(0, meanDifference(comparison.differenceImage(1), drawn), "3c-diff is 3a against 3c");
    }

    @Test
    void aPresetMakesEachPictureAgainWithItBesideTheDefaultAndItsCommandsRemakeThem() throws Exception {
        Path out = dir.resolve("paper");
        // a 2 km world: the paper's spectrum keeps wavelengths from 512 m, more than a 256² world's tile holds
        assertEquals(0, Main.execute("figures", "--out", out.toString(), "--only", "2,12", "--preset", "paper",
                "--size", "320x180", "--set", "terrain.size=1024"), console.stderr());

        // every picture twice: figure 2's maps take the preset's terrain keys, the shots the preset itself
        Set<String> expected = new HashSet<>();
        for (Figure figure : FigureCatalogue.all()) {
            if (figure.number() == 2 || figure.number() == 12) {
                expected.addAll(figure.files());
                expected.addAll(figure.with(figure.id() + "-paper", List.of()).files());
            }
        }
        assertEquals(expected, pngsUnder(out));
        assertTrue(Files.mismatch(out.resolve("2/height.png"), out.resolve("2-paper/height.png")) >= 0,
                "the paper's spectrum makes another height map");
        // 5 levels of mean difference: plainly another picture, where a preset that changed nothing gives 0
        assertTrue(meanDifference(Image.read(out.resolve("12.png")), Image.read(out.resolve("12-paper.png"))) > 5,
                "the preset changes the shot");

        String html = Files.readString(out.resolve(Gallery.INDEX));
        Set<String> links = links(html);
        assertEquals(expected, links);
        String figure12 = html.substring(html.indexOf("<figure id=\"12\">"),
                html.indexOf("<figure id=\"12-cascades\">"));
        assertTrue(figure12.indexOf("src=\"12.png\"") < figure12.indexOf("src=\"12-paper.png\""),
                "12 and its paper picture in one entry, the default first");

        Matcher maps = Pattern.compile("<code>(openworld heightmap --out 2-paper [^<]*)</code>").matcher(html);
        assertTrue(maps.find(), html);
        assertTrue(maps.group(1).contains("--set terrain.beta=1") && !maps.group(1).contains("shadow."),
                "figure 2 takes the preset's terrain keys alone: " + maps.group(1));

        Matcher command = Pattern.compile("<code>(openworld shot --out 12-paper\\.png [^<]*)</code>").matcher(html);
        assertTrue(command.find(), html);
        List<String> words = new ArrayList<>(Arrays.asList(command.group(1).split(" ")));
        assertTrue(words.contains("--preset") && words.contains("paper"), words.toString());
        Path again = dir.resolve("again.png");
        words.set(3, again.toString());
        assertEquals(0, Main.execute(words.subList(1, words.size()).toArray(String[]::new)), console.stderr());
        assertEquals(0, meanDifference(Image.read(out.resolve("12-paper.png")), Image.read(again)),
                "the printed command remakes the preset's picture");
    }

    @Test
    void unknownPresetIsAUserErrorBeforeAnyPicture() {
        Path out = dir.resolve("none");
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("figures", "--out", out.toString(), "--only", "2",
                "--preset", "papper"));
        assertTrue(console.stderr().contains("unknown preset 'papper'"), console.stderr());
        assertFalse(Files.exists(out));
    }

    @Test
    void unknownFigureIsAUserErrorListingTheFiguresAndMakesNothing() {
        Path out = dir.resolve("none");
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("figures", "--out", out.toString(), "--only", "15"));
        assertTrue(console.stderr().contains("--only 15"), console.stderr());
        assertTrue(console.stderr().contains("1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14"), console.stderr());
        assertFalse(console.stderr().contains("Exception"), console.stderr());
        assertFalse(Files.exists(out));
    }

    @Test
    void badOverrideIsAUserErrorBeforeAnyPicture() {
        Path out = dir.resolve("none");
        assertEquals(ExitCode.USER_MISTAKE.code(), Main.execute("figures", "--out", out.toString(), "--only", "2",
                "--set", "shadow.kernal=3"));
        assertTrue(console.stderr().contains("shadow.kernal"), console.stderr());
        assertFalse(Files.exists(out), "nothing made, not even figure 2's maps, which do not read shadow.*");
    }

    /**
     * A rendered picture, not a cleared screen: a wide spread of brightness and many distinct colours; and opaque, as
     * the window shows it (figure 13's stencil water leaves its alpha in the scene target).
     */
    private static void assertNotBlank(Image image, String id) {
        double min = 255;
        double max = 0;
        Set<Integer> colours = new HashSet<>();
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                assertEquals(255, image.channel(x, y, 3), id + ": alpha at " + x + "," + y);
                min = Math.min(min, image.luma(x, y));
                max = Math.max(max, image.luma(x, y));
                colours.add(image.channel(x, y, 0) << 16 | image.channel(x, y, 1) << 8 | image.channel(x, y, 2));
            }
        }
        // not blank: a luma span of 40 levels and over 200 distinct colours; a flat fill or a blank gives 1 or a
        // handful
        assertTrue(max - min > 40, id + ": luma from " + min + " to " + max);
        assertTrue(colours.size() > 200, id + ": only " + colours.size() + " colours");
    }

    /** Mean absolute difference over every colour channel, 0-255. */
    private static double meanDifference(Image a, Image b) {
        assertEquals(a.width(), b.width());
        assertEquals(a.height(), b.height());
        double sum = 0;
        for (int y = 0; y < a.height(); y++) {
            for (int x = 0; x < a.width(); x++) {
                for (int c = 0; c < 3; c++) {
                    sum += Math.abs(a.channel(x, y, c) - b.channel(x, y, c));
                }
            }
        }
        return sum / (3.0 * a.width() * a.height());
    }

    /** Every file the gallery's page links or shows. */
    private static Set<String> links(String html) {
        Set<String> links = new HashSet<>();
        Matcher link = LINK.matcher(html);
        while (link.find()) {
            links.add(link.group(1));
        }
        return links;
    }

    private static Set<String> pngsUnder(Path root) throws Exception {
        try (Stream<Path> files = Files.walk(root)) {
            Set<String> pngs = new HashSet<>();
            files.filter(p -> p.toString().endsWith(".png"))
                    .forEach(p -> pngs.add(root.relativize(p).toString().replace('\\', '/')));
            return pngs;
        }
    }

    private static String[] concat(String[] a, String[] b) {
        String[] all = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }
}
