package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.junit.jupiter.api.Test;
import org.openworld.engine.core.HeightField;

/**
 * Flicker and acne over hand-made buffers and height fields: each pixel's world point is laid out here on a grid
 * of the ground, so the expected counts follow from the layout, not from the code under test.
 */
class ShadowStatisticsTest {
    // Tolerances here: doubles: shares and norms of exact counts, to round-off (1e-12); 1e-6 where float pixels are
    // averaged

    /** Pixels per row and rows: multiples of the acne stride, so every 4th pixel is an exact count. */
    private static final int W = 32;
    private static final int H = 16;
    /** Metres between neighbouring pixels' ground points. */
    private static final float PIXEL_METRES = 2;
    /** The eye, above the middle of the patch of ground the pixels show. */
    private static final Vector3fc EYE = new Vector3f(0, 20, 0);
    /** The sun towards the north, 27° up: the cosine to an upward normal is 0.45, above the sun-facing 0.3. */
    private static final Vector3fc TO_NORTH_SUN = new Vector3f(0, 0.5f, -1).normalize();
    /** No ground above this in the fields here, metres. */
    private static final double MAX_HEIGHT = 60;
    /** The pixels the acne measure tests: every 4th in x and y. */
    private static final int TESTED = (W / ShadowStatistics.ACNE_STRIDE) * (H / ShadowStatistics.ACNE_STRIDE);

    /** A wall 50 m high from 20 to 30 m north of the origin, over a plain at 0 m. */
    private static final HeightField RIDGE = (x, z) -> z < -20 && z > -30 ? 50 : 0;

    interface Visibility {
        float at(int x, int y);
    }

    /** Every pixel showing the ground at height {@code y} of a grid centred on the origin, with this visibility. */
    private static float[] plain(float y, Visibility visibility) {
        float[] buffer = new float[W * H * ShadowStatistics.CHANNELS];
        for (int py = 0; py < H; py++) {
            for (int px = 0; px < W; px++) {
                int i = (py * W + px) * ShadowStatistics.CHANNELS;
                buffer[i] = visibility.at(px, py);
                buffer[i + 1] = (px - W / 2f) * PIXEL_METRES;
                buffer[i + 2] = y;
                buffer[i + 3] = (py - H / 2f) * PIXEL_METRES;
            }
        }
        return buffer;
    }

    private static ShadowStatistics.Acne acne(float[] buffer, HeightField ground) {
        return ShadowStatistics.acne(buffer, W, EYE, TO_NORTH_SUN, ground, MAX_HEIGHT);
    }

    @Test
    void aRidgeBetweenThePointAndTheSunLeavesItInShadow() {
        assertFalse(ShadowStatistics.trulyLit(RIDGE, 0, 0.3, 0, TO_NORTH_SUN, MAX_HEIGHT));
        // south of the ridge by far more than its shadow (50 m at 27°: 100 m), and north of it, the sun is seen
        assertTrue(ShadowStatistics.trulyLit(RIDGE, 0, 0.3, 200, TO_NORTH_SUN, MAX_HEIGHT));
        assertTrue(ShadowStatistics.trulyLit(RIDGE, 0, 0.3, -40, TO_NORTH_SUN, MAX_HEIGHT));
        // the same point with the sun in the south: the ridge is behind it
        assertTrue(ShadowStatistics.trulyLit(RIDGE, 0, 0.3, 0, new Vector3f(0, 0.5f, 1).normalize(), MAX_HEIGHT));
    }

    @Test
    void pointsTheRidgeShadowsAreNotCounted() {
        // the pixels' points lie from 16 m north to 14 m south of the origin, all within the ridge's 100 m shadow,
        // so none is truly lit
        ShadowStatistics.Acne acne = acne(plain(0, (x, y) -> 0), RIDGE);
        assertEquals(0, acne.pixels());
        assertEquals(0, acne.fraction());
    }

    @Test
    void aLitPlainShadowedEverywhereIsAllAcneAndLitEverywhereNone() {
        ShadowStatistics.Acne dark = acne(plain(0, (x, y) -> 0), HeightField.FLAT);
        assertEquals(TESTED, dark.pixels());
        assertEquals(1, dark.fraction());
        ShadowStatistics.Acne lit = acne(plain(0, (x, y) -> 1), HeightField.FLAT);
        assertEquals(TESTED, lit.pixels());
        assertEquals(0, lit.fraction());
    }

    @Test
    void onlyEveryFourthPixelIsTestedAndHalfShadowIsTheThreshold() {
        // shadowed except on the tested pixels: no acne
        ShadowStatistics.Acne between = acne(plain(0, (x, y) -> x % 4 == 0 && y % 4 == 0 ? 1 : 0), HeightField.FLAT);
        assertEquals(0, between.fraction());
        // the tested pixels of even columns of the tested grid at 0.49 (shadowed), the others at 0.5 (lit)
        ShadowStatistics.Acne half = acne(plain(0, (x, y) -> x % 8 == 0 ? 0.49f : 0.5f), HeightField.FLAT);
        // doubles: shares and norms of exact counts, equal to round-off (1e-12; 1e-6 where float pixels are averaged)
        assertEquals(0.5, half.fraction(), 1e-12);
    }

