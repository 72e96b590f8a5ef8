package org.openworld.engine.camera;

import static org.lwjgl.glfw.GLFW.GLFW_KEY_A;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_C;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_D;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_DOWN;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_CONTROL;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_LEFT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_RIGHT_SHIFT;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_S;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_SPACE;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_UP;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_V;
import static org.lwjgl.glfw.GLFW.GLFW_KEY_W;

import org.openworld.engine.input.InputState;

/**
 * What the user asks of the camera in one update, read from the {@link InputState}: the key bindings live here and
 * nowhere else. Each axis is −1, 0 or +1 (opposite keys cancel).
 *
 * <table>
 *   <caption>Bindings</caption>
 *   <tr><td>W / S</td><td>forward / back along the view (fly) or the heading (walk)</td></tr>
 *   <tr><td>A / D</td><td>strafe left / right</td></tr>
 *   <tr><td>Space / C or Left Ctrl</td><td>up / down (fly only)</td></tr>
 *   <tr><td>Shift</td><td>boost (fly) or run (walk)</td></tr>
 *   <tr><td>arrow keys</td><td>turn and look up or down</td></tr>
 *   <tr><td>mouse, while looking</td><td>turn and look up or down</td></tr>
 *   <tr><td>V</td><td>toggle fly / walk</td></tr>
 * </table>
 *
 * @param forward    +1 forward (W), −1 back (S)
 * @param right      +1 right (D), −1 left (A)
 * @param up         +1 up (Space), −1 down (C, Left Ctrl)
 * @param fast       Shift held: boost or run
 * @param turnRight  +1 right arrow, −1 left arrow
 * @param turnUp     +1 up arrow, −1 down arrow
 * @param mouseDx    mouse movement since the last update while looking, pixels, x right
 * @param mouseDy    mouse movement since the last update while looking, pixels, y down
 * @param toggleMode V was pressed since the last update
 */
public record CameraControls(int forward, int right, int up, boolean fast, int turnRight, int turnUp,
                             double mouseDx, double mouseDy, boolean toggleMode) {

    /** Nothing held, nothing moved. */
    public static final CameraControls NONE = new CameraControls(0, 0, 0, false, 0, 0, 0, 0, false);

    /**
     * Reads the held keys and consumes this update's mouse movement and V press. Mouse movement is always drained,
     * and counts only while {@link InputState#looking()}, so switching mouse look on never turns the view by what
     * the cursor did before.
     */
    public static CameraControls read(InputState input) {
        double[] mouse = input.consumeMouse();
        boolean looking = input.looking();
        return new CameraControls(
                axis(input, GLFW_KEY_W, GLFW_KEY_S),
                axis(input, GLFW_KEY_D, GLFW_KEY_A),
                (input.isHeld(GLFW_KEY_SPACE) ? 1 : 0)
                        - (input.isHeld(GLFW_KEY_C) || input.isHeld(GLFW_KEY_LEFT_CONTROL) ? 1 : 0),
                input.isHeld(GLFW_KEY_LEFT_SHIFT) || input.isHeld(GLFW_KEY_RIGHT_SHIFT),
                axis(input, GLFW_KEY_RIGHT, GLFW_KEY_LEFT),
                axis(input, GLFW_KEY_UP, GLFW_KEY_DOWN),
                looking ? mouse[0] : 0,
                looking ? mouse[1] : 0,
                input.consumePress(GLFW_KEY_V));
    }

    /** Whether any move key asks for motion (opposite keys cancel to none). */
    public boolean moving() {
        return forward != 0 || right != 0 || up != 0;
    }

    private static int axis(InputState input, int plus, int minus) {
        return (input.isHeld(plus) ? 1 : 0) - (input.isHeld(minus) ? 1 : 0);
    }
}
