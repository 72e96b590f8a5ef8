package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import org.joml.Matrix4f;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.junit.jupiter.api.Test;
import org.openworld.engine.shadow.ShadowSettings.Refresh;

/** The refresh rule, GL-free: with real stable boxes of a camera that stands, moves or turns. */
class CascadeRefreshTest {

    static final Matrix4f PROJECTION = new Matrix4f().perspective((float) Math.toRadians(60), 16f / 9, 0.5f, 1e4f);
    static final Vector3fc SUN = new Vector3f(1, 1, 0.3f).normalize();
    static final int RESOLUTION = 1024;
    /** Slices of a 3-cascade split, metres. */
    static final double[] SPLITS = {0.5, 40, 150, 600};

    /** A camera at (x, 30, z) looking along yaw degrees (0: north, −z), 10° down. */
    static Matrix4f view(double x, double z, double yaw) {
        return new Matrix4f().rotateX((float) Math.toRadians(10)).rotateY((float) Math.toRadians(yaw))
                .translate((float) -x, -30, (float) -z);
    }

    static LightBox box(Matrix4f view, int i, Vector3fc sun) {
        return LightFit.stable(view, PROJECTION, SPLITS[i], SPLITS[i + 1], sun, 200, RESOLUTION);
    }

    static Vector3d[] corners(Matrix4f view, int i) {
        return LightFit.sliceCorners(view, PROJECTION, SPLITS[i], SPLITS[i + 1]);
    }

    /** Runs one frame of the rule for every cascade; which were redrawn. */
    static boolean[] frame(CascadeRefresh refresh, Matrix4f view, Vector3fc sun, Refresh mode) {
        refresh.nextFrame();
        boolean[] redrawn = new boolean[SPLITS.length - 1];
        for (int i = 0; i < redrawn.length; i++) {
            Vector3fc fitSun = refresh.sunFor(i, sun, 0.05, mode);
            redrawn[i] = refresh.redraw(i, box(view, i, fitSun), fitSun, corners(view, i), mode);
        }
        return redrawn;
    }

    static CascadeRefresh fresh() {
        CascadeRefresh refresh = new CascadeRefresh();
        refresh.forget(SPLITS.length - 1);
        return refresh;
    }

    @Test
    void theNearestCascadeMayRedrawEveryFrameAndEachFarOneEvery2ToTheIFramesNeverTwoTogether() {
        for (int i = 1; i <= 3; i++) {
            long last = -1;
            for (long frame = 1; frame <= 256; frame++) {
                if (CascadeRefresh.mayRedraw(i, frame)) {
                    if (last >= 0) {
                        assertEquals(1L << i, frame - last, "cascade " + i + " at frame " + frame);
                    }
                    last = frame;
                }
            }
            assertTrue(last > 0);
        }
        for (long frame = 1; frame <= 256; frame++) {
            assertTrue(CascadeRefresh.mayRedraw(0, frame));
            int far = 0;
            for (int i = 1; i < 8; i++) {
                far += CascadeRefresh.mayRedraw(i, frame) ? 1 : 0;
            }
            assertTrue(far <= 1, "frame " + frame + ": " + far + " far cascades");
        }
    }

    @Test
    void anUnchangedLightAndOriginKeepEveryMapAndAMovedOneRedrawsIt() {
        for (Refresh mode : new Refresh[] {Refresh.MOVED, Refresh.STAGGERED}) {
            CascadeRefresh refresh = fresh();
            Matrix4f still = view(100, 200, 30);
            assertEquals("[true, true, true]", Arrays.toString(frame(refresh, still, SUN, mode)));
            LightBox far = refresh.box(2);
            assertEquals("[false, false, false]", Arrays.toString(frame(refresh, still, SUN, mode)));
            assertSame(far, refresh.box(2), "kept: the box its depths were drawn with");
            // 3 m: more than a texel of the near cascade (about 9 cm)
            assertTrue(frame(refresh, view(103, 200, 30), SUN, mode)[0], mode.toString());
        }
        CascadeRefresh always = fresh();
        frame(always, view(100, 200, 30), SUN, Refresh.ALWAYS);
        assertEquals("[true, true, true]", Arrays.toString(
                frame(always, view(100, 200, 30), SUN, Refresh.ALWAYS)));
    }

    @Test
    void aMovedFarCascadeWaitsForItsFrameWithItsOldBoxWhileThatHoldsItsSlice() {
        CascadeRefresh refresh = fresh();
        frame(refresh, view(0, 0, 0), SUN, Refresh.STAGGERED);   // frame 1: all
        LightBox before = refresh.box(1);
        // frame 2, 3 m east: cascade 1 (odd frames) waits; its old box still holds its moved slice
        boolean[] second = frame(refresh, view(3, 0, 0), SUN, Refresh.STAGGERED);
        assertTrue(second[0]);
        assertFalse(second[1]);
        assertTrue(CascadeRefresh.holds(before, corners(view(3, 0, 0), 1)));
        assertSame(before, refresh.box(1));
        // frame 3: its turn
        assertTrue(frame(refresh, view(6, 0, 0), SUN, Refresh.STAGGERED)[1]);
    }

    @Test
    void aKeptBoxThatNoLongerHoldsItsSliceIsRedrawnAtOnce() {
        CascadeRefresh refresh = fresh();
        frame(refresh, view(0, 0, 0), SUN, Refresh.STAGGERED);   // frame 1
        LightBox before = refresh.box(1);
        // frame 2, turned 90°: the slice lies beside the old box; cascade 1 is redrawn off its frame
        Matrix4f turned = view(0, 0, 90);
        assertFalse(CascadeRefresh.holds(before, corners(turned, 1)));
        assertTrue(frame(refresh, turned, SUN, Refresh.STAGGERED)[1]);
        assertTrue(CascadeRefresh.holds(refresh.box(1), corners(turned, 1)));
    }

    @Test
    void theSunMayTurnByTheRefreshAngleBeforeTheMapsFollowIt() {
        CascadeRefresh refresh = fresh();
        Matrix4f still = view(0, 0, 0);
        frame(refresh, still, SUN, Refresh.MOVED);
        Vector3f across = new Vector3f(SUN).cross(0, 1, 0).normalize();
        Vector3fc slightly = new Vector3f(SUN).rotateAxis((float) Math.toRadians(0.04), across.x, across.y, across.z);
        // 1e-7 rad: the same vector returned gives an angle of 0 to float rounding, 4 orders under the 0.04° (7e-4 rad)
        // turn told apart here
        assertEquals(0, refresh.sunFor(0, slightly, 0.05, Refresh.MOVED).angle(SUN), 1e-7, "the drawn sun kept");
        assertEquals("[false, false, false]", Arrays.toString(frame(refresh, still, slightly,
                Refresh.MOVED)));
        Vector3fc more = new Vector3f(SUN).rotateAxis((float) Math.toRadians(0.06), across.x, across.y, across.z);
        assertEquals(0, refresh.sunFor(0, more, 0.05, Refresh.MOVED).angle(more), 1e-7, "today's sun");
        assertEquals("[true, true, true]", Arrays.toString(frame(refresh, still, more, Refresh.MOVED)));
    }

    @Test
    void forgettingRedrawsEveryMap() {
        CascadeRefresh refresh = fresh();
        Matrix4f still = view(0, 0, 0);
        frame(refresh, still, SUN, Refresh.MOVED);
        refresh.forget(3);
        assertEquals("[true, true, true]", Arrays.toString(frame(refresh, still, SUN, Refresh.MOVED)));
    }
}
