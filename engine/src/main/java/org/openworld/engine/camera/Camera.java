package org.openworld.engine.camera;

import org.openworld.engine.core.ViewCamera;

/**
 * The viewer's camera, as a world resource: its pose and its depth range. The camera system moves it; the engine
 * turns it into the main pass's {@link ViewCamera} each frame.
 */
public final class Camera {

    /** Near plane, metres: close enough to walk, far enough to keep depth precision over kilometres. */
    public static final float NEAR = 0.5f;
    /** Far plane, metres: beyond the largest world's diagonal seen from high above. */
    public static final float FAR = 40_000f;

    private CameraPose pose = new CameraPose(0, 100, 300, 0, -10, CameraPose.DEFAULT_FOV);

    public CameraPose pose() {
        return pose;
    }

    public void setPose(CameraPose pose) {
        this.pose = pose;
    }

    /** The perspective view for a target of this aspect ratio (width / height). */
    public ViewCamera view(float aspect) {
        return ViewCamera.perspective(pose, aspect, NEAR, FAR);
    }
}
