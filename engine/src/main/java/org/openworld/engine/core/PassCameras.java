package org.openworld.engine.core;

import java.util.EnumMap;
import java.util.Map;

/**
 * The camera of each pass this frame, as a world resource. The engine sets {@link Pass#MAIN} and
 * {@link Pass#OVERLAY} from the viewer's camera; a system that owns a pass's camera (the shadow system the sun's,
 * the water system the mirror's) sets it in its {@code update}. A pass whose camera nobody set uses the main one.
 */
public final class PassCameras {

    private final Map<Pass, ViewCamera> cameras = new EnumMap<>(Pass.class);

    public void set(Pass pass, ViewCamera camera) {
        cameras.put(pass, camera);
    }

    /** This pass's camera, or the main camera when no system owns it. */
    public ViewCamera get(Pass pass) {
        ViewCamera camera = cameras.get(pass);
        return camera != null ? camera : cameras.get(Pass.MAIN);
    }
}
