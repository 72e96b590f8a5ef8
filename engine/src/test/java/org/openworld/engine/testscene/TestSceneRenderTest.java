package org.openworld.engine.testscene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.joml.Vector3f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Image;
import org.openworld.engine.sky.SkySettings;
import org.openworld.engine.sky.SkySystem;
import org.openworld.engine.sky.SolarPosition;

/**
 * The test scene under the daylight system, rendered headless at fixed poses and times. The pictures are written to
 * {@code target/test-images/} to look at; the assertions check what any sky-over-ground picture must show.
 */
@GlTest
class TestSceneRenderTest {

    static final int WIDTH = 320;
    static final int HEIGHT = 180;
    /** 60 m up, 400 m south of the ring of boxes, looking north and slightly down. */
    static final CameraPose LOOKING_NORTH = new CameraPose(0, 60, 400, 0, -5, 60);
    /** Rows at the top (sky) and bottom (ground near the camera) that the checks average over. */
    static final int BAND = 10;

    private static GlContext gl;
    private static Image morning;
    private static Image dusk;
    private static Image lowSun;
    private static Image highSun;
    private static int liveAfterClose;

    @BeforeAll
    static void render() throws IOException {
        gl = GlContext.headless();
        try (Engine engine = GlTestSupport.engine(gl, WIDTH, HEIGHT, List.of("clouds.cover=0"), new TestSceneSystem(),
                new SkySystem())) {
            morning = renderAt(engine, LOOKING_NORTH, 10.0);
            dusk = renderAt(engine, LOOKING_NORTH, 19.5);
            lowSun = renderAt(engine, lookingAtTheSun(18.5), 18.5);
            highSun = renderAt(engine, lookingAtTheSun(10.0), 10.0);
        }
        liveAfterClose = gl.objects().live();
        morning.writePng(Path.of("target/test-images/test-scene-1000.png"));
        dusk.writePng(Path.of("target/test-images/test-scene-1930.png"));
        lowSun.writePng(Path.of("target/test-images/test-scene-sun-1830.png"));
        highSun.writePng(Path.of("target/test-images/test-scene-sun-1000.png"));
    }

    @AfterAll
    static void closeContext() {
        gl.close();
    }

    /** Sets the clock, lets the daylight system move the sun (one update), and renders one frame. */
    static Image renderAt(Engine engine, CameraPose pose, double hours) {
        engine.world().resource(Camera.class).setPose(pose);
        engine.world().setResource(new TimeOfDay(hours, 0));
        engine.update();
        engine.render();
        return engine.readImage();
    }

    /** A camera at the usual place turned towards the sun of the default latitude and season. */
    static CameraPose lookingAtTheSun(double hours) {
        SkySettings s = SkySettings.DEFAULTS;
        Vector3f toSun = SolarPosition.direction(hours, s.latitude(), s.declination());
        double yaw = Math.toDegrees(Math.atan2(toSun.x, -toSun.z)); // clockwise from north (−Z)
        double pitch = Math.toDegrees(Math.asin(toSun.y));
        return new CameraPose(LOOKING_NORTH.x(), LOOKING_NORTH.y(), LOOKING_NORTH.z(), yaw, pitch, LOOKING_NORTH.fov());
    }

