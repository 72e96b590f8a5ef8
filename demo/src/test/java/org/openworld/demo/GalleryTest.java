package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.demo.Figure.Tool;

/** The gallery page and its command lines, without OpenGL. */
class GalleryTest {

    @Test
    void escapeLeavesNoMarkupCharacter() {
        String escaped = Gallery.escape("<b>\"Tom's\" & 'Jerry's'</b>");
        for (char c : "<>\"'".toCharArray()) {
            assertEquals(-1, escaped.indexOf(c), escaped);
        }
        assertEquals("&lt;b&gt;&quot;Tom&#39;s&quot; &amp; &#39;Jerry&#39;s&#39;&lt;/b&gt;", escaped);
    }

    @Test
    void aShellSplitsTheLineBackIntoTheSameWords() throws Exception {
        List<String> words = List.of("shot", "--out", "a b.png", "--camera=-780,10,0,270,-2", "--set",
                "terrain.import-file=it's here/h.png", "--set", "x=$HOME;`ls`*", "plain/path_1.png");
        String line = Gallery.shellLine(words);
        assertEquals(words, shellWords(line));
        assertTrue(line.contains(" --camera=-780,10,0,270,-2 "), "plain words stay unquoted: " + line);
    }

    @Test
    void pageGroupsByFigureEscapesTheTextAndLinksEveryFile() {
        Figure shot = new Figure("5a", 5, "A caption with <tags> & \"quotes\"", "Look at the horizon", Tool.SHOT,
                List.of("--seed", "1"));
        Figure maps = new Figure("2", 2, "(a) maps", "Height and snow", Tool.HEIGHTMAP, List.of("--seed", "1"));
        Gallery.Made made = new Gallery.Made("openworld figures --out g", "llvmpipe, headless-egl", "2017-06-01 12:00",
                new Size(320, 180), 1, List.of("terrain.size=256"), "", 12);
        Figure strip = new Figure("7-samples-noon", 7, "(findings)", "Samples", Tool.STRIP,
                List.of("--samples", "1"));
        String html = Gallery.html(made, List.of(
                plate(maps, "openworld heightmap --out 2 --seed 1", "", 1),
                plate(shot, "openworld shot --out 5a.png --set 'a=<b>'", "", 2),
                plate(strip, "openworld sky-strip --out 7-samples-noon.png --samples 1", "1: 22.42 <", 3)));

        assertTrue(html.contains("A caption with &lt;tags&gt; &amp; &quot;quotes&quot;"), html);
        assertFalse(html.contains("<tags>"));
        assertTrue(html.contains("<code>openworld shot --out 5a.png --set &#39;a=&lt;b&gt;&#39;</code>"), html);
        for (String file : List.of("5a.png", "2/height.png", "2/snow.png", "2/spectrum.png")) {
            assertTrue(html.contains("<img src=\"" + file + "\""), file);
        }
        assertTrue(html.indexOf("id=\"figure-2\"") < html.indexOf("id=\"figure-5\""), "figures in the given order");
        assertTrue(html.contains("<p class=\"measured\">Measured: 1: 22.42 &lt;</p>"), "a strip's numbers, escaped");
        assertEquals(2, html.split("class=\"measured\"", -1).length, "only the plate that measured shows numbers");
        assertTrue(html.contains("llvmpipe, headless-egl") && html.contains("320×180") && html.contains("seed 1")
                && html.contains("terrain.size=256"), "the header says how the set was made");
    }

    @Test
    void aPresetRunShowsEachPresetPictureBesideTheDefaultOne() {
        Figure shot = new Figure("13a", 13, "Water", "Alpha 0", Tool.SHOT, List.of("--seed", "1"));
        Figure paper = shot.with("13a-paper", List.of("--preset", "paper"));
        Figure strip = new Figure("7-samples-noon", 7, "(findings)", "Samples", Tool.STRIP,
                List.of("--samples", "1"));
        Gallery.Made made = new Gallery.Made("openworld figures --out g --preset paper", "llvmpipe", "2017-06-01 12:00",
                new Size(320, 180), 1, List.of(), "paper", 12);
        String html = Gallery.html(made, List.of(
                new Gallery.Plate(strip, List.of(new Gallery.Picture(strip, "openworld sky-strip --out "
                        + "7-samples-noon.png", "1: 22.42", 1))),
                new Gallery.Plate(shot, List.of(new Gallery.Picture(shot, "openworld shot --out 13a.png", "", 1),
                        new Gallery.Picture(paper, "openworld shot --out 13a-paper.png --preset paper", "", 2)))));

        String plate = html.substring(html.indexOf("<figure id=\"13a\">"), html.indexOf("</figure>",
                html.indexOf("<figure id=\"13a\">")));
        assertTrue(plate.indexOf(">default<") < plate.indexOf("src=\"13a.png\"")
                && plate.indexOf("src=\"13a.png\"") < plate.indexOf(">--preset paper<")
                && plate.indexOf(">--preset paper<") < plate.indexOf("src=\"13a-paper.png\""),
                "one entry: the default picture, then the preset's, each under its label: " + plate);
        assertTrue(plate.contains("<code>openworld shot --out 13a-paper.png --preset paper</code>"), plate);
        assertEquals(1, plate.split("class=\"id\"", -1).length - 1, "one caption for both");
        String strips = html.substring(html.indexOf("<figure id=\"7-samples-noon\">"),
                html.indexOf("<figure id=\"13a\">"));
        assertFalse(strips.contains("class=\"label\""), "a picture made once has no label");
        assertTrue(html.contains("<body class=\"beside\">") && html.contains("3 pictures"), html);
    }

    private static Gallery.Plate plate(Figure figure, String command, String measured, double seconds) {
        return new Gallery.Plate(figure, List.of(new Gallery.Picture(figure, command, measured, seconds)));
    }

    /** The words {@code sh} makes of a line, one per printed line. */
    private static List<String> shellWords(String line) throws IOException, InterruptedException {
        Process sh = new ProcessBuilder("sh", "-c", "for w in " + line + "; do printf '%s\\n' \"$w\"; done")
                .redirectErrorStream(true).start();
        String out = new String(sh.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, sh.waitFor(), out);
        return new ArrayList<>(List.of(out.split("\n")));
    }
}
