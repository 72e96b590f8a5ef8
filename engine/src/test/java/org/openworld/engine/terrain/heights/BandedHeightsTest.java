package org.openworld.engine.terrain.heights;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.openworld.engine.colour.Repetition;

/** The unbounded world made per level: its spectrum, its bands and levels, determinism, and that it does not repeat. */
class BandedHeightsTest {

    private static final TerrainSettings DEFAULTS = TestTerrain.settings();
    private static final BandedHeights WORLD = new BandedHeights(DEFAULTS, 1);
    /** Bounds on the power shares outside a level and a band (see aCoarserLevelIsTheFinerBandLimited). */
    private static final double COARSE_LEAK = 1e-7;
    private static final double BAND_LEAK = 3e-5;

    /**
     * A 512² window of a level, far from the origin, has the power spectrum of the paper: slope −2β over the
     * frequencies the level holds (the longest wavelength to the level's Nyquist frequency). Over 4 seeds × levels
     * 0, 2, 4 × β = 1.6, 2.2, 2.8 every slope came within 0.075 of −2β (standard deviation 0.03), so ±0.15 is twice
     * the worst seen, and the tile's tolerance too; bands with the wrong gain (without E^(β−1) the power would step
     * by 2^2.4 between octaves) move the slope by far more.
     */
    @ParameterizedTest
    @CsvSource({"2.2, 0", "2.2, 2", "2.2, 4", "1.6, 2", "2.8, 2"})
    void aWindowsSpectrumFallsWithSlopeMinusTwoBeta(double beta, int level) {
        TerrainSettings s = TestTerrain.settings("terrain.beta=" + beta);
        BandedHeights world = new BandedHeights(s, 7);
        int n = 512;
        float[] h = world.level(level, 3_000_000, -1_500_000, n);
        PowerSpectrum spectrum = PowerSpectrum.tapered(new HeightMap(n, world.spacing(level), h, false));
        double slope = spectrum.fit(1 / s.maxWavelength(), 1 / (2 * world.spacing(level))).slope();
        // 0.15: each ring's power is a χ² sample, so a single 512² window's fitted slope scatters by a few hundredths
        // to a tenth (as in SpectralSynthesisTest and PowerSpectrumTest)
        assertEquals(-2 * beta, slope, 0.15, "fitted log-log slope of the window's power spectrum");
    }

    /**
     * The normalisation: heights over the whole plane have the mean relief · (0.5 − sea) and the deviation relief / 6
     * that the bands' spectra promise (by Parseval). The interpolated bands must keep their power for that: the
     * B-spline without its sinc⁴ correction gives 111 m instead of 133 m.
     */
    @Test
    void heightsSpanTheReliefAsSixStandardDeviations() {
        SplittableRandom random = new SplittableRandom(5);
        double sum = 0;
        double sum2 = 0;
        int m = 100_000;
        for (int i = 0; i < m; i++) {
            double h = WORLD.heightAt(random.nextDouble(-1e6, 1e6), random.nextDouble(-1e6, 1e6));
            sum += h;
            sum2 += h * h;
        }
        double mean = sum / m;
        double deviation = Math.sqrt(sum2 / m - mean * mean);
        assertEquals(DEFAULTS.relief() * (0.5 - DEFAULTS.seaFraction()), mean, 5, "mean height, m");
        assertEquals(DEFAULTS.relief() / BandedHeights.RELIEF_SIGMAS, deviation, 5, "standard deviation, m");
    }

    /**
     * Level L minus its bands L and coarser is the same mean height at every point of every level: a level is the
     * sum of its bands, made at its own spacing.
     */
    @Test
    void aLevelIsTheMeanPlusItsBands() {
        int n = 32;
        double mean = DEFAULTS.relief() * (0.5 - DEFAULTS.seaFraction());
        for (int level = 0; level < WORLD.levels(); level++) {
            float[] h = WORLD.level(level, -7_000, 123_456, n);
            double[] rest = new double[n * n];
            for (int i = 0; i < rest.length; i++) {
                rest[i] = h[i];
            }
            for (int k = level; k < WORLD.levels(); k++) {
                float[] band = WORLD.band(k, level, -7_000, 123_456, n);
                for (int i = 0; i < rest.length; i++) {
                    rest[i] -= band[i];
                }
            }
            for (double r : rest) {
                // float heights of hundreds of metres (24-bit mantissa, ~3e-5 m): 1e-3 m
                assertEquals(mean, r, 1e-3, "level " + level + " less its bands");
            }
        }
    }

