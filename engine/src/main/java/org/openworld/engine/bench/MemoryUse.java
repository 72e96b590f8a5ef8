package org.openworld.engine.bench;

import java.util.Locale;

/**
 * What a benchmark run held in memory ({@link MemoryMeter}), as stored in {@code summary.json}'s {@code memory}.
 * A value the machine does not report is null.
 *
 * @param heapPeakMib    the most Java heap in use (live objects and garbage not yet collected) at the end of a
 *                       recorded frame, MiB
 * @param heapAfterGcPeakMib the most Java heap in use just after a collection that ended during the recorded frames
 *                       (what the run held, with the old generation's garbage a young collection leaves), MiB; null
 *                       if no collection ended then, or in a file written before it was measured
 * @param rssPeakMib     the process's peak resident set size over its whole life, world building included
 *                       ({@code VmHWM} of {@code /proc/self/status}), MiB; null off Linux
 * @param gpuTotalMib    the GPU's dedicated memory ({@code GL_NVX_gpu_memory_info}), MiB; null where not reported
 * @param gpuUsedPeakMib the most of it in use at the end of a recorded frame, total - available, MiB; null where the
 *                       total is not reported
 * @param gpuFreeLowMib  the least GPU memory free at the end of a recorded frame (NVX's available memory, or
 *                       {@code GL_ATI_meminfo}'s free texture memory), MiB; null where the driver reports neither
 *                       (Mesa's llvmpipe)
 * @param texturePeakMib the most memory the engine's textures held at once over the context's whole life, world
 *                       building included, by the engine's own count ({@link org.openworld.engine.gl.TextureMemory}:
 *                       texels × bytes per texel over every level and layer), MiB; every driver has it; null in a
 *                       file written before it was counted
 * @param textureEndMib  what the engine's textures held at the end of the last recorded frame, same count, MiB
 */
public record MemoryUse(Double heapPeakMib, Double heapAfterGcPeakMib, Double rssPeakMib, Double gpuTotalMib,
                        Double gpuUsedPeakMib, Double gpuFreeLowMib, Double texturePeakMib, Double textureEndMib) {

    /**
     * One sentence for {@link Summary#describe()}, e.g. "Memory: heap peak 412 MiB (after a collection 150 MiB), RSS
     * peak 1210 MiB, textures peak 160 MiB, GPU ...".
     */
    public String describe() {
        StringBuilder s = new StringBuilder("Memory: heap peak ").append(mib(heapPeakMib));
        if (heapAfterGcPeakMib != null) {
            s.append(" (after a collection ").append(mib(heapAfterGcPeakMib)).append(')');
        }
        s.append(", RSS peak ").append(rssPeakMib == null ? "not reported by the system" : mib(rssPeakMib));
        if (texturePeakMib != null) {
            s.append(", textures peak ").append(mib(texturePeakMib));
        }
        if (gpuUsedPeakMib != null) {
            s.append(", GPU used peak ").append(mib(gpuUsedPeakMib)).append(" of ").append(mib(gpuTotalMib));
        } else if (gpuFreeLowMib != null) {
            s.append(", GPU free at least ").append(mib(gpuFreeLowMib));
        } else {
            s.append(", GPU memory not reported by the driver");
        }
        return s.append('.').toString();
    }

    private static String mib(Double value) {
        return value == null ? "?" : String.format(Locale.ROOT, "%.0f MiB", value);
    }
}
