package org.openworld.engine.elevation;

import java.nio.file.Path;
import java.util.Locale;
import java.util.stream.IntStream;
import org.openworld.engine.terrain.heights.HeightImport;
import org.openworld.engine.terrain.heights.HeightImportException;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.SpectralSynthesis;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * Puts an elevation model of any size into the terrain's tile: a square of 2^n samples, centred on the world origin.
 *
 * <p>The model is resampled at one spacing D, the finer of its two (a geographic model's degrees give different
 * metres east and south), by a Catmull-Rom cubic through its samples: it passes through them, so a sample's height
 * comes back exactly where the grids coincide and within the cubic's overshoot (a few per cent of the step between
 * neighbours) between. With {@code terrain.import-detail} the tile is made 2^m times finer, to spacing d = D/2^m, as
 * far as {@code terrain.size} samples a side and {@code terrain.spacing} allow, and {@link DetailBands} adds the m
 * octaves between them. The tile's side is the next power of two above the model's, at least
 * {@value HeightImport#MIN_SIZE}.
 *
 * <p><b>The edge.</b> Around the model, out to the tile's edge, the ground fades into a plain at the mean height of
 * the model's border: a sample at distance r outside takes the height of the nearest point of the border (clamp),
 * blended towards that mean by smoothstep(r / {@value #FADE_FRACTION} of the tile's side), under the same synthesised
 * detail; past the tile the terrain clamps again ({@link HeightMap}). Without the fade the border's ridges and
 * valleys would run straight out to the tile's edge as level stripes. The model is centred, so the camera's default
 * place, the origin, is over its middle.
 */
final class TileEmbedding {

    /** Bytes the terrain keeps per tile sample: heights, their pyramid's third, snow and sky maps, a working copy. */
    static final int BYTES_PER_TILE_SAMPLE = 16;

    /** The fade into the plain around the model spans this share of the tile's side. */
    static final double FADE_FRACTION = 0.05;

    private TileEmbedding() {
    }

    /**
     * What the tile of a model will be: its side n, the octaves added, the model's spacing D (coarse) and the tile's
     * d (fine), and the detail's bands (null without them).
     */
    record Plan(int n, int octaves, double coarse, double fine, boolean trueScale, DetailBands detail) {
    }

    /** Sizes the tile of {@code grid} and measures its detail; refuses a model too large for the tile or the heap. */
    static Plan plan(Path file, ElevationGrid grid, TerrainSettings s, int seed, long heapBytes) {
        boolean trueScale = grid.scaled() && s.importScale();
        double coarse = Math.min(grid.spacingX(), grid.spacingZ());
        int w = (int) Math.floor(grid.extentX() / coarse + 1e-9) + 1;
        int h = (int) Math.floor(grid.extentZ() / coarse + 1e-9) + 1;
        int side = Math.max(HeightImport.MIN_SIZE, Integer.highestOneBit(Math.max(w, h) - 1) << 1);
        if (side > HeightImport.MAX_SIZE) {
            throw new HeightImportException(file + ": at " + fmt(coarse) + " m spacing it is " + w + "×" + h
                    + " samples; the tile holds at most " + HeightImport.MAX_SIZE + " a side: crop or coarsen it");
        }
        int octaves = 0;
        while (trueScale && s.importDetail() && side << (octaves + 1) <= Math.max(s.size(), side)
                && coarse / (2 << octaves) >= s.spacing()) {
            octaves++;
        }
        int n = side << octaves;
        double fine = coarse / (1 << octaves);
        ElevationImport.checkHeap(file, (long) n * n * BYTES_PER_TILE_SAMPLE, n + "² tile samples "
                + BYTES_PER_TILE_SAMPLE + " bytes each", heapBytes);
        int square = Integer.highestOneBit(Math.min(w, h));
        DetailBands detail = octaves > 0 && square >= 32
                ? DetailBands.measure(window(grid, square, coarse), square, coarse, fine, seed) : null;
        return new Plan(n, octaves, coarse, fine, trueScale, detail);
    }

    /** One line: the model, then the tile it becomes. */
    static String describe(ElevationGrid grid, Plan p, TerrainSettings s) {
        return String.format(Locale.ROOT, "%s; tile %d² samples %s m apart (%.2f km)%s%s", grid.summary(), p.n(),
                fmt(p.fine()), p.n() * p.fine() / 1000, p.trueScale() ? ", true scale, sea level at "
                        + fmt(s.seaLevel()) + " m" : ", normalised to terrain.relief",
                p.detail() == null ? ", no synthesised detail" : String.format(Locale.ROOT, ", detail: %d octaves "
                        + "below %s m continuing the measured beta %.2f (%.2f m rms)", p.octaves(),
                        fmt(2 * p.coarse()), p.detail().beta(), p.detail().sigma()));
    }

    /** The tile of {@code grid} (no-data already filled). */
    static HeightMap embed(Path file, ElevationGrid grid, TerrainSettings s, int seed, long heapBytes) {
        Plan p = plan(file, grid, s, seed, heapBytes);
        int n = p.n();
        double fine = p.fine();
        boolean trueScale = p.trueScale();
        DetailBands detail = p.detail();
        double spacing = grid.scaled() ? fine : s.spacing();
        float[] heights = new float[n * n];
        double sea = trueScale ? s.seaLevel() : 0;
        double plain = borderMean(grid);
        double fade = FADE_FRACTION * n * fine;
        IntStream.range(0, n).parallel().forEach(j -> {
            double z = (j - n / 2) * fine;
            double outZ = Math.max(0, Math.abs(z) - grid.extentZ() / 2);
            for (int i = 0; i < n; i++) {
                double x = (i - n / 2) * fine;
                double v = cubic(grid, (x + grid.extentX() / 2) / grid.spacingX(),
                        (z + grid.extentZ() / 2) / grid.spacingZ());
                double t = Math.min(1, Math.hypot(Math.max(0, Math.abs(x) - grid.extentX() / 2), outZ) / fade);
                v += (plain - v) * t * t * (3 - 2 * t);
                heights[j * n + i] = (float) (v - sea + (detail == null ? 0 : detail.at(x, z)));
            }
        });
        if (!trueScale) {
            SpectralSynthesis.normalise(heights, n, s.relief(), s.seaFraction());
        }
        return new HeightMap(n, spacing, heights, false);
    }

    /** The mean height of the model's outermost samples, metres. */
    private static double borderMean(ElevationGrid g) {
        double sum = 0;
        for (int x = 0; x < g.width(); x++) {
            sum += g.at(x, 0) + g.at(x, g.height() - 1);
        }
        for (int z = 0; z < g.height(); z++) {
            sum += g.at(0, z) + g.at(g.width() - 1, z);
        }
        return sum / (2.0 * (g.width() + g.height()));
    }

    /** The central side × side square of the model resampled at {@code spacing}, for the spectrum. */
    private static float[] window(ElevationGrid grid, int side, double spacing) {
        float[] a = new float[side * side];
        for (int j = 0; j < side; j++) {
            for (int i = 0; i < side; i++) {
                double x = (i - side / 2) * spacing;
                double z = (j - side / 2) * spacing;
                a[j * side + i] = (float) cubic(grid, (x + grid.extentX() / 2) / grid.spacingX(),
                        (z + grid.extentZ() / 2) / grid.spacingZ());
            }
        }
        return a;
    }

    /** Catmull-Rom bicubic at fractional column u, row v, both clamped to the model (the edge runs outwards). */
    static double cubic(ElevationGrid g, double u, double v) {
        u = Math.max(0, Math.min(g.width() - 1, u));
        v = Math.max(0, Math.min(g.height() - 1, v));
        int iu = (int) Math.min(Math.floor(u), g.width() - 2);
        int iv = (int) Math.min(Math.floor(v), g.height() - 2);
        double tu = u - iu;
        double tv = v - iv;
        double result = 0;
        for (int b = -1; b <= 2; b++) {
            int row = Math.max(0, Math.min(g.height() - 1, iv + b));
            double across = 0;
            for (int a = -1; a <= 2; a++) {
                int col = Math.max(0, Math.min(g.width() - 1, iu + a));
                across += weight(a, tu) * g.at(col, row);
            }
            result += weight(b, tv) * across;
        }
        return result;
    }

    /** Catmull-Rom weight of the sample at offset k ∈ {−1, 0, 1, 2} for fraction t. */
    private static double weight(int k, double t) {
        return switch (k) {
            case -1 -> ((-t + 2) * t - 1) * t / 2;
            case 0 -> ((3 * t - 5) * t * t + 2) / 2;
            case 1 -> ((-3 * t + 4) * t + 1) * t / 2;
            default -> (t - 1) * t * t / 2;
        };
    }

    private static String fmt(double metres) {
        return String.format(Locale.ROOT, metres == Math.rint(metres) ? "%.0f" : "%.2f", metres);
    }
}
