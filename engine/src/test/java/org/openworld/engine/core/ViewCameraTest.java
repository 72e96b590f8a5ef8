package org.openworld.engine.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.CameraPose;

/** The view the GPU takes, from a render origin, against the world's view in double. */
class ViewCameraTest {

    /** 10 000 km out on both axes, 600 m up, looking north-east and down. */
    static final CameraPose FAR = new CameraPose(10_003_432.25, 600, -9_998_001.5, 45, -60, 60);
    /** The render origin near it: whole tiles of 4096 m. */
    static final double OX = 2442 * 4096.0;
    static final double OZ = -2441 * 4096.0;

    @Test
    void theViewFromTheOriginPutsAPointWhereTheWorldsViewDoes() {
        ViewCamera camera = ViewCamera.perspective(FAR, 16 / 9f, 0.5f, 40_000f);
        Vector3d world = new Vector3d(FAR.x() + 123.456, 512.25, FAR.z() - 78.9);
        // the truth: the world's view applied in double
        Vector3d truth = new Matrix4d(camera.exactView()).transformPosition(world, new Vector3d());
        // the GPU's way: the point from the origin in float, the float view from the origin
        Vector4f relative = new Vector4f((float) (world.x - OX), (float) world.y, (float) (world.z - OZ), 1);
        Vector4f gpu = camera.viewFrom(OX, OZ).transform(relative);
        // a float's error at the few kilometres left: 24 bits of 4 km are a quarter of a millimetre
        double millimetre = 1e-3;
        assertEquals(truth.x, gpu.x, millimetre);
        assertEquals(truth.y, gpu.y, millimetre);
        assertEquals(truth.z, gpu.z, millimetre);
        // the world's float view at ten thousand kilometres is metres off: the reason for the origin
        Vector4f old = camera.view().transform(new Vector4f((float) world.x, (float) world.y, (float) world.z, 1));
        assertTrue(new Vector3d(old.x, old.y, old.z).distance(truth) > 0.1,
                "the float view of the world's coordinates at 10 000 km: " + old + " against " + truth);
    }

    @Test
    void theEyeFromTheOriginIsTheEyesFewMetres() {
        ViewCamera camera = ViewCamera.perspective(FAR, 1, 0.5f, 1000f);
        Vector3f eye = camera.positionFrom(OX, OZ);
        assertEquals(1000.25f, eye.x);
        assertEquals(600f, eye.y);
        assertEquals((float) (FAR.z() - OZ), eye.z);
        // the view from the origin takes the eye from the origin to view space's origin
        Vector4f inView = camera.viewFrom(OX, OZ).transform(new Vector4f(eye, 1));
        // float (24-bit mantissa): a millimetre over the few kilometres left, as above
        assertEquals(0, new Vector3f(inView.x, inView.y, inView.z).length(), 1e-3);
    }
}
