package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.gl.Image;
import org.openworld.engine.terrain.material.TerrainTextures.Material;

/**
 * The synthesised material textures, GL-free: they tile, they have the colours of their materials, and a seed fixes
 * them. Each texture is also written to {@code target/test-images/} as 2 × 2 tiles, so a seam would show.
 */
class TerrainTexturesTest {
    // Tolerances here: colours are linear albedo shares from 8-bit sRGB texels; the bands are real surfaces' albedos
    // and visible hue differences, explained beside them

    static final int SEED = 7;
    static TerrainTextures textures;
    static long synthesisMillis;

    @BeforeAll
    static void generate() throws IOException {
        long t0 = System.nanoTime();
        textures = TerrainTextures.generate(SEED);
        synthesisMillis = (System.nanoTime() - t0) / 1_000_000;
        System.out.println("TerrainTextures.generate: " + synthesisMillis + " ms (first call, JIT cold)");
        int n = textures.size();
        for (Material m : Material.values()) {
            String name = m.name().toLowerCase();
            tiled(n, textures.albedo(m), false).writePng(Path.of("target/test-images/terrain-texture-" + name + "-albedo.png"));
            tiled(n, textures.detail(m), false).writePng(Path.of("target/test-images/terrain-texture-" + name + "-normal.png"));
            tiled(n, textures.detail(m), true).writePng(Path.of("target/test-images/terrain-texture-" + name + "-height-gloss.png"));
        }
    }

    /** 2 × 2 copies of a tile; either as stored (alpha forced opaque) or its b (height) and a (gloss) as grey halves. */
    static Image tiled(int n, byte[] rgba, boolean heightAndGloss) {
        byte[] out = new byte[4 * n * n * 4];
        for (int y = 0; y < 2 * n; y++) {
            for (int x = 0; x < 2 * n; x++) {
                int src = 4 * ((y % n) * n + (x % n));
                int dst = 4 * (y * 2 * n + x);
                for (int c = 0; c < 3; c++) {
                    out[dst + c] = heightAndGloss ? rgba[src + (x < n ? 2 : 3)] : rgba[src + c];
                }
                out[dst + 3] = (byte) 255;
            }
        }
        return new Image(2 * n, 2 * n, out);
    }

    static int at(byte[] rgba, int n, int x, int y, int c) {
        return rgba[4 * (y * n + x) + c] & 0xFF;
    }

