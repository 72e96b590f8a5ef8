package org.openworld.engine.sky.clouds;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.sky.CloudField;
import org.openworld.engine.sky.CloudSettings;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.testscene.TestSceneSystem;

/**
 * The volumetric clouds on a real GL context: their shadow on the ground, where the field says a cloud is and not
 * beside it; and the amortised march, whose reprojected frame in fast flight must match a frame marched whole.
 * (Every GL test also checks that no GL object is left after the engine closes.)
 */
@GlTest
class CloudVolumeRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /** The cover strength's spread in standard deviations of the field ({@code clouds/volume.glsl}, COVER_SPREAD). */
    private static final double COVER_SPREAD = 1.5;

    /** Degrees the camera turns per frame in the flight. */
    private static final double TURN = 1;
    /**
     * Degrees of the turn between the two frames of the reprojection test: 15°, ten texels of the quarter grid at
     * 160 pixels over 60°, so a history read in place lies well beyond the clamp's 3 × 3 blocks (6 × 6 texels);
     * below the 20° of a cut, which would march every texel.
     */
    private static final double MOVE = 15;
    /**
     * Metres east of the world's origin where the reprojection test flies: the render origin is then 16 384 m away
     * from the world's (four steps of 4 096 m), so a reprojection that took the GPU's positions, which are from the
     * render origin, as the world's would miss by that much.
     */
    private static final double FAR = 18000;

    private static Engine engine(int width, int height, List<String> settings) {
        List<String> all = new ArrayList<>(List.of("clouds.mode=volumetric", "clouds.wind-speed=0"));
        all.addAll(settings);
        return GlTestSupport.engine(GL.context(), width, height, all, new TestSceneSystem(), new SkySystem(),
                new CloudVolumeSystem());
    }

    private static Image render(Engine engine, CameraPose pose) {
        engine.world().resource(Camera.class).setPose(pose);
        engine.update();
        engine.render();
        return engine.readImage();
    }

    /**
     * Looking straight down from below a thin cloud layer at noon: ground pixels whose sun ray crosses thick cloud
     * (by the base field on the CPU) are darker with the volume's shadow than with the layer (which casts none);
     * pixels whose sun ray meets no cloud are unchanged. Fails with the shadow left out of sunVisibility (every
     * ratio 1).
     */
    @Test
    void theShadowMapDarkensTheGroundUnderACloudAndNotBesideIt() {
        int size = 96;
        List<String> settings = List.of("clouds.tile-size=3000", "clouds.thickness=300", "clouds.cover=0.5",
                "clouds.type=1");
        CameraPose pose = new CameraPose(0, 1500, 0, 0, -89.9, 90);
        Image shadowed;
        Image open;
        Sun sun;
        Matrix4f inverse;
        CloudSettings c;
        int seed;
        try (Engine engine = engine(size, size, settings)) {
            engine.world().setResource(new TimeOfDay(12, 0));
            shadowed = render(engine, pose);
            sun = engine.world().resource(Sun.class);
            inverse = new Matrix4f(engine.world().resource(Camera.class).view(1).viewProjection()).invert();
            c = engine.settings().get(CloudSettings.class);
            seed = engine.settings().get(EngineSettings.class).seed();
        }
        List<String> layer = new ArrayList<>(settings);
        layer.add("clouds.mode=layer");
        try (Engine engine = engine(size, size, layer)) {
            engine.world().setResource(new TimeOfDay(12, 0));
            open = render(engine, pose);
        }
        CloudField field = CloudField.generate(c.resolution(), c.frames(), CloudVolumeSystem.BASE_BETA, seed);
        float threshold = CloudField.coverageThreshold(field, c.cover());
        double under = 0;
        double underOpen = 0;
        double beside = 0;
        double besideOpen = 0;
        int underCount = 0;
        int besideCount = 0;
        Vector3f toSun = new Vector3f(sun.direction());
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                Vector3f ground = groundPoint(inverse, pose, x, y, size);
                if (ground == null || ground.length() < 300) {
                    continue; // the ring of boxes stands within 220 m of the origin
                }
                double least = Double.MAX_VALUE;
                double most = -Double.MAX_VALUE;
                for (int k = 0; k <= 4; k++) { // the sun's ray from the base to the top
                    double up = c.base() + k * c.thickness() / 4;
                    double f = sample(field, (ground.x + toSun.x / toSun.y * up) / c.tileSize(),
                            (ground.z + toSun.z / toSun.y * up) / c.tileSize());
                    least = Math.min(least, f);
                    most = Math.max(most, f);
                }
                int row = size - 1 - y; // readImage's rows run from the top
                if ((least - threshold) / COVER_SPREAD >= 0.5) {
                    under += shadowed.luma(x, row);
                    underOpen += open.luma(x, row);
                    underCount++;
                } else if (most < threshold - 0.3) {
                    beside += shadowed.luma(x, row);
                    besideOpen += open.luma(x, row);
                    besideCount++;
                }
            }
        }
        assertTrue(underCount > 50 && besideCount > 50, "the view holds both: " + underCount + " pixels under a "
                + "thick cloud, " + besideCount + " beside every cloud");
        double underRatio = under / underOpen;
        double besideRatio = beside / besideOpen;
        // Under: the cover strength >= 0.5 along the whole ray is a column of optical depth >= 0.04/m x 0.5^2/2 x
        // 300 m = 1.5, so at least 78 % of the direct sun is gone; at noon the sun is most of the light on level
        // ground (the sky's ambient the rest), and through the tone curve and sRGB's 1/2.4 power a loss of half the
        // light still leaves the luma below 0.85 of the open ground's.
        assertTrue(underRatio < 0.85, "under a cloud the ground keeps " + underRatio + " of its brightness");
        // Beside: the same light, the same picture, up to the rounding of 8-bit colour (1 in a luma of 100 or more).
        assertTrue(Math.abs(besideRatio - 1) < 0.01, "beside the clouds the ground changes by " + besideRatio);
    }

    /**
     * Flying at 300 m/s (5 m per 1/60 s step) 600 m under the cloud base towards the clouds, turning by
     * {@link #TURN}° a frame, for 12 frames, each marching a quarter of the grid and reprojecting the rest: the last frame against the same pose marched whole (a fresh engine's first frame).
     * Bound: the just noticeable difference, a ΔE00 of 1 (Sharma et al. 2005), plus the march's own noise: each texel
     * starts its steps at a fixed jitter of its own (1/24 of its span), and a reprojected texel carries a
     * neighbour's, so even a perfect reprojection differs from the full march by that noise, measured 0.47 in
     * straight flight, taken as 0.5. Below 1.5, the motion adds less than a noticeable difference to it. This turn
     * is slow (two thirds of a texel a frame), so the clamp alone keeps it under the bound; it guards the flight
     * against smearing, and {@link #aFrameReprojectedAfterATurnMatchesAFullyMarchedOne} tests the reprojection.
     */
    @Test
    void aReprojectedFrameMatchesAFullyMarchedOneInFastFlight() {
        int width = 160;
        int height = 90;
        List<String> settings = List.of("clouds.cover=0.6");
        double speed = 300;
        double step = EngineSettings.DEFAULTS.step();
        int frames = 12;
        CameraPose last = null;
        Image amortised;
        try (Engine engine = engine(width, height, settings)) {
            engine.world().setResource(new TimeOfDay(15, 0));
            Image frame = null;
            for (int i = 0; i < frames; i++) {
                double yaw = 20 + TURN * i;
                last = new CameraPose(0, 1200, 2000 - speed * step * i, yaw, 12, 60);
                frame = render(engine, last);
            }
            amortised = frame;
        }
        Image full;
        try (Engine engine = engine(width, height, settings)) {
            engine.world().setResource(new TimeOfDay(15, 0));
            for (int i = 0; i < frames - 1; i++) {
                engine.update(); // the same simulation time, so the clouds have evolved alike
            }
            full = render(engine, last);
        }
        double mean = ImageComparison.of(amortised, full).meanDeltaE();
        assertTrue(mean < 1.5, "mean ΔE00 between the reprojected and the full frame " + mean);
    }

    /**
     * One frame reached by reprojection: a first frame marched whole at one yaw, then the camera turns by
     * {@link #MOVE}° and the second frame marches a quarter of the grid and reprojects the rest from the first;
     * against the same pose marched whole. A turn moves every cloud the same angle whatever its distance, so a right
     * reprojection finds each texel's point in a history that was marched whole, and differs from the full march only
     * by the history's bilinear resampling (a texel moved by a fraction of a texel takes a blend of four) and the
     * neighbour's jitter a reprojected texel's distance comes from. Many small clouds (cover 0.4 of a 6 km tile) put
     * an edge in most 6 × 6-texel neighbourhoods, so the clamp to this frame's marched neighbours cannot put a
     * history read in the wrong place right.
     * Bound: a third of what the turn changes in the fully marched picture (the first frame against the second's
     * pose marched whole). A history read without the turn carries that change into three texels in four, and the
     * clamp takes back only what lies in its neighbourhood's range; a right reprojection carries none of it and keeps
     * only the resampling and the jitter, which do not grow with the turn. Measured at the world's origin: the turn
     * 6.1, the history read in place 3.5, the reprojection 1.6 (1.5 after a 6° turn). Here, {@link #FAR} out, the
     * turn changes 4.4 and a reprojection through the last frame's world-to-clip matrix from the world's origin
     * rather than the render origin's gives 2.2: both fail.
     */
    @Test
    void aFrameReprojectedAfterATurnMatchesAFullyMarchedOne() {
        int width = 160;
        int height = 90;
        List<String> settings = List.of("clouds.cover=0.4", "clouds.tile-size=6000");
        CameraPose before = new CameraPose(FAR, 1200, 0, 20, 15, 60);
        CameraPose after = new CameraPose(FAR, 1200, 0, 20 + MOVE, 15, 60);
        Image first;
        Image reprojected;
        try (Engine engine = engine(width, height, settings)) {
            engine.world().setResource(new TimeOfDay(15, 0));
            first = render(engine, before);
            reprojected = render(engine, after);
        }
        Image full;
        try (Engine engine = engine(width, height, settings)) {
            engine.world().setResource(new TimeOfDay(15, 0));
            engine.update(); // the same simulation time as the second frame's
            full = render(engine, after);
        }
        double moved = ImageComparison.of(first, full).meanDeltaE();
        double error = ImageComparison.of(reprojected, full).meanDeltaE();
        assertTrue(moved > 4, "the turn changes the picture by a mean ΔE00 of only " + moved);
        assertTrue(error < moved / 3, "mean ΔE00 between the reprojected and the full frame " + error + ", above a"
                + " third of what the turn changes, " + moved / 3);
    }

    /**
     * The clouds stay in the world when the render origin moves: the same pose far from the world's origin, drawn
     * with the origin's step at 4 096 m (the origin 16 384 m away) and at 1 000 m (18 000 m), gives the same picture.
     * The GPU's positions differ by 1 616 m and the field's offset by the same, so only float rounding of metres at
     * 20 km (a few millimetres) is left: bound a tenth of a just noticeable difference. Clouds that followed the
     * origin would be 1.6 km apart.
     */
    @Test
    void theCloudsStayInTheWorldWhenTheRenderOriginMoves() {
        CameraPose pose = new CameraPose(FAR, 1200, 0, 20, 15, 60);
        Image[] pictures = new Image[2];
        double[] steps = {RenderOrigin.DEFAULT_STEP, 1000};
        for (int i = 0; i < 2; i++) {
            try (Engine engine = engine(160, 90, List.of("clouds.cover=0.4", "clouds.tile-size=6000"))) {
                engine.world().setResource(new TimeOfDay(15, 0));
                engine.world().setResource(new RenderOrigin(steps[i]));
                pictures[i] = render(engine, pose);
            }
        }
        double difference = ImageComparison.of(pictures[0], pictures[1]).meanDeltaE();
        assertTrue(difference < 0.1, "the clouds moved with the render origin: mean ΔE00 " + difference);
    }

    /**
     * The cloud shadow is where the clouds are on the frame the render origin steps: looking down on the ground under
     * a thin cloud layer at noon, the camera moves 40 m across the middle between two of the origin's positions (its
     * step 1 000 m, the field's tile 3 000 m, so a step moves the field's offset by a third of a tile), and that
     * frame is compared with the next one at the same pose, whose shadow no step can have displaced. Between the two
     * only 1/60 s of the sky's time passes with no wind, so the bound is a tenth of a just noticeable difference;
     * a shadow placed from the last frame's origin lies 1 000 m off on the stepping frame and changes most of the
     * ground under and beside the clouds.
     */
    @Test
    void theCloudShadowStaysOnTheGroundOnTheFrameTheRenderOriginSteps() {
        int size = 96;
        double step = 1000;
        Image stepped;
        Image settled;
        try (Engine engine = engine(size, size, List.of("clouds.tile-size=3000", "clouds.thickness=300",
                "clouds.cover=0.5", "clouds.type=1"))) {
            engine.world().setResource(new TimeOfDay(12, 0));
            engine.world().setResource(new RenderOrigin(step));
            render(engine, new CameraPose(step / 2 - 20, 1500, 0, 0, -89.9, 90));
            CameraPose across = new CameraPose(step / 2 + 20, 1500, 0, 0, -89.9, 90);
            stepped = render(engine, across);
            assertTrue(engine.world().resource(RenderOrigin.class).x() == step, "the origin stepped to " + step);
            settled = render(engine, across);
        }
        double difference = ImageComparison.of(stepped, settled).meanDeltaE();
        assertTrue(difference < 0.1, "the cloud shadow moved on the frame the origin stepped: mean ΔE00 " + difference);
    }

    /** Where the view ray through pixel (x, y) (y from the bottom) meets the ground plane y = 0, or null. */
    private static Vector3f groundPoint(Matrix4f inverse, CameraPose pose, int x, int y, int size) {
        Vector4f far = inverse.transform(new Vector4f((x + 0.5f) / size * 2 - 1, (y + 0.5f) / size * 2 - 1, 1, 1));
        Vector3f eye = new Vector3f((float) pose.x(), (float) pose.y(), (float) pose.z());
        Vector3f d = new Vector3f(far.x / far.w, far.y / far.w, far.z / far.w).sub(eye).normalize();
        if (d.y >= 0) {
            return null;
        }
        return eye.add(d.mul(-eye.y / d.y));
    }

    /** The field at (s, t) tiles, frame 0, bilinear with wrapping as the GPU's LINEAR_REPEAT reads it. */
    private static double sample(CloudField field, double s, double t) {
        int n = field.resolution();
        double u = s * n - 0.5;
        double v = t * n - 0.5;
        int x = (int) Math.floor(u);
        int y = (int) Math.floor(v);
        double fx = u - x;
        double fy = v - y;
        return (1 - fy) * ((1 - fx) * field.density(x, y, 0) + fx * field.density(x + 1, y, 0))
                + fy * ((1 - fx) * field.density(x, y + 1, 0) + fx * field.density(x + 1, y + 1, 0));
    }
}
