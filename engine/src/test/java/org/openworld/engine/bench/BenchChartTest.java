package org.openworld.engine.bench;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.knowm.xchart.XYChart;

import javax.imageio.ImageIO;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

class BenchChartTest {

    /** A chart with axes, text, two filled areas and two lines has far more colours than this. */
    private static final int MIN_DISTINCT_COLOURS = 8;

    @TempDir
    Path dir;

    @Test
    void reportWritesAPngOfTheChartSizeThatIsNotBlank() throws IOException {
        BenchReport.write(BenchFrames.RUN, BenchFrames.threeFrames(), BenchFrames.MEMORY, dir, true);
        Path png = dir.resolve(BenchReport.FRAMETIME_PNG);
        assertTrue(Files.isRegularFile(png));

        BufferedImage image = ImageIO.read(png.toFile());
        assertNotNull(image, "not a readable image: " + png);
        assertEquals(FrameTimeChart.WIDTH_PX, image.getWidth());
        assertEquals(FrameTimeChart.HEIGHT_PX, image.getHeight());

        Set<Integer> colours = new HashSet<>();
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                colours.add(image.getRGB(x, y));
            }
        }
        assertTrue(colours.size() >= MIN_DISTINCT_COLOURS, "only " + colours.size() + " colours");
    }

    @Test
    void passAreasAreCumulativeSoTheyStack() {
        XYChart chart = FrameTimeChart.chart(BenchFrames.RUN, BenchFrames.threeFrames());
        // terrain is the bottom of the stack; water sits on it (absent in frame 0, so it adds 0 there)
        assertArrayEquals(new double[] {3, 4, 5}, chart.getSeriesMap().get("GPU terrain").getYData());
        assertArrayEquals(new double[] {3, 6, 8}, chart.getSeriesMap().get("GPU water").getYData());
        assertArrayEquals(new double[] {5, 6, 8}, chart.getSeriesMap().get("frame time").getYData());
        assertTrue(chart.getTitle().contains("test renderer") && chart.getTitle().contains("640x360"));
    }

    @Test
    void aLongRunIsDrawnAsItsSlowestFramePerColumnSoItCostsNoMoreThanAShortOne() {
        // ten frames per column, frame times rising 0..9 ms within each column, and one spike of 1000 ms
        int frames = FrameTimeChart.WIDTH_PX * 10;
        int spike = 4321;
        List<FrameRecord> run = new ArrayList<>();
        for (int i = 0; i < frames; i++) {
            double ms = i == spike ? 1000 : i % 10;
            run.add(new FrameRecord(i, i / 60.0, ms, ms / 2, Map.of("terrain", ms / 2), Map.of("terrain", ms / 2),
                    1000, 10, Map.of()));
        }
        XYChart chart = FrameTimeChart.chart(BenchFrames.RUN, run);
        for (var series : chart.getSeriesMap().values()) {
            assertEquals(FrameTimeChart.WIDTH_PX, series.getXData().length, series.getName());
        }
        double[] frameTimes = chart.getSeriesMap().get("frame time").getYData();
        assertEquals(1000, Arrays.stream(frameTimes).max().orElseThrow(), "the spike is drawn");
        assertEquals(9, frameTimes[0], "each column shows its slowest frame");
        assertEquals(spike, chart.getSeriesMap().get("frame time").getXData()[spike / 10], "at its own frame");
    }
}
