package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySettings;
import org.openworld.engine.sky.SolarPosition;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * A sunlit rock face of the generated tile (seed 1, the default 4 km tile) seen from 60 m off it at 16:30, the
 * afternoon sun low in the west-south-west and the face turned to it: every point of it that the sun truly reaches
 * (a ray marched through the height field, {@link ShadowStatistics#acne}) must be lit by the maps too. The casters
 * must be the very surface the viewer sees: where the sun's pass drew them coarser than the viewer's ground (its
 * cascade's texels allowing it), the coarse surface stood above the fine ground in every hollow, and the face
 * shadowed itself in dark cross-hatched streaks.
 */
@GlTest
class SunlitFaceAcneTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 320;
    static final int H = 180;
    /** The face, from 60 m above the ground 40 m west of it, looking east and a little up along it. */
    static final CameraPose FACING_THE_FACE = new CameraPose(-545, 165, -156, 90, 5, 60);
    /** Hours: the afternoon sun, 25° up in the west-south-west at the default latitude. */
    static final double AFTERNOON = 16.5;

    /**
     * How much darker than its shadow-free twin a pixel of the lit face may be: one tap of the 3 × 3 filter
     * ({@code shadow.kernel}) out of nine, a lit point beside a bump finer than a texel that the map cannot resolve.
     * The sun's light is at most the whole of a pixel's, so one tap takes at most a ninth of it.
     */
    static final double LEAST_RATIO = 8.0 / 9;
    /**
     * The share of ground pixels that may fall below {@link #LEAST_RATIO}: the face in view has no real shadow (its
     * points all truly lit, which the test checks), so none should; a per-mille leaves room for a pixel on the sky's
     * edge, where the two pictures' silhouettes may round differently. Acne darkened 1.1 % of them, in streaks.
     */
    static final double MOST_DARKENED = 0.001;

    @Test
    void aSunlitFaceIsNotShadowedByItself() throws IOException {
        List<FrameRecord> records = new ArrayList<>();
        SkySettings sky = SkySettings.DEFAULTS;
        Image lit;
        Image shadowed;
        // at 2 px instead of the default 6 the viewer's cut is as fine at this size as the default's at 960 × 540
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H,
                List.of("terrain.world=tile", "lod.pixel-error=2", "shadow.measure=on", "shadow.refresh=always"),
                new CullingSystem(), new TerrainSystem(), new ShadowSystem())) {
            engine.world().setResource(new Sun(SolarPosition.direction(AFTERNOON, sky.latitude(), sky.declination()),
                    new Vector3f(1), new Vector3f(0.25f)));
            engine.world().resource(Camera.class).setPose(FACING_THE_FACE);
            shadowed = frame(engine, true);
            engine.collectFrames(true, records::add);
            lit = frame(engine, false);
        }
        shadowed.writePng(Path.of("target/test-images/sunlit-face.png"));
        Map<String, Double> counters = records.get(0).counters();
        // the face in view is lit wherever the sun's ray, marched through the height field, leaves the ground
        assertTrue(counters.get("shadow.acne-pixels") > 0.5 * (W / ShadowStatistics.ACNE_STRIDE)
                * (H / ShadowStatistics.ACNE_STRIDE), "the face in view and lit: " + counters);
        int ground = 0;
        int darkened = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if (lit.luma(x, y) == 0) {
                    continue; // no sky is drawn here: the clear colour
                }
                ground++;
                darkened += shadowed.luma(x, y) < LEAST_RATIO * lit.luma(x, y) ? 1 : 0;
            }
        }
        double share = (double) darkened / ground;
        System.out.println("sunlit face: " + darkened + " of " + ground + " ground pixels darkened, " + counters);
        assertTrue(share <= MOST_DARKENED, "the lit face shadows itself: " + darkened + " of " + ground
                + " ground pixels darker than " + LEAST_RATIO + " of the picture without shadows; " + counters);
    }

    private static Image frame(Engine engine, boolean shadows) {
        engine.setEnabled("shadow", shadows);
        engine.update();
        engine.render();
        return engine.readImage();
    }
}
