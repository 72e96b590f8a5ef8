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

    /** The counters the HUD shows on their own lines (every counter is in the list below them). */
    private static final String PATCHES_DRAWN = "terrain.main.patches";
    private static final String PATCHES_CULLED = "terrain.main.culled";
    private static final String NODES_TESTED = "culling.main.tested";
    private static final String NODES_OUTSIDE = "culling.main.outside";
    private static final String NODES_INSIDE = "culling.main.inside";

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
        Map<String, Double> c = r.counters();
        if (c.containsKey(PATCHES_DRAWN)) {
            ImGui.text(String.format("terrain patches: %,d drawn, %,d culled (main view)",
                    c.get(PATCHES_DRAWN).longValue(), c.getOrDefault(PATCHES_CULLED, 0.0).longValue()));
        }
        if (c.containsKey(NODES_TESTED)) {
            ImGui.text(String.format("culling nodes: %,d tested, %,d outside, %,d inside (main view)",
                    c.get(NODES_TESTED).longValue(), c.getOrDefault(NODES_OUTSIDE, 0.0).longValue(),
                    c.getOrDefault(NODES_INSIDE, 0.0).longValue()));
        }
        ImGui.separator();
        ImGui.text("GPU time by pass (ms)");
        FrameHistory.passTotals(r.passGpuMs()).forEach((pass, gpuMs) ->
                ImGui.text(String.format("  %-24s %7.2f", pass, gpuMs)));
        if (ImGui.treeNode("by pass.system")) {
            r.passGpuMs().forEach((span, gpuMs) -> ImGui.text(String.format("%-24s %7.2f", span, gpuMs)));
            ImGui.treePop();
        }
        ImGui.separator();
        if (ImGui.treeNode("every counter")) {
            Map<String, Double> sorted = new TreeMap<>(c);
            sorted.forEach((name, value) -> ImGui.text(String.format("%-28s %10s", name, value == Math.rint(value)
                    ? String.format("%,d", value.longValue()) : String.format("%.2f", value))));
            ImGui.treePop();
        }
    }
}
