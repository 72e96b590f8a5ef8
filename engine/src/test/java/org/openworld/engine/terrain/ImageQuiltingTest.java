package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.terrain.TerrainTextures.Material;

/**
 * Image quilting ({@link ImageQuilting}) on the real exemplar, the synthesised rock: the overlap error by FFT, seams
 * cut by minimum error, neighbouring blocks from different parts of the exemplar, the same bytes for the same seed.
 */
class ImageQuiltingTest {

    static final int SEED = EngineSettings.DEFAULTS.seed();
    static TerrainTextures exemplars;
    static ImageQuilting.Quilt rock;

    @BeforeAll
    static void quiltTheRock() {
        exemplars = TerrainTextures.generate(SEED);
        long start = System.nanoTime();
        rock = quilt(Material.ROCK, 1);
        System.out.printf("ImageQuilting: rock %d² -> %d² in %.0f ms%n", exemplars.size(), rock.size(),
                (System.nanoTime() - start) / 1e6);
    }

    static ImageQuilting.Quilt quilt(Material m, long seed) {
        return ImageQuilting.quilt(exemplars.albedo(m), exemplars.detail(m), exemplars.size(),
                new SplittableRandom(seed));
    }

    @Test
    void theCutIsTheLeastErrorPathThroughTheStrip() {
        // every path through a 4 × 6 strip, one texel per row moving at most one sideways, against the program's
        SplittableRandom random = new SplittableRandom(7);
        int width = 4;
        int length = 6;
        for (int trial = 0; trial < 20; trial++) {
            double[] e = random.doubles(width * length).toArray();
            int[] path = ImageQuilting.minimumPath(e, length, width);
            double best = Double.POSITIVE_INFINITY;
            for (int code = 0; code < Math.pow(width, length); code++) {
                double cost = 0;
                int previous = -1;
                boolean connected = true;
                for (int l = 0, c = code; l < length; l++, c /= width) {
                    int w = c % width;
                    connected &= previous < 0 || Math.abs(w - previous) <= 1;
                    previous = w;
                    cost += e[l * width + w];
                }
                if (connected) {
                    best = Math.min(best, cost);
                }
            }
            double found = 0;
            for (int l = 0; l < length; l++) {
                assertTrue(l == 0 || Math.abs(path[l] - path[l - 1]) <= 1, "the path moves one texel at most");
                found += e[l * width + path[l]];
            }
            assertEquals(best, found, 1e-12);
        }
    }

    @Test
    void theOverlapErrorByFftIsTheSumOfSquaredDifferences() {
        // block (5, 3)'s left and top strips in the finished quilt, against a few candidates summed texel by texel
        ImageQuilting quilting = new ImageQuilting(exemplars.albedo(Material.ROCK), exemplars.detail(Material.ROCK),
                exemplars.size());
        quilting.placeAll(new SplittableRandom(1));
        ImageQuilting.Quilt quilt = quilting.result();
        double[] error = quilting.overlapError(5, 3, true, true, false, false);
        int m = ImageQuilting.MATCH;
        int n = exemplars.size();
        int grid = n / m;
        byte[] albedo = exemplars.albedo(Material.ROCK);
        byte[] detail = exemplars.detail(Material.ROCK);
        for (int c : new int[] {0, 77, 1000, grid * grid - 1}) {
            double sum = 0;
            for (int cy = 0; cy < ImageQuilting.BLOCK / m; cy++) {
                for (int cx = 0; cx < ImageQuilting.BLOCK / m; cx++) {
                    if (cx >= ImageQuilting.OVERLAP / m && cy >= ImageQuilting.OVERLAP / m) {
                        continue;
                    }
                    double[] old = features(quilt.albedo(), quilt.detail(), quilt.size(),
                            5 * ImageQuilting.STEP + cx * m, 3 * ImageQuilting.STEP + cy * m);
                    double[] candidate = features(albedo, detail, n, (c % grid + cx) % grid * m,
                            (c / grid + cy) % grid * m);
                    for (int k = 0; k < old.length; k++) {
                        sum += (candidate[k] - old[k]) * (candidate[k] - old[k]);
                    }
                }
            }
            assertEquals(sum, error[c], 1e-4 * sum, "candidate " + c);
        }
    }

