package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.gl.ShaderPreprocessor;
import org.openworld.engine.gl.ShaderSources;
import org.openworld.engine.terrain.TerrainVariant.Kind;
import org.openworld.engine.terrain.TerrainVariant.Layout;
import org.openworld.engine.terrain.TerrainVariant.Light;
import org.openworld.engine.terrain.material.MaterialSettings.Cliffs;
import org.openworld.engine.terrain.material.MaterialSettings.Tiling;

/**
 * The terrain's program variants, without OpenGL: a role names one compiled source, every choice a variant reads
 * reaches its defines, and every define it yields is one the shaders test.
 */
class TerrainVariantTest {

    /** Every combination of the record's choices, before the kinds drop what they do not read. */
    private static List<TerrainVariant> everyCombination(Layout layout) {
        List<TerrainVariant> all = new ArrayList<>();
        for (Kind kind : Kind.values()) {
            for (Tiling tiling : Tiling.values()) {
                for (Cliffs cliffs : Cliffs.values()) {
                    for (Light light : Light.values()) {
                        all.add(new TerrainVariant(kind, tiling, cliffs, light, layout));
                    }
                }
            }
        }
        return all;
    }

    /** What the GL compiles: the stage files and the set of defines (their order does not matter). */
    private static List<Object> source(TerrainVariant v) {
        return List.of(v.stages(), Set.copyOf(v.defines()));
    }

    @ParameterizedTest
    @EnumSource(Layout.class)
    void twoCombinationsShareARoleExactlyWhenTheyCompileTheSameSource(Layout layout) {
        List<TerrainVariant> all = everyCombination(layout);
        for (TerrainVariant a : all) {
            for (TerrainVariant b : all) {
                assertEquals(source(a).equals(source(b)), a.role().equals(b.role()), a + " and " + b);
                assertEquals(a.equals(b), a.role().equals(b.role()), a + " and " + b);
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Layout.class)
    void eachChoiceReachesTheDefinesOfTheKindsThatReadIt(Layout layout) {
        for (TerrainVariant v : everyCombination(layout)) {
            List<String> d = v.defines();
            assertEquals(d.size(), Set.copyOf(d).size(), "no define twice: " + v);
            assertEquals(layout == Layout.CLIPMAP, d.contains("TERRAIN_CLIPMAP"), "every kind reads the heights: " + v);
            if (v.kind() == Kind.NEAR) {
                assertTrue(d.containsAll(v.tiling().defines()), "the near material lays its tiles: " + v);
                assertEquals(v.cliffs() == Cliffs.TRIPLANAR, d.contains("MAT_TRIPLANAR"), v.toString());
            }
            if (v.kind() == Kind.NEAR || v.kind() == Kind.FAR) {
                assertEquals(v.light() == Light.UNSHADOWED, d.contains("SUN_UNSHADOWED"), v.toString());
            }
            // the far field lies beyond every cascade: never a shadow lookup
            assertEquals(v.kind() == Kind.FAR_FIELD || v.light() == Light.UNSHADOWED, d.contains("SUN_UNSHADOWED"));
            // the unbounded world bakes nothing: its far ground samples the materials at the coarse scale alone
            assertEquals(d.contains("TERRAIN_FAR") && layout == Layout.CLIPMAP, d.contains("MAT_COARSE_ONLY"),
                    v.toString());
        }
    }

    @Test
    void theFarProgramOfATileServesEveryTilingAndTheClipmapsOneEach() {
        Set<String> tile = new HashSet<>();
        Set<String> clipmap = new HashSet<>();
        for (Tiling tiling : Tiling.values()) {
            tile.add(TerrainVariant.far(tiling, Light.SHADOWED, Layout.TILE).role());
            clipmap.add(TerrainVariant.far(tiling, Light.SHADOWED, Layout.CLIPMAP).role());
        }
        assertEquals(Set.of("program.far"), tile, "the bake holds whichever tiling made it");
        assertEquals(Tiling.values().length, clipmap.size());
    }

    @ParameterizedTest
    @EnumSource(Layout.class)
    void everyDefineIsOneTheStagesItCompilesTest(Layout layout) {
        ShaderPreprocessor preprocessor = new ShaderPreprocessor(ShaderSources.classpath());
        for (TerrainVariant v : TerrainVariant.all(layout, Cliffs.TRIPLANAR)) {
            String source = String.join("\n", v.stages().stream()
                    .map(stage -> preprocessor.expand(stage).source()).toList());
            for (String define : v.defines()) {
                Pattern tested = Pattern.compile("#\\s*(el)?if(n?def\\s+" + define + "\\b|.*defined\\s*\\(\\s*"
                        + define + "\\s*\\))");
                assertTrue(tested.matcher(source).find(), define + " is tested in " + v.stages() + " (" + v + ")");
            }
        }
    }

    @Test
    void allListsEachProgramOnce() {
        for (Layout layout : Layout.values()) {
            List<TerrainVariant> all = TerrainVariant.all(layout, Cliffs.PLANAR);
            assertEquals(all.size(), all.stream().map(TerrainVariant::role).distinct().count());
            Set<String> combinations = new HashSet<>();
            everyCombination(layout).stream().filter(v -> v.cliffs() == Cliffs.PLANAR)
                    .forEach(v -> combinations.add(v.role()));
            assertEquals(combinations, Set.copyOf(all.stream().map(TerrainVariant::role).toList()));
        }
    }
}
