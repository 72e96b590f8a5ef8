package org.openworld.engine.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class CatmullRomTest {

    private static final double EPS = 1e-9;

    @Test
    void segmentStartsAndEndsOnItsInnerPoints() {
        Vector3d p0 = new Vector3d(0, 0, 0);
        Vector3d p1 = new Vector3d(10, 5, 0);
        Vector3d p2 = new Vector3d(12, 5, 30);
        Vector3d p3 = new Vector3d(-4, 0, 31);
        assertEquals(0, p1.distance(CatmullRom.centripetal(p0, p1, p2, p3, 0, new Vector3d())), EPS);
        assertEquals(0, p2.distance(CatmullRom.centripetal(p0, p1, p2, p3, 1, new Vector3d())), EPS);
    }

    @Test
    void evenlySpacedCollinearPointsGiveTheStraightLine() {
        Vector3d p = CatmullRom.centripetal(new Vector3d(0, 0, 0), new Vector3d(1, 2, 3), new Vector3d(2, 4, 6),
                new Vector3d(3, 6, 9), 0.25, new Vector3d());
        assertEquals(0, p.distance(1.25, 2.5, 3.75), EPS);
    }

    @Test
    void scalarPyramidReproducesAStraightLineForAnyKnots() {
        // values 2t + 1 at uneven knots: a Catmull-Rom curve reproduces linear data exactly
        double v = CatmullRom.interpolate(1, 3, 9, 21, 0, 1, 4, 10, 2.5);
        assertEquals(6, v, EPS);
    }

    @Test
    void coincidentPointsStayFinite() {
        Vector3d a = new Vector3d(5, 5, 5);
        for (double u = 0; u <= 1; u += 0.125) {
            Vector3d p = CatmullRom.centripetal(a, a, a, new Vector3d(6, 5, 5), u, new Vector3d());
            assertTrue(p.isFinite(), "u=" + u + " gave " + p);
            assertEquals(0, p.distance(a), EPS);
        }
        Vector3d p = CatmullRom.centripetal(new Vector3d(0, 0, 0), a, new Vector3d(a), new Vector3d(9, 9, 9), 0.5,
                new Vector3d());
        // doubles: a segment between two equal keys stays on them; 1e-6 covers the centripetal weights' divisions by
        // short chords
        assertEquals(0, p.distance(a), 1e-6);
    }
}
