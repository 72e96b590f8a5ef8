package org.openworld.engine.gl;

import org.openworld.engine.GlTest;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_2D;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glGetError;
import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_GROUP_STACK_DEPTH;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_SEVERITY_MEDIUM;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_SOURCE_SHADER_COMPILER;
import static org.lwjgl.opengl.GL43C.GL_DEBUG_TYPE_PERFORMANCE;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.openworld.engine.HeadlessGl;

/** KHR_debug on real GL (Mesa llvmpipe has it): driver messages as lines, object labels, groups around spans. */
@GlTest
class GlDebugTest {

    @RegisterExtension
    static final HeadlessGl GL = new HeadlessGl();

    /** A texture name no glGenTextures returned: binding it is GL_INVALID_OPERATION in a core profile. */
    private static final int NEVER_MADE = 987_654;

    @Test
    void theContextHasTheExtension() {
        assertTrue(GL.context().debug().available(), "llvmpipe and every GL 4.3 driver have KHR_debug");
    }

    @Test
    void aGlErrorIsPrintedAsOneReadableLine() {
        GlDebug debug = GL.context().debug();
        List<String> lines = new ArrayList<>();
        debug.printMessages(lines::add);
        try {
            glBindTexture(GL_TEXTURE_2D, NEVER_MADE);
        } finally {
            debug.printMessages(null);
        }
        glGetError(); // the error flag too, so the next test starts clean
        assertEquals(1, lines.size(), "one message for one bad call: " + lines);
        String line = lines.get(0);
        assertTrue(line.startsWith("GL error (api, high, id "), line);
        assertTrue(line.contains("): "), "the driver's own text follows: " + line);
        assertEquals(-1, line.indexOf('\n'), "one line");
    }

    @Test
    void afterOutputStopsNothingMoreIsPrinted() {
        GlDebug debug = GL.context().debug();
        List<String> lines = new ArrayList<>();
        debug.printMessages(lines::add);
        debug.printMessages(null);
        glBindTexture(GL_TEXTURE_2D, NEVER_MADE);
        glGetError();
        assertEquals(List.of(), lines);
    }

    @Test
    void labelsReadBackFromTheDriver() {
        try (Texture2D heights = Texture2D.empty(GL.context(), 4, 4, Format.R32F, Sampling.NEAREST_CLAMP);
             Framebuffer reflection = new Framebuffer(GL.context(), 8, 8, Format.RGBA8, Format.DEPTH32F,
                     Sampling.LINEAR_CLAMP)) {
            heights.label("terrain.heights");
            reflection.label("water.reflection");
            GlDebug debug = GL.context().debug();
            assertEquals("terrain.heights", debug.labelOf(GL_TEXTURE, heights.id()));
            assertEquals("water.reflection", debug.labelOf(GL_FRAMEBUFFER, reflection.id()));
            assertEquals("water.reflection.color", debug.labelOf(GL_TEXTURE, reflection.color().id()));
            assertEquals("water.reflection.depth", debug.labelOf(GL_TEXTURE, reflection.depth().id()));
        }
    }

    @Test
    void eachTimerSpanIsADebugGroup() {
        try (GpuTimers timers = new GpuTimers(GL.context())) {
            int outside = glGetInteger(GL_DEBUG_GROUP_STACK_DEPTH);
            timers.begin("main.terrain");
            int inside = glGetInteger(GL_DEBUG_GROUP_STACK_DEPTH);
            timers.end();
            timers.endFrame(0);
            timers.collect(true, (frame, ms) -> { });
            assertEquals(outside + 1, inside);
            assertEquals(outside, glGetInteger(GL_DEBUG_GROUP_STACK_DEPTH));
        }
    }

    @Test
    void aMessageNamesItsTypeSourceAndSeverityInWords() {
        assertEquals("GL performance (shader compiler, medium, id 7): recompiled",
                GlDebug.line(GL_DEBUG_SOURCE_SHADER_COMPILER, GL_DEBUG_TYPE_PERFORMANCE, 7,
                        GL_DEBUG_SEVERITY_MEDIUM, "recompiled\n"));
    }
}
