package org.openworld.engine.input;

import java.util.HashSet;
import java.util.Set;

/**
 * The user's input as a world resource, filled by the window from GLFW callbacks and read by systems in their
 * fixed-step update. Keys are GLFW key codes ({@code GLFW_KEY_W} …). Mouse movement accumulates between updates
 * and is consumed by the first update that reads it, so a fast frame rate and a slow one turn the camera equally.
 * Headless runs have an empty input.
 */
public final class InputState {

    private final Set<Integer> held = new HashSet<>();
    private final Set<Integer> pressed = new HashSet<>();
    private double mouseDx;
    private double mouseDy;
    private boolean looking;

    /** A key went down (GLFW_PRESS). */
    public void keyDown(int key) {
        if (held.add(key)) {
            pressed.add(key);
        }
    }

    /** A key went up (GLFW_RELEASE). */
    public void keyUp(int key) {
        held.remove(key);
    }

    /** Cursor movement in screen pixels (x right, y down) while mouse look is on. */
    public void mouseMoved(double dx, double dy) {
        mouseDx += dx;
        mouseDy += dy;
    }

    /** Whether the mouse steers the view (cursor captured). */
    public void setLooking(boolean looking) {
        this.looking = looking;
    }

    public boolean looking() {
        return looking;
    }

    public boolean isHeld(int key) {
        return held.contains(key);
    }

    /** True once per key press: the first call after the key went down. */
    public boolean consumePress(int key) {
        return pressed.remove(key);
    }

    /** The mouse movement since the last call, pixels {x, y}; resets it. */
    public double[] consumeMouse() {
        double[] d = {mouseDx, mouseDy};
        mouseDx = 0;
        mouseDy = 0;
        return d;
    }
}
