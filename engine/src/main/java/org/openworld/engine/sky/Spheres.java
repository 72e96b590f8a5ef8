package org.openworld.engine.sky;

/**
 * Ray–sphere distances for rays that start inside the atmosphere, in the (r, μ) form of Bruneton 2017: a ray
 * starts at distance r from the planet's centre with μ the cosine of its zenith angle, so its points are at radius
 * √(r² + t² + 2rμt) after a distance t.
 */
final class Spheres {

    private Spheres() {
    }

    /** Radius after travelling t from radius r with zenith cosine μ. */
    static double radiusAt(double r, double mu, double t) {
        return Math.sqrt(Math.max(r * r + t * t + 2 * r * mu * t, 0));
    }

    /** Distance along the ray to the top of the atmosphere (the far intersection), m. */
    static double distanceToTop(double r, double mu) {
        double top = Atmosphere.TOP_RADIUS;
        double discriminant = r * r * (mu * mu - 1) + top * top;
        return Math.max(-r * mu + Math.sqrt(Math.max(discriminant, 0)), 0);
    }

    /** Whether the ray meets the ground. */
    static boolean hitsGround(double r, double mu) {
        double bottom = Atmosphere.BOTTOM_RADIUS;
        return mu < 0 && r * r * (mu * mu - 1) + bottom * bottom >= 0;
    }

    /** Distance along the ray to the ground (the near intersection), m; only meaningful if {@link #hitsGround}. */
    static double distanceToGround(double r, double mu) {
        double bottom = Atmosphere.BOTTOM_RADIUS;
        double discriminant = r * r * (mu * mu - 1) + bottom * bottom;
        return Math.max(-r * mu - Math.sqrt(Math.max(discriminant, 0)), 0);
    }

    /** Distance to where the ray leaves the atmosphere or meets the ground, whichever comes first, m. */
    static double distanceToEdge(double r, double mu) {
        return hitsGround(r, mu) ? distanceToGround(r, mu) : distanceToTop(r, mu);
    }
}
