package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
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
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * The far shore's reflection on rippled water seen at a grazing angle, on real GL: a wall of rock 80 m high across
 * the whole world, 184 m ahead of an eye 4 m above the water, the default wind (5 m/s) and the half-size reflection.
 * Right under the waterline the water must mirror the wall, in every column: a look-up that the ripples push past
 * the mirrored waterline reads the part of the mirror picture that the wall hides in the real view (sky or far
 * ground), a pale block in the dark band. And far water, whose pixels span many ripples, must not be a mosaic.
 */
@GlTest
class WaterShoreTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @TempDir
    static Path dir;
    static Path wall;

    /** The wall: samples 120 to 135 north to south (world z −16 to 16 m) at 1 (+80 m), the sea bed elsewhere. */
    @BeforeAll
    static void writeWorld() throws IOException {
        wall = ImportedWorld.write(dir.resolve("wall.raw"), WaterRenderTest.SAMPLES,
                (x, z) -> z >= 120 && z < 136 ? 1f : 0f);
    }

    /** North from z = 200 m, 4 m above the water, level: the wall's foot, z = 16, is 184 m ahead. */
    static final CameraPose LOW_OVER_THE_LAKE = new CameraPose(0, 4, 200, 0, 0, 60);

    /**
     * Rows 1 to 6 under the waterline (the wall's mirror image spans about 90 rows there, so all six mirror rock):
     * no column may have most of them nearer the sky's colour than the wall's. The sky's colour at each pixel is the
     * same water with the terrain switched off (the same ripples mirroring the open sky), the wall's is the mean of
     * the wall just above the waterline in that column and 2 either side (rows 2 to 8 above it: the wall is streaked,
     * and the ripples shift its image sideways by a few pixels), so the test needs no colour copied from a run;
     * nearer means by the RGB distance.
     */
    @Test
    void theReflectedShoreBandHasNoColumnOfSkyColour() {
        assertNoColumnOfSky(LOW_OVER_THE_LAKE);
    }

    /**
     * The same, 5 m from the wall's foot and 0.6 m above the water, looking 10° down: the water under the waterline is
     * 7° below the horizon and its pixels a few centimetres wide, fine enough to keep most of the ripples, which
     * still tilt a reflected ray by more than 7°. Here the footprint's fade cannot hide a look-up that crosses the
     * mirrored waterline; only the check that the look-up lands on water can.
     */
    @Test
    void nearTheShoreTheRipplesDoNotReachPastTheMirroredWaterline() {
        assertNoColumnOfSky(AT_THE_FOOT);
    }

    /** 120 m above the water, 400 m from the wall, 14° down: the water's pixels there are metres long. */
    static final CameraPose HIGH_ABOVE = new CameraPose(0, 120, 420, 0, -14, 60);

    /**
     * Far water under a strong wind must look like the calm water's mirror, not a mosaic: there a pixel's footprint
     * spans many ripples, and a slope read at one point per pixel sends neighbouring pixels to unrelated parts of the
     * mirror picture, so the mean difference between neighbours grows towards the contrast of what is mirrored. The
     * wind of 0.5 m/s is the reference; half as much again leaves room for ripples longer than the footprint, which
     * may stay (the unfiltered ripples gave about four times the calm's).
     */
    @Test
    void distantWaterIsNoMosaic() {
        double rippled = neighbourDifference(render(WaterRenderTest.settings(wall, "water.reflection=HALF",
                "water.wind=5"), HIGH_ABOVE, true));
        double calm = neighbourDifference(render(WaterRenderTest.settings(wall, "water.reflection=HALF",
                "water.wind=0.5"), HIGH_ABOVE, true));
        // 1.5: see the Javadoc above (the unfiltered ripples gave about 4× the calm's)
        assertTrue(rippled < 1.5 * calm, "the far water's neighbouring pixels differ by " + rippled
                + " levels of luma on average, the calm water's by " + calm);
    }

    /** The mean luma difference of horizontally neighbouring pixels over the water under the wall's mirror image. */
    static double neighbourDifference(Image picture) {
        int top = (int) Math.ceil(WaterRenderTest.rowOfZ(HIGH_ABOVE, 16)) + 2;
        double sum = 0;
        int n = 0;
        for (int y = top; y < top + 20; y++) {
            for (int x = 0; x + 1 < picture.width(); x++) {
                sum += Math.abs(picture.luma(x, y) - picture.luma(x + 1, y));
                n++;
            }
        }
        return sum / n;
    }

    static final CameraPose AT_THE_FOOT = new CameraPose(0, 0.6, 21, 0, -10, 60);

    static void assertNoColumnOfSky(CameraPose pose) {
        List<String> settings = WaterRenderTest.settings(wall, "water.reflection=HALF", "water.wind=5");
        Image picture = render(settings, pose, true);
        Image openSky = render(settings, pose, false);
        int waterline = (int) Math.ceil(WaterRenderTest.rowOfZ(pose, 16));
        int skyColumns = 0;
        StringBuilder where = new StringBuilder();
        for (int x = 0; x < picture.width(); x++) {
            double[] rock = meanOf(picture, x - 2, waterline - 8, x + 2, waterline - 2);
            int skyLike = 0;
            for (int y = waterline + 1; y <= waterline + 6; y++) {
                double[] sky = {openSky.channel(x, y, 0), openSky.channel(x, y, 1), openSky.channel(x, y, 2)};
                if (distance(picture, x, y, sky) < distance(picture, x, y, rock)) {
                    skyLike++;
                }
            }
            if (skyLike > 3) {
                skyColumns++;
                if (where.length() < 60) {
                    where.append(x).append(' ');
                }
            }
        }
        assertTrue(skyColumns == 0, skyColumns + " columns of sky colour under the waterline (row " + waterline
                + "), at x = " + where);
    }

    static Image render(List<String> settings, CameraPose pose, boolean terrain) {
        try (Engine engine = GlTestSupport.engine(GL.context(), WaterRenderTest.W, WaterRenderTest.H, settings,
                new SkySystem(), new CullingSystem(), new TerrainSystem(), new WaterSystem())) {
            engine.world().resource(Camera.class).setPose(pose);
            engine.setEnabled("terrain", terrain);
            engine.update();
            engine.render();
            return engine.readImage();
        }
    }

    /** The mean colour of the rectangle from (x0, y0) to (x1, y1) inclusive, clipped to the picture's columns. */
    static double[] meanOf(Image picture, int x0, int y0, int x1, int y1) {
        double[] mean = new double[3];
        int n = 0;
        for (int y = y0; y <= y1; y++) {
            for (int x = Math.max(0, x0); x <= Math.min(picture.width() - 1, x1); x++) {
                for (int c = 0; c < 3; c++) {
                    mean[c] += picture.channel(x, y, c);
                }
                n++;
            }
        }
        for (int c = 0; c < 3; c++) {
            mean[c] /= n;
        }
        return mean;
    }

    static double distance(Image picture, int x, int y, double[] colour) {
        double d = 0;
        for (int c = 0; c < 3; c++) {
            double e = picture.channel(x, y, c) - colour[c];
            d += e * e;
        }
        return Math.sqrt(d);
    }
}
