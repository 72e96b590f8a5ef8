package org.openworld.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;
import org.openworld.engine.camera.CameraDirection;
import org.openworld.engine.camera.CameraPath;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.camera.CameraSystem;
import org.openworld.engine.camera.HeightReference;
import org.openworld.engine.camera.Keyframe;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.gl.GlObjects;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.vegetation.VegetationSystem;

/**
 * A long run with every system on, to catch what short tests cannot: a GL object made every frame and never freed,
 * or a Java object kept every frame. A small world (64×36 pixels, a 256-sample terrain, 1 000 particles, trees on)
 * flies a looping orbit for {@value #FRAMES} frames, an update and a render each, and neither the GL objects alive nor
 * the heap used after a full collection may grow from the first quarter to the last. On both worlds: on the unbounded
 * one the orbit's {@value #RADIUS} m radius keeps the windows moving, so blocks are made, uploaded and reused all
 * along (level 0's window moves 21 times, level 1's 8; an 80 m circle moved level 0's once).
 *
 * <p>GL objects: the count at the end of the first quarter must hold through the whole last quarter, programs aside
 * (each is compiled at its first use, which may come late, and may only not be compiled twice). It is not flat
 * from the first frame: the systems make some objects on first use (GPU timer queries as frames queue up, the
 * trees' buffers once they are placed), 95 after the first frame and 116 within the first hundred here. The heap
 * (sampled at two points of each quarter, each the least of three full collections) wobbles by about 0.1 MB run to
 * run, as the JIT and JUnit allocate on their own; it may not grow by {@value #HEAP_TOLERANCE_MB} MB, which over the
 * 750 frames between the quarters is under 3 kB a frame: a leak of one small array a frame fails the test.
 *
 * <p>Cost, and why 1 000 frames and not 2 000: on the project's 2-core machine under Mesa llvmpipe a frame of this
 * world takes about 50 ms, most of it the terrain drawn into the shadow cascades, the reflection and the view, so
 * 2 000 frames would take close to two minutes; 1 000 fit the minute a CI test may take (measured: 51 s on a quiet
 * machine, 54 s beside other builds; later 24 s on the tile and 21 s on the unbounded world). Shadows use two
 * cascades over 400 m and the trees end at 200 m to keep the frame that cheap (with four cascades, 400 frames took
 * 66 s); every system still runs every pass.
 */
@GlTest
class SoakTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    static final int FRAMES = 1000;
    static final long HEAP_TOLERANCE_MB = 2;

    static final List<String> SMALL_WORLD = List.of("terrain.size=256", "lod.patch-vertices=33",
            "system.minimap=on", "system.particles=on", "particles.count=1000", "shadow.resolution=256",
            "shadow.cascades=2", "shadow.distance=400", "vegetation.view-distance=200");

    private static final MemoryMXBean MEMORY = ManagementFactory.getMemoryMXBean();

    /**
     * The GL objects alive but programs: a program is compiled on its first use, which may come late in the flight (a
     * variant first needed when the view first reaches it), so programs are held instead to at most one each of
     * those the systems made.
     */
    private static int liveButPrograms() {
        return GL.context().objects().live() - GL.context().objects().live(GlObjects.Kind.PROGRAM);
    }

    @ParameterizedTest
    @EnumSource(TerrainSettings.World.class)
    void glObjectsAndHeapDoNotGrowOverALongFlight(TerrainSettings.World world) {
        List<EngineSystem> systems = new ArrayList<>(List.of(new CameraSystem()));
        systems.addAll(SystemsOwnershipTest.systems());
        systems.add(new VegetationSystem());
        int[] frames = {0};
        int liveAfterFirstQuarter = 0;
        List<Integer> lastLive = new ArrayList<>();
        int programsMade = 0;
        int programsCompiled = 0;
        List<Long> firstHeap = new ArrayList<>();
        List<Long> lastHeap = new ArrayList<>();
        long start = System.nanoTime();
        List<String> settings = new ArrayList<>(SMALL_WORLD);
        settings.add("terrain.world=" + world);
        try (Engine engine = GlTestSupport.engine(GL.context(), 64, 36, settings,
                systems.toArray(EngineSystem[]::new))) {
            engine.world().setResource(CameraDirection.class, CameraDirection.play(orbit(), 0, true));
            for (int frame = 1; frame <= FRAMES; frame++) {
                engine.update();
                engine.render();
                engine.collectFrames(false, record -> frames[0]++);
                boolean first = frame <= FRAMES / 4;
                boolean last = frame > 3 * FRAMES / 4;
                if (frame == FRAMES / 4) {
                    liveAfterFirstQuarter = liveButPrograms();
                } else if (last) {
                    lastLive.add(liveButPrograms());
                }
                if (frame % (FRAMES / 8) == 0 && (first || last)) {
                    (first ? firstHeap : lastHeap).add(heapAfterFullCollection());
                }
            }
            engine.collectFrames(true, record -> frames[0]++);
            programsMade = engine.shaders().labels().size();
            programsCompiled = GL.context().objects().live(GlObjects.Kind.PROGRAM);
        }
        System.out.printf("soak, " + world + ": %d frames in %.1f s; GL objects %d then %s; heap after GC %s then %s bytes%n",
                FRAMES, (System.nanoTime() - start) / 1e9, liveAfterFirstQuarter, range(lastLive), firstHeap,
                lastHeap);
        assertEquals(FRAMES, frames[0], "every frame rendered and timed");
        assertTrue(liveAfterFirstQuarter > 40, "the systems made their objects: " + liveAfterFirstQuarter);
        assertEquals(List.of(liveAfterFirstQuarter, liveAfterFirstQuarter), range(lastLive),
                "GL objects but programs alive (least, most) through the last quarter, against the end of the first");
        assertTrue(programsCompiled <= programsMade, "GL programs " + programsCompiled + ", more than the "
                + programsMade + " programs the systems made: one compiled twice");
        long grown = Collections.max(lastHeap) - Collections.max(firstHeap);
        assertTrue(grown < HEAP_TOLERANCE_MB << 20, "the heap grew by " + grown + " bytes: " + firstHeap + " then "
                + lastHeap);
    }

    private static List<Integer> range(List<Integer> counts) {
        return List.of(Collections.min(counts), Collections.max(counts));
    }

    /** Radius of the orbit, metres. */
    static final double RADIUS = 400;

    /** A circle of {@link #RADIUS} around the world's centre, 40 m above the ground, once in 20 s, facing inwards. */
    private static CameraPath orbit() {
        List<Keyframe> keys = new ArrayList<>();
        for (int i = 0; i <= 16; i++) {
            double angle = 2 * Math.PI * i / 16;
            keys.add(Keyframe.of(20.0 * i / 16, new CameraPose(RADIUS * Math.sin(angle), 40, -RADIUS * Math.cos(angle),
                    180 + Math.toDegrees(angle), -20, CameraPose.DEFAULT_FOV)));
        }
        return new CameraPath(HeightReference.GROUND, keys);
    }

    /** Heap used after a full collection, bytes: the least of three collections, as one may leave some behind. */
    private static long heapAfterFullCollection() {
        long least = Long.MAX_VALUE;
        for (int i = 0; i < 3; i++) {
            System.gc();
            least = Math.min(least, MEMORY.getHeapMemoryUsage().getUsed());
        }
        return least;
    }
}
