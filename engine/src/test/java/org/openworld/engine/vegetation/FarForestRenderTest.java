package org.openworld.engine.vegetation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.DeltaE;
import org.openworld.engine.colour.Lab;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.gl.Image;
import org.openworld.engine.shadow.ShadowSystem;

/**
 * The forests past the plants' reach against the plants themselves, on real GL: the same ground seen once with the
 * plants drawn and once with only the far ground's forest colour, which must look alike where one gives way to the
 * other. {@link TreeRenderTest}'s shore world: flat land 10 m above the water west of x = 0.
 */
@GlTest
class FarForestRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    @TempDir
    static Path dir;

    @BeforeAll
    static void writeWorld() throws IOException {
        TreeRenderTest.shore = TreeRenderTest.writeShore(dir);
    }

    /** A sun in the south-east, 45° up: the crowns shade each other and the ground between them. */
    static final Sun SUN = new Sun(new Vector3f(0.5f, (float) Math.sin(Math.toRadians(45)), 0.5f).normalize(),
            new Vector3f(1), new Vector3f(0.25f));
    /** Over the lake, 60 m above the land, looking west across it, 20° down. */
    static final CameraPose POSE = new CameraPose(40, 70, 0, 270, -20, 60);
    static final double LAND = 10;
    /** Metres from the viewer (along the ground) over which the two are compared, in bands of BAND metres. */
    static final double NEAR = 110;
    static final double FAR = 290;
    static final double BAND = 30;
    /**
     * The largest mean ΔE00 allowed between the bands' mean colours, drawn against tinted: twice the just noticeable
     * difference 2.3, the bound of the plants' own switches ({@link TreeRenderTest#MEAN_BOUND}): across the fade
     * the plants shrink into a ground of the tint's colour, so what the eye sees change is the region's mean colour.
     */
    static final double MEAN_BOUND = TreeRenderTest.MEAN_BOUND;

    /**
     * With the plants drawn to 1000 m, and with them ending at 100 m (the ground's forest colour full from there), the
     * land 110 to 290 m away, band by band of 30 m: the mean colours differ by a mean ΔE00 under the bound, while the
     * forest itself stands out from the bare ground by far more.
     */
    @Test
    void theFarForestsColourMatchesTheDrawnForestWhereItTakesOver() {
        VegetationSystem plants = new VegetationSystem();
        VegetationSettings d = VegetationSettings.DEFAULTS;
        // the default forest, the far ground's program everywhere (the forest colour is in that program alone)
        List<String> more = List.of("vegetation.density=" + d.density(), "vegetation.min-height=" + d.minHeight(),
                "vegetation.max-height=" + d.maxHeight(), "materials.far-texels=0");
        try (Engine engine = TreeRenderTest.engine(GL.context(), plants, POSE, more, new ShadowSystem())) {
            engine.world().setResource(SUN);
            Image bare = draw(engine, false, 1000);

            Image drawn = draw(engine, true, 1000);
            Image tinted = draw(engine, true, 100);
            double[][][] bands = {means(bare), means(drawn), means(tinted)};
            double sum = 0;
            double forest = 0;
            int counted = 0;
            for (int b = 0; b < bands[0].length; b++) {
                if (bands[0][b] == null) {
                    continue;
                }
                double between = deltaE(bands[1][b], bands[2][b]);
                sum += between;
                forest += deltaE(bands[1][b], bands[0][b]);
                counted++;
            }
            assertTrue(counted >= 4, "bands in view: " + counted);
            double mean = sum / counted;
            // the test sees the forest: drawn, it changes the ground by more than the bound, so a far colour that
            // left the ground bare would fail
            assertTrue(forest / counted > MEAN_BOUND, "the forest against the bare ground: " + forest / counted);
            assertTrue(mean < MEAN_BOUND, "mean ΔE00 between the drawn forest and its far colour over " + counted
                    + " bands from " + NEAR + " to " + FAR + " m: " + mean);
        }
        assertEquals(0, GL.context().objects().live(), "live GL objects after close: " + GL.context().objects());
    }

    static Image draw(Engine engine, boolean on, double viewDistance) {
        engine.settings().set("vegetation.view-distance", String.valueOf(viewDistance));
        return TreeRenderTest.frame(engine, "vegetation", on);
    }

    /**
     * Each band's mean linear colour over the pixels whose ray meets the land (x under −5 m, clear of the shore) at a
     * ground distance within it; null for a band with no such pixel.
     */
    static double[][] means(Image image) {
        int bands = (int) ((FAR - NEAR) / BAND);
        double[][] sums = new double[bands][4];
        double tanHalf = Math.tan(Math.toRadians(POSE.fov() / 2));
        double aspect = (double) image.width() / image.height();
        double pitch = Math.toRadians(POSE.pitch());
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                // the pixel's ray in the camera's frame (looking west, -x): right is north (-z), up is up
                double sx = ((x + 0.5) / image.width() * 2 - 1) * tanHalf * aspect;
                double sy = (1 - (y + 0.5) / image.height() * 2) * tanHalf;
                double forward = Math.cos(pitch) - sy * Math.sin(pitch);
                double up = Math.sin(pitch) + sy * Math.cos(pitch);
                if (up >= 0) {
                    continue;
                }
                double t = (POSE.y() - LAND) / -up;
                double wx = POSE.x() - t * forward;
                double along = Math.hypot(t * forward, t * sx);
                int band = (int) Math.floor((along - NEAR) / BAND);
                if (wx > -5 || band < 0 || band >= bands) {
                    continue;
                }
                for (int c = 0; c < 3; c++) {
                    sums[band][c] += Lab.linear(image.channel(x, y, c));
                }
                sums[band][3]++;
            }
        }
        double[][] means = new double[bands][];
        for (int b = 0; b < bands; b++) {
            if (sums[b][3] > 0) {
                means[b] = new double[] {sums[b][0] / sums[b][3], sums[b][1] / sums[b][3], sums[b][2] / sums[b][3]};
            }
        }
        return means;
    }

    static Lab lab(double[] linear) {
        int[] code = new int[3];
        for (int c = 0; c < 3; c++) {
            double v = linear[c] <= 0.0031308 ? 12.92 * linear[c] : 1.055 * Math.pow(linear[c], 1 / 2.4) - 0.055;
            code[c] = (int) Math.round(255 * Math.min(1, Math.max(0, v)));
        }
        return Lab.fromSrgb(code[0], code[1], code[2]);
    }

    static double deltaE(double[] first, double[] second) {
        return DeltaE.ciede2000(lab(first), lab(second));
    }
}