    @Test
    void waterAndSkyAreSkipped() {
        // the ground 20 m under the pixels' points (the water's surface) on the western half, the plain elsewhere;
        // the shore 1 m west of the middle column, so that column's normal sees only the plain
        HeightField sea = (x, z) -> x < -1 ? -20 : 0;
        ShadowStatistics.Acne acne = acne(plain(0, (x, y) -> x < W / 2 ? 0 : 1), sea);
        assertEquals(TESTED / 2, acne.pixels());
        assertEquals(0, acne.fraction());
        // sky on the western half: the same
        ShadowStatistics.Acne sky = acne(plain(0, (x, y) -> x < W / 2 ? ShadowStatistics.SKY : 1), HeightField.FLAT);
        assertEquals(TESTED / 2, sky.pixels());
        assertEquals(0, sky.fraction());
    }

    @Test
    void groundTurnedFromTheSunIsSkipped() {
        // a slope rising to the north (−z) at 45°: its normal leans south, away from the northern sun
        HeightField slope = (x, z) -> -z;
        float[] buffer = plain(0, (x, y) -> 0);
        for (int i = 0; i < buffer.length; i += ShadowStatistics.CHANNELS) {
            buffer[i + 2] = -buffer[i + 3];
        }
        assertEquals(0, acne(buffer, slope).pixels());
        double[] n = ShadowStatistics.groundNormal(slope, 3, 7);
        assertEquals(0, n[0], 1e-12);
        assertEquals(Math.sqrt(0.5), n[1], 1e-12);
        assertEquals(Math.sqrt(0.5), n[2], 1e-12);
        // the same slope facing the sun (rising to the south) is tested everywhere, and all of it is acne
        HeightField facing = (x, z) -> z;
        for (int i = 0; i < buffer.length; i += ShadowStatistics.CHANNELS) {
            buffer[i + 2] = buffer[i + 3];
        }
        ShadowStatistics.Acne acne = acne(buffer, facing);
        assertEquals(TESTED, acne.pixels());
        assertEquals(1, acne.fraction());
    }

    @Test
    void identicalFramesDoNotFlicker() {
        float[] frame = plain(0, (x, y) -> (x * 7 + y * 3) % 5 / 4f);
        ShadowStatistics.Flicker flicker = ShadowStatistics.flicker(frame, frame.clone());
        assertEquals(0, flicker.mean());
        assertEquals(W * H, flicker.pixels());
    }

    @Test
    void flickerIsTheMeanChangeOverGroundPixelsOnly() {
        float[] before = plain(0, (x, y) -> 1);
        // every ground pixel loses a quarter of its light; the last row is sky, which must not count
        float[] after = plain(0, (x, y) -> 0.75f);
        for (int x = 0; x < W; x++) {
            before[((H - 1) * W + x) * ShadowStatistics.CHANNELS] = ShadowStatistics.SKY;
            after[((H - 1) * W + x) * ShadowStatistics.CHANNELS] = ShadowStatistics.SKY;
        }
        ShadowStatistics.Flicker flicker = ShadowStatistics.flicker(after, before);
        assertEquals(0.25, flicker.mean(), 1e-6);
        assertEquals(W * (H - 1), flicker.pixels());
    }

    @Test
    void theFirstFrameHasNoFlickerAndTheNextComparesTheLastPointsRevisited() {
        ShadowStatistics statistics = new ShadowStatistics();
        float[] frame = plain(0, (x, y) -> 1);
        ShadowStatistics.Measures first = statistics.measure(frame, null, W, EYE, TO_NORTH_SUN, HeightField.FLAT,
                MAX_HEIGHT);
        assertTrue(first.flicker().isEmpty());
        assertEquals(TESTED, first.acne().pixels());
        // the statistics keep a copy: changing the caller's buffer afterwards changes nothing remembered
        Arrays.fill(frame, 0f);
        // this frame shows other visibilities (0.25, its own points), but the last frame's points now read 0.5:
        // the flicker is the change at the same points, 1 - 0.5
        float[] second = plain(0, (x, y) -> 0.25f);
        float[] lastPointsNow = plain(0, (x, y) -> 0.5f);
        ShadowStatistics.Flicker flicker = statistics.measure(second, lastPointsNow, W, EYE, TO_NORTH_SUN,
                HeightField.FLAT, MAX_HEIGHT).flicker().orElseThrow();
        assertEquals(0.5, flicker.mean(), 1e-6);
        // without the revisited points, or for a picture of another size, there is no flicker to give
        assertTrue(statistics.measure(second, null, W, EYE, TO_NORTH_SUN, HeightField.FLAT, MAX_HEIGHT).flicker()
                .isEmpty());
        float[] wider = new float[2 * second.length];
        assertTrue(statistics.measure(wider, wider, 2 * W, EYE, TO_NORTH_SUN, HeightField.FLAT, MAX_HEIGHT)
                .flicker().isEmpty());
    }
}
