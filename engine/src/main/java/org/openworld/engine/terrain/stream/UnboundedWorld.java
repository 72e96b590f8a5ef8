package org.openworld.engine.terrain.stream;

import static org.lwjgl.opengl.GL11C.glFinish;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.util.Locale;
import java.util.function.Consumer;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.TextureArray;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.lod.PatchList;

/**
 * The unbounded world ({@code terrain.world=UNBOUNDED}) on the GPU: the {@link StreamedWorld}'s blocks, as
 * they arrive, uploaded into three texture arrays, one layer a level, at the texels the clipmap's toroidal storage
 * gives them (heights; slopes and snow for the shading).
 *
 * <p><b>Memory.</b> Heights R32F, slopes RG16F, snow RG8: {@value StreamedWorld#TEXEL_BYTES} · levels · size² bytes
 * on the GPU, fixed whatever the distance flown; on the Java side the bands' tiles (a MiB each) and the blocks in
 * flight, bounded by the clipmap.
 */
public final class UnboundedWorld implements AutoCloseable {

    private final StreamedWorld stream;
    public final TextureArray heightTexture;
    public final TextureArray slopeTexture;
    /** r: the snow's coverage ({@link StreamedSnow}); g: the share of the sky seen ({@link StreamedSky}). */
    public final TextureArray snowTexture;
    private final StreamedSnow snow;
    private final StreamedSky sky;
    private final FloatBuffer staging;
    private final ByteBuffer snowStaging;
    private final Consumer<String> progress;
    /** Whether the first pass's sky pass was timed. */
    private boolean skyTimed;

    /**
     * Makes the bands, the quadtree, the textures (handed to the context's owner as {@code terrain.clipmap...}) and
     * the sky's pass; the first {@link #follow} fills them around the camera, wherever its direction put it.
     *
     * @param cells N, the cells per patch side
     * @param unit  the first of the three texture units the sky's pass binds (the frame binds them again)
     */
    public UnboundedWorld(EngineContext context, TerrainSettings s, int seed, int cells, int unit, StageTimes times,
                   Consumer<String> progress) {
        stream = new StreamedWorld(s, seed, cells, times, progress);
        int size = stream.clipSize();
        int levels = stream.levels();
        snow = times.time("snow table", () -> new StreamedSnow(s, seed));
        heightTexture = context.own("clipmap.heights",
                TextureArray.empty(context.gl(), size, size, levels, Format.R32F, Sampling.NEAREST_CLAMP));
        slopeTexture = context.own("clipmap.slopes",
                TextureArray.empty(context.gl(), size, size, levels, Format.RG16F, Sampling.LINEAR_REPEAT));
        snowTexture = context.own("clipmap.snow",
                TextureArray.empty(context.gl(), size, size, levels, Format.RG8, Sampling.LINEAR_REPEAT));
        int block = StreamedWorld.BLOCK;
        staging = MemoryUtil.memAllocFloat(2 * block * block);
        snowStaging = MemoryUtil.memAlloc(2 * block * block);
        markUnwritten(size, levels);
        sky = new StreamedSky(context, stream, snowTexture, unit);
        this.progress = progress;
    }

    /**
     * Fills every height texel with NaN before any block arrives: a vertex that read a texel not yet written
     * would not be drawn (a triangle with a NaN corner is dropped), so a read before the upload shows as a hole,
     * which the tests look for, rather than as plausible ground at height 0.
     */
    private void markUnwritten(int size, int levels) {
        FloatBuffer nan = MemoryUtil.memAllocFloat(size * StreamedWorld.BLOCK);
        try {
            while (nan.hasRemaining()) {
                nan.put(Float.NaN);
            }
            nan.flip();
            for (int level = 0; level < levels; level++) {
                for (int z = 0; z < size; z += StreamedWorld.BLOCK) {
                    heightTexture.upload(level, 0, z, size, StreamedWorld.BLOCK, nan);
                }
            }
        } finally {
            MemoryUtil.memFree(nan);
        }
    }

