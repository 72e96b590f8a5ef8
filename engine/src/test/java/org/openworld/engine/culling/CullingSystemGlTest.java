package org.openworld.engine.culling;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.Engine;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;
import org.openworld.engine.bench.FrameRecord;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.BoundsTree;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.culling.Visibility.Containment;
import org.openworld.engine.gl.Image;

/**
 * The culling system in the engine's frame, headless: a probe system that draws in the main pass and reads
 * {@link Visibility} records what it is told about three boxes around a camera at (0, 10, 0).
 */
@GlTest
class CullingSystemGlTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int WIDTH = 320;
    static final int HEIGHT = 180;
    /** Leaves of the probe's tree; node 0 is the root around them. */
    static final int FRONT = 1;
    static final int BEHIND = 2;
    static final int SIDE = 3;
    /** Eye 10 m up at the origin, looking north (−Z), level. */
    static final CameraPose NORTH = new CameraPose(0, 10, 0, 0, 0, 60);
    /** The same eye looking south. */
    static final CameraPose SOUTH = new CameraPose(0, 10, 0, 180, 0, 60);
    /** 400 m south of the origin and 300 m up, looking north and down at where the camera stood. */
    static final CameraPose OVERVIEW = new CameraPose(0, 300, 400, 0, -30, 60);

    /**
     * Three 10 m boxes 10 m up: 55 m north of the eye (in a north-looking view), 55 m south (behind it), and 2 km
     * east at 55 m north (88° off the view axis, beyond the 46° half-width of a 60° view at 16:9).
     */
    static BoundsTree probeTree() {
        float[] front = {-5, 5, -60, 5, 15, -50};
        float[] behind = {-5, 5, 50, 5, 15, 60};
        float[] side = {2000, 5, -60, 2010, 15, -50};
        float[] root = {-5, 5, -60, 2010, 15, 60};
        float[] boxes = new float[24];
        System.arraycopy(root, 0, boxes, 0, 6);
        System.arraycopy(front, 0, boxes, 6 * FRONT, 6);
        System.arraycopy(behind, 0, boxes, 6 * BEHIND, 6);
        System.arraycopy(side, 0, boxes, 6 * SIDE, 6);
        return new BoundsTree(boxes, new int[] {1, 0, 0, 0}, new int[] {3, 0, 0, 0});
    }

    /** Owns a cullable entity and records, every main pass, the answer for each leaf (null: no Visibility). */
    static final class Probe implements EngineSystem {
        final List<Containment[]> seen = new ArrayList<>();
        private int entity;

        @Override
        public SystemSpec spec() {
            return SystemSpec.named("probe").reads(Visibility.class).draws(Pass.MAIN);
        }

        @Override
        public void init(EngineContext context) {
            entity = context.world().spawn();
            context.world().add(entity, new Cullable(probeTree(), new float[] {0, 0}));
        }

        @Override
        public void render(Pass pass, RenderContext context) {
            Visibility visibility = context.world().get(entity, Visibility.class).orElse(null);
            if (visibility == null) {
                seen.add(null);
                return;
            }
            Containment root = visibility.root(0);
            seen.add(new Containment[] {visibility.of(0, FRONT, root), visibility.of(0, BEHIND, root),
                visibility.of(0, SIDE, root)});
        }

        Containment[] last() {
            return seen.get(seen.size() - 1);
        }
    }

    @Test
    void boxesInFrontAreKeptAndBoxesBehindOrAsideCulled() {
        Probe probe = new Probe();
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, new CullingSystem(), probe)) {
            Map<String, Double> counters = renderAt(engine, NORTH);
            assertEquals(Containment.INSIDE, probe.last()[0 /* FRONT */]);
            assertEquals(Containment.OUTSIDE, probe.last()[1 /* BEHIND */]);
            assertEquals(Containment.OUTSIDE, probe.last()[2 /* SIDE */]);
            // the root straddles the frustum, so it and its three leaves are tested; two leaves are rejected
            assertEquals(4, counters.get("culling.main.tested"));
            assertEquals(2, counters.get("culling.main.outside"));
            assertEquals(1, counters.get("culling.main.inside"));

            renderAt(engine, SOUTH);
            assertEquals(Containment.OUTSIDE, probe.last()[0]);
            assertNotEquals(Containment.OUTSIDE, probe.last()[1]);
        }
    }

    @Test
    void aFrozenFrustumIgnoresTheCamera() {
        Probe probe = new Probe();
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, new CullingSystem(), probe)) {
            renderAt(engine, NORTH);
            Containment[] north = probe.last();
            engine.settings().set("culling.freeze", "on");
            renderAt(engine, NORTH);
            renderAt(engine, SOUTH);
            assertArrayEquals(north, probe.last(), "turning round changed what a frozen frustum sees");
            engine.settings().set("culling.freeze", "off");
            renderAt(engine, SOUTH);
            assertEquals(Containment.OUTSIDE, probe.last()[0], "unfrozen, the camera's own frustum counts again");
        }
    }

    @Test
    void theFrozenFrustumIsOutlined() throws IOException {
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, new CullingSystem(), new Probe())) {
            renderAt(engine, OVERVIEW);
            Image unfrozen = engine.readImage();
            renderAt(engine, NORTH);
            engine.settings().set("culling.freeze", "on");
            renderAt(engine, NORTH);
            renderAt(engine, OVERVIEW);
            Image frozen = engine.readImage();
            frozen.writePng(Path.of("target/test-images/culling-frozen-outline.png"));
            assertEquals(0, outlinePixels(unfrozen), "an outline without a frozen frustum");
            // the frustum's four side edges run from near the old eye out to 40 km: long lines across the view
            assertTrue(outlinePixels(frozen) > WIDTH, "outline pixels: " + outlinePixels(frozen));
        }
    }

    @Test
    void switchedOffItLeavesNoVisibilityBehind() {
        Probe probe = new Probe();
        try (Engine engine = GlTestSupport.engine(GL.context(), WIDTH, HEIGHT, new CullingSystem(), probe)) {
            renderAt(engine, NORTH);
            assertEquals(Containment.OUTSIDE, probe.last()[1]);
            engine.setEnabled("culling", false);
            renderAt(engine, NORTH);
            assertNull(probe.last(), "a drawer found a stale Visibility while culling was off");
        }
    }

    /** Renders one frame at a pose and returns its counters. */
    private static Map<String, Double> renderAt(Engine engine, CameraPose pose) {
        engine.world().resource(Camera.class).setPose(pose);
        engine.render();
        List<FrameRecord> records = new ArrayList<>();
        engine.collectFrames(true, records::add);
        return records.get(records.size() - 1).counters();
    }

    /** Pixels of the outline's magenta on the probe's black picture. */
    private static int outlinePixels(Image image) {
        int count = 0;
        for (int y = 0; y < image.height(); y++) {
            for (int x = 0; x < image.width(); x++) {
                if (image.channel(x, y, 0) > 200 && image.channel(x, y, 1) < 80 && image.channel(x, y, 2) > 150) {
                    count++;
                }
            }
        }
        return count;
    }
}
