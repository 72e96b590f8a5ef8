package org.openworld.demo;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferUShort;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.Callable;
import javax.imageio.ImageIO;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.XYSeries.XYSeriesRenderStyle;
import org.knowm.xchart.style.Styler.LegendPosition;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.openworld.engine.Engine;
import org.openworld.engine.elevation.ElevationImport;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.files.AtomicFiles;
import org.openworld.engine.gl.Image;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.PowerSpectrum;
import org.openworld.engine.terrain.material.SnowMap;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.UniformHeights;
import org.openworld.engine.erosion.ErodedWorld;
import org.openworld.engine.terrain.TerrainData;
import org.openworld.engine.terrain.heights.TerrainSettings;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code openworld heightmap}: makes the terrain data without OpenGL, as the terrain system would, and writes it as
 * pictures: {@code height.png} (16-bit grayscale, lowest sample black, highest white; it can be imported again with
 * {@code --set terrain.import-file=...}), {@code snow.png} (white where snow lies) and {@code spectrum.png} (the
 * radially averaged power spectrum on log-log axes with its fitted line). With {@code --repeat N} it is also the
 * generation benchmark: the median time of each stage over N runs and the peak heap. {@code --out} is checked before
 * the maps are made ({@link Outputs}), and each picture is written whole or not at all ({@link AtomicFiles#write}).
 * With {@code --overview} it pictures the unbounded world instead ({@link WorldOverview}).
 */
@Command(name = "heightmap", mixinStandardHelpOptions = true,
        description = "Generate (or import) the height map and snow map without OpenGL; write height.png (16-bit), "
                + "snow.png and spectrum.png, and time each stage. With --overview, picture 64 km of the unbounded "
                + "world instead.")
final class HeightmapCommand implements Callable<Integer> {

    @Mixin
    DevOption dev;

    static final String HEIGHT_PNG = "height.png";
    static final String SNOW_PNG = "snow.png";
    static final String SPECTRUM_PNG = "spectrum.png";

    /** Size of the spectrum chart, pixels. */
    private static final int CHART_WIDTH_PX = 900;
    private static final int CHART_HEIGHT_PX = 600;
    /** Largest 16-bit sample value: the highest height maps to it. */
    private static final int MAX_16_BIT = 65535;
    private static final double BYTES_PER_MIB = 1024.0 * 1024.0;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Output folder, created if missing.")
    Path out;

    @Option(names = "--seed", paramLabel = "N", converter = RenderOptions.SeedConverter.class,
            description = "World seed, 0 .. 2147483647; short for --set engine.seed=N (default: ${DEFAULT-VALUE}).",
            defaultValue = "1")
    int seed;

    @Option(names = "--set", paramLabel = "KEY=VALUE",
            description = "Change a setting, engine.* or terrain.* keys (e.g. terrain.size=4096); repeatable.")
    List<String> set = new ArrayList<>();

    @Option(names = "--repeat", paramLabel = "N",
            description = "Make the data N times and print each stage's median time and the peak heap "
                    + "(default: ${DEFAULT-VALUE}).", defaultValue = "1")
    int repeat;

    @Option(names = "--overview",
            description = "Instead of the tile, picture the unbounded world: 64 km x 64 km around the origin, 32 m "
                    + "between samples; writes height.png (16-bit) and relief.png (shaded relief).")
    boolean overview;

    @Option(names = "--stats",
            description = "Instead of the pictures, measure the drainage (concavity, Hack's exponent, hypsometric "
                    + "integral, slopes, drainage density) of the tile or import, or for the unbounded world of "
                    + "1024² samples around the origin; writes drainage.png (channels over shaded relief).")
    boolean stats;

    @Option(names = "--stats-level", paramLabel = "K",
            description = "Pyramid level measured by --stats: samples 2^K times terrain.spacing apart "
                    + "(default: ${DEFAULT-VALUE}, 8 m at the default spacing).", defaultValue = "2")
    int statsLevel;

    /** Side of the unbounded world's window that --stats measures, samples: 8 km at level 2. */
    private static final int STATS_WINDOW = 1024;

    @Override
    public Integer call() throws IOException {
        Settings settings = newSettings();
        settings.set("engine.seed", Integer.toString(seed));
        set.forEach(assignment -> apply(settings, assignment));
        TerrainSettings terrain = settings.get(TerrainSettings.class);
        int worldSeed = settings.get(EngineSettings.class).seed();
        if (repeat < 1) {
            throw new UserError("--repeat must be at least 1, got " + repeat);
        }
        if (stats) {
            return stats(terrain, worldSeed);
        }
        if (overview) {
            if (terrain.imports()) {
                throw new UserError("--overview pictures the generated unbounded world; it cannot show "
                        + "terrain.import-file");
            }
            if (repeat != 1) {
                throw new UserError("--overview makes the overview once; leave out --repeat");
            }
            if (terrain.world() == TerrainSettings.World.TILE) {
                throw new UserError("--overview pictures the unbounded world, not terrain.world=tile; leave out "
                        + "--overview to make the tile's maps");
            }
            Outputs.folder(out);
            Outputs.png(out.resolve(HEIGHT_PNG), false);
            Outputs.png(out.resolve(WorldOverview.RELIEF_PNG), false);
            return WorldOverview.write(terrain, worldSeed, out);
        }
        Outputs.folder(out);
        for (String name : List.of(HEIGHT_PNG, SNOW_PNG, SPECTRUM_PNG)) {
            Outputs.png(out.resolve(name), false);
        }

        Path importFile = Path.of(terrain.importFile());
        System.out.println(terrain.imports() && ElevationImport.handles(importFile)
                ? "heightmap: importing " + importFile + ": " + ElevationImport.describe(importFile, terrain, worldSeed)
                : terrain.imports()
                ? String.format(Locale.ROOT, "heightmap: importing %s, %s m between samples", terrain.importFile(),
                        terrain.spacing())
                : String.format(Locale.ROOT, "heightmap: %d² samples %s m apart (%s m across), beta %s, seed %d",
                        terrain.size(), terrain.spacing(), terrain.extent(), terrain.beta(), worldSeed));

        // 1. make the data, N times for the benchmark
        Map<String, double[]> stageMs = new LinkedHashMap<>();
        double[] totalMs = new double[repeat];
        long peakHeap = 0;
        TerrainData data = null;
        for (int run = 0; run < repeat; run++) {
            String prefix = repeat > 1 ? String.format(Locale.ROOT, "run %d/%d: ", run + 1, repeat) : "";
            data = null; // let the collector take the previous run's maps before measuring this one
            List<MemoryPoolMXBean> heapPools = resetHeapPeaks();
            StageTimes times = new StageTimes(stage -> System.out.printf(Locale.ROOT, "%s%-10s %8.0f ms%n", prefix,
                    stage.name(), stage.ms()));
            data = TerrainData.create(terrain, worldSeed, times);
            peakHeap = Math.max(peakHeap, heapPools.stream().mapToLong(p -> p.getPeakUsage().getUsed()).sum());
            for (StageTimes.Stage stage : times.stages()) {
                stageMs.computeIfAbsent(stage.name(), name -> new double[repeat])[run] = stage.ms();
            }
            totalMs[run] = times.totalMs();
        }
        if (repeat > 1) {
            System.out.printf(Locale.ROOT, "median of %d runs:%n", repeat);
            stageMs.forEach((name, ms) -> System.out.printf(Locale.ROOT, "  %-10s %8.0f ms%n", name, median(ms)));
            System.out.printf(Locale.ROOT, "  %-10s %8.0f ms%n", "total", median(totalMs));
        }
        System.out.printf(Locale.ROOT, "peak heap: %.0f MiB (sum of the heap pools' peaks%s)%n",
                peakHeap / BYTES_PER_MIB, repeat > 1 ? ", largest run" : "");

        HeightMap tile = data.pyramid().base();
        System.out.printf(Locale.ROOT, "tile: %d² samples %.2f m apart, %.2f km across, heights %.1f .. %.1f m%n",
                tile.size(), tile.spacing(), tile.extent() / 1000, tile.min(), tile.max());

        // 2. the spectrum and its slope: none for a map whose power lies in fewer than two rings (a regular
        // pattern such as a checkerboard of two heights, whose power is all at one frequency)
        HeightMap base = data.pyramid().base();
        PowerSpectrum spectrum = PowerSpectrum.of(base);
        // a generated map over the band it was synthesised in, unless the map is too small to hold two of its rings
        boolean band = !terrain.imports()
                && spectrum.ringsWithin(1 / terrain.maxWavelength(), 1 / terrain.minWavelength()) >= 2;
        int rings = spectrum.ringsWithin(0, Double.POSITIVE_INFINITY);
        Optional<PowerSpectrum.Fit> fit = band ? Optional.of(spectrum.fit(terrain))
                : rings >= 2 ? Optional.of(spectrum.fit(0, Double.POSITIVE_INFINITY)) : Optional.empty();
        if (fit.isEmpty()) {
            System.out.printf(Locale.ROOT, "spectrum slope: none: the map's power lies in %d ring(s) of the spectrum, "
                    + "too few for a line (a regular pattern, not a relief)%n", rings);
        } else if (terrain.imports()) {
            System.out.printf(Locale.ROOT, "spectrum slope: %.2f (power ~ 1/f^%.2f)%n", fit.get().slope(),
                    -fit.get().slope());
        } else if (band) {
            System.out.printf(Locale.ROOT, "spectrum slope: %.2f (expected -2 beta = %.2f)%n", fit.get().slope(),
                    -2 * terrain.beta());
        } else {
            System.out.printf(Locale.ROOT, "spectrum slope: %.2f over all rings: the band of %.0f-%.0f m holds fewer "
                    + "than two rings of this %.0f m map (expected -2 beta = %.2f)%n", fit.get().slope(),
                    terrain.minWavelength(), terrain.maxWavelength(), base.extent(), -2 * terrain.beta());
        }

        // 3. the pictures
        writeHeight(base.size(), base.heights(), out.resolve(HEIGHT_PNG));
        writeSnow(data.snow(), out.resolve(SNOW_PNG));
        BufferedImage spectrumChart = BitmapEncoder.getBufferedImage(chart(spectrum, fit, terrain));
        AtomicFiles.write(out.resolve(SPECTRUM_PNG), file -> ImageIO.write(spectrumChart, "png", file.toFile()));
        System.out.printf(Locale.ROOT, "snow covers %.1f %% of the map%n", 100 * data.snow().fraction());
        System.out.println("wrote " + out.resolve(HEIGHT_PNG) + ", " + out.resolve(SNOW_PNG) + ", "
                + out.resolve(SPECTRUM_PNG));
        return 0;
    }

    /** {@code --stats}: the drainage measures of the world that {@code terrain.world} names, or the import. */
    private int stats(TerrainSettings terrain, int worldSeed) throws IOException {
        if (overview || repeat != 1) {
            throw new UserError("--stats measures the world once; leave out --overview and --repeat");
        }
        if (statsLevel < 0) {
            throw new UserError("--stats-level must be 0 or more, got " + statsLevel);
        }
        Outputs.folder(out);
        Outputs.png(out.resolve(DrainageReport.DRAINAGE_PNG), false);
        if (terrain.world() == TerrainSettings.World.UNBOUNDED) {
            UniformHeights world = ErodedWorld.unbounded(terrain, worldSeed);
            if (statsLevel >= world.levels()) {
                throw new UserError("--stats-level " + statsLevel + ": the unbounded world has levels 0 to "
                        + (world.levels() - 1));
            }
            float[] h = world.level(statsLevel, -STATS_WINDOW / 2, -STATS_WINDOW / 2, STATS_WINDOW);
            DrainageReport.write(String.format(Locale.ROOT, "the unbounded world, level %d around the origin, seed %d",
                    statsLevel, worldSeed), h, STATS_WINDOW, world.spacing(statsLevel), out);
            return 0;
        }
        TerrainData data = TerrainData.create(terrain, worldSeed, new StageTimes(stage ->
                System.out.printf(Locale.ROOT, "%-10s %8.0f ms%n", stage.name(), stage.ms())));
        if (statsLevel >= data.pyramid().levelCount()) {
            throw new UserError("--stats-level " + statsLevel + ": the map has levels 0 to "
                    + (data.pyramid().levelCount() - 1));
        }
        HeightMap level = data.pyramid().level(statsLevel);
        DrainageReport.write(terrain.imports() ? terrain.importFile() + ", level " + statsLevel
                : String.format(Locale.ROOT, "the tile, level %d, seed %d", statsLevel, worldSeed), level.heights(),
                level.size(), level.spacing(), out);
        return 0;
    }

    /**
     * The settings this command reads, at their defaults: the world seed and the terrain group, checked the way
     * {@code Launch.settings} checks every group. No renderer's group, as the maps need no OpenGL.
     */
    /**
     * Applies one {@code --set}: a key of the renderer that {@code heightmap} does not build (a shadow, sky or water
     * key) is said to exist but not apply here, rather than be called unknown.
     */
    private static void apply(Settings settings, String assignment) {
        String key = assignment.substring(0, Math.max(0, assignment.indexOf('='))).trim();
        if (!settings.keys().contains(key) && Engine.settingsFor(DemoScene.systems()).keys().contains(key)) {
            throw new UserError("--set " + key + ": a setting of the renderer, which heightmap does not use; "
                    + "heightmap takes the engine.* and terrain.* keys");
        }
        settings.apply(assignment);
    }

    static Settings newSettings() {
        return new Settings(List.of(EngineSettings.GROUP, TerrainSettings.SETTINGS));
    }

    /**
     * Collects garbage, then resets and returns the heap pools, whose peaks then measure one run. The sum of the
     * pools' peaks is an upper bound of the true peak: the pools need not peak at the same moment.
     */
    static List<MemoryPoolMXBean> resetHeapPeaks() {
        System.gc();
        List<MemoryPoolMXBean> pools = ManagementFactory.getMemoryPoolMXBeans().stream()
                .filter(p -> p.getType() == MemoryType.HEAP).toList();
        pools.forEach(MemoryPoolMXBean::resetPeakUsage);
        return pools;
    }

    private static double median(double[] values) {
        double[] sorted = values.clone();
        Arrays.sort(sorted);
        int m = sorted.length / 2;
        return sorted.length % 2 == 1 ? sorted[m] : (sorted[m - 1] + sorted[m]) / 2;
    }

    /**
     * The n × n heights (row-major) as a 16-bit grayscale PNG, north (z = 0) at the top, lowest sample 0 and highest
     * 65535. stb_image_write writes 8 bits per channel only, and 256 levels would terrace the relief, so this one file
     * goes through {@code javax.imageio}, whose PNG writer takes a {@link BufferedImage#TYPE_USHORT_GRAY} image as
     * 16-bit gray.
     */
    static void writeHeight(int n, float[] h, Path file) throws IOException {
        BufferedImage image = new BufferedImage(n, n, BufferedImage.TYPE_USHORT_GRAY);
        short[] pixels = ((DataBufferUShort) image.getRaster().getDataBuffer()).getData();
        float min = Float.POSITIVE_INFINITY;
        float max = Float.NEGATIVE_INFINITY;
        for (float v : h) {
            min = Math.min(min, v);
            max = Math.max(max, v);
        }
        double scale = MAX_16_BIT / Math.max(max - (double) min, Double.MIN_NORMAL);
        for (int i = 0; i < h.length; i++) {
            pixels[i] = (short) Math.round((h[i] - min) * scale);
        }
        AtomicFiles.write(file, temp -> {
            if (!ImageIO.write(image, "png", temp.toFile())) {
                throw new IOException(file + ": no PNG writer for 16-bit gray");
            }
        });
    }

    /** The snow map as an 8-bit grayscale PNG through stb_image_write: white snow, black bare ground. */
    private static void writeSnow(SnowMap snow, Path file) throws IOException {
        AtomicFiles.write(file, Image.encodePng(file, snow.size(), snow.size(), 1, snow.coverage()));
    }

    /** Log-log chart: the rings' power, the fitted line if any and, for a generated map, the line of slope −2β. */
    private static XYChart chart(PowerSpectrum spectrum, Optional<PowerSpectrum.Fit> fitted, TerrainSettings terrain) {
        XYChart chart = new XYChartBuilder().width(CHART_WIDTH_PX).height(CHART_HEIGHT_PX)
                .title("Radially averaged power spectrum of the height map")
                .xAxisTitle("frequency (cycles/m)").yAxisTitle("mean |DFT|² per ring (m², unnormalised)").build();
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(LegendPosition.InsideSW);

        List<PowerSpectrum.Bin> bins = spectrum.bins().stream().filter(b -> b.power() > 0).toList();
        if (bins.isEmpty()) {
            chart.setTitle(chart.getTitle() + ": no ring holds power");
            return chart;
        }
        XYSeries rings = chart.addSeries("power per ring",
                bins.stream().mapToDouble(PowerSpectrum.Bin::frequency).toArray(),
                bins.stream().mapToDouble(PowerSpectrum.Bin::power).toArray());
        rings.setXYSeriesRenderStyle(XYSeriesRenderStyle.Scatter).setMarker(SeriesMarkers.CIRCLE);
        rings.setMarkerColor(new Color(0x0072B2));

        if (fitted.isEmpty()) {
            return chart;
        }
        PowerSpectrum.Fit fit = fitted.get();
        // the lines span the rings, or for a generated map the band between its cut-offs
        double lo = bins.get(0).frequency();
        double hi = bins.get(bins.size() - 1).frequency();
        if (!terrain.imports()) {
            lo = Math.max(lo, 1 / terrain.maxWavelength());
            hi = Math.min(hi, 1 / terrain.minWavelength());
        }
        line(chart, String.format(Locale.ROOT, "fit: slope %.2f", fit.slope()), lo, hi, fit, new Color(0xD55E00),
                new BasicStroke(2.5f));
        if (!terrain.imports()) {
            // the expected slope through the fit's value at the band's geometric middle
            double mid = Math.sqrt(lo * hi);
            double slope = -2 * terrain.beta();
            PowerSpectrum.Fit expected = new PowerSpectrum.Fit(slope,
                    Math.log10(fit.power(mid)) - slope * Math.log10(mid));
            line(chart, String.format(Locale.ROOT, "expected: slope -2 beta = %.2f", slope), lo, hi, expected,
                    new Color(0x009E73), new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
                            new float[] {8f, 5f}, 0));
        }
        return chart;
    }

    private static void line(XYChart chart, String name, double lo, double hi, PowerSpectrum.Fit fit, Color colour,
            BasicStroke stroke) {
        XYSeries series = chart.addSeries(name, new double[] {lo, hi}, new double[] {fit.power(lo), fit.power(hi)});
        series.setXYSeriesRenderStyle(XYSeriesRenderStyle.Line).setMarker(SeriesMarkers.NONE);
        series.setLineColor(colour);
        series.setLineStyle(stroke);
    }
}