    /** The matched features, albedo r, g, b and relief (0..1), averaged over the MATCH² texels at (x, y). */
    static double[] features(byte[] albedo, byte[] detail, int side, int x, int y) {
        double[] f = new double[4];
        int m = ImageQuilting.MATCH;
        for (int dy = 0; dy < m; dy++) {
            for (int dx = 0; dx < m; dx++) {
                int t = 4 * ((y + dy) * side + x + dx);
                f[0] += (albedo[t] & 0xFF) / (255.0 * m * m);
                f[1] += (albedo[t + 1] & 0xFF) / (255.0 * m * m);
                f[2] += (albedo[t + 2] & 0xFF) / (255.0 * m * m);
                f[3] += (detail[t + 2] & 0xFF) / (255.0 * m * m);
            }
        }
        return f;
    }

    @Test
    void seamsAreCutWhereTheBlocksAgree() {
        double cut = 0;
        double straight = 0;
        for (ImageQuilting.Seam seam : rock.seams()) {
            assertTrue(seam.cut() <= seam.straight() + 1e-9, "a straight line is one of the paths: " + seam);
            cut += seam.cut();
            straight += seam.straight();
        }
        // blocks 16 per side, wrapped: a left seam for all but the first column and a top one for all but the first
        // row, plus the last column's right seams and the last row's bottom ones
        int b = rock.blocks();
        assertEquals(2 * b * b, rock.seams().size());
        assertTrue(cut < 0.5 * straight, "the cuts' cost " + cut + " against straight seams' " + straight);
    }

    @Test
    void neighbouringBlocksComeFromDifferentPartsOfTheExemplar() {
        int b = rock.blocks();
        int n = exemplars.size();
        for (int j = 0; j < b; j++) {
            for (int i = 0; i < b; i++) {
                int k = j * b + i;
                for (int other : new int[] {j * b + (i + 1) % b, ((j + 1) % b) * b + i}) {
                    int dx = Math.floorMod(rock.sourceX()[k] - rock.sourceX()[other] + n / 2, n) - n / 2;
                    int dy = Math.floorMod(rock.sourceY()[k] - rock.sourceY()[other] + n / 2, n) - n / 2;
                    assertTrue(Math.abs(dx) >= ImageQuilting.BLOCK || Math.abs(dy) >= ImageQuilting.BLOCK,
                            "blocks " + k + " and " + other + " share exemplar texels: " + dx + ", " + dy);
                }
            }
        }
        // the recorded sources are where the texels came from: a block's centre, which no seam reaches, is its source's
        byte[] exemplar = exemplars.albedo(Material.ROCK);
        for (int k = 0; k < b * b; k++) {
            for (int y = ImageQuilting.OVERLAP; y < ImageQuilting.STEP; y += 17) {
                for (int x = ImageQuilting.OVERLAP; x < ImageQuilting.STEP; x += 17) {
                    int to = 4 * (((k / b) * ImageQuilting.STEP + y) * rock.size() + (k % b) * ImageQuilting.STEP + x);
                    int from = 4 * (((rock.sourceY()[k] + y) % n) * n + (rock.sourceX()[k] + x) % n);
                    assertArrayEquals(Arrays.copyOfRange(exemplar, from, from + 4),
                            Arrays.copyOfRange(rock.albedo(), to, to + 4));
                }
            }
        }
    }

    @Test
    void theSameSeedGivesTheSameBytes() {
        ImageQuilting.Quilt again = quilt(Material.ROCK, 1);
        ImageQuilting.Quilt other = quilt(Material.ROCK, 2);
        assertArrayEquals(rock.albedo(), again.albedo());
        assertArrayEquals(rock.detail(), again.detail());
        assertFalse(Arrays.equals(rock.albedo(), other.albedo()), "another seed, another quilt");
    }
}
