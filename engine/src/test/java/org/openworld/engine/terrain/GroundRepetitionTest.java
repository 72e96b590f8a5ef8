package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.ImportedWorld;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.Repetition;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;

/**
 * How much the ground repeats ({@link Repetition}, docs/terrain.md's measure), on a flat grass world seen straight down from
 * 20, 100 and 500 m: the paper's named flaw, 1 m-scale detail textures that tile visibly, as one number per height.
 * The numbers of today's tiling are in docs/terrain.md; here the measure is shown to see the tiles on a real picture:
 * from 100 m (about 115 m of ground across the picture) the 2.7 m detail tile repeats strongly, and with tiles 50 m
 * wide, fewer than three across, it does not; stochastic tiling ({@code materials.tiling=stochastic}) removes the
 * repeat, and so do the quilted Wang tiles ({@code quilted}), laid without a period. Pictures go to
 * {@code target/test-images/ground-repetition-*.png}.
 */
@GlTest
class GroundRepetitionTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 320;
    static final int H = 180;
    static final int SAMPLES = 512;

    @TempDir
    static Path dir;
    static Path flat;

    /** A flat world 2 km wide, 4 m between samples (one raised corner sample, which the import needs for a range). */
    @BeforeAll
    static void writeWorld() throws IOException {
        flat = ImportedWorld.write(dir.resolve("flat.raw"), SAMPLES, (x, z) -> x == 0 && z == 0 ? 1f : 0f);
    }

    /** The repetition of the ground seen straight down from {@code height} metres, with more settings. */
    static double repetition(double height, String... more) throws IOException {
        List<String> settings = new ArrayList<>(List.of("terrain.import-file=" + flat, "terrain.spacing=4",
                "terrain.relief=10", "terrain.sea-fraction=0"));
        settings.addAll(List.of(more));
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings, new TerrainSystem(),
                new CullingSystem())) {
            engine.world().resource(Camera.class).setPose(new CameraPose(100, height, 100, 0, -89, 60));
            engine.update();
            engine.render();
            Image image = engine.readImage();
            image.writePng(Path.of("target/test-images/ground-repetition-" + (int) height
                    + String.join("", List.of(more).stream().map(m -> "-" + m.substring(m.lastIndexOf('=') + 1))
                    .toList()) + ".png"));
            return Repetition.peak(image, 6);
        }
    }

    @Test
    void theDetailTilesRepeatFromAHundredMetresAndWideOnesDoNot() throws IOException {
        double tiled = repetition(100);
        double wide = repetition(100, "materials.detail-scale=50");
        // a peak of 1 is an exact repeat (see RepetitionTest); 0.8 allows the lighting's variation over the tiles; with
        // 50 m tiles no repeat fits in the picture, so only detail's chance likeness (under 0.5) is left
        assertTrue(tiled > 0.8, "repetition from 100 m with the default 2.7 m tiles: " + tiled);
        assertTrue(wide < 0.5, "repetition from 100 m with 50 m tiles: " + wide);
    }

    /**
     * The goal docs/terrain.md states, at most half the repeated tiles' repetition from 20, 100 and 500 m: stochastic tiling meets it
     * by far (0.04 to 0.08 against 0.54 to 0.97: nothing in its pictures repeats), the quilted Wang tiles with 0.20,
     * 0.31 and 0.17 (0.28 to 0.32 of repeat's): two colours per edge leave each edge one of two diamonds, so some
     * likeness at one tile's shift stays, but each tile's own centre block and the random layout break the rest.
     */
    @ParameterizedTest
    @CsvSource({"20", "100", "500"})
    void quiltedAndStochasticTilingRepeatAtMostHalfAsMuch(double height) throws IOException {
        double repeat = repetition(height, "materials.tiling=repeat");
        double quilted = repetition(height, "materials.tiling=quilted");
        double stochastic = repetition(height, "materials.tiling=stochastic");
        String all = String.format(java.util.Locale.ROOT, "repetition from %.0f m: repeat %.3f, quilted %.3f, "
                + "stochastic %.3f", height, repeat, quilted, stochastic);
        System.out.println(all);
        // "at most half", the goal the docs state; the measured values are in the Javadoc above
        assertTrue(stochastic <= 0.5 * repeat, all);
        assertTrue(quilted <= 0.5 * repeat, all);
    }
}