    /** Mean of channel c (0 r, 1 g, 2 b) over whole rows y0 ≤ y &lt; y1. */
    static double mean(Image image, int c, int y0, int y1) {
        double sum = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = 0; x < image.width(); x++) {
                sum += image.channel(x, y, c);
            }
        }
        return sum / ((y1 - y0) * image.width());
    }

    static double meanLuma(Image image) {
        return image.meanLuma(0, 0, image.width(), image.height());
    }

    @Test
    void topRowsAreABrightBlueSky() {
        double r = mean(morning, 0, 0, BAND);
        double b = mean(morning, 2, 0, BAND);
        double luma = morning.meanLuma(0, 0, WIDTH, BAND);

        // 20 levels of blue over red: a hue a viewer calls blue; luma 90 of 255: a daytime sky, not dusk
        assertTrue(b > r + 20, "sky blue " + b + " vs red " + r);
        assertTrue(luma > 90, "sky luma " + luma);
    }

    @Test
    void bottomRowsAreGroundGreenerThanTheSky() {
        double skyLuma = morning.meanLuma(0, 0, WIDTH, BAND);
        double groundLuma = morning.meanLuma(0, HEIGHT - BAND, WIDTH, HEIGHT);
        double skyGreenOverBlue = mean(morning, 1, 0, BAND) - mean(morning, 2, 0, BAND);
        double groundGreenOverBlue = mean(morning, 1, HEIGHT - BAND, HEIGHT) - mean(morning, 2, HEIGHT - BAND, HEIGHT);

        // a sunlit ground is brighter than the blue sky (as outdoors: albedo 0.3 under the sun against the zenith),
        // but must not be white: the exposure keeps it readable
        assertTrue(groundLuma < 230 && groundLuma > skyLuma / 2, "ground " + groundLuma + " vs sky " + skyLuma);
        assertTrue(groundGreenOverBlue > 0, "ground green − blue " + groundGreenOverBlue);
        assertTrue(skyGreenOverBlue < 0, "sky green − blue " + skyGreenOverBlue);
    }

    @Test
    void gridLeavesThinBrightLinesAcrossTheGround() {
        int y = HEIGHT - 5;
        double[] luma = new double[WIDTH];
        for (int x = 0; x < WIDTH; x++) {
            luma[x] = morning.luma(x, y);
        }
        double mean = Arrays.stream(luma).average().orElseThrow();
        double variance = Arrays.stream(luma).map(l -> (l - mean) * (l - mean)).average().orElseThrow();
        double median = Arrays.stream(luma).sorted().toArray()[WIDTH / 2];
        int lines = 0;
        int linePixels = 0;
        for (int x = 0; x < WIDTH; x++) {
            boolean on = luma[x] > median + 10;
            if (on) {
                linePixels++;
                if (x == 0 || luma[x - 1] <= median + 10) {
                    lines++;
                }
            }
        }

        // a variance of 10 (a σ of 3 levels): the grid's texture is there, a flat fill gives 0; three lines a row at
        // least, from the grid's spacing
        assertTrue(variance > 10, "luma variance along row " + y + ": " + variance);
        assertTrue(lines >= 3, lines + " grid lines crossed by row " + y);
        assertTrue(linePixels < WIDTH / 10, "lines are thin: " + linePixels + " of " + WIDTH + " pixels");
    }

    @Test
    void duskIsMuchDarkerThanMorning() {
        // The ground, not the sky: with the sun 8° down the sky is the light itself, and the exposure that keeps the
        // ground readable (sky.Adaptation's night floor) shows it about as bright as a white surface, so about as
        // bright as the morning's sky, whose exposure the sun set. The ground lit by that sky alone is what darkens: a
        // white surface is shown at B = 0.053 against the morning's 0.77 (the square root of its light, about 0.6),
        // 0.07 times, 0.10 with the rods' V / Y of the blue light (1.5); through the tone curve and sRGB's power
        // 1/2.4 about a quarter, and under a third.
        double groundMorning = morning.meanLuma(0, HEIGHT - BAND, WIDTH, HEIGHT);
        double groundDusk = dusk.meanLuma(0, HEIGHT - BAND, WIDTH, HEIGHT);
        assertTrue(groundDusk < groundMorning / 3, "ground luma at 19:30 " + groundDusk + " vs 10:00 " + groundMorning);
        // The sun is below the horizon at 19:30: what light is left is the blue of the sky, not sunlight.
        assertTrue(mean(dusk, 2, 0, BAND) > mean(dusk, 0, 0, BAND), "dusk sky stays blue");
    }

    @Test
    void aLowSunWarmsTheSkyAroundIt() {
        // beside the sun's disc (which saturates to white), 10° along the horizon: the glow around it
        int x = WIDTH / 2 + 30;
        int y = HEIGHT / 2 - 2;
        double lowRedOverBlue = (double) lowSun.channel(x, y, 0) / lowSun.channel(x, y, 2);
        double highRedOverBlue = (double) highSun.channel(x, y, 0) / highSun.channel(x, y, 2);

        // 40 levels of red over blue: plainly warm; the red/blue ratio 1.5× the morning's, the long path's Rayleigh
        // loss of blue (see TwilightTest)
        assertTrue(lowSun.channel(x, y, 0) > lowSun.channel(x, y, 2) + 40, "glow of the setting sun is warm: "
                + lowSun.channel(x, y, 0) + "," + lowSun.channel(x, y, 1) + "," + lowSun.channel(x, y, 2));
        assertTrue(lowRedOverBlue > 1.5 * highRedOverBlue, "red/blue at 18:30 " + lowRedOverBlue
                + " vs 10:00 " + highRedOverBlue);
    }

    @Test
    void everyGlObjectIsDeletedWhenTheEngineCloses() {
        assertEquals(0, liveAfterClose);
    }
}
