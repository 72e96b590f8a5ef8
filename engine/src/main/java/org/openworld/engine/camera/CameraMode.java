package org.openworld.engine.camera;

/** How the camera controller moves the viewer; key V switches between them. */
public enum CameraMode {
    /** Free flight with inertia, along the view direction (the setting's text is {@code fly}). */
    FLY,
    /** On foot: horizontal movement, the eye kept at eye height over the ground ({@code walk}). */
    WALK;

    /** The other mode. */
    public CameraMode toggled() {
        return this == FLY ? WALK : FLY;
    }
}