    /**
     * Sampled at level L's spacing d, level L + 1 (level L less band L) has no power above its own Nyquist frequency
     * 1/(4d): it is level L band-limited, so taking every other sample of it does not alias. And band L's power lies
     * inside its octave 1/(4d) .. 1/(2d): its B-spline adds little outside. Over 4 seeds the shares measured at most
     * 1.1·10⁻⁸ and 3.4·10⁻⁶ (the Hann taper's own leakage included); the bounds are ten times that.
     */
    @Test
    void aCoarserLevelIsTheFinerBandLimited() {
        int level = 2;
        int n = 512;
        double d = WORLD.spacing(level);
        float[] fine = WORLD.level(level, 40_000, 90_000, n);
        float[] band = WORLD.band(level, level, 40_000, 90_000, n);
        float[] coarse = new float[n * n];
        for (int i = 0; i < coarse.length; i++) {
            coarse[i] = fine[i] - band[i];
        }
        double cut = 1 / (4 * d);
        double coarseAbove = share(PowerSpectrum.tapered(new HeightMap(n, d, coarse, false)), 1.1 * cut, 1);
        assertTrue(coarseAbove < COARSE_LEAK, "share of level 3's power above its Nyquist frequency: " + coarseAbove);
        double bandOutside = share(PowerSpectrum.tapered(new HeightMap(n, d, band, false)), 0, 0.9 * cut);
        assertTrue(bandOutside < BAND_LEAK, "share of band 2's power below its octave: " + bandOutside);
    }

    /** The share of a spectrum's power in the rings from {@code low} to {@code high} cycles per metre. */
    private static double share(PowerSpectrum spectrum, double low, double high) {
        double inside = 0;
        double all = 0;
        for (PowerSpectrum.Bin b : spectrum.bins()) {
            all += b.power() * b.frequency(); // a ring's power times its circumference
            if (b.frequency() >= low && b.frequency() <= high) {
                inside += b.power() * b.frequency();
            }
        }
        return inside / all;
    }

    /** Two worlds of one seed, asked different things in different orders, give 1 000 heights bit for bit alike. */
    @Test
    void theSameSeedGivesTheSameBitsWhateverWasAskedBefore() {
        SplittableRandom random = new SplittableRandom(11);
        int m = 1000;
        double[] x = new double[m];
        double[] z = new double[m];
        int[] level = new int[m];
        for (int i = 0; i < m; i++) {
            x[i] = random.nextDouble(-5e6, 5e6);
            z[i] = random.nextDouble(-5e6, 5e6);
            level[i] = random.nextInt(WORLD.levels());
        }
        // the first flight: a window near the origin, then the points in order on this thread
        BandedHeights first = new BandedHeights(DEFAULTS, 4);
        first.level(3, -64, -64, 128);
        long[] a = new long[m];
        for (int i = 0; i < m; i++) {
            a[i] = Double.doubleToRawLongBits(first.height(level[i], x[i], z[i]));
        }
        // the second: other windows thousands of kilometres away, then the points backwards on several threads
        BandedHeights second = new BandedHeights(DEFAULTS, 4);
        second.level(0, 1_000_000, -3_000_000, 256);
        second.level(6, -20_000, 5_000, 200);
        long[] b = new long[m];
        IntStream.range(0, m).parallel().map(i -> m - 1 - i)
                .forEach(i -> b[i] = Double.doubleToRawLongBits(second.height(level[i], x[i], z[i])));
        assertArrayEquals(a, b);
        BandedHeights other = new BandedHeights(DEFAULTS, 5);
        assertNotEquals(first.heightAt(x[0], z[0]), other.heightAt(x[0], z[0]), "another seed, another world");
    }

    /**
     * 5 000 km out, heights 10 cm apart still differ: positions are doubles. As floats they would snap to 0.5 m
     * steps there, and neighbours would share a height.
     */
    @Test
    void keepsCentimetresThousandsOfKilometresOut() {
        double previous = WORLD.heightAt(5e6, -5e6);
        for (int i = 1; i <= 200; i++) {
            double h = WORLD.heightAt(5e6 + 0.1 * i, -5e6);
            assertNotEquals(previous, h, "heights 10 cm apart at x = " + (5e6 + 0.1 * i));
            // 0.5 m: the float step there (see the Javadoc); real slopes change a 10 cm step's height by centimetres
            assertTrue(Math.abs(h - previous) < 0.5, "a 10 cm step changes the height by " + (h - previous) + " m");
            previous = h;
        }
    }

