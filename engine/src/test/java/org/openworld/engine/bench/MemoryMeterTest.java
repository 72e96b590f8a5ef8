package org.openworld.engine.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.openworld.engine.gl.TextureMemory;

class MemoryMeterTest {

    @Test
    void thePeakResidentSetIsReadFromVmHwmInKibibytes() {
        String status = "Name:\tjava\nVmPeak:\t 9000000 kB\nVmHWM:\t  1048576 kB\nVmRSS:\t  524288 kB\n";
        assertEquals(1024.0, MemoryMeter.vmHwmMib(status));
        assertNull(MemoryMeter.vmHwmMib("Name:\tjava\nVmRSS:\t  524288 kB\n"));
    }

    /** A collection ended while 32 MiB were held: the heap after it holds them, and the figure is the largest seen. */
    @Test
    void theHeapAfterACollectionHoldsWhatIsHeld() {
        MemoryMeter meter = new MemoryMeter(Optional.empty(), new TextureMemory());
        long[] held = new long[32 * 1024 * 1024 / 8];
        System.gc();
        meter.sample();
        double withArray = meter.result().heapAfterGcPeakMib();
        assertTrue(withArray >= 32, () -> "heap after a collection " + withArray + " MiB with 32 MiB held");
        assertEquals(held.length, 4 * 1024 * 1024);
        held = null;
        System.gc();
        meter.sample();
        assertEquals(withArray, meter.result().heapAfterGcPeakMib(), "the peak stays when the array is let go");
    }

    @Test
    void theHeapPeakCoversAnArrayHeldAtASampleAndNoGpuMeansNulls() {
        MemoryMeter meter = new MemoryMeter(Optional.empty(), new TextureMemory());
        assertNull(meter.result().textureEndMib(), "no texture figure before the first sample");
        meter.sample();
        long[] held = new long[32 * 1024 * 1024 / 8]; // 32 MiB alive at the next sample
        meter.sample();
        MemoryUse use = meter.result();
        assertTrue(use.heapPeakMib() >= 32, () -> "heap peak " + use.heapPeakMib() + " MiB with 32 MiB held");
        assertEquals(held.length, 4 * 1024 * 1024);
        assertNull(use.gpuTotalMib());
        assertNull(use.gpuUsedPeakMib());
        assertNull(use.gpuFreeLowMib());
        assertEquals(0.0, use.texturePeakMib(), "no texture made");
        assertEquals(0.0, use.textureEndMib(), "no texture made");
        if (System.getProperty("os.name").equals("Linux")) {
            // the array was written (zeroed) when made, so its pages were resident
            assertTrue(use.rssPeakMib() >= 32, () -> "RSS peak " + use.rssPeakMib() + " MiB with 32 MiB held");
        }
    }
}
