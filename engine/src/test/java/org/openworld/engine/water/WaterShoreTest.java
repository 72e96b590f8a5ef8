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
 * ground), a pale block in the dark band.
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
     * the picture's row 3 pixels above the waterline, so the test needs no colour copied from a run; nearer means by
     * the RGB distance.
     */
    @Test
    void theReflectedShoreBandHasNoColumnOfSkyColour() {
        List<String> settings = WaterRenderTest.settings(wall, "water.reflection=HALF", "water.wind=5");
        Image picture = render(settings, LOW_OVER_THE_LAKE, true);
        Image openSky = render(settings, LOW_OVER_THE_LAKE, false);
        int waterline = (int) Math.ceil(WaterRenderTest.rowOfZ(LOW_OVER_THE_LAKE, 16));
        double[] rock = meanRow(picture, waterline - 3);
        int skyColumns = 0;
        StringBuilder where = new StringBuilder();
        for (int x = 0; x < picture.width(); x++) {
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

    static double[] meanRow(Image picture, int y) {
        double[] mean = new double[3];
        for (int x = 0; x < picture.width(); x++) {
            for (int c = 0; c < 3; c++) {
                mean[c] += picture.channel(x, y, c) / (double) picture.width();
            }
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
