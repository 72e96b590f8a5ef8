package org.openworld.engine.terrain.material;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.terrain.material.TerrainTextures.Material;

/**
 * Quilted Wang tiles ({@link WangTiles}) on the real exemplar, the synthesised rock: every edge of one colour holds
 * the same texels in every tile, the atlas is a valid Wang tiling, the 16 tiles differ and their pieces come from
 * apart in the exemplar, the seams are cut where the pieces agree, the same bytes for the same seed.
 */
class WangTilesTest {

    static final int SEED = EngineSettings.DEFAULTS.seed();
    static TerrainTextures exemplars;
    static WangTiles.Atlas rock;
    static int n;

    @BeforeAll
    static void cutTheRock() {
        exemplars = TerrainTextures.generate(SEED);
        n = exemplars.size();
        long start = System.nanoTime();
        rock = atlas(1);
        System.out.printf("WangTiles: rock %d² -> %d² atlas in %.0f ms%n", n, rock.size(),
                (System.nanoTime() - start) / 1e6);
    }

    static WangTiles.Atlas atlas(long seed) {
        return WangTiles.build(exemplars.albedo(Material.ROCK), exemplars.detail(Material.ROCK), n,
                new SplittableRandom(seed));
    }

    /** The atlas's albedo and detail texel (x, y) of tile (col, row), eight bytes. */
    static byte[] texel(WangTiles.Atlas a, int col, int row, int x, int y) {
        int i = 4 * ((row * n + y) * a.size() + col * n + x);
        byte[] out = new byte[8];
        System.arraycopy(a.albedo(), i, out, 0, 4);
        System.arraycopy(a.detail(), i, out, 4, 4);
        return out;
    }

    /** The exemplar's albedo and detail texel (x, y), wrapped. */
    static byte[] exemplar(int x, int y) {
        int i = 4 * (Math.floorMod(y, n) * n + Math.floorMod(x, n));
        byte[] out = new byte[8];
        System.arraycopy(exemplars.albedo(Material.ROCK), i, out, 0, 4);
        System.arraycopy(exemplars.detail(Material.ROCK), i, out, 4, 4);
        return out;
    }

    @Test
    void everyEdgeHoldsItsColoursDiamondSoTilesSharingAColourMeetWithoutASeam() {
        for (int row = 0; row < WangTiles.ATLAS; row++) {
            for (int col = 0; col < WangTiles.ATLAS; col++) {
                int north = WangTiles.first(row);
                int south = WangTiles.second(row);
                int west = 2 + WangTiles.first(col);
                int east = 2 + WangTiles.second(col);
                for (int k = 1; k < n - 1; k++) {
                    // the edge row itself (the cut may take texels from the next one on)
                    for (int depth = 0; depth < 1; depth++) {
                        int far = n - 1 - depth;
                        assertArrayEquals(exemplar(k + rock.offsetX()[north], depth + rock.offsetY()[north]),
                                texel(rock, col, row, k, depth), "north edge of tile " + col + "," + row);
                        assertArrayEquals(exemplar(k + rock.offsetX()[south], far + rock.offsetY()[south]),
                                texel(rock, col, row, k, far), "south edge of tile " + col + "," + row);
                        assertArrayEquals(exemplar(depth + rock.offsetX()[west], k + rock.offsetY()[west]),
                                texel(rock, col, row, depth, k), "west edge of tile " + col + "," + row);
                        assertArrayEquals(exemplar(far + rock.offsetX()[east], k + rock.offsetY()[east]),
                                texel(rock, col, row, far, k), "east edge of tile " + col + "," + row);
                    }
                }
            }
        }
    }

    @Test
    void aSouthEdgeAndTheNorthEdgeBelowItAreOneUnbrokenPieceOfTheExemplar() {
        // the tile above's last row and the tile below's first are consecutive exemplar rows, whichever tiles they are
        for (int row = 0; row < WangTiles.ATLAS; row++) {
            int below = (row + 1) % WangTiles.ATLAS;
            for (int k = 1; k < n - 1; k++) {
                byte[] last = texel(rock, 0, row, k, n - 1);
                byte[] first = texel(rock, 0, below, k, 0);
                int c = WangTiles.second(row);
                assertArrayEquals(exemplar(k + rock.offsetX()[c], n - 1 + rock.offsetY()[c]), last);
                assertArrayEquals(exemplar(k + rock.offsetX()[c], n + rock.offsetY()[c]), first);
            }
        }
    }

