package org.openworld.engine.bench;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.XYSeries.XYSeriesRenderStyle;
import org.knowm.xchart.style.Styler.LegendPosition;
import org.knowm.xchart.style.markers.SeriesMarkers;

import javax.imageio.ImageIO;
import java.awt.BasicStroke;
import java.awt.Color;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Map;

/**
 * Draws {@code frametime.png}: each frame's GPU time split by pass as stacked filled areas, with the frame time and
 * the CPU time as lines on top, so a spike can be traced to the pass (or the CPU) that caused it.
 *
 * <p>XChart has no stacked XY areas, so each pass's area is drawn from zero up to the <em>cumulative</em> sum of the
 * passes up to and including it, and the areas are added from the top of the stack down: each lower pass then paints
 * over the part of the taller areas below its own top. Drawn into a {@link java.awt.image.BufferedImage}, so it needs
 * no display ({@code -Djava.awt.headless=true} works).
 *
 * <p>A run longer than the chart is wide is drawn as its slowest frame per pixel column
 * ({@link #slowestPerColumn}): every spike stays, with the passes that made it, and the chart costs the same for
 * ten thousand frames as for {@value #WIDTH_PX}, about 0.5 s warm (1.5 s with Java2D's first use) on the project's
 * 2-core machine, so a run stopped by a signal is written in well under the stop's limit. frames.csv keeps every
 * frame.
 */
public final class FrameTimeChart {

    /** Image width, pixels: about one pixel per frame for a typical 1000-frame run. */
    public static final int WIDTH_PX = 1200;
    /** Image height, pixels. */
    public static final int HEIGHT_PX = 600;

    /** Width of the frame and CPU time lines, pixels. */
    private static final float LINE_WIDTH_PX = 1.5f;
    /** Dash and gap lengths of the CPU time line, pixels. */
    private static final float[] CPU_DASH_PX = {6f, 4f};
    /**
     * Pass colours, cycled by pass order: the Okabe-Ito palette, told apart with colour-blindness too. Opaque, so a
     * lower area hides the taller ones instead of blending into a new colour.
     */
    private static final Color[] PASS_COLOURS = {
            new Color(0xE69F00), new Color(0x56B4E9), new Color(0x009E73), new Color(0xF0E442),
            new Color(0x0072B2), new Color(0xD55E00), new Color(0xCC79A7)};

    private FrameTimeChart() {
    }

    /** Draws the chart of a run and writes it as a PNG to {@code file}, replacing it. */
    public static void write(RunInfo run, List<FrameRecord> frames, Path file) throws IOException {
        ImageIO.write(BitmapEncoder.getBufferedImage(chart(run, frames)), "png", file.toFile());
    }

    /** The chart of a run, for callers that want to show or restyle it. */
    public static XYChart chart(RunInfo run, List<FrameRecord> frames) {
        XYChart chart = new XYChartBuilder().width(WIDTH_PX).height(HEIGHT_PX)
                .title("Frame time: " + run.renderer() + ", " + run.width() + "x" + run.height())
                .xAxisTitle("frame").yAxisTitle("time (ms)").build();
        chart.getStyler().setLegendPosition(LegendPosition.OutsideE);
        chart.getStyler().setYAxisMin(0.0);

        frames = slowestPerColumn(frames);
        double[] x = frames.stream().mapToDouble(FrameRecord::frame).toArray();

        // 1. cumulative GPU time: stack[p][i] = sum of passes 0..p in frame i (a pass missing in a frame costs 0)
        List<String> passes = FrameColumns.PASS_GPU_MS.names(frames);
        double[][] stack = new double[passes.size()][frames.size()];
        for (int i = 0; i < frames.size(); i++) {
            double sum = 0;
            for (int p = 0; p < passes.size(); p++) {
                sum += frames.get(i).passGpuMs().getOrDefault(passes.get(p), 0.0);
                stack[p][i] = sum;
            }
        }

        // 2. areas from the top of the stack down, so each lower pass paints over the taller ones
        for (int p = passes.size() - 1; p >= 0; p--) {
            Color colour = PASS_COLOURS[p % PASS_COLOURS.length];
            XYSeries area = chart.addSeries("GPU " + passes.get(p), x, stack[p]);
            area.setXYSeriesRenderStyle(XYSeriesRenderStyle.Area).setMarker(SeriesMarkers.NONE);
            area.setFillColor(colour);
            area.setLineColor(colour);
        }

        // 3. frame time (wall-clock interval) and CPU time as lines over the areas
        line(chart, "frame time", x, frames.stream().mapToDouble(FrameRecord::frameMs).toArray(), Color.BLACK,
                new BasicStroke(LINE_WIDTH_PX));
        line(chart, "CPU", x, frames.stream().mapToDouble(FrameRecord::cpuMs).toArray(), Color.DARK_GRAY,
                new BasicStroke(LINE_WIDTH_PX, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 1f, CPU_DASH_PX, 0f));
        return chart;
    }

    /**
     * Draws a small chart on a daemon thread and throws it away: Java2D's first use (its classes, the fonts) takes
     * about a second, several on a loaded machine, and a run stopped by a signal should not spend the stop's time
     * on it. Called before a run's frames, it overlaps the world's building.
     */
    public static void warmUpInBackground() {
        RunInfo none = new RunInfo("", "", "", 1, 1, 0, Map.of(), "", 0, false);
        FrameRecord frame = new FrameRecord(0, 0, 1, 1, Map.of("", 1.0), Map.of("", 1.0), 0, 0,
                Map.of());
        Thread warmUp = new Thread(() -> BitmapEncoder.getBufferedImage(chart(none, List.of(frame, frame))),
                "frametime-chart-warm-up");
        warmUp.setDaemon(true);
        warmUp.start();
    }

    /**
     * At most {@value #WIDTH_PX} frames, one per pixel column: of each column's consecutive frames the one with the
     * longest frame time, so the drawn line reaches every spike. Drawing more points than columns adds nothing to
     * the picture and costs time in proportion.
     */
    static List<FrameRecord> slowestPerColumn(List<FrameRecord> frames) {
        if (frames.size() <= WIDTH_PX) {
            return frames;
        }
        List<FrameRecord> kept = new ArrayList<>(WIDTH_PX);
        for (int column = 0; column < WIDTH_PX; column++) {
            int from = (int) ((long) column * frames.size() / WIDTH_PX);
            int to = (int) ((long) (column + 1) * frames.size() / WIDTH_PX);
            kept.add(frames.subList(from, to).stream().max(Comparator.comparingDouble(FrameRecord::frameMs))
                    .orElseThrow());
        }
        return kept;
    }

    private static void line(XYChart chart, String name, double[] x, double[] y, Color color, BasicStroke stroke) {
        XYSeries series = chart.addSeries(name, x, y);
        series.setXYSeriesRenderStyle(XYSeriesRenderStyle.Line).setMarker(SeriesMarkers.NONE);
        series.setLineColor(color).setLineStyle(stroke);
    }
}
