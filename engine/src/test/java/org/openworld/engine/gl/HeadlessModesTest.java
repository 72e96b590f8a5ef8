package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.ImageComparison;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.failure.ExitCode;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.testscene.TestSceneSystem;

/**
 * The headless modes on this machine: the device mode comes first and works on Mesa (its software device), and every
 * mode that works draws the same picture.
 */
@GlTest
class HeadlessModesTest {

    private static final int WIDTH = 160;
    private static final int HEIGHT = 90;
    /** 60 m up, 400 m south of the test scene's boxes, looking north and slightly down: sky, ground and boxes. */
    private static final CameraPose POSE = new CameraPose(0, 60, 400, 0, -5, 60);
    /**
     * Mean CIEDE2000 difference allowed between two modes' pictures: a hundredth of a just-noticeable difference
     * (ΔE00 about 1). The modes differ only in how the context is made, not in the driver that draws, so the
     * pictures should be identical; the margin admits a driver that rounds a few pixels differently per platform,
     * and nothing that could be seen.
     */
    private static final double SAME_PICTURE_DE = 0.01;

    @Test
    void theDeviceModeIsTriedFirstAndChosenWhereEglListsADevice() {
        try (GlContext gl = GlContext.headless()) {
            assertEquals(GlContext.Mode.HEADLESS_EGL_DEVICE, gl.mode(), "modes tried before: " + gl.tried());
            assertTrue(gl.device().startsWith("0: "), "the device as --gpu numbers it: " + gl.device());
            assertTrue(gl.tried().isEmpty(), "nothing failed before the first mode: " + gl.tried());
        }
    }

    @Test
    void everyHeadlessModeThisMachineHasDrawsTheSamePicture() {
        Map<GlContext.Mode, Image> pictures = new LinkedHashMap<>();
        for (GlContext.Mode mode : GlContext.Mode.headless()) {
            GlContext gl;
            try {
                gl = GlContext.headless(HeadlessChoice.any(false).only(mode));
            } catch (GlUnavailableException e) {
                continue; // a mode this machine lacks (headless-x11 without DISPLAY)
            }
            try (gl) {
                assertEquals(mode, gl.mode());
                pictures.put(mode, render(gl));
                assertEquals(0, gl.objects().live(), "live GL objects in " + mode + ": " + gl.objects());
            }
        }
        assertTrue(pictures.containsKey(GlContext.Mode.HEADLESS_EGL_DEVICE), "modes that drew: " + pictures.keySet());
        assertTrue(pictures.size() >= 2, "at least two modes to compare: " + pictures.keySet());
        Image first = pictures.get(GlContext.Mode.HEADLESS_EGL_DEVICE);
        // 20 of 255: any drawn scene is far brighter, an undrawn one black
        assertTrue(first.meanLuma(0, 0, WIDTH, HEIGHT) > 20, "the device mode drew a picture, not black");
        pictures.forEach((mode, picture) -> {
            double mean = ImageComparison.of(first, picture).meanDeltaE();
            assertTrue(mean < SAME_PICTURE_DE, mode + " against headless-egl-device: mean ΔE00 " + mean);
        });
    }

    @Test
    void aDeviceNumberPastEglsListIsTheUsersMistakeNamingTheDevices() {
        int count = HeadlessChoice.devices().size();
        var error = assertThrows(GlUnavailableException.class, () -> GlContext.headless(
                new HeadlessChoice(null, count, false, false)).close());
        assertEquals(ExitCode.USER_MISTAKE, error.exitCode());
        assertTrue(error.getMessage().startsWith("--gpu " + count + ": expected a device number 0 .. " + (count - 1)),
                error.getMessage());
    }

    @Test
    void aForcedModeThisMachineLacksSaysWhatEveryModeSaid() {
        Assumptions.assumeTrue(System.getenv("DISPLAY") == null, "headless-x11 is missing only without DISPLAY");
        var error = assertThrows(GlUnavailableException.class, () -> GlContext.headless(
                HeadlessChoice.any(false).only(GlContext.Mode.HEADLESS_X11)).close());
        assertEquals(ExitCode.USER_MISTAKE, error.exitCode());
        for (GlContext.Mode mode : GlContext.Mode.headless()) {
            assertTrue(error.getMessage().contains("\n  - " + mode), mode + " in: " + error.getMessage());
        }
    }

    @Test
    void aGuiContextLeavesOutTheDeviceModeWhichHasNoWindow() {
        try (GlContext gl = GlContext.headless(new HeadlessChoice(null, HeadlessChoice.ANY_DEVICE, false, true))) {
            assertFalse(gl.mode() == GlContext.Mode.HEADLESS_EGL_DEVICE);
            assertTrue(gl.window() != 0, "a GLFW window for Dear ImGui");
        }
    }

    /** The test scene under the sky at ten in the morning, one frame. */
    private static Image render(GlContext gl) {
        try (Engine engine = GlTestSupport.engine(gl, WIDTH, HEIGHT, List.of("clouds.cover=0"), new TestSceneSystem(),
                new SkySystem())) {
            engine.world().resource(Camera.class).setPose(POSE);
            engine.world().setResource(new TimeOfDay(10.0, 0));
            engine.update();
            engine.render();
            return engine.readImage();
        }
    }
}
