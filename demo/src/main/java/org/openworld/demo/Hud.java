package org.openworld.demo;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;
import java.util.Map;
import java.util.TreeMap;
import org.openworld.engine.bench.FrameRecord;

/**
 * The heads-up display (Dear ImGui, F3 toggles it): the frame rate, a graph of the last frames' times, each pass's
 * GPU time per system, triangles and draw calls, and every counter the systems report (visible and culled terrain
 * patches, culling tests, flakes...). The numbers are those {@code openworld bench} records, from the same
 * {@link FrameRecord}s.
 */
final class Hud {

    /** Frames the graph spans: four seconds at 60 fps. */
    static final int GRAPH_FRAMES = 240;
    /** Size of the graph, pixels. */
    private static final float GRAPH_WIDTH_PX = 300;
    private static final float GRAPH_HEIGHT_PX = 60;
    /** The graph's scale never drops below this, milliseconds, so a steady 60 fps does not fill it. */
    private static final float GRAPH_MIN_SCALE_MS = 20;
    /** Distance from the picture's right edge, pixels. */
    private static final float MARGIN_PX = 10;

    private final FrameHistory history = new FrameHistory(GRAPH_FRAMES);

    /** Takes a finished frame's record. */
    void add(FrameRecord record) {
        history.add(record);
    }

    /** Draws the HUD window at the top right; call between {@code ImGui.newFrame} and {@code ImGui.render}. */
    void draw() {
        ImGui.setNextWindowPos(ImGui.getIO().getDisplaySizeX() - MARGIN_PX, MARGIN_PX, ImGuiCond.Always, 1, 0);
        ImGui.setNextWindowBgAlpha(0.6f);
        int flags = ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoNav
                | ImGuiWindowFlags.NoFocusOnAppearing | ImGuiWindowFlags.NoSavedSettings;
        if (ImGui.begin("HUD", flags)) {
            if (history.latest().isEmpty()) {
                ImGui.text("waiting for the first frame's timings");
            } else {
                drawNumbers(history.latest().get());
            }
        }
        ImGui.end();
    }

    private void drawNumbers(FrameRecord r) {
        ImGui.text(String.format("%.0f fps   %.1f ms a frame (mean of %d)", history.fps(), history.meanFrameMs(),
                history.frameMs().length));
        float[] ms = history.frameMs();
        float scale = Math.max(GRAPH_MIN_SCALE_MS, (float) history.maxFrameMs());
        ImGui.plotLines("##frames", ms, ms.length, 0, String.format("frame time, 0 .. %.0f ms", scale), 0, scale,
                GRAPH_WIDTH_PX, GRAPH_HEIGHT_PX);
        ImGui.text(String.format("%,d triangles   %,d draw calls   CPU %.1f ms", r.triangles(), r.drawCalls(),
                r.cpuMs()));
        ImGui.separator();
        ImGui.text("GPU time by pass.system (ms)");
        r.passGpuMs().forEach((span, gpuMs) -> ImGui.text(String.format("  %-24s %6.2f", span, gpuMs)));
        ImGui.separator();
        ImGui.text("counters");
        Map<String, Double> sorted = new TreeMap<>(r.counters());
        sorted.forEach((name, value) -> ImGui.text(String.format("  %-24s %8s", name,
                value == Math.rint(value) ? String.format("%,d", value.longValue()) : String.format("%.2f", value))));
    }
}
