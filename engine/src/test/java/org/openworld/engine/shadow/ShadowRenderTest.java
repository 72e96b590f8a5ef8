package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL30C.*;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.joml.Matrix4fc;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.gl.GlObjects;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.TerrainSystem;
import org.openworld.engine.water.WaterSystem;

/**
 * The sun's shadows on real GL, over {@link WallWorld}: flat ground at −20 m and a wall 100 m high just west of the
 * centre (x from −16 to 0 m), lit by a sun in the east 35° up, so the wall's shadow lies on the ground west of it,
 * 100 / tan 35° = 143 m long (x from −159 to −16 m). The two rules that need no wall (maps re-made once when their
 * size changes; no shadow with the sun down) hold on the unbounded world's ground too.
 */
@GlTest
class ShadowRenderTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 320;
    static final int H = 180;
    static final Sun EAST_SUN = WallWorld.EAST_SUN;
    /** Above the shadow, looking almost straight down, north up. */
    static final CameraPose ABOVE = new CameraPose(-60, 230, 0, 0, -89, 60);

    @TempDir
    static Path dir;
    static Path wall;

    @BeforeAll
    static void writeWorld() throws IOException {
        wall = WallWorld.write(dir);
    }

    static List<String> settings(String... more) {
        return settings(TerrainSettings.World.TILE, more);
    }

    /** The wall's map (a tile), or the unbounded world, for the tests whose rules do not need the wall. */
    static List<String> settings(TerrainSettings.World world, String... more) {
        List<String> s = new ArrayList<>(world == TerrainSettings.World.TILE ? WallWorld.terrain(wall)
                : List.of("terrain.world=" + world));
        s.addAll(List.of("shadow.resolution=512", "shadow.distance=600"));
        s.addAll(List.of(more));
        return s;
    }

    static Image render(List<String> settings, Consumer<Engine> before) {
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings, new CullingSystem(),
                new TerrainSystem(), new ShadowSystem())) {
            engine.world().setResource(EAST_SUN);
            engine.world().resource(Camera.class).setPose(ABOVE);
            before.accept(engine);
            engine.update();
            engine.render();
            return engine.readImage();
        }
    }

    static Image render(String... settings) {
        return render(settings(settings), engine -> { });
    }

    static Image unshadowed() {
        return render(settings(), engine -> engine.setEnabled("shadow", false));
    }

    /** The pixel a ground point at (x, z) appears at, or null when it is off the picture. */
    static int[] pixel(double x, double z) {
        Matrix4fc viewProjection = ViewCamera.perspective(ABOVE, (float) W / H, Camera.NEAR, Camera.FAR)
                .viewProjection();
        Vector4f clip = viewProjection.transform(new Vector4f((float) x, (float) WallWorld.GROUND, (float) z, 1));
        double px = (clip.x / clip.w * 0.5 + 0.5) * W;
        double py = (0.5 - clip.y / clip.w * 0.5) * H;
        return px < 0 || px >= W || py < 0 || py >= H ? null : new int[] {(int) px, (int) py};
    }

    /** Mean luma over the ground from x0 to x1 (metres, west to east), z from −40 to 40 m. */
    static double groundLuma(Image image, double x0, double x1) {
        int[] a = pixel(x0, -40);
        int[] b = pixel(x1, 40);
        return image.meanLuma(Math.min(a[0], b[0]), Math.min(a[1], b[1]), Math.max(a[0], b[0]),
                Math.max(a[1], b[1]));
    }

    @Test
    void theWallShadowsTheGroundWestOfItAndNotEast() {
        Image image = render();
        double shadowed = groundLuma(image, -130, -40);
        double litWest = groundLuma(image, -240, -190);
        double litEast = groundLuma(image, 50, 120); // clear of the wall's top, which leans out of the picture
        // in shadow the ground keeps the sky's light only (10–20 % of the sun's at noon, see SkyLightTest): under 60 %
        // of the lit luma leaves room for the tone curve; the two lit sides agree within 15 % (their slopes differ a
        // little)
        assertTrue(shadowed < 0.6 * litWest && shadowed < 0.6 * litEast, "in the wall's shadow " + shadowed
                + ", lit west of it " + litWest + ", east of it " + litEast);
        assertEquals(litWest, litEast, 0.15 * litEast, "lit ground on both sides alike");
        Image none = unshadowed();
        // the same 15 % as the lit sides above: the two patches' slopes differ a little
        assertEquals(groundLuma(none, -130, -40), groundLuma(none, -240, -190), 0.15 * litWest,
                "without the shadow system the same ground is lit alike");
    }

    @Test
    void theWaterReceivesTheShadowToo() {
        // the sea at 0 m over the ground at -20 m: 20 m of water, through which the shadowed bed hardly shows
        List<String> withWater = settings("water.level=0", "water.clarity=4");
        Image image;
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, withWater, new CullingSystem(),
                new TerrainSystem(), new ShadowSystem(), new WaterSystem())) {
            engine.world().setResource(EAST_SUN);
            engine.world().resource(Camera.class).setPose(ABOVE);
            engine.update();
            engine.render();
            image = engine.readImage();
        }
        // the wall stands 80 m out of the water: its shadow on the surface reaches 114 m west, to x = -130 m
        double shadowed = groundLuma(image, -110, -40);
        double lit = groundLuma(image, -240, -190);
        // water shows the sky's reflection in shadow and in sun alike, so the shadow darkens it less than the ground:
        // 20 % darker is still a plain shadow
        assertTrue(shadowed < 0.8 * lit, "water in the wall's shadow " + shadowed + ", in the sun " + lit);
    }

    /** Pixels, along the row through z = 0, over which the luma climbs from 20 % to 80 % of the way out of shadow. */
    static int edgeWidth(Image image) {
        int[] from = pixel(-200, 0);
        int[] to = pixel(-120, 0);
        double lit = groundLuma(image, -240, -190);
        double dark = groundLuma(image, -130, -60);
        int row = from[1];
        int inBetween = 0;
        for (int x = Math.min(from[0], to[0]); x <= Math.max(from[0], to[0]); x++) {
            double t = (image.luma(x, row) - dark) / (lit - dark);
            if (t > 0.2 && t < 0.8) {
                inBetween++;
            }
        }
        return inBetween;
    }

    @Test
    void theShadowEdgeWidensWithTheFilterKernel() {
        int sharp = edgeWidth(render("shadow.method=PAPER", "shadow.margin=0.01", "shadow.kernel=1"));
        int soft = edgeWidth(render("shadow.method=PAPER", "shadow.margin=0.01", "shadow.kernel=7"));
        // a 7×7 filter spreads the edge over 6 more map texels than 1×1; on screen that is several pixels: at least 4
        // more, and twice as wide
        assertTrue(soft >= sharp + 4 && soft >= 2 * sharp, "edge " + sharp + " px at 1×1, " + soft + " px at 7×7");
    }

    /** Fraction of lit ground (both sides of the shadow) drawn darker than unshadowed ground: shadow acne. */
    static double acne(Image image, Image unshadowed) {
        int dark = 0;
        int all = 0;
        for (double[] span : new double[][] {{-240, -180}, {20, 140}}) {
            int[] a = pixel(span[0], -60);
            int[] b = pixel(span[1], 60);
            for (int y = Math.min(a[1], b[1]); y <= Math.max(a[1], b[1]); y++) {
                for (int x = Math.min(a[0], b[0]); x <= Math.max(a[0], b[0]); x++) {
                    all++;
                    if (image.luma(x, y) < 0.85 * unshadowed.luma(x, y)) {
                        dark++;
                    }
                }
            }
        }
        return (double) dark / all;
    }

    /** Figure 10 at both depths: the acne comes from a texel's footprint, not from rounding, so 24 bits change nothing. */
    @ParameterizedTest
    @ValueSource(strings = {"float32", "fixed24"})
    void acneFallsAsTheMarginGrows(String depth) {
        Image reference = unshadowed();
        double[] margins = {0, 0.001, 0.01, 0.1};
        double[] acne = new double[margins.length];
        for (int i = 0; i < margins.length; i++) {
            acne[i] = acne(render("shadow.method=PAPER", "shadow.kernel=1", "shadow.resolution=256",
                    "shadow.depth=" + depth, "shadow.margin=" + margins[i]), reference);
        }
        String series = java.util.Arrays.toString(acne);
        // without a margin the ground compares its depth against itself and rounds either way: acne is widespread
        // (over 20 %); with 0.01 or more it is a few pixels (under 1 %), an order of magnitude apart
        assertTrue(acne[0] > 0.2, "no margin: the ground shadows itself " + series);
        assertTrue(acne[0] > acne[1] && acne[1] > acne[2], "acne falls with the margin " + series);
        assertTrue(acne[2] < 0.01 && acne[3] < 0.01, "0.01 and above: no acne " + series);
        assertTrue(acne(render("shadow.depth=" + depth), reference) < 0.01,
                "the cascades' slope and normal biases: no acne");
    }

    /** The map's internal format and depth bits as GL reports them. */
    static int[] formatOf(SunShadow sun) {
        sun.map().bind(0);
        return new int[] {glGetTexLevelParameteri(GL_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_INTERNAL_FORMAT),
            glGetTexLevelParameteri(GL_TEXTURE_2D_ARRAY, 0, GL_TEXTURE_DEPTH_SIZE)};
    }

    /**
     * Share of the map's depths below 1/4 that lie on a 24-bit step, k / (2^24 − 1): all of them in a 24-bit map.
     * Below 1/4 a float's rounding of such a step is under an eighth of a step, so the test is exact there; a float
     * map's depths fall anywhere between the steps.
     */
    static double onTwentyFourBitSteps(float[] depths) {
        double steps = (1 << 24) - 1;
        int near = 0;
        int on = 0;
        for (float d : depths) {
            if (d > 0 && d < 0.25f) {
                near++;
                double k = d * steps;
                if (Math.abs(k - Math.rint(k)) < 0.125) {
                    on++;
                }
            }
        }
        // enough depths that a 0.1 % share (see below) is one whole pixel
        assertTrue(near > 1000, "only " + near + " depths below 1/4 to look at");
        return (double) on / near;
    }

    @Test
    void theDepthSettingMakesTwentyFourBitMapsAndBack() {
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings("shadow.method=PAPER"),
                new CullingSystem(), new TerrainSystem(), new ShadowSystem())) {
            engine.world().setResource(EAST_SUN);
            engine.world().resource(Camera.class).setPose(ABOVE);
            engine.update();
            engine.render();
            SunShadow floats = engine.world().resource(SunShadow.class);
            assertArrayEquals(new int[] {GL_DEPTH_COMPONENT32F, 32}, formatOf(floats), "the default: 32-bit float");
            double floatSteps = onTwentyFourBitSteps(floats.map().read());

            engine.settings().set("shadow.depth", "fixed24");
            engine.render();
            SunShadow fixed = engine.world().resource(SunShadow.class);
            assertArrayEquals(new int[] {GL_DEPTH_COMPONENT24, 24}, formatOf(fixed), "the paper's 24 bits");
            double fixedSteps = onTwentyFourBitSteps(fixed.map().read());
            // an on-step test passes a random depth with probability 1/4 (±1/8 of a step): a float map's share is near
            // 0.25, under 0.5; a 24-bit map's is 1, less a rounding or two
            assertTrue(fixedSteps > 0.999 && floatSteps < 0.5, "depths on 24-bit steps: " + fixedSteps
                    + " of the 24-bit map's, " + floatSteps + " of the float map's");
        }
    }

    /** This frame's maps and boxes, after rendering at a pose. */
    record Maps(float[] depths, List<LightBox> boxes, int size) {
    }

    static Maps maps(Engine engine, ShadowSystem shadow, CameraPose pose) {
        engine.world().resource(Camera.class).setPose(pose);
        engine.update();
        engine.render();
        SunShadow sun = engine.world().resource(SunShadow.class);
        return new Maps(sun.map().read(), shadow.boxes(), sun.map().size());
    }

    /**
     * Fraction of texels of each map that differ from the other frame's, compared where each world point lies: the
     * second frame's map shifted back by the whole texels its box moved. Texels within two of the border are left
     * out, as is a map whose box did not move by whole texels (then every texel counts as changed).
     */
    static double changed(Maps a, Maps b) {
        int n = a.size();
        int differ = 0;
        int all = 0;
        for (int layer = 0; layer < a.boxes().size(); layer++) {
            // a world point's texel moves by the change of the box's clip translation, in texels
            Vector4f ta = a.boxes().get(layer).viewProjection().transform(new Vector4f(0, 0, 0, 1));
            Vector4f tb = b.boxes().get(layer).viewProjection().transform(new Vector4f(0, 0, 0, 1));
            double sx = (tb.x - ta.x) * n / 2;
            double sy = (tb.y - ta.y) * n / 2;
            long dx = Math.round(sx);
            long dy = Math.round(sy);
            boolean whole = Math.abs(sx - dx) < 1e-3 && Math.abs(sy - dy) < 1e-3;
            for (int y = 2; y < n - 2; y++) {
                for (int x = 2; x < n - 2; x++) {
                    long xb = x + dx;
                    long yb = y + dy;
                    if (xb < 2 || yb < 2 || xb >= n - 2 || yb >= n - 2) {
                        continue;
                    }
                    all++;
                    float da = a.depths()[layer * n * n + y * n + x];
                    float db = b.depths()[(int) (layer * n * n + yb * n + xb)];
                    // the depth of one world point may differ by the box's depth snap: far below a millimetre
                    if (!whole || Math.abs(da - db) * a.boxes().get(layer).depthRange() > 1e-3) {
                        differ++;
                    }
                }
            }
        }
        return (double) differ / all;
    }

    static double changeUnderSmallMove(String... settings) {
        ShadowSystem shadow = new ShadowSystem();
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings(settings), new CullingSystem(),
                new TerrainSystem(), shadow)) {
            engine.world().setResource(EAST_SUN);
            CameraPose low = new CameraPose(-60, 40, 150, 0, -20, 60);
            Maps before = maps(engine, shadow, low);
            // sideways (east) by a third of the finest map's texel
            double step = before.boxes().get(0).texelSize() / 3;
            Maps after = maps(engine, shadow, new CameraPose(low.x() + step, low.y(), low.z(), low.yaw(),
                    low.pitch(), low.fov()));
            return changed(before, after);
        }
    }

    @Test
    void aSubTexelSidewaysMoveLeavesSnappedCascadesUnchangedButMovesThePapersMap() {
        double snapped = changeUnderSmallMove("shadow.cascades=2", "shadow.resolution=256");
        double paper = changeUnderSmallMove("shadow.method=PAPER", "shadow.resolution=256");
        // snapping makes a sub-texel move change nothing (0, less a stray texel's rounding: 0.1 %); the paper's refit
        // moves every edge by a third of a texel, which changes ≥ 5 % of the texels
        assertTrue(snapped < 0.001, "snapped cascades changed at " + snapped + " of their texels");
        assertTrue(paper > 0.05, "the paper's map, refitted, changed at only " + paper + " of its texels");
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void changingTheResolutionOrCascadeCountRebuildsTheMapsOnce(TerrainSettings.World world) {
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings(world, "shadow.cascades=3"),
                new CullingSystem(), new TerrainSystem(), new ShadowSystem())) {
            engine.world().setResource(EAST_SUN);
            engine.update();
            engine.render();
            SunShadow first = engine.world().resource(SunShadow.class);
            assertEquals(3, first.map().layers());
            int textures = GL.context().objects().live(GlObjects.Kind.TEXTURE);
            int framebuffers = GL.context().objects().live(GlObjects.Kind.FRAMEBUFFER);
            engine.settings().set("shadow.resolution", "128");
            engine.settings().set("shadow.cascades", "2");
            engine.render();
            SunShadow second = engine.world().resource(SunShadow.class);
            assertEquals(128, second.map().size());
            assertEquals(2, second.map().layers());
            assertEquals(textures, GL.context().objects().live(GlObjects.Kind.TEXTURE), "one map for another");
            assertEquals(framebuffers - 1, GL.context().objects().live(GlObjects.Kind.FRAMEBUFFER),
                    "one layer's framebuffer fewer");
            engine.render();
            assertTrue(second == engine.world().resource(SunShadow.class), "not rebuilt again");
        }
    }

    /** On both worlds, looking down from {@link #ABOVE}'s 250 m over the ground. */
    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void withTheSunDownNothingIsShadowed(TerrainSettings.World world) {
        Sun down = new Sun(new Vector3f(0.9f, -0.1f, 0), new Vector3f(1), new Vector3f(0.25f));
        Consumer<Engine> overTheGround = engine -> {
            double ground = engine.world().resource(HeightField.class).heightAt(ABOVE.x(), ABOVE.z());
            engine.world().resource(Camera.class).setPose(new CameraPose(ABOVE.x(),
                    ground + ABOVE.y() - WallWorld.GROUND, ABOVE.z(), ABOVE.yaw(), ABOVE.pitch(), ABOVE.fov()));
            engine.world().setResource(down);
        };
        Image night = render(settings(world), overTheGround);
        Image off = render(settings(world), overTheGround.andThen(engine -> engine.setEnabled("shadow", false)));
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                // the same pixels must come out: luma of equal bytes, equal to round-off
                assertEquals(off.luma(x, y), night.luma(x, y), 1e-9, "no map, no shadow: (" + x + ", " + y + ")");
            }
        }
    }

    /** Records what each MAIN pass was told. */
    static final class Probe implements EngineSystem {
        final List<Boolean> told = new ArrayList<>();

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("probe").draws(Pass.MAIN);
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            told.add(context.shares(SunShadow.class));
        }
    }

    /**
     * The passes tell their systems whether the sun's shadow maps are bound ({@link RenderContext#sunShadowed}), and
     * the terrain picks its programs by it (with the lookup, or compiled without it): while the shadow system runs,
     * MAIN is shadowed and the wall's shadow shows; switched off, MAIN is not, and the ground behind the wall is lit.
     * A terrain that took the unshadowed programs while the maps are bound would lose the shadow; one that took the
     * shadowed programs without them would draw the same picture, only dearer (bench measures that).
     */
    @Test
    void mainIsShadowedExactlyWhileTheShadowSystemRuns() {
        Probe probe = new Probe();
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H,
                settings(), new CullingSystem(), new TerrainSystem(), new ShadowSystem(), probe)) {
            engine.world().setResource(EAST_SUN);
            engine.world().resource(Camera.class).setPose(ABOVE);
            Image shadowed = frame(engine);
            assertEquals(List.of(true), probe.told, "MAIN with the shadow system running");

            engine.setEnabled("shadow", false);
            Image lit = frame(engine);
            assertEquals(List.of(true, false), probe.told, "MAIN with the shadow system switched off");

            int darker = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    if (lit.channel(x, y, 1) - shadowed.channel(x, y, 1) > 20) {
                        darker++;
                    }
                }
            }
            assertTrue(darker > W * H / 20,
                    "pixels the wall's shadow darkens while the maps are bound: " + darker);
        }
    }

    private static Image frame(Engine engine) {
        engine.update();
        engine.render();
        return engine.readImage();
    }
}
