package org.openworld.engine.grass;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.ImportedWorld;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.DeltaE;
import org.openworld.engine.colour.Lab;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.vegetation.VegetationSystem;

/**
 * The grass on real GL, over an imported world of four strips from west to east, each running the world's length
 * north to south: a flat meadow 10 m above the water, a 45° slope (rock), a plateau above the snow line and a lake
 * bed 10 m under the water. Each strip is flat along its length and wider than twice the grass's distance here, so a
 * camera in its middle looking north sees only that strip's grass, or none. The vegetation is there without trees, for
 * the placement field it publishes, which the grass grows from.
 */
@GlTest
class GrassRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 320;
    static final int H = 180;
    /** Samples per side, 2 m apart: a 512 m world from −256 to 256 m. */
    static final int SAMPLES = 256;
    /** Metres: the grass's distance here, under half the narrowest strip (the slope, 60 m). */
    static final int DISTANCE = 25;

    @TempDir
    static Path dir;
    static Path strips;

    /**
     * Normalised heights, 0 → −20 m and 1 → 80 m (relief 100): the meadow (x &lt; −100 m) at 0.3 (+10 m); the slope
     * from −100 m to −40 m rising 0.3 to 0.9 (10 m to 70 m over 60 m: 45°); the plateau to 60 m at 0.95 (+75 m); the
     * lake bed beyond at 0.1 (−10 m).
     */
    @BeforeAll
    static void writeWorld() throws IOException {
        strips = ImportedWorld.write(dir.resolve("strips.raw"), SAMPLES, (i, j) -> {
            double x = 2.0 * (i - SAMPLES / 2);
            if (j == SAMPLES - 1 && i == 0) {
                return 0f; // the range's two ends, in corners behind every camera here
            }
            if (j == SAMPLES - 1 && i == SAMPLES - 1) {
                return 1f;
            }
            return (float) (x < -100 ? 0.3 : x < -40 ? 0.3 + 0.6 * (x + 100) / 60 : x < 60 ? 0.95 : 0.1);
        });
    }

    static GrassSystem GRASS;
    static Engine engine(GrassSystem grass, String... more) {
        GRASS = grass;
        List<String> settings = new ArrayList<>(List.of("terrain.import-file=" + strips, "terrain.spacing=2",
                "terrain.relief=100", "terrain.sea-fraction=0.2", "grass.distance=" + DISTANCE,
                "vegetation.density=0"));
        settings.addAll(List.of(more));
        Engine engine = GlTestSupport.engine(GL.context(), W, H, settings, new TerrainSystem(),
                new VegetationSystem(), grass);
        engine.world().setResource(new WaterLevel(0));
        return engine;
    }

    /**
     * The share of the picture's pixels that the grass changes, standing 3 m over the ground at (x, 0) looking north
     * and 35° down: the ground fills the picture from 3 m to about 30 m ahead.
     */
    static double grassShare(Engine engine, double x) {
        double ground = engine.world().resource(HeightField.class).heightAt(x, 0);
        engine.world().resource(Camera.class).setPose(new CameraPose(x, Math.max(ground, 0) + 3, 0, 0, -35, 60));
        Image off = frame(engine, false);
        Image on = frame(engine, true);
        int changed = 0;
        for (int y = 0; y < H; y++) {
            for (int px = 0; px < W; px++) {
                for (int c = 0; c < 3; c++) {
                    // the same frame but for the grass: any change of over two levels is a blade
                    if (Math.abs(on.channel(px, y, c) - off.channel(px, y, c)) > 2) {
                        changed++;
                        break;
                    }
                }
            }
        }
        return (double) changed / (W * H);
    }

    static Image frame(Engine engine, boolean grass) {
        engine.setEnabled("grass", grass);
        engine.update();
        GRASS.settle(engine.world());
        engine.render();
        return engine.readImage();
    }

    @Test
    void grassGrowsOnTheMeadowAndNotOnTheSlopeTheSnowOrUnderWater() {
        GrassSystem grass = new GrassSystem();
        try (Engine engine = engine(grass)) {
            engine.update();
            SnowLine snow = engine.world().resource(SnowLine.class);
            // the premises: the plateau is above the full snow line and the meadow below its start
            assertTrue(snow.full() < 75 && snow.start() > 10, "snow line from " + snow.start() + " m to " + snow.full()
                    + " m");
            double meadow = grassShare(engine, -180);
            double slope = grassShare(engine, -70);
            double plateau = grassShare(engine, 10);
            double lake = grassShare(engine, 160);
            // the meadow: blades of 0.35 to 0.65 m, four to a cell of 0.4 m, seen from 3 m: the ground is covered
            // by blades over most of the picture's lower half; a fifth of the whole picture is far less than that
            assertTrue(meadow > 0.2, "the meadow's pixels the grass changed: " + meadow);
            // elsewhere no blade may stand within the distance: not one pixel may change
            assertEquals(0, slope, "pixels changed on the 45° slope");
            assertEquals(0, plateau, "pixels changed above the snow line");
            assertEquals(0, lake, "pixels changed on the lake bed under the water");
        }
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }

    /** Metres the test's eye stands over the meadow, its pitch down and its vertical field, degrees. */
    static final double EYE = 2;
    static final double PITCH = 5;
    static final double FOV = 20;
    /**
     * CIEDE2000's just-noticeable difference (Sharma, Wu and Dalal 2005's data put a pair "just noticeable" near 2.3):
     * a band of the fading meadow whose mean is closer than this to the bare ground's shows no change of tone.
     */
    static final double JUST_NOTICEABLE = 2.3;

    /**
     * Where the blades thin away (from 0.7 to 1 of the distance), the meadow looks like the bare ground: looking north
     * over the flat meadow from 2 m, 5° down (a 20° field, so the ring is 19 rows high), the ground from the ring's
     * start to 30 % of the distance beyond it is cut into bands by distance, and each band's mean colour with the grass
     * must be within a just-noticeable difference of the same band without it. (Before the blades took on the ground's
     * look, its sheen at this grazing view included, the bands from 0.7 to 0.95 of the distance differed by ΔE00 4.0
     * and 3.2: the end of the grass showed as a change of tone.)
     */
    @Test
    void theBladesThinIntoTheGroundWithNoChangeOfTone() {
        GrassSystem grass = new GrassSystem();
        try (Engine engine = engine(grass)) {
            engine.update();
            double x = -180;
            double ground = engine.world().resource(HeightField.class).heightAt(x, 0);
            engine.world().resource(Camera.class).setPose(new CameraPose(x, ground + EYE, 0, 0, -PITCH, FOV));
            Image off = frame(engine, false);
            Image on = frame(engine, true);
            // bands of an eighth of the distance each, from the ring's start (0.7) to 1.3 of the distance
            double step = DISTANCE / 8.0;
            StringBuilder seen = new StringBuilder();
            double worst = 0;
            for (double near = (1 - GrassField.FADE_SHARE) * DISTANCE; near < 1.3 * DISTANCE - 1e-9; near += step) {
                int top = row(near + step);
                int bottom = row(near);
                double e = DeltaE.ciede2000(meanLab(on, top, bottom), meanLab(off, top, bottom));
                seen.append(String.format(" %.1f-%.1f m: %.2f;", near, near + step, e));
                worst = Math.max(worst, e);
            }
            assertTrue(worst <= JUST_NOTICEABLE, "ΔE00 of the bands' means with and without grass:" + seen);
        }
    }

    /** The picture's row where the flat ground lies {@code d} metres ahead of the test's eye. */
    static int row(double d) {
        double below = Math.atan(EYE / d) - Math.toRadians(PITCH);
        return (int) Math.round(H / 2.0 * (1 + Math.tan(below) / Math.tan(Math.toRadians(FOV / 2))));
    }

    /** The mean L*a*b* of rows [top, bottom) of the picture. */
    static Lab meanLab(Image image, int top, int bottom) {
        double l = 0;
        double a = 0;
        double b = 0;
        int n = 0;
        for (int y = top; y < bottom; y++) {
            for (int px = 0; px < W; px++) {
                Lab c = Lab.fromSrgb(image.channel(px, y, 0), image.channel(px, y, 1), image.channel(px, y, 2));
                l += c.l();
                a += c.a();
                b += c.b();
                n++;
            }
        }
        return new Lab(l / n, a / n, b / n);
    }

    /**
     * The contact shadow: a meadow's own blades darken their roots by their number. Over the meadow from 1.5 m, 40°
     * down, the pixels the grass changes are darker on the whole at 96 blades/m² than at 1: the roots of the dense
     * meadow get 1 − 0.55 (1 − e⁻⁴) = 46 % of the light, the sparse one's 98 %, the tips all of it, so a blade seen
     * along its length keeps about three quarters of the light against nearly all of it, some 13 % less luma (the
     * display's gamma of about 1 / 2.2 on 0.73). At least a third of that must show: in the dense meadow tips hide
     * many roots. (With the roots' fixed 0.6 shade, before the shadow went by density, the dense meadow was no darker.)
     */
    @Test
    void denseGrassDarkensItsRoots() {
        double dense = bladeLuma("grass.density=96");
        double sparse = bladeLuma("grass.density=1");
        assertTrue(dense < (1 - 0.13 / 3) * sparse, "mean luma of the blades' pixels: " + dense + " at 96 blades/m², "
                + sparse + " at 1");
    }

    /** The mean luma of the pixels the grass changes over the meadow, seen from 1.5 m and 40° down. */
    static double bladeLuma(String density) {
        GrassSystem grass = new GrassSystem();
        try (Engine engine = engine(grass, density)) {
            engine.update();
            double x = -180;
            double ground = engine.world().resource(HeightField.class).heightAt(x, 0);
            engine.world().resource(Camera.class).setPose(new CameraPose(x, ground + 1.5, 0, 0, -40, 60));
            Image off = frame(engine, false);
            Image on = frame(engine, true);
            double sum = 0;
            int n = 0;
            for (int y = 0; y < H; y++) {
                for (int px = 0; px < W; px++) {
                    if (Math.abs(on.luma(px, y) - off.luma(px, y)) > 2) { // as grassShare: a blade
                        sum += on.luma(px, y);
                        n++;
                    }
                }
            }
            return sum / n;
        }
    }
}