    @Test
    void theAtlasIsAValidPeriodicWangTilingOfAllSixteenTiles() {
        Set<String> tiles = new HashSet<>();
        for (int k = 0; k < WangTiles.ATLAS; k++) {
            int next = (k + 1) % WangTiles.ATLAS;
            assertEquals(WangTiles.second(k), WangTiles.first(next), "column " + k + "'s east, the next's west");
            for (int m = 0; m < WangTiles.ATLAS; m++) {
                tiles.add(WangTiles.first(k) + "" + WangTiles.second(k) + WangTiles.first(m) + WangTiles.second(m));
            }
        }
        assertEquals(16, tiles.size(), "every (west, east, north, south) once");
    }

    @Test
    void theSixteenTilesDifferAndTheirDiamondsComeFromApartInTheExemplar() {
        Set<Integer> hashes = new HashSet<>();
        for (int row = 0; row < WangTiles.ATLAS; row++) {
            for (int col = 0; col < WangTiles.ATLAS; col++) {
                byte[] tile = new byte[4 * n * n];
                for (int y = 0; y < n; y++) {
                    System.arraycopy(rock.albedo(), 4 * ((row * n + y) * rock.size() + col * n), tile, 4 * y * n,
                            4 * n);
                }
                hashes.add(Arrays.hashCode(tile));
            }
        }
        assertEquals(16, hashes.size());
        for (int a = 0; a < 4; a++) {
            for (int b = 0; b < a; b++) {
                int dx = Math.abs(Math.floorMod(rock.offsetX()[a] - rock.offsetX()[b] + n / 2, n) - n / 2);
                int dy = Math.abs(Math.floorMod(rock.offsetY()[a] - rock.offsetY()[b] + n / 2, n) - n / 2);
                assertTrue(dx >= n / 4 || dy >= n / 4, "diamonds " + a + " and " + b + " overlap in the exemplar");
            }
        }
    }

    @Test
    void eachTilesCentreIsItsOwnBlockFromApartFromTheDiamonds() {
        int side = (int) Math.round(WangTiles.CENTRE * n);
        int middle = n / 2; // the block's middle, which no strip's cut reaches
        for (int k = 0; k < WangTiles.ATLAS * WangTiles.ATLAS; k++) {
            for (int c = 0; c < 4; c++) {
                int dx = Math.abs(Math.floorMod(rock.centreX()[k] - rock.offsetX()[c] + n / 2, n) - n / 2);
                int dy = Math.abs(Math.floorMod(rock.centreY()[k] - rock.offsetY()[c] + n / 2, n) - n / 2);
                assertTrue(dx >= n / 4 || dy >= n / 4, "tile " + k + "'s centre overlaps diamond " + c);
            }
            for (int y = middle - side / 4; y < middle + side / 4; y += 13) {
                for (int x = middle - side / 4; x < middle + side / 4; x += 13) {
                    assertArrayEquals(exemplar(x + rock.centreX()[k], y + rock.centreY()[k]),
                            texel(rock, k % WangTiles.ATLAS, k / WangTiles.ATLAS, x, y), "tile " + k);
                }
            }
        }
    }

    @Test
    void seamsAreCutWhereThePiecesAgree() {
        double cut = 0;
        double straight = 0;
        for (ImageQuilting.Seam seam : rock.seams()) {
            assertTrue(seam.cut() <= seam.straight() + 1e-9, "a straight seam is one of the paths: " + seam);
            cut += seam.cut();
            straight += seam.straight();
        }
        // 16 tiles: four diagonal cuts and four strips around the centre each
        assertEquals(16 * 8, rock.seams().size());
        // the minimum-error cut follows the low-difference texels, so it costs a fraction of a straight seam on a
        // random texture; half is the bound chosen, not measured
        assertTrue(cut < 0.5 * straight, "the cuts' cost " + cut + " against straight seams' " + straight);
    }

    @Test
    void theCutsBandStaysInsideTheQuarterAndOffItsEdges() {
        int h = n / 2;
        for (int d = 1; d <= 2 * h - 2; d++) {
            int lo = WangTiles.lowest(d, h);
            int hi = WangTiles.highest(d, h);
            assertTrue(lo >= 1 && hi <= d && hi <= h - 1 && lo >= d - h + 1 && lo <= hi, "anti-diagonal " + d);
            if (d > 1) {
                // reachable from the previous anti-diagonal one texel at a time
                assertTrue(lo <= WangTiles.highest(d - 1, h) + 1 && hi >= WangTiles.lowest(d - 1, h) - 1);
            }
        }
    }

    @Test
    void theSameSeedGivesTheSameTilesAndAnotherOtherTiles() {
        WangTiles.Atlas again = atlas(1);
        assertArrayEquals(rock.albedo(), again.albedo());
        assertArrayEquals(rock.detail(), again.detail());
        assertFalse(Arrays.equals(rock.albedo(), atlas(2).albedo()));
    }
}
