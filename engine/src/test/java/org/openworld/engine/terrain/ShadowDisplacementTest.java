package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Vector3d;
import org.joml.Vector4d;
import org.junit.jupiter.api.Test;

/**
 * Why the sun's pass needs no finer casters at a low sun: a height error δh moves a shadow on flat ground by
 * δh / tan(e) metres (e the sun's elevation), unbounded as the sun sets, but the map sees the ground stretched by the
 * same 1 / sin(e) along the sun's azimuth, so in the map's own texels the shadow moves by δh · cos(e) / t ≤ δh / t,
 * what the texel rule bounds. Checked here by casting the shadows and projecting them through the light's matrices,
 * not by the rule's formula.
 */
class ShadowDisplacementTest {

    @Test
    void anAcceptedHeightErrorMovesItsShadowByAtMostTheTexelBoundAtAnySunElevation() {
        Random random = new Random(23);
        int accepted = 0;
        int longInMetres = 0;
        for (int trial = 0; trial < 4000; trial++) {
            double elevation = Math.toRadians(random.nextDouble(0.5, 89));
            double azimuth = random.nextDouble(0, 2 * Math.PI);
            Vector3d toSun = new Vector3d(Math.cos(elevation) * Math.sin(azimuth), Math.sin(elevation),
                    Math.cos(elevation) * Math.cos(azimuth));
            double side = Math.pow(2, random.nextDouble(6, 14));
            int resolution = 1 << (8 + random.nextInt(5));
            double bound = Math.pow(2, random.nextDouble(-2, 3));
            Matrix4f projection = new Matrix4f().ortho((float) (-side / 2), (float) (side / 2), (float) (-side / 2),
                    (float) (side / 2), 0, 20_000);
            // the same box in doubles for the check: shadows of a low sun land kilometres away
            Matrix4d lightViewProjection = new Matrix4d().ortho(-side / 2, side / 2, -side / 2, side / 2, 0, 20_000)
                    .lookAt(new Vector3d(toSun).mul(10_000), new Vector3d(), new Vector3d(0, 1, 0));
            DetailLimit limit = DetailLimit.projected(projection, resolution, resolution, bound);
            double texel = side / resolution;
            double error = random.nextDouble(0, 3 * bound * texel);
            if (!limit.fineEnough(1 + random.nextInt(8), error, random.nextDouble(0, 10_000))) {
                continue;
            }
            accepted++;
            // a caster point at height y above flat ground at 0, drawn δh too low
            double x = random.nextDouble(-side / 4, side / 4);
            double z = random.nextDouble(-side / 4, side / 4);
            double y = random.nextDouble(0, 200);
            Vector3d exact = shadowOnGround(x, y, z, toSun);
            Vector3d drawn = shadowOnGround(x, y - error, z, toSun);
            double texels = texels(lightViewProjection, exact, drawn, resolution);
            assertTrue(texels <= bound * (1 + 1e-4), "sun " + Math.toDegrees(elevation) + "°: error " + error
                    + " m moves the shadow " + exact.distance(drawn) + " m, " + texels + " texels; bound " + bound);
            // a receiver drawn δh too low looks the map up where the sun sees that lower point
            double looked = texels(lightViewProjection, new Vector3d(x, y, z),
                    new Vector3d(x, y - error, z), resolution);
            assertTrue(looked <= bound * (1 + 1e-4), "a receiver's error of " + error + " m moves its lookup "
                    + looked + " texels; bound " + bound);
            longInMetres += exact.distance(drawn) > 4 * bound * texel ? 1 : 0;
        }
        assertTrue(accepted > 1000, accepted + " errors accepted");
        assertTrue(longInMetres > 50, "on the ground, in metres, a low sun's shadows move by many texels' widths: "
                + longInMetres);
    }

    /** Where the sun's ray through (x, y, z) meets the ground at height 0. */
    private static Vector3d shadowOnGround(double x, double y, double z, Vector3d toSun) {
        double t = y / toSun.y;
        return new Vector3d(x - t * toSun.x, 0, z - t * toSun.z);
    }

    /** Distance between two points in the map's texels, across the light's view. */
    private static double texels(Matrix4d lightViewProjection, Vector3d a, Vector3d b, int resolution) {
        Vector4d pa = lightViewProjection.transform(new Vector4d(a, 1));
        Vector4d pb = lightViewProjection.transform(new Vector4d(b, 1));
        return Math.hypot(pa.x - pb.x, pa.y - pb.y) * resolution / 2;
    }
}
