package org.openworld.engine.colour;

/**
 * CIEDE2000 (ΔE00), the CIE's colour difference between two CIELAB colours, with the reference conditions' weights
 * k_L = k_C = k_H = 1. It is scaled so that about 1 is a just noticeable difference between two flat patches side by
 * side; about 2 to 3 is seen at a glance; tens are different colours.
 *
 * <p>The steps follow Sharma, Wu and Dalal (2005), equations 2 to 22: a* is stretched for near-neutral colours (G),
 * then lightness, chroma and hue differences are each weighted by how sensitive the eye is there (S_L, S_C, S_H), and
 * a rotation term (R_T) corrects the blue region. Hue angles are in degrees, as in the paper. It costs a few
 * square roots and six cosines: fine for millions of pixels, not for a shader.
 */
public final class DeltaE {

    /** 25^7: the chroma at which the neutral-axis correction G and the rotation R_T are half on. */
    private static final double POW25_7 = Math.pow(25, 7);

    private DeltaE() {
    }

    /** ΔE00 between two colours: 0 for equal colours, symmetric in its arguments. */
    public static double ciede2000(Lab first, Lab second) {
        // 1. a* stretched near the neutral axis, then chroma C' and hue h' (degrees, 0 for a grey)
        double cMean = (Math.hypot(first.a(), first.b()) + Math.hypot(second.a(), second.b())) / 2;
        double g = 0.5 * (1 - Math.sqrt(pow7(cMean) / (pow7(cMean) + POW25_7)));
        double a1 = (1 + g) * first.a();
        double a2 = (1 + g) * second.a();
        double c1 = Math.hypot(a1, first.b());
        double c2 = Math.hypot(a2, second.b());
        double h1 = hueDegrees(a1, first.b());
        double h2 = hueDegrees(a2, second.b());

        // 2. differences in lightness, chroma and hue (the hue difference taken the short way round)
        double dL = second.l() - first.l();
        double dC = c2 - c1;
        double dh = 0;
        if (c1 * c2 != 0) {
            dh = h2 - h1;
            if (dh > 180) {
                dh -= 360;
            } else if (dh < -180) {
                dh += 360;
            }
        }
        double dH = 2 * Math.sqrt(c1 * c2) * Math.sin(Math.toRadians(dh / 2));

        // 3. the weights at the pair's mean lightness, chroma and hue
        double lMean = (first.l() + second.l()) / 2;
        double cMeanPrime = (c1 + c2) / 2;
        double hMean = h1 + h2;
        if (c1 * c2 != 0) {
            hMean = Math.abs(h1 - h2) <= 180 ? hMean / 2 : (hMean < 360 ? hMean + 360 : hMean - 360) / 2;
        }
        double t = 1 - 0.17 * cosDegrees(hMean - 30) + 0.24 * cosDegrees(2 * hMean)
                + 0.32 * cosDegrees(3 * hMean + 6) - 0.20 * cosDegrees(4 * hMean - 63);
        double lFromMid = (lMean - 50) * (lMean - 50);
        double sL = 1 + 0.015 * lFromMid / Math.sqrt(20 + lFromMid);
        double sC = 1 + 0.045 * cMeanPrime;
        double sH = 1 + 0.015 * cMeanPrime * t;

        // 4. the rotation that corrects the blue region, around hue 275 degrees
        double dTheta = 30 * Math.exp(-Math.pow((hMean - 275) / 25, 2));
        double rC = 2 * Math.sqrt(pow7(cMeanPrime) / (pow7(cMeanPrime) + POW25_7));
        double rT = -Math.sin(Math.toRadians(2 * dTheta)) * rC;

        double l = dL / sL;
        double c = dC / sC;
        double h = dH / sH;
        return Math.sqrt(l * l + c * c + h * h + rT * c * h);
    }

    private static double hueDegrees(double a, double b) {
        if (a == 0 && b == 0) {
            return 0;
        }
        double h = Math.toDegrees(Math.atan2(b, a));
        return h < 0 ? h + 360 : h;
    }

    private static double cosDegrees(double degrees) {
        return Math.cos(Math.toRadians(degrees));
    }

    private static double pow7(double x) {
        double x2 = x * x;
        return x2 * x2 * x2 * x;
    }
}
