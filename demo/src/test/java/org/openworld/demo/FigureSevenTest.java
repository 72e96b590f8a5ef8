package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code openworld figures --only 7}, which needs no OpenGL: the diagram and the four findings strips are written,
 * and the gallery prints each strip's measured ΔE00, the noticeable ones (over 2) where the strips show them. Tagged
 * gl by the project's rule for any test that runs {@code figures} (GlTestTagsTest), though figure 7 makes no context.
 */
@Tag("gl")
class FigureSevenTest {

    private static final Pattern MEASURED = Pattern.compile("Measured: mean ΔE00 to (\\d+) [a-z ]+: ([^<]*)</p>");

    @TempDir
    Path dir;

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @Test
    void theDiagramAndTheStripsAreMadeAndTheirNumbersPrinted() throws Exception {
        Path out = dir.resolve("gallery");
        assertEquals(0, Main.execute("figures", "--out", out.toString(), "--only", "7"), console.stderr());
        for (String file : List.of("7.png", "7-wavelengths-noon.png", "7-wavelengths-sunset.png",
                "7-samples-noon.png", "7-samples-sunset.png")) {
            assertTrue(Files.isRegularFile(out.resolve(file)), file);
        }

        // each strip: one number per panel, in the catalogue's order; the coarsest noticeable, the finest not
        String html = Files.readString(out.resolve(Gallery.INDEX));
        Matcher line = MEASURED.matcher(html);
        List<String> references = new ArrayList<>();
        while (line.find()) {
            references.add(line.group(1));
            String[] panels = line.group(2).split(", ");
            assertEquals(line.group(1).equals("32") ? 5 : 4, panels.length, line.group());
            // ΔE00 2: about where a difference between two pictures of smooth sky becomes noticeable (1 is the JND
            // between flat patches side by side); the coarsest panel must exceed it, the finest stay under
            assertTrue(deltaE(panels[0]) > 2 && deltaE(panels[panels.length - 1]) < 2, line.group());
        }
        assertEquals(List.of("32", "64", "32", "64"), references, "noon's two strips, then sunset's");

        // the diagram: the ground's green, the view ray's blue and the sun's orange are all drawn
        BufferedImage diagram = ImageIO.read(out.resolve("7.png").toFile());
        assertTrue(has(diagram, 0x8a9a6a) && has(diagram, 0x1f5fbf) && has(diagram, 0xd08000), "parts missing");
    }

    private static double deltaE(String panel) {
        return Double.parseDouble(panel.substring(panel.indexOf(": ") + 2));
    }

    private static boolean has(BufferedImage image, int rgb) {
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                if ((image.getRGB(x, y) & 0xffffff) == rgb) {
                    return true;
                }
            }
        }
        return false;
    }
}
