package org.openworld.engine.bench;

import com.sun.management.GarbageCollectorMXBean;
import com.sun.management.GcInfo;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Collectors;
import org.openworld.engine.gl.GpuMemoryInfo;
import org.openworld.engine.gl.TextureMemory;

/**
 * Measures a benchmark run's memory ({@link MemoryUse}): {@link #sample()} after each recorded frame reads the Java
 * heap in use, the GPU memory free and the engine's own count of its texture memory ({@link TextureMemory}), keeping
 * the extremes and the last texture figure; {@link #result()} adds the process's peak resident set size, which Linux
 * keeps itself ({@code VmHWM}), and the texture count's peak, which the count keeps itself at every texture made.
 *
 * <p>The heap is sampled, not watched: its use between two samples (garbage made and collected within a frame) is
 * not seen, so the peak is the largest heap at a frame's end. With a collector that runs when the young generation
 * fills, that is close to the true peak, since garbage piles up over several frames before each collection. That
 * peak moves with how much garbage the collector lets pile up (a longer run grows its young generation), so the meter
 * also keeps the most heap in use just after a collection ({@code GcInfo}'s usage after it, summed over the heap's
 * pools): what the run holds, plus the old generation's garbage a young collection leaves. Cost: a few reads per
 * frame, an allocation only after a collection, no GPU wait.
 */
public final class MemoryMeter {

    private static final double BYTES_PER_MIB = 1024.0 * 1024.0;
    private static final Path PROC_STATUS = Path.of("/proc/self/status");

    private final MemoryMXBean heap = ManagementFactory.getMemoryMXBean();
    private final List<GarbageCollectorMXBean> collectors = ManagementFactory.getGarbageCollectorMXBeans().stream()
            .filter(GarbageCollectorMXBean.class::isInstance).map(GarbageCollectorMXBean.class::cast).toList();
    private final Set<String> heapPools = ManagementFactory.getMemoryPoolMXBeans().stream()
            .filter(p -> p.getType() == MemoryType.HEAP).map(MemoryPoolMXBean::getName).collect(Collectors.toSet());
    /** Per collector, the id of the last collection read; -1 before any. */
    private final long[] collectionSeen;
    private final Optional<GpuMemoryInfo> gpu;
    private final TextureMemory textures;
    private double heapPeakMib;
    private Double heapAfterGcPeakMib;
    private double gpuFreeLowMib = Double.POSITIVE_INFINITY;
    private Double textureEndMib;

    /**
     * @param gpu      the context's GPU memory reader, empty where the driver reports none
     * @param textures the context's count of its texture memory
     */
    public MemoryMeter(Optional<GpuMemoryInfo> gpu, TextureMemory textures) {
        this.gpu = gpu;
        this.textures = textures;
        collectionSeen = new long[collectors.size()];
        Arrays.fill(collectionSeen, -1);
    }

    /**
     * Reads the heap in use, the GPU memory free and the texture memory held now; call at the end of each recorded
     * frame.
     */
    public void sample() {
        heapPeakMib = Math.max(heapPeakMib, heap.getHeapMemoryUsage().getUsed() / BYTES_PER_MIB);
        for (int i = 0; i < collectors.size(); i++) {
            GcInfo last = collectors.get(i).getLastGcInfo();
            if (last != null && last.getId() != collectionSeen[i]) {
                collectionSeen[i] = last.getId();
                double after = last.getMemoryUsageAfterGc().entrySet().stream()
                        .filter(e -> heapPools.contains(e.getKey())).mapToLong(e -> e.getValue().getUsed()).sum()
                        / BYTES_PER_MIB;
                heapAfterGcPeakMib = heapAfterGcPeakMib == null ? after : Math.max(heapAfterGcPeakMib, after);
            }
        }
        gpu.ifPresent(g -> gpuFreeLowMib = Math.min(gpuFreeLowMib, g.freeMib()));
        textureEndMib = textures.bytes() / BYTES_PER_MIB;
    }

    /**
     * The run's memory: the extremes of the samples so far, the texture memory at the last sample (null before the
     * first), and the process's and the texture count's peaks now.
     */
    public MemoryUse result() {
        Double total = gpu.flatMap(GpuMemoryInfo::totalMib).orElse(null);
        Double freeLow = gpu.isPresent() && gpuFreeLowMib != Double.POSITIVE_INFINITY ? gpuFreeLowMib : null;
        Double usedPeak = total != null && freeLow != null ? total - freeLow : null;
        return new MemoryUse(heapPeakMib, heapAfterGcPeakMib, rssPeakMib(), total, usedPeak, freeLow,
                textures.peakBytes() / BYTES_PER_MIB, textureEndMib);
    }

    /** {@code VmHWM} of {@code /proc/self/status}, MiB; null where there is no such file (not Linux). */
    private static Double rssPeakMib() {
        try {
            return Files.isReadable(PROC_STATUS) ? vmHwmMib(Files.readString(PROC_STATUS)) : null;
        } catch (IOException e) {
            return null;
        }
    }

    /**
     * The peak resident set size in a {@code /proc/PID/status} text, MiB: its line {@code VmHWM:   123456 kB}
     * (kibibytes, whatever the unit's spelling says); null if the text has no such line.
     */
    static Double vmHwmMib(String status) {
        return status.lines().filter(line -> line.startsWith("VmHWM:")).findFirst()
                .map(line -> Long.parseLong(line.substring("VmHWM:".length()).replace("kB", "").strip()) / 1024.0)
                .orElse(null);
    }
}
