package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.lwjgl.opengl.GL11C.*;

import java.nio.FloatBuffer;
import java.util.function.IntBinaryOperator;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.GlTest;
import org.openworld.engine.GlTestSupport;
import org.openworld.engine.HeadlessGl;

/**
 * A 3D texture uploaded and read back through a shader on the real driver: texel centres return their values,
 * linear filtering blends slices, and the two samplings wrap or clamp. The extension checks that nothing leaks.
 */
@GlTest
class Texture3DTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    private static final int W = 8;
    private static final int H = 4;
    private static final int D = 2;
    /** One 8-bit step of the read-back, plus the half float's rounding of values below 1. */
    private static final int TOLERANCE = 1;

    /** The test volume: distinct values in [0, 1), x fastest. */
    private static float value(int x, int y, int z) {
        return (x + W * y + W * H * z) / 64f;
    }

    private static FloatBuffer volume(float add) {
        FloatBuffer data = MemoryUtil.memAllocFloat(W * H * D);
        for (int z = 0; z < D; z++) {
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    data.put(value(x, y, z) + add);
                }
            }
        }
        return data.flip();
    }

    /** Draws the read-back shader over a W × H target and returns the red channel of texel column x, row y. */
    private static int[][] read(Texture3D texture, float s, float t, float r) {
        ShaderLibrary library = new ShaderLibrary(GL.context(), ShaderSources.classpath());
        try (ShaderProgram program = library.program("cloudtest/fullscreen.vert", "cloudtest/volume.frag");
             Framebuffer target = new Framebuffer(GL.context(), W, H, Format.RGBA8, null,
                     Sampling.NEAREST_CLAMP);
             Mesh triangle = GlTestSupport.fullScreenTriangle(GL.context())) {
            target.bind();
            glClearColor(0, 0, 0, 0);
            glClear(GL_COLOR_BUFFER_BIT);
            program.use();
            program.sampler("volume", 0);
            program.vec4("lookup").set(s, t, r, 0);
            texture.bind(0);
            triangle.draw(new DrawStats());
            Image image = target.read();
            int[][] red = new int[H][W];
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    red[y][x] = image.channel(x, H - 1 - y, 0); // the image's top row is the texture's last
                }
            }
            return red;
        }
    }

    private static void assertTexels(int[][] red, IntBinaryOperator expected255, String what) {
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                assertEquals(expected255.applyAsInt(x, y), red[y][x], TOLERANCE, what + " at (" + x + ", " + y + ")");
            }
        }
    }

    private static int bytes(double v) {
        return (int) Math.round(255 * v);
    }

    private static Texture3D create(Sampling sampling) {
        FloatBuffer data = volume(0);
        try {
            return Texture3D.of(GL.context(), W, H, D, Format.R16F, sampling, data);
        } finally {
            MemoryUtil.memFree(data);
        }
    }

    @Test
    void texelCentresReturnTheUploadedValuesAndSlicesBlendBetween() {
        try (Texture3D t = create(Sampling.LINEAR_REPEAT)) {
            assertEquals(W, t.width());
            assertEquals(H, t.height());
            assertEquals(D, t.depth());
            assertTexels(read(t, 0, 0, 0.25f), (x, y) -> bytes(value(x, y, 0)), "slice 0");
            assertTexels(read(t, 0, 0, 0.75f), (x, y) -> bytes(value(x, y, 1)), "slice 1");
            assertTexels(read(t, 0, 0, 0.5f), (x, y) -> bytes((value(x, y, 0) + value(x, y, 1)) / 2), "halfway");
        }
    }

    @Test
    void repeatWrapsEveryAxis() {
        try (Texture3D t = create(Sampling.LINEAR_REPEAT)) {
            // whole tiles away in s and t, and one period later in r: the same texels
            assertTexels(read(t, 1, -2, 1.25f), (x, y) -> bytes(value(x, y, 0)), "shifted by whole tiles");
            // r = 0 lies halfway between slice 0's centre (0.25) and slice 1's wrapped one (−0.25)
            assertTexels(read(t, 0, 0, 0), (x, y) -> bytes((value(x, y, 0) + value(x, y, 1)) / 2), "wrapped in r");
        }
    }

    @Test
    void clampStopsAtTheEdgeTexels() {
        try (Texture3D t = create(Sampling.LINEAR_CLAMP)) {
            assertTexels(read(t, 0, 0, 0), (x, y) -> bytes(value(x, y, 0)), "below the first slice");
            // pushed a whole tile right: every column reads the last one
            assertTexels(read(t, 1, 0, 0.25f), (x, y) -> bytes(value(W - 1, y, 0)), "right of the last column");
        }
    }

    @Test
    void uploadReplacesTheVolume() {
        try (Texture3D t = Texture3D.of(GL.context(), W, H, D, Format.R16F,
                Sampling.LINEAR_REPEAT, null)) {
            FloatBuffer data = volume(0.01f);
            try {
                t.upload(data);
            } finally {
                MemoryUtil.memFree(data);
            }
            assertTexels(read(t, 0, 0, 0.75f), (x, y) -> bytes(value(x, y, 1) + 0.01f), "after upload");
        }
    }

    @Test
    void aVolumeOfTheWrongSizeIsRefusedWithoutCreatingATexture() {
        FloatBuffer data = MemoryUtil.memAllocFloat(W * H);
        try {
            var e = assertThrows(IllegalArgumentException.class, () -> Texture3D.of(GL.context(), W, H, D,
                    Format.R16F, Sampling.LINEAR_REPEAT, data));
            assertEquals("a 8x4x2 volume takes 64 floats, got 32", e.getMessage());
        } finally {
            MemoryUtil.memFree(data);
        }
    }

    @Test
    void eachVolumeIsOneTextureUntilClosed() {
        int before = GL.context().objects().live();
        Texture3D t = create(Sampling.LINEAR_CLAMP);
        assertEquals(before + 1, GL.context().objects().live());
        t.close();
        t.close(); // closing twice deletes once
        assertEquals(before, GL.context().objects().live());
    }
}
