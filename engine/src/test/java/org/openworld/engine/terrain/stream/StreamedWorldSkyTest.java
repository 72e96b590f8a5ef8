package org.openworld.engine.terrain.stream;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TestTerrain;
import org.openworld.engine.terrain.lod.LodSettings;

/**
 * When {@link StreamedWorld} lets the sky's pass run over a block ({@link StreamedWorld#skyReady}), GL-free: once
 * every window is whole, every block, those at a window's edge too (what lies beyond is not waited for); during a
 * flight that outruns the uploads, not the blocks whose next one east, in the window, is still missing.
 */
class StreamedWorldSkyTest {

    @Test
    void aBlockWaitsForTheBlocksItsSearchReads() throws InterruptedException {
        try (StreamedWorld world = new StreamedWorld(TestTerrain.settings("terrain.world=unbounded"), 1,
                LodSettings.DEFAULTS.patchVertices() - 1, new StageTimes(), line -> { })) {
            HeightClipmap.BlockSink none = (level, ix0, iz0, texelX, texelZ, block, heights) -> { };
            world.follow(new CameraPose(0, 500, 0, 90, -8, 60), 0, none);
            int blocks = world.clipSize() / StreamedWorld.BLOCK;
            for (int level = 0; level < world.levels(); level++) {
                for (long bz = -blocks; bz < blocks; bz++) {
                    for (long bx = -blocks; bx < blocks; bx++) {
                        assertTrue(!world.holds(level, bx, bz) || world.skyReady(level, bx, bz),
                                "level " + level + " block (" + bx + ", " + bz + ") after the start");
                    }
                }
            }
            // east at 240 m a step (just under a jump): level 0's new blocks come 8 a step, fewer than it needs
            double x = 0;
            for (int step = 0; step < 10; step++) {
                x += 240;
                world.follow(new CameraPose(x, 500, 0, 90, -8, 60), 1 / 60.0, none);
            }
            // then hovering while the rest arrives, 8 blocks a step: on level 0, a held block whose east neighbour
            // has not come yet, where that neighbour lies in the window (the leading edge's), waits
            long half = world.clipSize() / 2 / StreamedWorld.BLOCK;
            long cx = Math.floorDiv((long) (x / world.heights().spacing(0)), StreamedWorld.BLOCK);
            int awaited = 0;
            int held = 0;
            for (int step = 0; step < 200; step++) {
                Thread.sleep(2); // the workers make blocks meanwhile
                world.follow(new CameraPose(x, 500, 0, 90, -8, 60), 1 / 60.0, none);
                for (long bz = -half; bz <= half; bz++) {
                    for (long bx = cx - half; bx <= cx + half; bx++) {
                        held += world.holds(0, bx, bz) ? 1 : 0;
                        if (world.holds(0, bx, bz) && !world.holds(0, bx + 1, bz) && !world.skyReady(0, bx, bz)) {
                            awaited++;
                        }
                    }
                }
            }
            assertTrue(awaited > 0, "blocks waiting for their east neighbour; level-0 blocks held, summed over the steps: " + held);
        }
    }
}