    static double srgbToLinear(int v) {
        double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /** Mean linear albedo, r, g, b. */
    static double[] meanLinear(Material m) {
        byte[] a = textures.albedo(m);
        double[] mean = new double[3];
        int texels = a.length / 4;
        for (int i = 0; i < texels; i++) {
            for (int c = 0; c < 3; c++) {
                mean[c] += srgbToLinear(a[4 * i + c] & 0xFF) / texels;
            }
        }
        return mean;
    }

    /** Mean |v(x1, y) − v(x0, y)| over all rows y, for channel c: a column-pair difference. */
    static double columnDifference(byte[] t, int n, int x0, int x1, int c) {
        double sum = 0;
        for (int y = 0; y < n; y++) {
            sum += Math.abs(at(t, n, x1, y, c) - at(t, n, x0, y, c));
        }
        return sum / n;
    }

    /** The same for rows. */
    static double rowDifference(byte[] t, int n, int y0, int y1, int c) {
        double sum = 0;
        for (int x = 0; x < n; x++) {
            sum += Math.abs(at(t, n, x, y1, c) - at(t, n, x, y0, c));
        }
        return sum / n;
    }

    /** Interior neighbour pairs on each side of the seam that the wrap-around pair is compared with. */
    static final int NEAR_SEAM = 6;

    /**
     * The wrap-around pair (last and first column, last and first row) differs like the interior neighbour pairs
     * next to the seam. Near ones, not the whole tile's mean, because the texture's statistics drift slowly across
     * it (grass clumps thin out, a drift rises) and a fair comparison looks at the same place.
     */
    @Test
    void everyTextureTilesLikeAnInteriorNeighbour() {
        int n = textures.size();
        for (Material m : Material.values()) {
            for (boolean isDetail : new boolean[] {false, true}) {
                byte[] t = isDetail ? textures.detail(m) : textures.albedo(m);
                for (int c = 0; c < 4; c++) {
                    if (!isDetail && c == 3) {
                        continue; // albedo alpha is constant
                    }
                    String what = m + (isDetail ? " detail" : " albedo") + " channel " + c;
                    double nearColumns = 0;
                    double nearRows = 0;
                    for (int k = 0; k < NEAR_SEAM; k++) {
                        nearColumns += (columnDifference(t, n, k, k + 1, c)
                                + columnDifference(t, n, n - 2 - k, n - 1 - k, c)) / (2 * NEAR_SEAM);
                        nearRows += (rowDifference(t, n, k, k + 1, c)
                                + rowDifference(t, n, n - 2 - k, n - 1 - k, c)) / (2 * NEAR_SEAM);
                    }
                    double wrapColumns = columnDifference(t, n, n - 1, 0, c);
                    double wrapRows = rowDifference(t, n, n - 1, 0, c);
                    // the wrap may differ from interior neighbours by 30 % of their mean difference plus half an 8-bit
                    // level (rounding); theTilingMeasureSeesASeam shows a real seam exceeds the same band
                    assertTrue(wrapColumns < 1.3 * nearColumns + 0.5,
                            what + ": wrap-around columns " + wrapColumns + " vs neighbours " + nearColumns);
                    assertTrue(wrapRows < 1.3 * nearRows + 0.5,
                            what + ": wrap-around rows " + wrapRows + " vs neighbours " + nearRows);
                }
            }
        }
    }

    /** The tiling check sees a seam: the same measure across a cut through the middle of the tile fails it. */
    @Test
    void theTilingMeasureSeesASeam() {
        int n = textures.size();
        byte[] snow = textures.albedo(Material.SNOW);
        // neighbours of column n/2 − 1 are the interior; compare column n/2 − 1 with column 0, a cut-and-join seam
        double near = 0;
        for (int k = 0; k < NEAR_SEAM; k++) {
            near += columnDifference(snow, n, n / 2 - 2 - k, n / 2 - 1 - k, 0) / NEAR_SEAM;
        }
        double seam = columnDifference(snow, n, n / 2 - 1, 0, 0);
        assertTrue(seam > 1.3 * near + 0.5, "seam " + seam + " vs neighbours " + near);
    }

    @Test
    void grassIsGreenRockGreyAndSnowBrightNeutralAndSlightlyBlue() {
        double[] grass = meanLinear(Material.GRASS);
        double[] rock = meanLinear(Material.ROCK);
        double[] snow = meanLinear(Material.SNOW);

        // measured albedos of real surfaces (linear): grass 0.1–0.25 and green-dominant, rock 0.1–0.35 and near grey
        // (channels within 25 % of their mean), fresh snow 0.8–0.9 and near neutral (within 12 %, a faint blue)
        assertTrue(grass[1] > 1.2 * grass[0] && grass[1] > 2 * grass[2], "grass " + Arrays.toString(grass));
        assertTrue(grass[1] < 0.3, "grass is a dark surface: " + Arrays.toString(grass));

        double rockMean = (rock[0] + rock[1] + rock[2]) / 3;
        double rockSpread = Arrays.stream(rock).max().orElseThrow() - Arrays.stream(rock).min().orElseThrow();
        assertTrue(rockSpread < 0.25 * rockMean, "rock is near grey: " + Arrays.toString(rock));
        assertTrue(rockMean > 0.08 && rockMean < 0.4, "rock mid-dark: " + Arrays.toString(rock));

        double snowMean = (snow[0] + snow[1] + snow[2]) / 3;
        double snowSpread = Arrays.stream(snow).max().orElseThrow() - Arrays.stream(snow).min().orElseThrow();
        assertTrue(snowMean > 0.7, "snow is bright: " + Arrays.toString(snow));
        assertTrue(snowSpread < 0.12 * snowMean, "snow is near neutral: " + Arrays.toString(snow));
        assertTrue(snow[2] > snow[0], "snow leans blue: " + Arrays.toString(snow));
    }

    /** Mean slope of the tangent-space normal, |n.xy|, over a detail texture. */
    static double meanSlope(Material m) {
        byte[] d = textures.detail(m);
        double sum = 0;
        for (int i = 0; i < d.length / 4; i++) {
            double nx = (d[4 * i] & 0xFF) / 255.0 * 2 - 1;
            double ny = (d[4 * i + 1] & 0xFF) / 255.0 * 2 - 1;
            sum += Math.hypot(nx, ny);
        }
        return sum / (d.length / 4);
    }

    @Test
    void rockHasTheStrongestReliefAndSnowTheSoftest() {
        double grass = meanSlope(Material.GRASS);
        double rock = meanSlope(Material.ROCK);
        double snow = meanSlope(Material.SNOW);

        assertTrue(rock > grass && grass > snow, "mean normal tilt: rock " + rock + ", grass " + grass + ", snow " + snow);
        // a mean tilt of 0.02 (about 1°): below that an 8-bit normal map's steps (1/127) are all the relief left
        assertTrue(snow > 0.02, "snow still has a grain: " + snow);
    }

    @Test
    void snowSparklesInAFewTexelsOfFullGloss() {
        byte[] d = textures.detail(Material.SNOW);
        int texels = d.length / 4;
        int sparkling = 0;
        double meanGloss = 0;
        for (int i = 0; i < texels; i++) {
            int gloss = d[4 * i + 3] & 0xFF;
            sparkling += gloss >= 240 ? 1 : 0;
            meanGloss += gloss / 255.0 / texels;
        }
        double share = (double) sparkling / texels;
        // sparkle is a few isolated texels: 0.05 %–1 % of the texture at full gloss (fewer would not show at a glance,
        // more reads as wet); the mean gloss sits mid-range, between matte and mirror
        assertTrue(share > 0.0005 && share < 0.01, "sparkling share " + share);
        assertTrue(meanGloss > 0.45 && meanGloss < 0.75, "mean snow gloss " + meanGloss);
    }

    @Test
    void theSeedFixesTheTextures() {
        TerrainTextures again = TerrainTextures.generate(SEED);
        TerrainTextures other = TerrainTextures.generate(SEED + 1);
        for (Material m : Material.values()) {
            assertArrayEquals(textures.albedo(m), again.albedo(m), m + " albedo");
            assertArrayEquals(textures.detail(m), again.detail(m), m + " detail");
            assertFalse(Arrays.equals(textures.detail(m), other.detail(m)), m + " differs for another seed");
        }
        assertEquals(TerrainTextures.SIZE, textures.size());
        assertEquals(4 * TerrainTextures.SIZE * TerrainTextures.SIZE, textures.albedo(Material.GRASS).length);
    }
}
