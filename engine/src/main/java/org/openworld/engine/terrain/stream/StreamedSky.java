package org.openworld.engine.terrain.stream;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.OffscreenState;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureArray;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.terrain.heights.HeightSource;
import org.openworld.engine.terrain.lod.PatchList;
import org.openworld.engine.terrain.material.HorizonSearch;

/**
 * The unbounded world's share of the sky seen, made on the GPU as the blocks stream ({@link UnboundedWorld}): the
 * {@link HorizonSearch} the tile's {@code TileSky} runs (the same azimuths, distances, level choice and
 * {@code V = (1/N) Σ cos² α_φ}), by {@code shaders/terrain/stream/sky.frag} over the 64² texels of one block of
 * level L, reading the clipmap's own height levels, and written into the g channel of the snow map's layer L (the snow in r is masked off). One full-screen
 * triangle per block, the viewport on the block's texels: GL 3.3, no compute.
 *
 * <p><b>When.</b> A block is shaded once the heights its search reads have arrived ({@link StreamedWorld#skyReady}):
 * on each level, those within its reach of the block, as far as that level's window holds them. Until then its g is
 * 1, the whole sky. A colour pass about to draw its patches first shades the waiting blocks they read, so no pass
 * reads a block before its turn and a picture does not depend on the order the blocks came in; the picture's pass
 * then shades others, nearest the camera first, within a budget per frame ({@link #BUDGET_BLOCKS}, a
 * {@link FrameBudget}; what the drawn blocks took counts against it). The driver runs a block's pass when a later
 * draw reads the snow map, so the passes a frame asks for are waited for by that frame's picture: shading the
 * blocks of a column of level 0 eight at once took the terrain's CPU time to 200–850 ms in the frames it arrived
 * in, against a median of 85 ms (the crossing at 240×135 on a loaded llvmpipe); one a frame spreads it over 8
 * frames, and a block, which arrives 256 to 384 samples ahead of the camera, is seldom drawn before its turn
 * (2 or 3 blocks, a few times in the first 400 frames of the crossing, while the start's blocks still wait). At
 * start, and after a jump, every block is waiting, and the first frame shades only
 * those its passes draw (107 of 512 at the demo's default shot); the rest follow over the next frames, one
 * level-0 block's worth a frame. A block whose slot moves on before its turn is forgotten.
 *
 * <p><b>What the window holds.</b> At distance r the search reads the level whose samples lie about r / 4 apart.
 * Near the edge of a window that level may not hold the point (a block near the edge of a fine window reaches
 * beyond the next coarser one's), or may no longer hold it. A table of one texel per slot and level (RG32I) says
 * which block each slot's texels hold, written as each block is uploaded; the search reads a point only where the
 * slots of its four samples hold their blocks, and otherwise falls back on the next coarser level that does (the
 * coarsest window spans 131 km, so some level always does within the 3 km reach).
 *
 * <p><b>Cost.</b> Per texel {@code 8 · log(3000 m / d_L) / log 1.4} bilinear reads (23 distances on level 0, 9 on
 * level 7), each four texel fetches and four fetches of the table. On llvmpipe 6 ms a block (all 512 of the
 * windows in 3.0 s on a quiet two-core machine, the 107 of the default shot's first frame in 0.6 s); on a GPU well
 * under a millisecond.
 *
 * <p><b>Limits.</b> A block's horizon near a fine window's edge is read from a coarser level, and a block's value is
 * fixed once shaded: where the window lay when it was shaded decides what its search could read there, so a place
 * near a window's edge may differ slightly after two different flights (nowhere drawn at that level: a level is drawn
 * well inside its window). Each level has its own V from its own heights, so the same place seen on two levels gets
 * two slightly different values (the coarser level's smoothed relief hides less), which a tile's single map does not.
 */
final class StreamedSky {

    /**
     * The block index a slot holds before its first block: none the world reaches (level 0's blocks, 128 m, number
     * under 10⁵ within the 10 000 km before it repeats).
     */
    private static final int NOTHING = Integer.MIN_VALUE;
    /**
     * The passes a frame may run for blocks no pass draws yet, in level-0 blocks' worth (one level-0 block: 64² texels
     * of 23 distances; a level-7 block, of 9, costs 0.4 of it). The crossing's 300 m/s with a 1/60 s step brings
     * 37 blocks a second, 0.6 a frame, so one a frame keeps up with room to spare (a column of 8 level-0 blocks is
     * done 8 frames after it arrives); on a quiet llvmpipe it is 6 ms of a frame.
     */
    static final int BUDGET_BLOCKS = 1;

