package org.openworld.engine.gl;

import org.openworld.engine.GlTest;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL11C.GL_TEXTURE_2D;
import static org.lwjgl.opengl.GL11C.glBindTexture;
import static org.lwjgl.opengl.GL11C.glGetError;
import static org.lwjgl.opengl.GL11C.glGetInteger;
import static org.lwjgl.opengl.GL30C.GL_CONTEXT_FLAGS;
import static org.lwjgl.opengl.GL43C.GL_CONTEXT_FLAG_DEBUG_BIT;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/**
 * {@code --dev}'s context: a debug context whose driver messages go to stderr. Its own context, made and closed
 * here, so it does not share {@code HeadlessGl}'s.
 */
@GlTest
class DebugContextTest {

    @Test
    void aDebugContextPrintsAGlErrorOnStderr() {
        ByteArrayOutputStream captured = new ByteArrayOutputStream();
        PrintStream stderr = System.err;
        int flags;
        System.setErr(new PrintStream(captured, true, StandardCharsets.UTF_8));
        try (GlContext gl = GlContext.headless(true)) {
            flags = glGetInteger(GL_CONTEXT_FLAGS);
            glBindTexture(GL_TEXTURE_2D, 987_654); // never made: GL_INVALID_OPERATION
            glGetError();
        } finally {
            System.setErr(stderr);
        }
        String printed = captured.toString(StandardCharsets.UTF_8);
        assertTrue((flags & GL_CONTEXT_FLAG_DEBUG_BIT) != 0, "a debug context, flags " + flags);
        assertTrue(printed.startsWith("GL error (api, high, id "), "stderr: " + printed);
        assertEquals(1, printed.strip().lines().count(), "one line: " + printed);
    }
}
