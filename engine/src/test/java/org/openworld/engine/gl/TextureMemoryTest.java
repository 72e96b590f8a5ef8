package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The texture memory count without a context: the bytes of a mip chain, and current and peak as storage comes and goes. */
class TextureMemoryTest {

    @Test
    void aSquareFullChainIsTheGeometricSeries() {
        // levels of 2^k × 2^k texels down to 1 × 1: 4^k + 4^(k−1) + ... + 1 = (4^(k+1) − 1) / 3, about 4/3 of level 0
        for (int k = 0; k <= 11; k++) {
            int size = 1 << k;
            long texels = ((1L << (2 * k + 2)) - 1) / 3;
            assertEquals(texels * 4, TextureMemory.bytes(Format.R32F, size, size, 1, k + 1), "R32F " + size + "²");
        }
    }

    @Test
    void aNarrowChainKeepsItsShortSideAtOneTexel() {
        // 8 × 2, 4 × 1, 2 × 1, 1 × 1: the height stops halving at 1 while the width goes on
        assertEquals(16 + 4 + 2 + 1, TextureMemory.bytes(Format.R8, 8, 2, 1, 4));
        assertEquals(TextureMemory.bytes(Format.R8, 8, 2, 1, 4), TextureMemory.bytes(Format.R8, 2, 8, 1, 4),
                "either way round");
    }

    @Test
    void layersAndTexelSizeMultiply() {
        long one = TextureMemory.bytes(Format.R8, 64, 32, 1, 3);
        assertEquals(6 * one * 6, TextureMemory.bytes(Format.RGB16F, 64, 32, 6, 3), "six faces of 6-byte texels");
        assertEquals(64 * 32 * 4, TextureMemory.bytes(Format.DEPTH24, 64, 32, 1, 1), "24-bit depth in 4 bytes");
    }

    @Test
    void thePeakStaysWhenStorageIsReleased() {
        TextureMemory memory = new TextureMemory();
        memory.allocated(300);
        memory.allocated(200);
        memory.released(300);
        memory.allocated(50);
        assertEquals(250, memory.bytes());
        assertEquals(500, memory.peakBytes());
        assertThrows(IllegalStateException.class, () -> memory.released(251), "more released than held");
    }
}