    private final HeightSource heights;
    private final int size;
    private final int block;
    private final ShaderProgram program;
    private final Mesh triangle;
    /** Layer k, one texel a slot: the block (x, z) whose heights the slot's texels hold; NOTHING before any. */
    private final TextureArray held;
    private final Framebuffer[] targets;
    private final HorizonSearch.Uniforms search;
    private final Uniform.Int originX;
    private final Uniform.Int originZ;
    private final ByteBuffer heldStaging;
    private final int unit;
    /** Blocks uploaded and not yet given their visibility. */
    private final Set<Block> pending = new LinkedHashSet<>();
    private final DrawStats stats = new DrawStats();
    /** Per level: a block's pass in texel-distances (block² · the search's distances), what the budget counts. */
    private final long[] costs;
    private final FrameBudget budget;

    /**
     * The program ({@code terrain.sky}), the table of held blocks ({@code terrain.clipmap.held}) and a target for each
     * layer of {@code snow}, handed to the context's owner; the pass binds its three textures from {@code unit} on.
     */
    StreamedSky(EngineContext context, StreamedWorld stream, TextureArray snow, int unit) {
        this.heights = stream.heights();
        this.size = stream.clipSize();
        this.block = StreamedWorld.BLOCK;
        this.unit = unit;
        int levels = stream.levels();
        program = context.own("sky", context.shaders().program(HorizonSearch.defines(heights.spacing(0)),
                "terrain/material/bake.vert", "terrain/stream/sky.frag"));
        search = new HorizonSearch.Uniforms(program, levels, heights.spacing(0), heights.spacing(0));
        program.sampler("heights", unit);
        program.sampler("slopes", unit + 1);
        program.sampler("held", unit + 2);
        program.int1("clipSize").set(size);
        program.int1("blockShift").set(Integer.numberOfTrailingZeros(block));
        originX = program.int1("originX");
        originZ = program.int1("originZ");
        triangle = context.own(Mesh.fullScreenTriangle(context.gl()));
        int slots = size / block;
        held = context.own("clipmap.held",
                TextureArray.empty(context.gl(), slots, slots, levels, Format.RG32I, Sampling.NEAREST_CLAMP));
        heldStaging = MemoryUtil.memAlloc(2 * Integer.BYTES * slots * slots);
        for (int l = 0; l < levels; l++) {
            heldStaging.clear();
            while (heldStaging.hasRemaining()) {
                heldStaging.putInt(NOTHING);
            }
            held.upload(l, 0, 0, slots, slots, heldStaging.flip());
        }
        costs = new long[levels];
        for (int l = 0; l < levels; l++) {
            costs[l] = (long) block * block * HorizonSearch.distances(heights.spacing(l)).length;
        }
        budget = new FrameBudget(BUDGET_BLOCKS * costs[0]);
        targets = new Framebuffer[levels];
        for (int l = 0; l < levels; l++) {
            targets[l] = context.own("sky.level" + l, Framebuffer.onLayer(context.gl(), snow, l));
        }
    }

    /**
     * Notes that the slot of level {@code l}'s block (bx, bz) now holds it, its heights, slopes and snow just
     * uploaded (with g = 1, the whole sky, until its turn comes in {@link #shadeSome} or
     * {@link #shadeUnder}).
     */
    void arrived(int l, long bx, long bz) {
        int slots = size / block;
        heldStaging.clear();
        heldStaging.putInt((int) bx).putInt((int) bz).flip();
        held.upload(l, (int) (bx & (slots - 1)), (int) (bz & (slots - 1)), 1, 1, heldStaging);
        pending.add(new Block(l, bx, bz));
    }