    /** Once per simulation step: {@link StreamedWorld#follow}, uploading what it hands on. */
    public void follow(CameraPose pose, double step) {
        stream.follow(pose, step, this::upload);
    }

    /**
     * Before a pass shades these patches: the sky's pass over the waiting blocks they read, and with the picture's
     * pass ({@code picture}, the frame's last colour pass) over others whose surroundings are there, nearest
     * first, within the sky's budget per frame ({@link StreamedSky#BUDGET_BLOCKS}), so the sky keeps pace with
     * the streaming without stalling the frame a burst of blocks arrives in, and a block is seldom left for the pass
     * that first draws it. At start, and after a jump, every block is waiting, and the first frame shades only
     * those its passes draw: on a software rasteriser the whole windows' pass was most of the start. The first
     * call after the start's streaming is timed.
     */
    public void shadeFor(PatchList patches, float[] copyOffsets, boolean picture) {
        long start = System.nanoTime();
        int blocks = sky.shadeUnder(patches, copyOffsets, stream, heightTexture, slopeTexture);
        if (!skyTimed && blocks + sky.waiting() > 0) { // a window's first frame may come before its first step
            glFinish(); // the pass runs when the driver gets to it; the first frame waits for it, and so does its time
            progress.accept(String.format(Locale.ROOT, "terrain: %-10s %7.0f ms (%d blocks the first pass draws, "
                    + "%d to come)", "sky view", (System.nanoTime() - start) / 1e6, blocks, sky.waiting()));
            skyTimed = true;
        }
        if (picture) {
            sky.shadeSome(stream, heightTexture, slopeTexture);
        }
    }

    /** Blocks whose share of the sky seen has not been written yet. */
    int skyWaiting() {
        return sky.waiting();
    }

    /**
     * Runs the sky's pass over every waiting block whose surroundings have arrived, a frame's budget at a time
     * without the frames between (tests: the sky as it stands once the streaming has settled).
     */
    void settleSky() {
        while (sky.shadeSome(stream, heightTexture, slopeTexture) > 0) {
            continue;
        }
    }

    /**
     * Uploads a block given with its border: its heights, its slopes by central differences, and its snow; its
     * share of the sky seen waits for the sky's pass ({@link StreamedSky#arrived}).
     */
    private void upload(int level, long ix0, long iz0, int texelX, int texelZ, int block, float[] bordered) {
        int border = stream.border();
        int side = block + 2 * border;
        staging.clear();
        for (int j = border; j < border + block; j++) {
            staging.put(bordered, j * side + border, block);
        }
        heightTexture.upload(level, texelX, texelZ, block, block, staging.flip());
        float inv2d = (float) (1 / (2 * stream.heights().spacing(level)));
        staging.clear();
        for (int j = border; j < border + block; j++) {
            for (int i = border; i < border + block; i++) {
                int at = j * side + i;
                staging.put((bordered[at + 1] - bordered[at - 1]) * inv2d);
                staging.put((bordered[at + side] - bordered[at - side]) * inv2d);
            }
        }
        slopeTexture.upload(level, texelX, texelZ, block, block, staging.flip());
        snowStaging.clear();
        for (byte b : snow.block(level, ix0, iz0, block, bordered, border)) {
            snowStaging.put(b).put((byte) 255); // g: the whole sky until the sky's pass writes it
        }
        snowTexture.upload(level, texelX, texelZ, block, block, snowStaging.flip());
        sky.arrived(level, Math.floorDiv(ix0, block), Math.floorDiv(iz0, block));
    }

    /** The snow cover the coarse levels show at this height, metres. */
    public double snowCoverageAt(double height) {
        return snow.coverageAt(height);
    }

    /** The world's heights, streaming and level choice. */
    public StreamedWorld stream() {
        return stream;
    }

    @Override
    public void close() {
        stream.close();
        MemoryUtil.memFree(staging);
        MemoryUtil.memFree(snowStaging);
        sky.close();
    }
}
