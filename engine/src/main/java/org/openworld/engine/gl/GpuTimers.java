package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL15C.*;
import static org.lwjgl.opengl.GL33C.GL_TIME_ELAPSED;
import static org.lwjgl.opengl.GL33C.glGetQueryObjectui64;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import org.lwjgl.opengl.GL15C;

/**
 * GPU time per labelled span (one span per system in each pass), from {@code GL_TIME_ELAPSED} queries.
 *
 * <p>The GPU runs a frame or two behind the CPU, so results are read when they are available, not when the span
 * ends: asking at once would stall the pipeline. Spans are grouped by frame; {@link #collect} hands over every
 * finished frame in order, and {@code collect(true)} waits for all (end of a benchmark). Spans cannot nest, as
 * timer queries cannot. Each span is also a {@code KHR_debug} group of the same label ({@code main.terrain}), so a
 * capture in RenderDoc or Nsight is grouped as the timings are.
 */
public final class GpuTimers implements AutoCloseable {

    private record Span(String label, int query) {
    }

    private record PendingFrame(long frame, List<Span> spans) {
    }

    private final GlContext gl;
    private final Deque<Integer> free = new ArrayDeque<>();
    private final Deque<PendingFrame> pending = new ArrayDeque<>();
    private List<Span> current = new ArrayList<>();
    private int created;

    public GpuTimers(GlContext gl) {
        this.gl = gl;
    }

    /** Opens a span, and a debug group of the same label ({@link GlDebug#pushGroup}) for GPU debuggers. */
    public void begin(String label) {
        int query = free.isEmpty() ? newQuery() : free.pop();
        current.add(new Span(label, query));
        gl.debug().pushGroup(label);
        glBeginQuery(GL_TIME_ELAPSED, query);
    }

    /** Closes the open span and its debug group. */
    public void end() {
        glEndQuery(GL_TIME_ELAPSED);
        gl.debug().popGroup();
    }

    /** Closes the current frame's group of spans. */
    public void endFrame(long frame) {
        pending.add(new PendingFrame(frame, current));
        current = new ArrayList<>();
    }

    /**
     * Hands over the GPU milliseconds per label of every finished frame, oldest first.
     *
     * @param wait true to wait for every pending frame (at the end of a run)
     */
    public void collect(boolean wait, BiConsumer<Long, Map<String, Double>> frameTimes) {
        while (!pending.isEmpty()) {
            PendingFrame oldest = pending.peek();
            List<Span> spans = oldest.spans();
            if (!wait && !spans.isEmpty()
                    && glGetQueryObjecti(spans.get(spans.size() - 1).query(), GL_QUERY_RESULT_AVAILABLE) == GL_FALSE) {
                return;
            }
            pending.pop();
            Map<String, Double> ms = new LinkedHashMap<>();
            for (Span span : spans) {
                long ns = glGetQueryObjectui64(span.query(), GL_QUERY_RESULT);
                ms.merge(span.label(), ns / 1e6, Double::sum);
                free.push(span.query());
            }
            frameTimes.accept(oldest.frame(), ms);
        }
    }

    private int newQuery() {
        created++;
        return gl.objects().create(GlObjects.Kind.QUERY, GL15C::glGenQueries);
    }

    @Override
    public void close() {
        pending.forEach(f -> f.spans().forEach(s -> free.push(s.query())));
        current.forEach(s -> free.push(s.query()));
        pending.clear();
        current.clear();
        while (!free.isEmpty()) {
            gl.objects().delete(GlObjects.Kind.QUERY, free.pop(), GL15C::glDeleteQueries);
            created--;
        }
        if (created != 0) {
            throw new IllegalStateException(created + " timer queries lost track of");
        }
    }
}
