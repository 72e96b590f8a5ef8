package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL11C.glGetIntegerv;

import java.util.Optional;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GLCapabilities;

/**
 * The GPU memory the driver reports, where it reports any: OpenGL itself has no query for it, so this reads one of
 * two vendor extensions. {@code GL_NVX_gpu_memory_info} (NVIDIA) gives the total dedicated memory and what is
 * available now, so used = total - available; {@code GL_ATI_meminfo} (AMD) gives only the free memory of the texture
 * pool. Mesa's llvmpipe, like most drivers, has neither, and {@link #of()} is empty there.
 *
 * <p>Cost: one {@code glGetIntegerv} per read, answered by the driver without waiting for the GPU.
 */
public final class GpuMemoryInfo {

    /** GL_NVX_gpu_memory_info: dedicated video memory, KiB. */
    private static final int NVX_TOTAL_AVAILABLE_KIB = 0x9048;
    /** GL_NVX_gpu_memory_info: dedicated video memory available now, KiB. */
    private static final int NVX_CURRENT_AVAILABLE_KIB = 0x9049;
    /** GL_ATI_meminfo: the texture pool's {total free, largest free block, auxiliary free, largest auxiliary}, KiB. */
    private static final int ATI_TEXTURE_FREE_MEMORY = 0x87FC;
    private static final double KIB_PER_MIB = 1024;

    private final boolean nvx;
    /** NVX: the total, MiB; ATI: not reported (NaN). */
    private final double totalMib;

    private GpuMemoryInfo(boolean nvx, double totalMib) {
        this.nvx = nvx;
        this.totalMib = totalMib;
    }

    /** The current context's reader, or empty where the driver reports no memory (llvmpipe among them). */
    public static Optional<GpuMemoryInfo> of() {
        GLCapabilities caps = GL.getCapabilities();
        if (caps.GL_NVX_gpu_memory_info) {
            return Optional.of(new GpuMemoryInfo(true, read(NVX_TOTAL_AVAILABLE_KIB) / KIB_PER_MIB));
        }
        if (caps.GL_ATI_meminfo) {
            return Optional.of(new GpuMemoryInfo(false, Double.NaN));
        }
        return Optional.empty();
    }

    /** The driver's total, MiB; empty where it reports only the free memory ({@code GL_ATI_meminfo}). */
    public Optional<Double> totalMib() {
        return nvx ? Optional.of(totalMib) : Optional.empty();
    }

    /** The memory free now, MiB: NVX's available dedicated memory, or ATI's free texture memory. */
    public double freeMib() {
        return read(nvx ? NVX_CURRENT_AVAILABLE_KIB : ATI_TEXTURE_FREE_MEMORY) / KIB_PER_MIB;
    }

    /** The first value of a query, KiB (ATI's queries answer four values, so the array holds four). */
    private static int read(int name) {
        int[] values = new int[4];
        glGetIntegerv(name, values);
        return values[0];
    }
}
