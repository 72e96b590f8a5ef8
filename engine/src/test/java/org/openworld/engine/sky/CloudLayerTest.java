package org.openworld.engine.sky;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.*;

import java.io.IOException;
import java.nio.FloatBuffer;
import java.nio.file.Path;
import java.util.EnumMap;
import java.util.Map;
import java.util.function.DoublePredicate;
import org.joml.Vector3d;
import org.joml.Vector4f;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.ShaderSources;
import org.openworld.engine.gl.Texture3D;
import org.openworld.engine.sky.CloudSettings.Mapping;

/**
 * {@code sky/clouds.glsl} drawn over a plain gradient sky by a test fixture shader ({@code cloudtest/layer.frag}),
 * once per mapping of the paper's figure 5, with a camera looking south-south-west and up so the horizon runs just
 * above the bottom row. The fixture writes the cloud's opacity to alpha, which the checks read; the pictures, made
 * opaque, are written to {@code target/test-images/clouds-*.png} to look at.
 */
@GlTest
class CloudLayerTest {

    static final int WIDTH = 320;
    static final int HEIGHT = 180;
    static final double YAW = Math.toRadians(200);
    /** Looking 29° up with a 60° vertical view: the bottom centre of the picture is 1° below the horizon. */
    static final double PITCH = Math.toRadians(29);
    static final double TAN_HALF_FOV = Math.tan(Math.toRadians(30));
    static final long SEED = 3;

    private static GlContext gl;
    private static Framebuffer target;
    private static Mesh triangle;
    private static ShaderProgram program;
    private static Texture3D field;
    private static CloudField cloudField;
    private static double[][] elevation;
    private static Image reference;
    private static final Map<Mapping, Image> pictures = new EnumMap<>(Mapping.class);

    @BeforeAll
    static void render() throws IOException {
        gl = GlContext.headless();
        target = new Framebuffer(gl, WIDTH, HEIGHT, Format.RGBA8, null, Sampling.NEAREST_CLAMP);
        triangle = GlTestSupport.fullScreenTriangle(gl);
        program = new ShaderLibrary(gl, ShaderSources.classpath()).program("cloudtest/fullscreen.vert",
                "cloudtest/layer.frag");
        CloudSettings d = CloudSettings.DEFAULTS;
        cloudField = CloudField.generate(d.resolution(), d.frames(), d.beta(), SEED);
        FloatBuffer values = MemoryUtil.memAllocFloat(cloudField.values().length).put(cloudField.values()).flip();
        try {
            field = Texture3D.of(gl, d.resolution(), d.resolution(), d.frames(), Format.R16F,
                    Sampling.LINEAR_REPEAT, values);
        } finally {
            MemoryUtil.memFree(values);
        }
        elevation = elevations();
        reference = draw(CloudSettings.DEFAULTS, d.cover(), 0, false);
        for (Mapping m : Mapping.values()) {
            Image picture = draw(with(m), d.cover(), 0, true);
            pictures.put(m, picture);
            opaque(picture).writePng(Path.of("target/test-images/clouds-" + m.name().toLowerCase() + ".png"));
        }
    }

    @AfterAll
    static void close() {
        field.close();
        program.close();
        triangle.close();
        target.close();
        assertEquals(0, gl.objects().live(), "live GL objects: " + gl.objects());
        gl.close();
    }

    static CloudSettings with(Mapping mapping, String... more) {
        String[] assignments = new String[more.length + 1];
        assignments[0] = "clouds.mapping=" + mapping.name().toLowerCase().replace('_', '-');
        System.arraycopy(more, 0, assignments, 1, more.length);
        return CloudSettingsTest.settings(assignments);
    }

    /** Renders the fixture with the settings' uniforms at {@code seconds}, for the given cover. */
    static Image draw(CloudSettings s, double cover, double seconds, boolean clouds) {
        target.bind();
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        program.use();
        program.sampler("cloudField", 0);
        program.vec4("cloudParams").set(s.cloudParams(CloudField.coverageThreshold(cloudField, cover), new Vector4f()));
        program.vec4("cloudMotion").set(s.cloudMotion(seconds, new Vector4f()));
        program.vec4("camera").set((float) YAW, (float) PITCH, (float) TAN_HALF_FOV, (float) WIDTH / HEIGHT);
        Vector3d sun = new Vector3d(Math.sin(Math.toRadians(215)), Math.tan(Math.toRadians(30)),
                -Math.cos(Math.toRadians(215))).normalize(); // 30° up in the south-west, inside the picture
        program.vec3("uSunDir").set((float) sun.x, (float) sun.y, (float) sun.z);
        program.vec3("sunColor").set(1.0f, 0.95f, 0.85f);
        program.vec3("ambientColor").set(0.30f, 0.38f, 0.50f);
        program.vec3("horizonColor").set(0.62f, 0.70f, 0.80f);
        program.vec3("zenithColor").set(0.12f, 0.30f, 0.70f);
        program.float1("cloudsOn").set(clouds ? 1 : 0);
        field.bind(0);
        triangle.draw(new DrawStats());
        return target.read();
    }

