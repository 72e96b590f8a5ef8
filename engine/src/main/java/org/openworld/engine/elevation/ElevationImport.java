package org.openworld.engine.elevation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Optional;
import org.openworld.engine.terrain.heights.HeightImport;
import org.openworld.engine.terrain.heights.HeightImportException;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * Imports a real elevation model (the package comment says how): a GeoTIFF, or a 16-bit PNG or raw float32 file with
 * a JSON {@link Sidecar}. Other files go to {@link HeightImport} (square 2^n maps, normalised).
 */
public final class ElevationImport {

    /** Bytes a model's sample takes while read: the decoded raster and the float grid made of it. */
    static final int BYTES_PER_MODEL_SAMPLE = 8;

    private ElevationImport() {
    }

    /** Whether this package reads {@code file}: a TIFF, or a PNG or raw file with a sidecar. */
    public static boolean handles(Path file) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        return name.endsWith(".tif") || name.endsWith(".tiff") || name.contains(".") && Sidecar.of(file).isPresent();
    }

    /**
     * Reads, fills and embeds the model {@code file}: the tile the terrain draws.
     *
     * @throws HeightImportException naming the file and what is wrong with it
     */
    public static HeightMap read(Path file, TerrainSettings s, int seed) {
        return TileEmbedding.embed(file, grid(file, s), s, seed, availableHeap());
    }

    /** One line saying what {@code file} holds and the tile it becomes, without making the tile. */
    public static String describe(Path file, TerrainSettings s, int seed) {
        ElevationGrid grid = grid(file, s);
        return TileEmbedding.describe(grid, TileEmbedding.plan(file, grid, s, seed, availableHeap()), s);
    }

    /** The model as its file holds it, no-data filled, before it becomes the tile. */
    public static ElevationGrid grid(Path file, TerrainSettings s) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!Files.isRegularFile(file)) {
            throw new HeightImportException(file + ": no such file");
        }
        long heap = availableHeap();
        ElevationGrid grid;
        if (name.endsWith(".tif") || name.endsWith(".tiff")) {
            grid = GeoTiff.read(file, s.importScale(), s.spacing(), heap);
        } else {
            Optional<Path> sidecar = Sidecar.of(file);
            if (sidecar.isEmpty()) {
                throw new HeightImportException(file + ": no sidecar " + name.replaceAll("\\.[^.]*$", ".json")
                        + " beside it to give its spacing");
            }
            try {
                grid = Sidecar.read(file, sidecar.get(), name.endsWith(".png"), heap);
            } catch (IOException e) {
                throw new HeightImportException(file + ": cannot be read: " + e.getMessage());
            }
        }
        try {
            grid.fillNoData();
        } catch (IllegalStateException e) {
            throw new HeightImportException(file + ": every sample is no-data");
        }
        return grid;
    }

    /** Refuses a model of w × h samples that the heap cannot hold while it is read. */
    static void checkHeap(Path file, int w, int h, long heapBytes) {
        checkHeap(file, (long) w * h * BYTES_PER_MODEL_SAMPLE, w + "×" + h + " samples " + BYTES_PER_MODEL_SAMPLE
                + " bytes each while read", heapBytes);
    }

    /** Refuses a step that needs more than {@code heapBytes}, saying what it needs and why. */
    static void checkHeap(Path file, long bytes, String what, long heapBytes) {
        if (bytes > heapBytes) {
            throw new HeightImportException(String.format(Locale.ROOT, "%s: needs about %.1f GiB (%s) but the heap "
                    + "has %.1f GiB free: crop or coarsen the model, or give Java more (-Xmx)", file, bytes / GIB, what,
                    heapBytes / GIB));
        }
    }

    private static final double GIB = 1024.0 * 1024 * 1024;

    /**
     * The metres a true-scale map's normalised height n spans, from the file's 0 m: n = (h + seaLevel) / 5000 m, so
     * the fractions {@code terrain.snow-base} and {@code snow-full} (0.35 and 0.60 by default) put speckled snow
     * from 1750 m and closed snow fields from 3000 m, the Alps' permanent snow line, and the materials' grass line
     * (0.45 ± 0.06) gives way to rock between 1950 and 2550 m, about the Alps' tree line. A real place's snow and rock
     * lie by altitude, whatever its own range: no snow on hills that top out at 1000 m.
     */
    public static final double TRUE_SCALE_RELIEF = 5000;

    /**
     * The settings the snow map reads a true-scale tile with: relief {@link #TRUE_SCALE_RELIEF} and the sea-level
     * height as its sea fraction, so the snow map's n = h / relief + seaFraction = (h + seaLevel) / 5000 m counts from
     * the file's 0 m, whatever {@code terrain.sea-level} floods.
     */
    public static TerrainSettings trueScale(TerrainSettings s) {
        return new TerrainSettings(s.size(), s.spacing(), TRUE_SCALE_RELIEF, s.seaLevel() / TRUE_SCALE_RELIEF,
                s.beta(), s.minWavelength(), s.maxWavelength(), s.importFile(), s.snowBase(), s.snowFull(),
                s.snowMorphology(), s.world(), s.memoryBudget(), s.importScale(), s.seaLevel(), s.importDetail(),
                s.erosion(), s.erosionTalus(), s.ranges());
    }

    /** The heap not yet used: the most the JVM may grow to, less what is in use now. */
    static long availableHeap() {
        Runtime r = Runtime.getRuntime();
        return r.maxMemory() - (r.totalMemory() - r.freeMemory());
    }
}
