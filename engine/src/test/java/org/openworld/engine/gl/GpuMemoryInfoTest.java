package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.lwjgl.opengl.GL;
import org.openworld.engine.GlTest;
import org.openworld.engine.HeadlessGl;

/** The GPU memory reader on the real context: empty on a driver without the extensions, sane numbers with them. */
@GlTest
class GpuMemoryInfoTest {

    @RegisterExtension
    static final HeadlessGl GL_CONTEXT = new HeadlessGl();

    @Test
    void readsWhatTheDriverReportsAndNothingElse() {
        var caps = GL.getCapabilities();
        Optional<GpuMemoryInfo> info = GpuMemoryInfo.of();
        assertEquals(caps.GL_NVX_gpu_memory_info || caps.GL_ATI_meminfo, info.isPresent(),
                GL_CONTEXT.context().renderer());
        info.ifPresent(gpu -> {
            double free = gpu.freeMib();
            assertTrue(free > 0, "free " + free + " MiB");
            gpu.totalMib().ifPresent(total -> assertTrue(total >= free, "total " + total + " MiB, free " + free));
        });
        if (GL_CONTEXT.context().renderer().startsWith("llvmpipe")) {
            assertTrue(info.isEmpty(), "llvmpipe reports no GPU memory");
        }
    }
}
