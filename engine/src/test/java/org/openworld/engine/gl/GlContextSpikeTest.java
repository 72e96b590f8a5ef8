package org.openworld.engine.gl;

import static org.junit.jupiter.api.Assertions.*;
import org.junit.jupiter.api.Test;

class GlContextSpikeTest {
    @Test
    void headless() {
        try (GlContext gl = GlContext.headless()) {
            System.out.println(gl.mode() + " " + gl.renderer() + " " + gl.version());
            assertTrue(gl.versionAtLeast(3, 3));
        }
    }
}
