package org.openworld.engine.shadow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_WRITEMASK;
import static org.lwjgl.opengl.GL11C.GL_VIEWPORT;
import static org.lwjgl.opengl.GL11C.glGetBoolean;
import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL11C.glGetIntegerv;
import static org.lwjgl.opengl.GL11C.glIsEnabled;
import static org.lwjgl.opengl.GL30C.GL_DRAW_FRAMEBUFFER_BINDING;
import static org.lwjgl.opengl.GL30C.GL_READ_FRAMEBUFFER_BINDING;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.joml.Vector3f;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.ImportedWorld;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.culling.CullingSystem;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.terrain.TerrainSystem;

/**
 * The probe on real GL, over an imported plain: flat at sea level but for one sample 10 m high in the south-east
 * corner, behind the camera and casting its short shadow away from it, so the whole plain in view is truly lit.
 * A small system of the test's own calls the probe in the OVERLAY pass, as the shadow system does when
 * {@code shadow.measure} is on.
 */
@GlTest
class ShadowProbeTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int W = 160;
    static final int H = 90;
    /** Samples per side of the imported map, 2 m apart: a 512 m world. */
    static final int SAMPLES = 256;
    /** Looking north over the plain from 30 m up, 15° down: ground from below the eye to the map's far edge. */
    static final CameraPose OVER_THE_PLAIN = new CameraPose(0, 30, 150, 0, -15, 60);
    /** The sun 37° up in the north-east: the plain's upward normal meets it at a cosine of 0.6. */
    static final Sun SUN = new Sun(new Vector3f(0.4f, 0.6f, -0.7f), new Vector3f(1), new Vector3f(0.3f));

    @TempDir
    static Path dir;
    static Path plain;

    @BeforeAll
    static void writeWorld() throws IOException {
        // an imported map must have some relief to be scaled: one sample, at the corner behind the camera
        plain = ImportedWorld.write(dir.resolve("plain.raw"), SAMPLES,
                (x, z) -> x == SAMPLES - 1 && z == SAMPLES - 1 ? 1f : 0f);
    }

    /** The paper's single map, 256 texels, one depth test per point: the setting most prone to acne. */
    static List<String> settings(String margin) {
        return List.of("terrain.import-file=" + plain, "terrain.spacing=2", "terrain.relief=10",
                "terrain.sea-fraction=0", "shadow.method=PAPER", "shadow.resolution=256", "shadow.kernel=1",
                "shadow.distance=800", "shadow.margin=" + margin);
    }

    /** Calls the probe in OVERLAY, and checks the state it leaves: the scene bound, depth test off, writes on. */
    static final class ProbeSystem implements EngineSystem {

        private ShadowProbe probe;
        final List<String> leftState = new ArrayList<>();

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("probe").reads(SunShadow.class).draws(Pass.OVERLAY);
        }

        @Override
        public void init(EngineContext context) {
            probe = new ShadowProbe(context);
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            probe.measure(context);
            int[] viewport = new int[4];
            glGetIntegerv(GL_VIEWPORT, viewport);
            int target = context.target().id();
            if (glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING) != target || glGetInteger(GL_READ_FRAMEBUFFER_BINDING)
                    != target || viewport[2] != W || viewport[3] != H || glIsEnabled(GL_DEPTH_TEST)
                    || !glGetBoolean(GL_DEPTH_WRITEMASK)) {
                leftState.add("frame left with draw " + glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING) + ", read "
                        + glGetInteger(GL_READ_FRAMEBUFFER_BINDING) + " (scene " + target + "), viewport "
                        + viewport[2] + "x" + viewport[3] + ", depth test " + glIsEnabled(GL_DEPTH_TEST)
                        + ", depth writes " + glGetBoolean(GL_DEPTH_WRITEMASK));
            }
        }
    }

    /** Renders frames with the margin each gives, all from the same pose, and returns each frame's counters. */
    static List<Map<String, Double>> frames(String... margins) {
        ProbeSystem probe = new ProbeSystem();
        List<FrameRecord> records = new ArrayList<>();
        try (Engine engine = GlTestSupport.engine(GL.context(), W, H, settings(margins[0]), new CullingSystem(),
                new TerrainSystem(), new ShadowSystem(), probe)) {
            engine.world().setResource(SUN);
            engine.world().resource(Camera.class).setPose(OVER_THE_PLAIN);
            for (String margin : margins) {
                engine.settings().set("shadow.margin", margin);
                engine.update();
                engine.render();
            }
            engine.collectFrames(true, records::add);
        }
        assertEquals(List.of(), probe.leftState);
        return records.stream().map(FrameRecord::counters).toList();
    }

    @Test
    void aLitPlainShowsAcneOnlyWithoutAMargin() {
        List<Map<String, Double>> counters = frames("0.1", "0");
        Map<String, Double> margin = counters.get(0);
        Map<String, Double> none = counters.get(1);
        // most of the 40 x 23 tested pixels see the plain (the sky fills the top third)
        assertTrue(margin.get("shadow.acne-pixels") > 400, margin.toString());
        assertEquals(margin.get("shadow.acne-pixels"), none.get("shadow.acne-pixels"));
        // under 1 % of the ~400+ probed plain pixels (a handful at most) against over 20 % without a margin: the two
        // cases lie an order of magnitude either side of the bands
        assertTrue(margin.get("shadow.acne") < 0.01, "a margin of 0.1 still shadows the plain: " + margin);
        assertTrue(none.get("shadow.acne") > 0.2, "no margin and no filter should give acne: " + none);
    }

    @Test
    void identicalFramesDoNotFlickerAndAChangedMarginDoes() {
        List<Map<String, Double>> counters = frames("0", "0", "0.1");
        assertFalse(counters.get(0).containsKey("shadow.flicker"), "no flicker on the first frame");
        Map<String, Double> same = counters.get(1);
        assertEquals(0, same.get("shadow.flicker"), same.toString());
        assertTrue(same.get("shadow.flicker-pixels") > W * H / 2, same.toString());
        // every pixel stayed put, so every ground pixel is compared; the margin's change switched the acne off
        Map<String, Double> changed = counters.get(2);
        assertEquals(same.get("shadow.flicker-pixels"), changed.get("shadow.flicker-pixels"));
        // the margin's change switches the acne (over 20 % of the plain, see above) off: at least 10 % of the compared
        // pixels must change
        assertTrue(changed.get("shadow.flicker") > 0.1, changed.toString());
    }
}