    /** The elevation in degrees of each pixel's view direction, top row first, as the fixture computes it. */
    static double[][] elevations() {
        double cy = Math.cos(YAW), sy = Math.sin(YAW), cp = Math.cos(PITCH), sp = Math.sin(PITCH);
        Vector3d forward = new Vector3d(sy * cp, sp, -cy * cp);
        Vector3d right = new Vector3d(cy, 0, sy);
        Vector3d up = new Vector3d(right).cross(forward);
        double[][] e = new double[HEIGHT][WIDTH];
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                double nx = 2 * (x + 0.5) / WIDTH - 1;
                double ny = 1 - 2 * (y + 0.5) / HEIGHT;
                Vector3d dir = new Vector3d(forward).fma(nx * TAN_HALF_FOV * WIDTH / HEIGHT, right)
                        .fma(ny * TAN_HALF_FOV, up).normalize();
                e[y][x] = Math.toDegrees(Math.asin(dir.y));
            }
        }
        return e;
    }

    /** A copy with alpha 255, to look at. */
    static Image opaque(Image image) {
        byte[] rgba = new byte[WIDTH * HEIGHT * 4];
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                for (int c = 0; c < 3; c++) {
                    rgba[(y * WIDTH + x) * 4 + c] = (byte) image.channel(x, y, c);
                }
                rgba[(y * WIDTH + x) * 4 + 3] = (byte) 255;
            }
        }
        return new Image(WIDTH, HEIGHT, rgba);
    }

    /** Opacity statistics over the pixels whose elevation (degrees) passes the test. */
    record Band(double meanAlpha, double cloudFraction, double maxColourDifference, int pixels) {
    }

    static Band band(Image image, DoublePredicate elevationDeg) {
        double alpha = 0;
        int cloudy = 0;
        int count = 0;
        double maxDiff = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                if (!elevationDeg.test(elevation[y][x])) {
                    continue;
                }
                int a = image.channel(x, y, 3);
                alpha += a / 255.0;
                cloudy += a > 0 ? 1 : 0;
                for (int c = 0; c < 3; c++) {
                    maxDiff = Math.max(maxDiff, Math.abs(image.channel(x, y, c) - reference.channel(x, y, c)));
                }
                count++;
            }
        }
        return new Band(alpha / count, cloudy / (double) count, maxDiff, count);
    }

    static final DoublePredicate BELOW_HORIZON = e -> e < -0.3;
    /** The lowest 3° of sky, a few rows of the picture. */
    static final DoublePredicate HORIZON = e -> e > 0.3 && e < 3;
    static final DoublePredicate HIGH = e -> e > 40;

    /** Times the opacity crosses one half along the rows of a band, per row. */
    static double edgesPerRow(Image image, DoublePredicate band) {
        int edges = 0;
        int rows = 0;
        for (int y = 0; y < HEIGHT; y++) {
            if (!band.test(elevation[y][WIDTH / 2])) {
                continue;
            }
            rows++;
            for (int x = 1; x < WIDTH; x++) {
                if ((image.channel(x, y, 3) >= 128) != (image.channel(x - 1, y, 3) >= 128)) {
                    edges++;
                }
            }
        }
        return edges / (double) rows;
    }

    @Test
    void theBandsHoldPixels() {
        assertTrue(band(reference, HORIZON).pixels() > 3 * WIDTH, "horizon band " + band(reference, HORIZON));
        assertTrue(band(reference, HIGH).pixels() > 10 * WIDTH, "high band " + band(reference, HIGH));
        assertTrue(band(reference, BELOW_HORIZON).pixels() > 0, "ground in the picture");
    }

    @ParameterizedTest
    @EnumSource(Mapping.class)
    void noCloudBelowTheHorizon(Mapping m) {
        Band ground = band(pictures.get(m), BELOW_HORIZON);
        assertEquals(0, ground.meanAlpha());
        assertEquals(0, ground.maxColourDifference());
    }

    @ParameterizedTest
    @EnumSource(value = Mapping.class, names = {"SPHERICAL", "PERSPECTIVE"})
    void withoutFogTheCloudsReachTheHorizon(Mapping m) {
        Band horizon = band(pictures.get(m), HORIZON);
        assertTrue(horizon.cloudFraction() > 0.15 && horizon.cloudFraction() < 0.85, m + " " + horizon);
        assertTrue(horizon.maxColourDifference() > 20, m + " " + horizon);
    }

    @ParameterizedTest
    @EnumSource(value = Mapping.class, names = {"SPHERICAL_FOG", "PERSPECTIVE_FOG"})
    void theFogFadesTheHorizonIntoTheSkyButNotTheCloudsOverhead(Mapping m) {
        Band horizon = band(pictures.get(m), HORIZON);
        Band high = band(pictures.get(m), HIGH);
        assertTrue(horizon.meanAlpha() < 0.03, m + " " + horizon);
        assertTrue(horizon.maxColourDifference() <= 12, m + " " + horizon);
        assertTrue(high.cloudFraction() > 0.15 && high.meanAlpha() > 0.1, m + " " + high);
    }

    /**
     * On the plane, clouds shrink with distance: a row near the horizon crosses many more of them than a high row.
     * The spherical mapping keeps their angular size, which is what makes figure 5a look closed.
     */
    @Test
    void onlyThePerspectiveMappingShrinksTheCloudsTowardsTheHorizon() {
        double perspective = edgesPerRow(pictures.get(Mapping.PERSPECTIVE), HORIZON)
                / edgesPerRow(pictures.get(Mapping.PERSPECTIVE), HIGH);
        double spherical = edgesPerRow(pictures.get(Mapping.SPHERICAL), HORIZON)
                / edgesPerRow(pictures.get(Mapping.SPHERICAL), HIGH);
        assertTrue(perspective > 3 * spherical, "edges per row, horizon / high: perspective " + perspective
                + ", spherical " + spherical);
    }

    @ParameterizedTest
    @EnumSource(Mapping.class)
    void coverZeroIsAClearSky(Mapping m) {
        Image clear = draw(with(m), 0, 0, true);
        Band sky = band(clear, e -> true);
        assertEquals(0, sky.meanAlpha());
        assertEquals(0, sky.maxColourDifference());
    }

    @ParameterizedTest
    @EnumSource(value = Mapping.class, names = {"SPHERICAL", "PERSPECTIVE"})
    void coverOneIsOvercast(Mapping m) {
        Image overcast = draw(with(m), 1, 0, true);
        Band sky = band(overcast, e -> e > 0.3);
        assertEquals(1, sky.cloudFraction());
        assertEquals(1, sky.meanAlpha(), 1e-9);
    }

    @ParameterizedTest
    @EnumSource(value = Mapping.class, names = {"SPHERICAL_FOG", "PERSPECTIVE_FOG"})
    void coverOneWithFogIsOvercastOverheadAndFadedAtTheHorizon(Mapping m) {
        Image overcast = draw(with(m), 1, 0, true);
        Band high = band(overcast, HIGH);
        Band horizon = band(overcast, HORIZON);
        // 40° up on the default layer the fog's distance is 3 km, a quarter of its 12 km e-folding length
        assertTrue(high.cloudFraction() == 1 && high.meanAlpha() > 0.7, m + " " + high);
        assertTrue(horizon.meanAlpha() < 0.1, m + " " + horizon);
    }

    /** The time phase runs through the frames and back: just before a full loop looks like the start. */
    @Test
    void theAnimationLoopsOnScreen() {
        CloudSettings still = with(Mapping.PERSPECTIVE, "clouds.wind-speed=0");
        double period = still.period();
        Image start = draw(still, still.cover(), 0, true);
        Image almostLoop = draw(still, still.cover(), 0.995 * period, true);
        Image halfLoop = draw(still, still.cover(), 0.5 * period, true);

        double nearEnd = meanAlphaDifference(start, almostLoop);
        double half = meanAlphaDifference(start, halfLoop);
        assertTrue(half > 0.02, "half a loop changes the clouds: " + half);
        assertTrue(nearEnd < 0.2 * half, "0.995 of a loop " + nearEnd + " vs half a loop " + half);
    }

    static double meanAlphaDifference(Image a, Image b) {
        double sum = 0;
        for (int y = 0; y < HEIGHT; y++) {
            for (int x = 0; x < WIDTH; x++) {
                sum += Math.abs(a.channel(x, y, 3) - b.channel(x, y, 3)) / 255.0;
            }
        }
        return sum / (WIDTH * HEIGHT);
    }
}
