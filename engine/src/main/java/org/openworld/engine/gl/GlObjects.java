package org.openworld.engine.gl;

import java.util.EnumMap;
import java.util.Map;
import java.util.function.IntConsumer;
import java.util.function.IntSupplier;

/**
 * Counts the live GL objects of one context by kind. Every wrapper in this package registers on creation and
 * unregisters on {@code close()}, so a test can assert that a full start-up and shutdown leaves {@link #live()} at zero.
 */
public final class GlObjects {

    /** The kinds of GL object the engine creates. */
    public enum Kind { PROGRAM, SHADER, BUFFER, VERTEX_ARRAY, TEXTURE, FRAMEBUFFER, RENDERBUFFER, QUERY, SYNC }

    private final Map<Kind, Integer> live = new EnumMap<>(Kind.class);

    /** Makes one GL name with {@code glGen} (e.g. {@code glGenTextures}) and counts it. */
    int create(Kind kind, IntSupplier glGen) {
        int name = glGen.getAsInt();
        created(kind);
        return name;
    }

    /**
     * Deletes one GL name with {@code glDelete} (e.g. {@code glDeleteTextures}) and counts it, unless it is 0 (never
     * made, or deleted already); returns 0 for the owner to keep, so closing twice deletes once:
     * {@code id = gl.objects().delete(Kind.TEXTURE, id, GL11C::glDeleteTextures)}.
     */
    int delete(Kind kind, int name, IntConsumer glDelete) {
        if (name != 0) {
            glDelete.accept(name);
            deleted(kind);
        }
        return 0;
    }

    void created(Kind kind) {
        live.merge(kind, 1, Integer::sum);
    }

    void deleted(Kind kind) {
        int left = live.getOrDefault(kind, 0) - 1;
        if (left < 0) {
            throw new IllegalStateException("GL " + kind + " deleted more often than created");
        }
        live.put(kind, left);
    }

    /** Live objects of every kind together. */
    public int live() {
        return live.values().stream().mapToInt(Integer::intValue).sum();
    }

    /** Live objects of one kind. */
    public int live(Kind kind) {
        return live.getOrDefault(kind, 0);
    }

    @Override
    public String toString() {
        StringBuilder s = new StringBuilder();
        live.forEach((k, n) -> { if (n > 0) s.append(s.length() == 0 ? "" : ", ").append(n).append(' ').append(k); });
        return s.length() == 0 ? "none" : s.toString();
    }
}
