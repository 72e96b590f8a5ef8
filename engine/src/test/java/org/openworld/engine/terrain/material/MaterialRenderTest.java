package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_ALWAYS;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_LESS;
import static org.lwjgl.opengl.GL11C.glDepthFunc;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.SplittableRandom;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.gl.GlObjects;
import org.openworld.engine.gl.Image;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;
import org.openworld.engine.sky.SkySystem;

/**
 * The terrain materials on real GL: test shaders build {@code TerrainSurface}s, call {@code shadeTerrain} and show
 * the result. {@code material-cases.frag} lays out eight cases in a 4 × 2 grid of cells (its header lists them);
 * the pictures go to {@code target/test-images/material-*.png}.
 */
@GlTest
class MaterialRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int WIDTH = 640;
    static final int HEIGHT = 360;
    static final int COLUMNS = 4;
    static final int ROWS = 2;
    /** Cells of material-cases.frag. */
    static final int MEADOW = 0, SNOWFIELD = 1, STEEP = 2, BARE_PEAK = 3, FLAT_ROCK = 7;
    /** Ten in the morning: the sun in the south-east, about 45 degrees up. */
    static final double MORNING = 10.0;
    /** Five in the afternoon: the sun in the west-south-west, 18 degrees up; its mirror image is seen at grazing angles. */
    static final double AFTERNOON = 17.0;
    /** The cells' viewer: 4 m above the origin, a person on a low rise (its pose's angles do not matter to the cells). */
    static final CameraPose ABOVE = new CameraPose(0, 4, 0, 0, -90, 60);

    static TerrainTextures textures;

    @BeforeAll
    static void synthesise() {
        // the world seed the demo starts with, so these pictures show its textures
        textures = TerrainTextures.generate(EngineSettings.DEFAULTS.seed());
    }

    /**
     * Draws one full-screen triangle with a test fragment shader that includes material.glsl. For the cells shader,
     * it sets {@code uCentre} to the ground point where the sun's mirror image is seen from the camera.
     */
    static final class MaterialPreview implements EngineSystem {
        final String vertex;
        final String fragment;
        ShaderProgram program;
        TerrainMaterials materials;
        TerrainMaterials.Uniforms uniforms;
        Uniform.Vec3 centre;
        Uniform.Float sediment;
        Uniform.Float bare;
        /** What the erosion left on every cell of the cases shader (ErosionCover's b and 1 - a). */
        float sedimentCover;
        float bareCover;
        Mesh triangle;

        MaterialPreview(String vertex, String fragment) {
            this.vertex = vertex;
            this.fragment = fragment;
        }

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("material-preview").reads(Sun.class, Settings.class).draws(Pass.MAIN);
        }

        @Override
        public List<SettingsGroup<?>> settings() {
            return List.of(MaterialSettings.SETTINGS);
        }

        @Override
        public void init(EngineContext context) {
            program = context.shaders().program(vertex, fragment);
            uniforms = TerrainMaterials.uniforms(program);
            if (fragment.endsWith("material-cases.frag")) {
                centre = program.vec3("uCentre");
                sediment = program.float1("uSediment");
                bare = program.float1("uBare");
            }
            program.use();
            program.float1("uSkyVisibility").set(1f);
            materials = new TerrainMaterials(context.gl(), textures);
            triangle = GlTestSupport.fullScreenTriangle(context.gl());
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            // an opaque surface over the whole view: it writes its depth, so the sky (the background, drawn after
            // it on the far plane) leaves every pixel to it
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            glDepthMask(true);
            materials.bind(uniforms, context.world().resource(Settings.class).get(MaterialSettings.class), 0);
            if (centre != null) {
                centre.set(mirrorPoint(context.camera().position(), context.world().resource(Sun.class).direction()));
                sediment.set(sedimentCover);
                bare.set(bareCover);
            }
            triangle.draw(context.stats());
            glDepthFunc(GL_LESS);
        }

        @Override
        public void close() {
            if (triangle != null) {
                triangle.close();
            }
            if (materials != null) {
                materials.close();
            }
            if (program != null) {
                program.close();
            }
        }
    }

    /** The point on the ground y = 0 where a flat mirror shows the sun to an eye at {@code eye}. */
    static Vector3f mirrorPoint(Vector3fc eye, Vector3fc toSun) {
        float t = eye.y() / toSun.y();
        return new Vector3f(eye.x() + toSun.x() * t, 0, eye.z() + toSun.z() * t);
    }

    static Engine engine(String vertex, String fragment) {
        return engine(new MaterialPreview(vertex, fragment));
    }

    static Engine engine(MaterialPreview preview) {
        Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, preview, new SkySystem());
        engine.world().setResource(new TimeOfDay(MORNING, 0));
        engine.world().resource(Camera.class).setPose(ABOVE);
        return engine;
    }

    static Engine cases() {
        return engine("test/fullscreen.vert", "test/terrain/material-cases.frag");
    }

    static Image render(Engine engine, String name) throws IOException {
        engine.update();
        engine.render();
        Image image = engine.readImage();
        image.writePng(Path.of("target/test-images/material-" + name + ".png"));
        return image;
    }

    /** A rectangle of one cell, as fractions of the cell (0..1 from its top-left corner). */
    record Region(int cell, double x0, double y0, double x1, double y1) {
        static Region whole(int cell) {
            return new Region(cell, 0.05, 0.05, 0.95, 0.95);
        }

        int px0() {
            return (int) ((cell % COLUMNS + x0) * WIDTH / COLUMNS);
        }

        int px1() {
            return (int) ((cell % COLUMNS + x1) * WIDTH / COLUMNS);
        }

        int py0() {
            return (int) ((cell / COLUMNS + y0) * HEIGHT / ROWS);
        }

        int py1() {
            return (int) ((cell / COLUMNS + y1) * HEIGHT / ROWS);
        }
    }

    /** Mean r, g, b (0–255) and luma over a region. */
    static double[] mean(Image image, Region r) {
        return mean(image, r.px0(), r.py0(), r.px1(), r.py1());
    }

    /** Mean r, g, b (0–255) and luma over pixels x0 ≤ x &lt; x1, y0 ≤ y &lt; y1. */
    static double[] mean(Image image, int x0, int y0, int x1, int y1) {
        double[] sum = new double[4];
        int count = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                for (int c = 0; c < 3; c++) {
                    sum[c] += image.channel(x, y, c);
                }
                sum[3] += image.luma(x, y);
                count++;
            }
        }
        for (int c = 0; c < 4; c++) {
            sum[c] /= count;
        }
        return sum;
    }

    static double lumaVariance(Image image, Region r) {
        double mean = mean(image, r)[3];
        double sum = 0;
        int count = 0;
        for (int y = r.py0(); y < r.py1(); y++) {
            for (int x = r.px0(); x < r.px1(); x++) {
                double d = image.luma(x, y) - mean;
                sum += d * d;
                count++;
            }
        }
        return sum / count;
    }

    static String rgb(double[] m) {
        return String.format("rgb(%.0f, %.0f, %.0f) luma %.0f", m[0], m[1], m[2], m[3]);
    }

    /**
     * What the erosion left shows: sediment on the flat low meadow is pale gravel, not grass; the bared bed is grey
     * rock on the meadow, and snow does not hold on it (the snowfield).
     */
    @Test
    void sedimentIsGravelAndTheBaredBedRock() throws IOException {
        MaterialPreview preview = new MaterialPreview("test/fullscreen.vert", "test/terrain/material-cases.frag");
        try (Engine engine = engine(preview)) {
            double[] meadow = mean(render(engine, "cases"), Region.whole(MEADOW));
            preview.sedimentCover = 1;
            double[] gravel = mean(render(engine, "sediment"), Region.whole(MEADOW));
            preview.sedimentCover = 0;
            preview.bareCover = 1;
            Image bared = render(engine, "bare");
            double[] rock = mean(bared, Region.whole(MEADOW));
            double[] snow = mean(bared, Region.whole(SNOWFIELD));
            // the meadow test's green: green leads red by 10 levels; gravel's does not, and it is paler than grass
            assertTrue(meadow[1] > meadow[0] + 10, "meadow " + rgb(meadow));
            assertTrue(gravel[1] < gravel[0] + 10 && gravel[3] > meadow[3], "gravel " + rgb(gravel)
                    + ", meadow " + rgb(meadow));
            // rock's channels within 25 % of their mean, as the meadow test's; snow's luma above 185 is snow
            double rockMean = (rock[0] + rock[1] + rock[2]) / 3;
            double spread = Math.max(rock[0], Math.max(rock[1], rock[2]))
                    - Math.min(rock[0], Math.min(rock[1], rock[2]));
            assertTrue(spread < 0.25 * rockMean, "the bared meadow is grey rock: " + rgb(rock));
            assertTrue(snow[3] < 185, "no snow holds on the bared bed: " + rgb(snow));
        }
    }

    @Test
    void meadowIsGreenSnowfieldBrightSteepSlopeGreyRock() throws IOException {
        try (Engine engine = cases()) {
            Image image = render(engine, "cases");
            double[] meadow = mean(image, Region.whole(MEADOW));
            double[] snow = mean(image, Region.whole(SNOWFIELD));
            double[] steep = mean(image, Region.whole(STEEP));

            // 8-bit display levels: green leads red and blue by 10–15 levels (a hue a viewer calls green); snow's luma
            // above 185 of 255 (albedo 0.8+ under noon light and the tone curve); rock's channels within 25 % of their
            // mean, as TerrainTexturesTest
            assertTrue(meadow[1] > meadow[0] + 10 && meadow[1] > meadow[2] + 15, "meadow " + rgb(meadow));
            assertTrue(snow[3] > 185, "snowfield " + rgb(snow));
            assertTrue(snow[2] >= snow[0] - 3, "snow is not yellow: " + rgb(snow));
            double steepMean = (steep[0] + steep[1] + steep[2]) / 3;
            double spread = Math.max(steep[0], Math.max(steep[1], steep[2]))
                    - Math.min(steep[0], Math.min(steep[1], steep[2]));
            assertTrue(spread < 0.25 * steepMean, "a steep slope is grey rock: " + rgb(steep));
            assertTrue(steep[1] < steep[0] + 5, "a steep slope at meadow height has no grass: " + rgb(steep));
        }
    }

    @Test
    void normalMapsAddShadingDetail() throws IOException {
        try (Engine engine = cases()) {
            Image on = render(engine, "cases");
            engine.settings().set("materials.normal-map", "off");
            Image off = render(engine, "cases-no-normal-map");

            // grass least: its blades are a few texels wide and mostly averaged away at this distance
            int[] cells = {MEADOW, FLAT_ROCK, SNOWFIELD};
            double[] factors = {1.1, 1.3, 1.3};
            for (int i = 0; i < cells.length; i++) {
                double varianceOn = lumaVariance(on, Region.whole(cells[i]));
                double varianceOff = lumaVariance(off, Region.whole(cells[i]));
                assertTrue(varianceOn > factors[i] * varianceOff, "cell " + cells[i] + ": luma variance " + varianceOn
                        + " with normal maps, " + varianceOff + " without");
            }
        }
    }

    @Test
    void glossMapsAddAHighlightWhereTheSunIsMirrored() throws IOException {
        try (Engine engine = cases()) {
            engine.world().setResource(new TimeOfDay(AFTERNOON, 0));
            engine.settings().set("materials.normal-map", "off");
            Image on = render(engine, "cases-1700-gloss-only");
            engine.settings().set("materials.gloss-map", "off");
            Image off = render(engine, "cases-1700-none");

            // snow: a sheen around the mirror point, brighter than away from it
            Region centre = new Region(SNOWFIELD, 0.4, 0.4, 0.6, 0.6);
            Region corner = new Region(SNOWFIELD, 0.02, 0.02, 0.15, 0.15);
            double gainCentre = mean(on, centre)[3] - mean(off, centre)[3];
            double gainCorner = mean(on, corner)[3] - mean(off, corner)[3];
            // 3 levels of mean luma over a cell: a visible sheen, three times the 8-bit step; and 2 more at the mirror
            // point than at the corner
            assertTrue(gainCentre > 3, "gloss brightens the snow at the mirror point by " + gainCentre);
            assertTrue(gainCentre > gainCorner + 2, "gain at the mirror point " + gainCentre + ", away from it " + gainCorner);
            // rock: rougher, so no sharp highlight, but the sky it reflects at this grazing angle
            double rockGain = mean(on, Region.whole(FLAT_ROCK))[3] - mean(off, Region.whole(FLAT_ROCK))[3];
            assertTrue(rockGain > 3, "gloss brightens rock by " + rockGain);
        }
    }

    @Test
    void altitudeBandsPutSnowOnTheBarePeakThatTheSnowMapLeavesBare() throws IOException {
        try (Engine engine = cases()) {
            Image map = render(engine, "cases");
            engine.settings().set("materials.snow-mode", "altitude-bands");
            Image bands = render(engine, "cases-altitude-bands");

            double[] peakMap = mean(map, Region.whole(BARE_PEAK));
            double[] peakBands = mean(bands, Region.whole(BARE_PEAK));
            assertTrue(peakBands[3] > peakMap[3] + 50, "peak with bands " + rgb(peakBands) + ", with the map " + rgb(peakMap));
            double[] meadowMap = mean(map, Region.whole(MEADOW));
            double[] meadowBands = mean(bands, Region.whole(MEADOW));
            // one level of 255: below the snow both modes shade the meadow alike, so only rounding may part them
            assertEquals(meadowMap[3], meadowBands[3], 1, "low ground is the same in both modes");
        }
    }

    /**
     * A stand-in landscape to see the materials from afar until the terrain system draws the real one: a mesh over
     * {@link #SIDE} metres whose heights are a sum of sine waves with amplitude rising with wavelength (a 1/f-like
     * spectrum), flattened into a valley floor around the origin.
     */
    static final class Landscape implements EngineSystem {
        static final int GRID = 256;        // quads per side: 47 m each, the materials add the detail
        static final float SIDE = 12000;    // metres
        static final int WAVES = 48;
        final double[] kx = new double[WAVES], kz = new double[WAVES], phase = new double[WAVES], amp = new double[WAVES];
        float top;
        ShaderProgram program;
        TerrainMaterials materials;
        TerrainMaterials.Uniforms uniforms;
        Uniform.Int sky;
        Mesh mesh;
        Mesh fullScreen;

        Landscape() {
            SplittableRandom rng = new SplittableRandom(3);
            for (int i = 0; i < WAVES; i++) {
                double wavelength = 8000 * Math.pow(60 / 8000.0, (double) i / (WAVES - 1)); // 8 km down to 60 m
                double angle = rng.nextDouble() * Math.PI;
                kx[i] = 2 * Math.PI / wavelength * Math.cos(angle);
                kz[i] = 2 * Math.PI / wavelength * Math.sin(angle);
                phase[i] = rng.nextDouble() * 2 * Math.PI;
                amp[i] = 0.09 * Math.pow(wavelength, 0.9);
            }
        }

        double height(double x, double z) {
            double sum = 0;
            for (int i = 0; i < WAVES; i++) {
                sum += amp[i] * Math.sin(kx[i] * x + kz[i] * z + phase[i]);
            }
            double t = Math.min(1, Math.max(0, (Math.hypot(x, z) - 300) / 3000));
            double mountains = t * t * (3 - 2 * t);
            return mountains * Math.max(sum + 500, 0) + (1 - mountains) * 0.03 * sum;
        }

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("landscape").reads(Sun.class, Settings.class).draws(Pass.MAIN);
        }

        @Override
        public List<SettingsGroup<?>> settings() {
            return List.of(MaterialSettings.SETTINGS);
        }

        @Override
        public void init(EngineContext context) {
            program = context.shaders().program("test/terrain/landscape.vert", "test/terrain/landscape.frag");
            uniforms = TerrainMaterials.uniforms(program);
            sky = program.int1("uSky");
            Uniform.Float topUniform = program.float1("uTop");
            int n = GRID + 1;
            double step = SIDE / GRID;
            float[] vertices = new float[n * n * 6];
            for (int j = 0; j < n; j++) {
                for (int i = 0; i < n; i++) {
                    double x = -SIDE / 2 + i * step;
                    double z = -SIDE / 2 + j * step;
                    double h = height(x, z);
                    double dhdx = (height(x + 1, z) - height(x - 1, z)) / 2;
                    double dhdz = (height(x, z + 1) - height(x, z - 1)) / 2;
                    double len = Math.sqrt(dhdx * dhdx + dhdz * dhdz + 1);
                    int v = 6 * (j * n + i);
                    vertices[v] = (float) x;
                    vertices[v + 1] = (float) h;
                    vertices[v + 2] = (float) z;
                    vertices[v + 3] = (float) (-dhdx / len);
                    vertices[v + 4] = (float) (1 / len);
                    vertices[v + 5] = (float) (-dhdz / len);
                    top = Math.max(top, (float) h);
                }
            }
            int[] triangles = new int[GRID * GRID * 6];
            int k = 0;
            for (int j = 0; j < GRID; j++) {
                for (int i = 0; i < GRID; i++) {
                    int a = j * n + i;
                    triangles[k++] = a;
                    triangles[k++] = a + n;
                    triangles[k++] = a + 1;
                    triangles[k++] = a + 1;
                    triangles[k++] = a + n;
                    triangles[k++] = a + n + 1;
                }
            }
            mesh = new Mesh(context.gl(), vertices, triangles, new Mesh.Attribute(0, 3), new Mesh.Attribute(1, 3));
            fullScreen = new Mesh(context.gl(), new float[] {-1, -1, 0, 0, 1, 0, 3, -1, 0, 0, 1, 0, -1, 3, 0, 0, 1, 0},
                    new int[] {0, 1, 2}, new Mesh.Attribute(0, 3), new Mesh.Attribute(1, 3));
            materials = new TerrainMaterials(context.gl(), textures);
            program.use();
            topUniform.set(top);
            program.float1("uSkyVisibility").set(1f);
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            materials.bind(uniforms, context.world().resource(Settings.class).get(MaterialSettings.class), 0);
            // 1. the sky behind everything
            glDisable(GL_DEPTH_TEST);
            sky.set(1);
            fullScreen.draw(context.stats());
            // 2. the landscape
            glEnable(GL_DEPTH_TEST);
            sky.set(0);
            mesh.draw(context.stats());
        }

        @Override
        public void close() {
            for (AutoCloseable c : new AutoCloseable[] {fullScreen, mesh, materials, program}) {
                if (c != null) {
                    try {
                        c.close();
                    } catch (Exception e) {
                        throw new IllegalStateException(e);
                    }
                }
            }
        }
    }

    /** Views of the stand-in landscape, to look at: the valley towards the mountains, and a mountainside. */
    @Test
    void landscapeFromAfarHasGrassBelowRockAndSnowAbove() throws IOException {
        Landscape landscape = new Landscape();
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, landscape, new SkySystem())) {
            engine.world().setResource(new TimeOfDay(MORNING, 0));
            engine.world().resource(Camera.class).setPose(
                    new CameraPose(0, landscape.height(0, 900) + 30, 900, 0, -2, 60));
            Image valley = render(engine, "landscape-valley");
            engine.world().resource(Camera.class).setPose(
                    new CameraPose(0, landscape.height(0, 300) + 1.7, 300, 20, -25, 60));
            render(engine, "landscape-meadow");
            engine.world().resource(Camera.class).setPose(new CameraPose(-2500, 1400, 2500, 45, -15, 60));
            Image mountains = render(engine, "landscape-mountains");
            engine.world().setResource(new TimeOfDay(AFTERNOON, 0));
            engine.world().resource(Camera.class).setPose(
                    new CameraPose(0, landscape.height(0, 900) + 30, 900, 250, 2, 60));
            render(engine, "landscape-valley-1700");

            double[] foreground = mean(valley, WIDTH / 5, HEIGHT * 17 / 20, WIDTH * 4 / 5, HEIGHT);
            assertTrue(foreground[1] > foreground[0] && foreground[1] > foreground[2], "valley floor " + rgb(foreground));
            double brightest = 0;
            for (int y = 0; y < HEIGHT; y++) {
                for (int x = 0; x < WIDTH; x++) {
                    brightest = Math.max(brightest, mountains.luma(x, y));
                }
            }
            // luma 200 of 255: lit snow (albedo 0.8+) reaches it under the default sun, grass and rock (albedo
            // 0.1–0.35) do not
            assertTrue(brightest > 200, "snow on the peaks: brightest luma " + brightest);
        }
    }

    @Test
    void materialsFreeTheirTexturesWhenClosed() {
        GlObjects objects = GL.context().objects();
        int before = objects.live(GlObjects.Kind.TEXTURE);
        TerrainMaterials materials = new TerrainMaterials(GL.context(), textures);
        assertEquals(before + TerrainMaterials.UNITS, objects.live(GlObjects.Kind.TEXTURE));
        materials.close();
        assertEquals(before, objects.live(GlObjects.Kind.TEXTURE));
    }
}