    /**
     * The overview (`heightmap --overview`), smaller: 512² samples 128 m apart (level 6, 65 km a side, the overview's area). Its
     * normalised autocorrelation has no peak above 0.2 beyond the longest wavelength (2048 m; nearer lags are the
     * mountains' own shape); over 4 seeds it measured 0.10 .. 0.11. The periodic tile of 4096 m, sampled the same
     * way, peaks near 1.0 at its period: the measure sees a repeat.
     */
    @Test
    void theOverviewHasNoRepeatedRegion() {
        int n = 512;
        int level = 6;
        double d = WORLD.spacing(level);
        double beyond = DEFAULTS.maxWavelength();
        double peak = peakAutocorrelation(WORLD.level(level, -n / 2, -n / 2, n), n, d, beyond);
        // measured 0.10–0.11 over 4 seeds (Javadoc): 0.2 is twice that; a repeat reads near 1, as the tile below (over
        // 0.9)
        assertTrue(peak < 0.2, "largest autocorrelation beyond " + beyond + " m: " + peak);

        HeightMap tile = SpectralSynthesis.generate(TestTerrain.settings("terrain.size=512", "terrain.spacing=8"), 1);
        float[] repeating = new float[n * n];
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                repeating[j * n + i] = (float) tile.heightAt(i * d, j * d);
            }
        }
        double tilePeak = peakAutocorrelation(repeating, n, d, beyond);
        assertTrue(tilePeak > 0.9, "the periodic tile's largest autocorrelation beyond " + beyond + " m: " + tilePeak);
    }

    /**
     * Every band's period divides the coarsest one's, P = 512 · 512 m / 2 = 131 km: unturned, the whole world would
     * repeat 131 km east. Turned per seed, the window there is another place: correlation under 0.2 with the
     * window at the origin (it would be 1).
     */
    @Test
    void theBandsTurnsBreakTheirCommonPeriod() {
        int n = 256;
        int level = 6;
        long period = Math.round(OctaveBand.TILE * WORLD.spacing(WORLD.levels() - 1) / 2 / WORLD.spacing(level));
        float[] here = WORLD.level(level, 0, 0, n);
        float[] there = WORLD.level(level, period, 0, n);
        double correlation = correlation(here, there);
        // unturned it would be 1; two unrelated 256² windows of smooth terrain correlate by chance at ±0.1 or so (few
        // independent mountains in a window), 0.2 above that
        assertTrue(Math.abs(correlation) < 0.2, "correlation with the window " + period * WORLD.spacing(level)
                + " m east: " + correlation);
    }

    /** Every height of every level, anywhere, lies within the world's bounds: each band within its largest term. */
    @Test
    void noHeightLiesOutsideTheBounds() {
        SplittableRandom random = new SplittableRandom(12);
        double low = Double.MAX_VALUE;
        double high = -Double.MAX_VALUE;
        for (int i = 0; i < 50_000; i++) {
            double h = WORLD.height(random.nextInt(WORLD.levels()), random.nextDouble(-1e7, 1e7),
                    random.nextDouble(-1e7, 1e7));
            low = Math.min(low, h);
            high = Math.max(high, h);
        }
        assertTrue(WORLD.lowest() <= low && high <= WORLD.highest(),
                "heights " + low + " .. " + high + " within " + WORLD.lowest() + " .. " + WORLD.highest());
        // and the bounds are not absurd: within a few reliefs of the heights seen
        assertTrue(WORLD.highest() - WORLD.lowest() < 4 * DEFAULTS.relief(),
                "bounds span " + (WORLD.highest() - WORLD.lowest()) + " m");
    }

    /**
     * A level's error, measured at one set of random places, holds at another: the drawn triangles of level L lie
     * within it of the finest heights at 5 000 fresh places (the margin covers the sample's luck), it grows with
     * the level, and it is not a loose bound: the largest error seen is over half of it.
     */
    @Test
    void levelErrorsHoldAtPlacesTheyWereNotMeasuredAt() {
        float[] errors = WORLD.levelErrors(WORLD.levels());
        assertEquals(0, errors[0]);
        SplittableRandom random = new SplittableRandom(99);
        for (int level = 1; level < errors.length; level++) {
            assertTrue(errors[level] > errors[level - 1], "error grows from level " + (level - 1) + " to " + level);
            double worst = 0;
            for (int i = 0; i < 5_000; i++) {
                double x = random.nextDouble(-1e6, 1e6);
                double z = random.nextDouble(-1e6, 1e6);
                worst = Math.max(worst, Math.abs(WORLD.heightAt(x, z) - WORLD.surface(level, x, z)));
            }
            String seen = "level " + level + ": " + worst + " m seen, " + errors[level] + " m estimated";
            assertTrue(worst <= errors[level], seen);
            // "not a loose bound": the largest of 5 000 random errors reaches over half the estimate, which was itself
            // a maximum over another random set
            assertTrue(worst > 0.5 * errors[level], seen);
        }
    }

    private static double correlation(float[] a, float[] b) {
        double ma = 0;
        double mb = 0;
        for (int i = 0; i < a.length; i++) {
            ma += a[i];
            mb += b[i];
        }
        ma /= a.length;
        mb /= b.length;
        double ab = 0;
        double aa = 0;
        double bb = 0;
        for (int i = 0; i < a.length; i++) {
            ab += (a[i] - ma) * (b[i] - mb);
            aa += (a[i] - ma) * (a[i] - ma);
            bb += (b[i] - mb) * (b[i] - mb);
        }
        return ab / Math.sqrt(aa * bb);
    }

    /** {@link Repetition#peak} of the heights, over shifts of more than {@code beyond} metres. */
    private static double peakAutocorrelation(float[] heights, int n, double spacing, double beyond) {
        double[] values = new double[heights.length];
        for (int i = 0; i < heights.length; i++) {
            values[i] = heights[i];
        }
        return Repetition.peak(values, n, n, beyond / spacing);
    }
}
