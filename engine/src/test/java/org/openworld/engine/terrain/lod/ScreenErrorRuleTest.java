package org.openworld.engine.terrain.lod;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.HeightPyramid;
import org.openworld.engine.terrain.heights.TerrainSettings;
import org.openworld.engine.terrain.heights.TestPyramids;
import org.openworld.engine.erosion.TileErosion;

/**
 * The screen-error rule against heights measured here, not by the rule's code: for every selected patch, every
 * level-0 sample of its area is compared with the surface its level draws there (the two triangles of the cell around
 * it, either diagonal, interpolated by barycentric weights), and the difference, seen from the camera at the
 * distance of that very point, must cover at most the allowed pixels.
 */
class ScreenErrorRuleTest {

    /** Rough ground: hills plus seeded noise, through the engine's own Gaussian pyramid. */
    private static HeightPyramid rough(int size, double spacing, long seed) {
        Random random = new Random(seed);
        float[] heights = new float[size * size];
        double k = 2 * Math.PI / size;
        for (int z = 0; z < size; z++) {
            for (int x = 0; x < size; x++) {
                heights[z * size + x] = (float) (40 * Math.sin(3 * k * x) * Math.cos(2 * k * z)
                        + 6 * Math.sin(11 * k * (x + 2 * z)) + (x > size / 2 ? 3 * random.nextGaussian() : 0));
            }
        }
        return HeightPyramid.build(new HeightMap(size, spacing, heights, true));
    }

    /**
     * Over random cameras, fields of view, target sizes and bounds, in both schemes and over the 3 × 3 copies: no
     * sample of any drawn patch is off by more than the bound, in pixels, from where the camera sees it.
     */
    @Test
    void everySelectedPatchStaysWithinThePixelBound() {
        staysWithinThePixelBound(rough(256, 2, 3));
    }

    /** The same on eroded ground: valleys cut to their rivers and faces at the talus, each level's error its own. */
    @Test
    void erodedGroundStaysWithinThePixelBound() {
        HeightMap eroded = TileErosion.erode(rough(256, 2, 3).base(), TerrainSettings.DEFAULTS.erosionTalus());
        staysWithinThePixelBound(HeightPyramid.build(eroded));
    }

    private static void staysWithinThePixelBound(HeightPyramid pyramid) {
        TerrainQuadtree tree = new TerrainQuadtree(pyramid, 16);
        float[] offsets = TestPyramids.threeByThree(pyramid.base().extent());
        PatchSelection selection = new PatchSelection(tree);
        PatchList patches = new PatchList();
        Random random = new Random(19);
        int coarse = 0;
        for (int trial = 0; trial < 60; trial++) {
            double half = pyramid.base().extent() / 2;
            Vector3f eye = new Vector3f((float) random.nextDouble(-half, half), (float) random.nextDouble(-10, 400),
                    (float) random.nextDouble(-half, half));
            double fov = Math.toRadians(random.nextDouble(20, 100));
            int height = 180 + random.nextInt(900);
            int width = height * 16 / 9;
            double pixels = Math.pow(2, random.nextDouble(-2, 3));
            Matrix4f projection = new Matrix4f().perspective((float) fov, (float) width / height, 0.5f, 40_000);
            DetailLimit limit = DetailLimit.projected(projection, width, height, pixels);
            // pixels per metre at one metre: half the image height over tan of half the vertical field of view
            double focal = height / 2.0 / Math.tan(fov / 2);
            LodMode mode = trial % 2 == 0 ? LodMode.QUADTREE : LodMode.FLAT_GRID;
            selection.select(eye, offsets, limit, mode, null, patches);
            for (int i = 0; i < patches.size(); i++) {
                coarse += patches.level(i) > 0 ? 1 : 0;
                double worst = worstPixels(pyramid, tree.cells(), patches, i, offsets, eye, focal, true);
                assertTrue(worst <= pixels * (1 + 1e-4), mode + " patch " + i + " at level " + patches.level(i)
                        + " shows an error of " + worst + " px, bound " + pixels + " px; eye " + eye);
            }
        }
        assertTrue(coarse > 0, "some patches were drawn coarser than the finest level");
    }

