package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.joml.Matrix4f;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.environment.Exposure;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.Image;

/**
 * The sky as drawn by the GPU against the CPU's physics: the same radiance at sampled directions, noon against
 * sunset, and tables rebuilt only when the sun moved. Clouds off, so the sky is the atmosphere's alone.
 */
@GlTest
class SkyRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int WIDTH = 320;
    static final int HEIGHT = 180;
    static final double ALTITUDE = 400;
    static final SkySettings SKY = SkySettings.DEFAULTS;

    private static Engine sky(String... settings) {
        List<String> all = new ArrayList<>(List.of("clouds.cover=0"));
        all.addAll(List.of(settings));
        return GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, all, new SkySystem());
    }

    /** Sets the clock and the camera (yaw degrees clockwise from north, pitch up), updates once, renders. */
    private static Image render(Engine engine, double hours, double yaw, double pitch) {
        engine.world().setResource(new TimeOfDay(hours, 0));
        engine.world().resource(Camera.class).setPose(new CameraPose(0, ALTITUDE, 0, yaw, pitch, 60));
        engine.update();
        engine.render();
        return engine.readImage();
    }

    /** Yaw of the sun at {@code hours}, degrees clockwise from north. */
    private static double sunYaw(double hours) {
        Vector3f s = SolarPosition.direction(hours, SKY.latitude(), SKY.declination());
        return Math.toDegrees(Math.atan2(s.x, -s.z));
    }

    /** The world direction through the centre of pixel (x, y), y from the top. */
    private static Vector3d direction(Engine engine, int x, int y) {
        Matrix4f inverse = new Matrix4f(engine.world().resource(Camera.class).view((float) WIDTH / HEIGHT)
                .viewProjection()).invert();
        Vector4f far = inverse.transform(new Vector4f((x + 0.5f) / WIDTH * 2 - 1, 1 - (y + 0.5f) / HEIGHT * 2, 1, 1));
        Vector3f eye = new Vector3f(0, (float) ALTITUDE, 0);
        Vector3f d = new Vector3f(far.x / far.w, far.y / far.w, far.z / far.w).sub(eye).normalize();
        return new Vector3d(d.x, d.y, d.z);
    }

    /** shaders/common/color.glsl's displayColor for one channel, 0..255. */
    static double display(double linear, double exposure) {
        double x = linear * exposure;
        double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
        double mapped = Math.min(1, Math.max(0, (x * (a * x + b)) / (x * (c * x + d) + e)));
        double srgb = mapped <= 0.0031308 ? mapped * 12.92 : 1.055 * Math.pow(mapped, 1 / 2.4) - 0.055;
        return srgb * 255;
    }

    @Test
    void renderedSkyMatchesTheCpuReference() throws IOException {
        for (double hours : new double[] {10, 18.8}) {
            try (Engine engine = sky()) {
                Image image = render(engine, hours, sunYaw(hours) + 40, 25);
                image.writePng(Path.of("target/test-images/sky-reference-" + (int) (hours * 100) + ".png"));
                AtmosphereTables tables = AtmosphereTables.build(AtmosphereSettings.DEFAULTS);
                Vector3f s = engine.world().resource(Sun.class).direction().get(new Vector3f());
                Vector3d toSun = new Vector3d(s.x, s.y, s.z);
                double exposure = engine.world().resource(Exposure.class).scale();
                int compared = 0;
                for (int y = 5; y < HEIGHT; y += 17) {
                    for (int x = 7; x < WIDTH; x += 29) {
                        Vector3d dir = direction(engine, x, y);
                        if (dir.y < 0.02 || dir.angle(toSun) < Math.toRadians(3)) {
                            continue; // the distant ground, and the sun's disc and its steepest glow
                        }
                        Vector3d expected = SkyReference.radiance(tables, dir, toSun, ALTITUDE);
                        for (int c = 0; c < 3; c++) {
                            double want = display(expected.get(c), exposure);
                            assertEquals(want, image.channel(x, y, c), 6 + 0.06 * want,
                                    "at " + hours + " h, pixel " + x + "," + y + " (elevation "
                                            + Math.round(Math.toDegrees(Math.asin(dir.y))) + "°) channel " + c);
                        }
                        compared++;
                    }
                }
                assertTrue(compared > 40, compared + " directions compared");
            }
        }
    }

    @Test
    void noonSkyIsBlueAndSunsetHorizonTowardsTheSunIsRed() throws IOException {
        double sunset = SolarPosition.hoursAtElevation(1, false, SKY.latitude(), SKY.declination());
        Image noon;
        Image evening;
        try (Engine engine = sky()) {
            noon = render(engine, 12, sunYaw(12) + 180, 30);
            evening = render(engine, sunset, sunYaw(sunset), 5);
        }
        noon.writePng(Path.of("target/test-images/sky-noon.png"));
        evening.writePng(Path.of("target/test-images/sky-sunset.png"));
        int top = 10;
        assertTrue(noon.channel(WIDTH / 2, top, 2) > noon.channel(WIDTH / 2, top, 0) + 30,
                "noon sky away from the sun is blue: " + rgb(noon, WIDTH / 2, top));
        // the horizon below the sun at sunset: the row just above the horizon, a little to the side of the disc
        int horizon = HEIGHT / 2 + (int) (HEIGHT / 2 * Math.tan(Math.toRadians(5)) / Math.tan(Math.toRadians(30))) - 2;
        int x = WIDTH / 2 + 30;
        assertTrue(evening.channel(x, horizon, 0) > evening.channel(x, horizon, 2) + 30,
                "sunset horizon towards the sun is red: " + rgb(evening, x, horizon));
    }

    @Test
    void tablesAreRebuiltWhenTheSunMovesAndNotWhileItStandsStill() {
        try (Engine engine = sky()) {
            List<FrameRecord> frames = new ArrayList<>();
            engine.update(); // the first frame carries the tables built at start-up
            engine.render();
            engine.collectFrames(true, f -> { });
            for (int i = 0; i < 8; i++) {
                engine.update();
                engine.render();
            }
            engine.collectFrames(true, frames::add);
            assertFalse(frames.stream().anyMatch(f -> f.counters().containsKey("sky.tables-ms")),
                    "the sun stood still: no new tables");

            // a jump of an hour: new tables at once, in the very next update
            frames.clear();
            engine.world().setResource(new TimeOfDay(11, 0));
            engine.update();
            engine.render();
            engine.collectFrames(true, frames::add);
            assertTrue(frames.get(0).counters().getOrDefault("sky.tables-ms", 0.0) > 0, frames.get(0).counters().toString());

            // a fast day: the sun drifts, and new tables arrive from the worker now and then, not every frame
            engine.world().setResource(new TimeOfDay(17, 0));
            engine.update();
            engine.render();
            engine.collectFrames(true, f -> { });
            frames.clear();
            engine.world().setResource(new TimeOfDay(17, 3600)); // an hour per second: 0.2° of sun per step
            for (int i = 0; i < 400 && frames.stream().noneMatch(f -> f.counters().containsKey("sky.tables-ms")); i++) {
                engine.update();
                engine.render();
                engine.collectFrames(true, frames::add);
            }
            long rebuilt = frames.stream().filter(f -> f.counters().containsKey("sky.tables-ms")).count();
            assertEquals(1, rebuilt, "tables arrived once in " + frames.size() + " frames of a drifting sun");
            assertTrue(frames.size() > 1, "not on the first frame: a drift of one step is not worth new tables");
        }
    }

    private static String rgb(Image image, int x, int y) {
        return image.channel(x, y, 0) + "," + image.channel(x, y, 1) + "," + image.channel(x, y, 2);
    }
}
