package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4d;
import org.joml.Vector4d;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.ViewCamera;

/**
 * The far field's squeezed depths ({@link FarField#depthEnd}) end where the camera's own projection still writes a
 * depth below 1 in a 24-bit buffer, by the steps the class asks for, and not far before the far plane (they need the
 * room between the farthest patch and it). GL-free: the projection matrix the main pass uses, applied to points on
 * the view axis.
 */
class FarFieldDepthTest {

    private static final ViewCamera VIEW = ViewCamera.perspective(new CameraPose(0, 0, 0, 0, 0, 60), 16 / 9f,
            Camera.NEAR, Camera.FAR);

    /**
     * The depth [0, 1] of a point {@code distance} metres ahead on the view axis (yaw 0 looks along −z), the
     * projection's coefficients applied in double precision.
     */
    private static double exactDepth(double distance) {
        Vector4d clip = new Matrix4d(VIEW.projection()).transform(new Vector4d(0, 0, -distance, 1));
        return 0.5 * clip.z / clip.w + 0.5;
    }

    /** The same in single precision, as a GPU computes it. */
    private static double floatDepth(double distance) {
        Vector4f clip = VIEW.projection().transform(new Vector4f(0, 0, (float) -distance, 1), new Vector4f());
        return 0.5f * clip.z / clip.w + 0.5f;
    }

    @Test
    void theSqueezedDepthsEndTheirStepsShortOfTheFarPlane() {
        double step = Math.scalb(1.0, -24);
        double end = FarField.depthEnd();
        double exact = (1 - exactDepth(end)) / step;
        // the projection's coefficients are floats: its z row's −(f + n) / (f − n) ≈ −1.00003 is off by up to half
        // its ulp, 2^−24, which moves the depth, half the normalised z, by up to half a step; the formula's
        // (f − n) / f taken as 1 adds 1.25e-5 of the steps
        assertTrue(Math.abs(exact - FarField.DEPTH_STEPS_SHORT) <= 0.5 + 1e-3,
                "the end lies " + exact + " steps short of depth 1, not " + FarField.DEPTH_STEPS_SHORT);
        // single precision loses about a step near depth 1 (its spacing there is 2^-24), so of the four at least
        // one must be left: a depth that rounds to 1 fails the test against the cleared buffer
        double single = (1 - floatDepth(end)) / step;
        // one whole depth step: the float result falls short by at least one representable step, the failure the test
        // shows
        assertTrue(single >= 1, "in single precision the end lies " + single + " steps short of depth 1");
        // and the map keeps the patches' range: the end lies beyond 95 % of the far plane (38 km of 40)
        assertTrue(end > 0.95 * Camera.FAR && end < Camera.FAR, "the end at " + end + " m");
    }
}
