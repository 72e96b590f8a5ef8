package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.ViewCamera;

/** The water plane's depth, horizon and bounds on the screen, against rays cast through random pixels. */
class PlaneOnScreenTest {

    private static final float LEVEL = 3;

    /** Random cameras above the water, looking anywhere from straight down to straight up. */
    private static ViewCamera camera(Random random) {
        CameraPose pose = new CameraPose(random.nextDouble() * 2000 - 1000, LEVEL + 0.1 + random.nextDouble() * 500,
                random.nextDouble() * 2000 - 1000, random.nextDouble() * 360, random.nextDouble() * 180 - 90,
                30 + random.nextDouble() * 60);
        return ViewCamera.perspective(pose, 16 / 9f, 0.5f, 20000);
    }

    /** The world point seen at NDC (x, y) where the ray meets the plane, or null where it does not (sky). */
    private static Vector3f hit(ViewCamera camera, float x, float y) {
        Matrix4f inverse = camera.viewProjection().invert(new Matrix4f());
        Vector4f far = inverse.transform(new Vector4f(x, y, 1, 1));
        Vector3f dir = new Vector3f(far.x / far.w, far.y / far.w, far.z / far.w).sub(camera.position());
        float t = (LEVEL - camera.position().y()) / dir.y;
        return dir.y < 0 ? dir.mul(t).add(camera.position()) : null;
    }

    private static float dot(org.joml.Vector3fc line, float x, float y) {
        return line.x() * x + line.y() * y + line.z();
    }

    @Test
    void depthHorizonAndBoundsAgreeWithTheRayThroughEachPixel() {
        Random random = new Random(19);
        int water = 0;
        int sky = 0;
        for (int c = 0; c < 300; c++) {
            ViewCamera camera = camera(random);
            PlaneOnScreen plane = PlaneOnScreen.of(camera.viewProjection(), camera.position().y(), LEVEL);
            for (int p = 0; p < 200; p++) {
                float x = random.nextFloat() * 2 - 1;
                float y = random.nextFloat() * 2 - 1;
                Vector3f point = hit(camera, x, y);
                float side = dot(plane.horizon(), x, y);
                if (Math.abs(side) < 1e-4 * plane.horizon().length()) {
                    continue; // on the horizon line itself: either answer is right
                }
                if (point == null) {
                    sky++;
                    assertTrue(side < 0, "sky at (" + x + ", " + y + ") on the water's side of the horizon");
                    continue;
                }
                water++;
                assertTrue(side > 0, "water at (" + x + ", " + y + ") on the sky's side of the horizon");
                assertTrue(plane.visible());
                assertTrue(x >= plane.bounds().x() - 1e-5 && x <= plane.bounds().z() + 1e-5
                        && y >= plane.bounds().y() - 1e-5 && y <= plane.bounds().w() + 1e-5,
                        "water at (" + x + ", " + y + ") outside the bounds " + plane.bounds());
                Vector4f clip = camera.viewProjection().transform(new Vector4f(point, 1));
                double ndcDepth = clip.z / clip.w;
                if (ndcDepth < 1) { // beyond the far plane the depth is clamped, whatever the plane says
                    double windowDepth = ndcDepth * 0.5 + 0.5;
                    double planeDepth = dot(plane.depth(), x, y) * 0.5 + 0.5;
                    // float depth (24-bit mantissa): the error of 1 − d grows as the depth nears 1, so the band is
                    // relative to 1 − d, plus 1e-6 absolute
                    assertEquals(windowDepth, planeDepth, 2e-4 * (1 - windowDepth) + 1e-6,
                            "depth at (" + x + ", " + y + ")");
                }
            }
        }
        // 10 000 of the sampled pixels on each side: a picture split by the horizon, not one side grazed
        assertTrue(water > 10000 && sky > 10000, "both sides are covered: " + water + " water, " + sky + " sky");
    }

    @Test
    void boundsHugTheWaterBelowALevelHorizon() {
        // pitch 0: the horizon is the middle row, the water fills the lower half
        ViewCamera level = ViewCamera.perspective(new CameraPose(0, 10, 0, 0, 0, 60), 16 / 9f, 0.5f, 20000);
        Vector4f expected = new Vector4f(-1, -1, 1, 0);
        PlaneOnScreen plane = PlaneOnScreen.of(level.viewProjection(), 10, LEVEL);
        assertTrue(plane.bounds().equals(expected, 1e-5f), "bounds " + plane.bounds());
        // looking up so the whole picture is above the horizon: no water at all
        ViewCamera up = ViewCamera.perspective(new CameraPose(0, 10, 0, 0, 40, 60), 16 / 9f, 0.5f, 20000);
        assertFalse(PlaneOnScreen.of(up.viewProjection(), 10, LEVEL).visible());
        // looking straight down: water everywhere
        ViewCamera down = ViewCamera.perspective(new CameraPose(0, 10, 0, 0, -90, 60), 16 / 9f, 0.5f, 20000);
        assertTrue(PlaneOnScreen.of(down.viewProjection(), 10, LEVEL).bounds()
                .equals(new Vector4f(-1, -1, 1, 1), 1e-5f));
    }
}
