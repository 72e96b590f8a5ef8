package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL31C.GL_UNIFORM_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_DRAW;

import java.nio.ByteBuffer;
import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Vector3fc;
import org.lwjgl.system.MemoryUtil;

/**
 * The per-pass uniform block every shader includes from {@code shaders/common/frame.glsl}: one std140 buffer,
 * bound at {@link SharedBlock#FRAME}'s point, rewritten before each pass. The Java field order here and the GLSL
 * block must match; std140 makes that simple because every member is a vec4 or a mat4 (16-byte aligned, no padding
 * rules to remember).
 *
 * <p>Two positions: {@code cameraPos} is the pass camera's eye (in SHADOW the sun's camera, in REFLECTION the
 * mirrored eye), {@code viewerPos} the viewer's (the MAIN camera's) in every pass. Whatever must agree between the
 * passes (a fade or a level of detail by distance) follows the viewer; what belongs to the picture being drawn (the
 * view ray, the air in front of a surface) follows the pass camera.
 *
 * <p>Every position here is measured from the render origin ({@code org.openworld.engine.origin.RenderOrigin}), whose
 * place the block holds as a whole number of steps (exact in a float up to 2^24 steps) and the step in metres.
 */
public final class FrameUniforms implements Labelled {

    private static final int MAT4 = 64;
    private static final int VEC4 = 16;
    /**
     * The sky's irradiance factors (spherical harmonics of order 2) and the light of the terrain that hides part of
     * it, one RGB vector each.
     */
    public static final int SKY_FACTORS = 10;
    /** 4 matrices, 9 vectors and the sky's factors, bytes. */
    static final int SIZE = 4 * MAT4 + 9 * VEC4 + SKY_FACTORS * VEC4;

    /**
     * Everything the block holds, gathered by the engine for one pass.
     *
     * @param cameraPos the pass camera's eye (the sun's camera in SHADOW, the mirrored eye in REFLECTION)
     * @param viewerPos the viewer's eye, the MAIN camera's, whatever the pass
     * @param originSteps the render origin's x and z in steps (whole numbers); {@code step} its step, metres
     * @param sky       the nine factors of the sky's irradiance for any normal and the hidden sky's light
     *                  (frame.glsl's skyIrradiance; environment.SkyIrradiance#shaderFactors)
     */
    public record Values(Matrix4f view, Matrix4f projection, Vector3fc cameraPos, float near, float far,
                         Vector3fc sunDir, Vector3fc sunColor, Vector3fc ambient, float exposure, float scotopic,
                         double simTime, double timeOfDayHours, long frame,
                         int width, int height, Vector3fc viewerPos,
                         double originStepsX, double originStepsZ, double step, Vector3fc[] sky) {
    }

    private final GpuBuffer buffer;
    private final ByteBuffer data = MemoryUtil.memCalloc(SIZE);

    public FrameUniforms(GlContext gl) {
        buffer = new GpuBuffer(gl, GL_UNIFORM_BUFFER);
        buffer.allocate(SIZE, GL_DYNAMIC_DRAW);
        buffer.bindBase(SharedBlock.FRAME.binding());
    }

    /** Writes the block for one pass (std140: each mat4 is 64 bytes column-major, each vec4 16 bytes). */
    public void write(Values v) {
        Matrix4f viewProj = new Matrix4f(v.projection()).mul(v.view());
        // inverted in double: a deep projection (0.5 m to 40 km) is ill-conditioned, and float loses centimetres
        Matrix4f invViewProj = new Matrix4f(new Matrix4d(v.projection()).mul(new Matrix4d(v.view())).invert());
        v.view().get(0, data);
        v.projection().get(MAT4, data);
        viewProj.get(2 * MAT4, data);
        invViewProj.get(3 * MAT4, data);
        int o = 4 * MAT4;
        o = vec4(o, v.cameraPos().x(), v.cameraPos().y(), v.cameraPos().z(), v.near());
        o = vec4(o, v.sunDir().x(), v.sunDir().y(), v.sunDir().z(), v.far());
        o = vec4(o, v.sunColor().x(), v.sunColor().y(), v.sunColor().z(), 0);
        o = vec4(o, v.ambient().x(), v.ambient().y(), v.ambient().z(), 0);
        o = vec4(o, v.exposure(), v.scotopic(), 0, 0);
        o = vec4(o, (float) v.simTime(), (float) v.timeOfDayHours(), v.frame(), 0);
        o = vec4(o, v.width(), v.height(), 1f / v.width(), 1f / v.height());
        o = vec4(o, v.viewerPos().x(), v.viewerPos().y(), v.viewerPos().z(), 0);
        o = vec4(o, (float) v.originStepsX(), 0, (float) v.originStepsZ(), (float) v.step());
        for (Vector3fc c : v.sky()) {
            o = vec4(o, c.x(), c.y(), c.z(), 0);
        }
        buffer.update(data);
        buffer.bindBase(SharedBlock.FRAME.binding());
    }

    private int vec4(int offset, float x, float y, float z, float w) {
        data.putFloat(offset, x).putFloat(offset + 4, y).putFloat(offset + 8, z).putFloat(offset + 12, w);
        return offset + VEC4;
    }

    @Override
    public void label(String name) {
        buffer.label(name);
    }

    @Override
    public void close() {
        buffer.close();
        MemoryUtil.memFree(data);
    }
}
