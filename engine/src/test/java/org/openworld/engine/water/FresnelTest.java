package org.openworld.engine.water;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The Fresnel reflectance against values worked out by hand for n = 1.333 (air taken as n = 1). */
class FresnelTest {

    private static final double N = 1.333;

    @Test
    void straightDownWaterReflectsTwoPercent() {
        // ((n - 1) / (n + 1))^2 = (0.333 / 2.333)^2 = 0.1427347^2
        assertEquals(0.0203732, Fresnel.reflectance(1, 1, N), 1e-6);
    }

    @Test
    void atBrewstersAngleOnlyTheSPolarisationIsReflected() {
        // tan θB = n: θB = 53.1232°, cos θB = 0.600136, and θt = 90° − θB, so cos θt = sin θB = 0.799898;
        // rs = (0.600136 − 1.333 · 0.799898) / (0.600136 + 1.333 · 0.799898) = −0.279760, rp = 0, R = rs² / 2
        double cosBrewster = Math.cos(Math.atan(N));
        // the reference to 7 places: 1e-6 is a unit of the last; the table is float (1e-6 below), the exact cases
        // double (1e-12)
        assertEquals(0.0391355, Fresnel.reflectance(cosBrewster, 1, N), 1e-6);
    }

    @Test
    void sixtyDegreesFromTheVertical() {
        // sin θt = sin 60° / 1.333 = 0.649676, cos θt = 0.760201; cos θi = 0.5
        // rs = (0.5 − 1.013348) / (0.5 + 1.013348) = −0.339213, rp = (0.760201 − 0.6665) / (0.760201 + 0.6665) = 0.065676
        // R = (0.115065 + 0.004313) / 2
        assertEquals(0.0596909, Fresnel.reflectance(0.5, 1, N), 1e-6);
    }

    @Test
    void grazingLightIsAllReflected() {
        assertEquals(1, Fresnel.reflectance(0, 1, N), 1e-12);
    }

    @Test
    void fromBelowBeyondTheCriticalAngleEverythingIsReflected() {
        // sin θc = 1 / 1.333: θc = 48.6066°
        double critical = Math.toRadians(48.6066);
        assertEquals(1, Fresnel.reflectance(Math.cos(critical + 1e-3), N, 1), 0);
        // 0.05 rad (3°) inside the critical angle the reflectance is already well down from total (1)
        assertTrue(Fresnel.reflectance(Math.cos(critical - 0.05), N, 1) < 0.5);
        // straight up from below reflects as much as straight down from above
        assertEquals(0.0203732, Fresnel.reflectance(1, N, 1), 1e-6);
    }

    @Test
    void theTableHoldsBothDirectionsAtTexelCentres() {
        int size = 8;
        float[] table = Fresnel.table(size);
        assertEquals(2 * size, table.length);
        for (int i = 0; i < size; i++) {
            double cos = (i + 0.5) / size;
            assertEquals(Fresnel.reflectance(cos, Fresnel.AIR_INDEX, Fresnel.WATER_INDEX), table[i], 1e-6);
            assertEquals(Fresnel.reflectance(cos, Fresnel.WATER_INDEX, Fresnel.AIR_INDEX), table[size + i], 1e-6);
        }
        // from the air the reflectance falls as the ray steepens; from below, the shallow half is total reflection
        assertTrue(table[0] > table[size - 1]);
        assertEquals(1, table[size], 0);
    }
}