    /**
     * Through an orthographic box the error is measured in the box's pixels (texels), whatever the distance. Every patch
     * stays within the texel bound; the cut does not move with the eye; and a cascade with bigger texels draws the
     * same ground with fewer, coarser patches, down to none at level 0 where the level-1 error fits in a texel.
     */
    @Test
    void theShadowPassFollowsTheTexelSize() {
        HeightPyramid pyramid = rough(256, 2, 7);
        TerrainQuadtree tree = new TerrainQuadtree(pyramid, 16);
        float[] offsets = {0, 0};
        PatchSelection selection = new PatchSelection(tree);
        PatchList patches = new PatchList();
        double extent = pyramid.base().extent();
        int resolution = 512;
        int previousCount = Integer.MAX_VALUE;
        for (double side : new double[] {128, 512, 2048, 8192, 32768}) {
            Matrix4f box = new Matrix4f().ortho((float) (-side / 2), (float) (side / 2), (float) (-side / 2),
                    (float) (side / 2), 0, 1000);
            DetailLimit limit = DetailLimit.projected(box, resolution, resolution, 1);
            double texel = side / resolution;
            selection.select(new Vector3f(0, 200, 0), offsets, limit, LodMode.QUADTREE, null, patches);
            String near = describe(patches);
            int count = patches.size();
            int finest = Integer.MAX_VALUE;
            for (int i = 0; i < count; i++) {
                finest = Math.min(finest, patches.level(i));
                double texels = worstPixels(pyramid, tree.cells(), patches, i, offsets, null, 1 / texel, false);
                // 1e-4: the rule's float arithmetic may round a patch exactly at one texel a hair over
                assertTrue(texels <= 1 + 1e-4, "patch " + i + " shows " + texels + " texels at " + texel + " m");
            }
            selection.select(new Vector3f((float) extent, 5000, (float) -extent), offsets, limit, LodMode.QUADTREE,
                    null, patches);
            assertEquals(near, describe(patches), "an orthographic view has no distance: the eye does not matter");
            assertTrue(count <= previousCount, "bigger texels, no more patches: " + count + " after " + previousCount);
            previousCount = count;
            boolean levelOneFits = true;
            for (int node = 0; node < tree.nodeCount(); node++) {
                levelOneFits &= tree.level(node) != 1 || maxError(pyramid, tree, node) <= texel;
            }
            if (levelOneFits) {
                assertTrue(finest > 0, "no full-resolution casters with " + texel + " m texels");
            }
        }
        assertEquals(1, previousCount, "texels far bigger than the relief: the whole tile as one patch");
    }

    /** Largest error of a node's own level over its samples, measured as in {@link #worstPixels} (texels of 1 m). */
    private static double maxError(HeightPyramid pyramid, TerrainQuadtree tree, int node) {
        PatchList one = new PatchList();
        one.add(node, 0, tree.sampleX(node), tree.sampleZ(node), 1 << tree.level(node), tree.level(node), 0);
        return worstPixels(pyramid, tree.cells(), one, 0, new float[] {0, 0}, null, 1, false);
    }

    /**
     * The largest error of patch i over its level-0 samples, borders included, in pixels: |drawn − finest| · focal /
     * (distance from the eye to the sample's true point) for a perspective view, · focal alone for an orthographic one.
     */
    private static double worstPixels(HeightPyramid pyramid, int cells, PatchList patches, int i, float[] offsets,
            Vector3f eye, double focal, boolean perspective) {
        HeightMap fine = pyramid.base();
        int level = patches.level(i);
        assertEquals(1 << level, patches.sampleStep(i) << patches.strideLog2(i), "vertices 2^L samples apart");
        HeightMap coarse = pyramid.level(level);
        int step = 1 << level;
        int x0 = patches.originSampleX(i);
        int z0 = patches.originSampleZ(i);
        int span = cells * patches.sampleStep(i);
        double worst = 0;
        for (int z = z0; z <= z0 + span; z++) {
            for (int x = x0; x <= x0 + span; x++) {
                int cx = Math.floorDiv(x, step);
                int cz = Math.floorDiv(z, step);
                double u = (x - cx * step) / (double) step;
                double v = (z - cz * step) / (double) step;
                double[] corners = {coarse.sample(cx, cz), coarse.sample(cx + 1, cz), coarse.sample(cx, cz + 1),
                        coarse.sample(cx + 1, cz + 1)};
                double h = fine.sample(x, z);
                double error = Math.max(Math.abs(diagonal(corners, u, v, true) - h),
                        Math.abs(diagonal(corners, u, v, false) - h));
                if (error == 0) {
                    continue;
                }
                double scale = focal;
                if (perspective) {
                    int copy = patches.copy(i);
                    double wx = (x - fine.size() / 2.0) * fine.spacing() + offsets[2 * copy] - eye.x;
                    double wz = (z - fine.size() / 2.0) * fine.spacing() + offsets[2 * copy + 1] - eye.z;
                    scale /= Math.sqrt(wx * wx + (h - eye.y) * (h - eye.y) + wz * wz);
                }
                worst = Math.max(worst, error * scale);
            }
        }
        return worst;
    }

    /**
     * Height at (u, v) ∈ [0, 1]² of a cell with corners {nw, ne, sw, se}, cut into two triangles along the diagonal
     * nw–se or ne–sw, by barycentric weights in the triangle holding the point.
     */
    private static double diagonal(double[] c, double u, double v, boolean northWestToSouthEast) {
        double[][] p = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
        int[][] triangles = northWestToSouthEast ? new int[][] {{0, 2, 3}, {0, 3, 1}} : new int[][] {{0, 1, 2},
                {1, 3, 2}};
        for (int[] t : triangles) {
            double[] a = p[t[0]], b = p[t[1]], d = p[t[2]];
            double area = (b[0] - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (b[1] - a[1]);
            double wb = ((u - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (v - a[1])) / area;
            double wd = ((b[0] - a[0]) * (v - a[1]) - (u - a[0]) * (b[1] - a[1])) / area;
            double wa = 1 - wb - wd;
            if (wa >= -1e-9 && wb >= -1e-9 && wd >= -1e-9) {
                return wa * c[t[0]] + wb * c[t[1]] + wd * c[t[2]];
            }
        }
        throw new AssertionError("(" + u + ", " + v + ") in neither triangle");
    }

    private static String describe(PatchList patches) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < patches.size(); i++) {
            s.append(patches.node(i)).append('@').append(patches.level(i)).append(' ');
        }
        return s.toString();
    }
}