    /**
     * Writes the visibility of the waiting blocks whose surroundings have arrived ({@link StreamedWorld#skyReady}),
     * nearest the camera first ({@link StreamedWorld#priority}, the order a pass comes to draw them), as many as
     * what is left of this frame's {@link #BUDGET_BLOCKS} pays for (at least one if the drawn blocks took none of
     * it), and ends the frame's budget; forgets those whose slot has moved on. The coarsest level's blocks are
     * drawn where no patch lies (the far field reads them), so they are shaded as soon as they can be, as the drawn
     * blocks are: 8 of them a 16 km column, a few times a flight. Returns how many it wrote.
     */
    int shadeSome(StreamedWorld stream, TextureArray heightTexture, TextureArray slopeTexture) {
        List<Block> candidates = new ArrayList<>();
        for (Iterator<Block> it = pending.iterator(); it.hasNext(); ) {
            Block b = it.next();
            if (!stream.holds(b.level, b.x, b.z)) {
                it.remove();
            } else if (stream.skyReady(b.level, b.x, b.z)) {
                candidates.add(b);
            }
        }
        candidates.sort(Comparator.comparingLong(b -> stream.priority(b.level, b.x, b.z)));
        List<Block> ready = new ArrayList<>();
        for (Block b : candidates) {
            if (b.level == targets.length - 1) {
                budget.spend(cost(b.level)); // the far field reads the coarsest level wherever its window holds it
            } else if (!budget.take(cost(b.level))) {
                continue;
            }
            ready.add(b);
            pending.remove(b);
        }
        budget.nextFrame();
        return shade(ready, heightTexture, slopeTexture);
    }

    /**
     * Writes the visibility of the waiting blocks, with their surroundings arrived, that these patches read: on the
     * patch's level, its samples and the next beyond its far sides (the shading filters the level's texels
     * linearly), so a pass that draws them reads no block still waiting. Returns how many it wrote.
     */
    int shadeUnder(PatchList patches, float[] copyOffsets, StreamedWorld stream, TextureArray heightTexture,
                   TextureArray slopeTexture) {
        int cells = stream.tree().cells();
        List<Block> ready = new ArrayList<>();
        for (int i = 0; i < patches.size() && !pending.isEmpty(); i++) {
            int l = patches.level(i);
            long originX = stream.rootOrigin(copyOffsets[2 * patches.copy(i)]) + patches.originSampleX(i);
            long originZ = stream.rootOrigin(copyOffsets[2 * patches.copy(i) + 1]) + patches.originSampleZ(i);
            long span = (long) cells * patches.sampleStep(i);
            long bz1 = Math.floorDiv(((originZ + span) >> l) + 1, block);
            long bx1 = Math.floorDiv(((originX + span) >> l) + 1, block);
            for (long bz = Math.floorDiv(originZ >> l, block); bz <= bz1; bz++) {
                for (long bx = Math.floorDiv(originX >> l, block); bx <= bx1; bx++) {
                    Block b = new Block(l, bx, bz);
                    if (pending.contains(b) && stream.skyReady(l, bx, bz)) {
                        pending.remove(b);
                        ready.add(b);
                        budget.spend(cost(l));
                    }
                }
            }
        }
        return shade(ready, heightTexture, slopeTexture);
    }

    /** A level-{@code l} block's pass, in texel-distances: its texels times the distances its search reads. */
    private long cost(int l) {
        return costs[l];
    }

    /** Blocks uploaded and not yet given their visibility. */
    int waiting() {
        return pending.size();
    }

    /**
     * The passes of these blocks. Leaves the framebuffer, viewport, colour mask, depth test, blending and face
     * culling as they were; the program in use and the bindings of the three units change.
     */
    private int shade(List<Block> ready, TextureArray heightTexture, TextureArray slopeTexture) {
        if (ready.isEmpty()) {
            return 0;
        }
        heightTexture.bind(unit);
        slopeTexture.bind(unit + 1);
        held.bind(unit + 2);
        program.use();
        try (OffscreenState state = OffscreenState.enter()) {
            glColorMask(false, true, false, false); // the snow in r stays
            for (Block b : ready) {
                shade(b);
            }
        } finally {
            glColorMask(true, true, true, true);
        }
        return ready.size();
    }

    /** One block's pass: its level's distances and the levels they read, its texels of its layer. */
    private void shade(Block b) {
        search.set(b.level, targets.length, heights::spacing);
        originX.set((int) (b.x * block));
        originZ.set((int) (b.z * block));
        int slots = size / block;
        targets[b.level].bind();
        glViewport((int) (b.x & (slots - 1)) * block, (int) (b.z & (slots - 1)) * block, block, block);
        triangle.draw(stats);
    }

    /** A block waiting for its pass: level, and its index along x and z. */
    private record Block(int level, long x, long z) {
    }

    void close() {
        MemoryUtil.memFree(heldStaging);
    }
}
