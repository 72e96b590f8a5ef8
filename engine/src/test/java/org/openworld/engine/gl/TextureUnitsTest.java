package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

class TextureUnitsTest {

    /** The main sources of both modules (the tests run in engine/). */
    static final List<Path> SOURCES = List.of(Path.of("src/main/java"), Path.of("../demo/src/main/java"));
    /**
     * A unit numbered by hand: an int constant named {@code UNIT_...} given a number, a sampler set to a number, a
     * texture bound to a number.
     */
    static final Pattern BY_HAND = Pattern.compile(
            "int UNIT_\\w+ = \\d|\\.sampler\\(\"\\w+\", *\\d|\\.bind\\(\\d");

    /** The places in {@code source} that number a unit by hand, one line each. */
    static List<String> byHand(String file, String source) {
        List<String> found = new ArrayList<>();
        Matcher m = BY_HAND.matcher(source);
        while (m.find()) {
            found.add(file + ": " + m.group());
        }
        return found;
    }

    @Test
    void samplersGetTheUnitsFromZeroInTheOrderAdded() {
        TextureUnits units = new TextureUnits();
        assertEquals(new TextureUnits.Sampler("heights", 0), units.add("heights"));
        assertEquals(new TextureUnits.Sampler("gradients", 1), units.add("gradients"));
    }

    @Test
    void aSamplerAddedTwiceIsRefused() {
        TextureUnits units = new TextureUnits();
        units.add("scene");
        assertThrows(IllegalArgumentException.class, () -> units.add("scene"));
    }

    @Test
    void theSystemsUnitsNeverReachTheSharedOnes() {
        TextureUnits units = new TextureUnits();
        Set<Integer> shared = new HashSet<>();
        for (SharedTexture texture : SharedTexture.values()) {
            shared.add(texture.unit());
        }
        // every unit below the shared ones can be handed out, and not one more
        for (int i = 0; i < SharedTexture.lowestUnit(); i++) {
            assertTrue(!shared.contains(units.add("s" + i).unit()));
        }
        IllegalStateException full = assertThrows(IllegalStateException.class, () -> units.add("one-too-many"));
        assertTrue(full.getMessage().contains("one-too-many"), full.getMessage());
    }

    @Test
    void theSharedTexturesTakeTheTopOfTheSixteenGuaranteedUnits() {
        // OpenGL 3.3 guarantees 16 units to a fragment shader; the shared textures take its last ones, distinct
        Set<Integer> units = new HashSet<>();
        for (SharedTexture texture : SharedTexture.values()) {
            assertTrue(texture.unit() < 16 && units.add(texture.unit()), texture + " on unit " + texture.unit());
        }
        assertEquals(15, SharedTexture.values()[SharedTexture.values().length - 1].unit());
    }

    @Test
    void noSourceNumbersAUnitByHand() throws IOException {
        List<String> found = new ArrayList<>();
        for (Path root : SOURCES) {
            try (Stream<Path> files = Files.walk(root)) {
                for (Path f : files.filter(p -> p.toString().endsWith(".java")).sorted().toList()) {
                    found.addAll(byHand(f.toString(), Files.readString(f)));
                }
            }
        }
        assertEquals(List.of(), found, "texture units come from a TextureUnits, not from numbers");
    }

    @Test
    void aUnitNumberedByHandIsFound() {
        String source = """
                static final int UNIT_FIELD = 0;
                program.sampler("cloudField", 1);
                field.bind(2);
                program.sampler(FIELD);
                field.bind(FIELD.unit());
                """;
        assertEquals(3, byHand("Clouds.java", source).size(), byHand("Clouds.java", source).toString());
    }
}
