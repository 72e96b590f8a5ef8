package org.openworld.engine.elevation;

import org.openworld.engine.terrain.heights.BandedHeights;
import org.openworld.engine.terrain.heights.HeightMap;
import org.openworld.engine.terrain.heights.PowerSpectrum;
import org.openworld.engine.terrain.heights.TerrainSettings;

/**
 * The octaves an elevation model is too coarse to hold, synthesised with the unbounded world's band machinery
 * ({@link BandedHeights}) and scaled to continue the model's own measured spectrum.
 *
 * <h2>Measuring the slope</h2>
 * The largest power-of-two square inside the model, resampled at its spacing D, is Hann-tapered (its edges would
 * otherwise add a 1/f² leak) and its radially averaged power spectrum fitted as {@code log P = s · log f + c}
 * ({@link PowerSpectrum#tapered}) from 4 cycles per square to 1/(4D): the top octave up to the model's Nyquist
 * frequency 1/(2D) is left out, as every model smooths it (averaging at capture, resampling). Real relief gives
 * s ≈ −4 (β = −s/2 ≈ 2); β is held within the engine's 1 .. 3.
 *
 * <h2>The missing variance</h2>
 * Parseval for the unnormalised n² DFT of a square E = nD metres across: the variance between the frequencies f₁ and f₂
 * is {@code σ² = 2π E²/n⁴ · ∫ P(f) f df = 2π E²/n⁴ · 10^c (f₂^(s+2) − f₁^(s+2))/(s+2)}, divided by 9/64, the power
 * the Hann taper keeps ((3/8)² for its mean square along each axis). The detail spans f₁ = 1/(2D) (the model's
 * Nyquist frequency) to f₂ = 1/(2d), d the detail's spacing.
 *
 * <h2>The bands</h2>
 * {@link BandedHeights} made with spacing d, exponent β and wavelengths 2d .. 2D holds exactly the octaves
 * 2d–4d, 4d–8d, ... D–2D, each a randomly turned periodic tile; its relief is set to 6σ (the world spans ±3σ) and its
 * sea fraction to one half, so its height is the bands' sum with mean 0 and standard deviation σ. Cost: one 512² FFT
 * and 1 MiB per octave, then 16 samples per octave per height.
 */
final class DetailBands {

    /** The Hann window keeps (3/8)² of a stationary field's power in 2D. */
    private static final double HANN_POWER = 9.0 / 64;

    private final BandedHeights bands;
    private final double beta;
    private final double sigma;

    private DetailBands(BandedHeights bands, double beta, double sigma) {
        this.bands = bands;
        this.beta = beta;
        this.sigma = sigma;
    }

    /**
     * The detail between the model's spacing {@code coarse} and {@code fine} (a power of two below it), measured from
     * {@code square}, an n × n window of the model at spacing {@code coarse}.
     */
    static DetailBands measure(float[] square, int n, double coarse, double fine, int seed) {
        PowerSpectrum spectrum = PowerSpectrum.tapered(new HeightMap(n, coarse, square, false));
        double extent = n * coarse;
        PowerSpectrum.Fit fit = spectrum.fit(4 / extent, 1 / (4 * coarse));
        double beta = Math.max(1, Math.min(3, -fit.slope() / 2));
        double s = -2 * beta;
        double f1 = 1 / (2 * coarse);
        double f2 = 1 / (2 * fine);
        double integral = Math.pow(10, fit.intercept()) * (Math.pow(f2, s + 2) - Math.pow(f1, s + 2)) / (s + 2);
        double variance = 2 * Math.PI * extent * extent / Math.pow(n, 4) * integral / HANN_POWER;
        double sigma = Math.sqrt(Math.max(0, variance));
        TerrainSettings d = TerrainSettings.DEFAULTS;
        TerrainSettings s2 = new TerrainSettings(256, fine, Math.max(6 * sigma, 1e-6), 0.5, beta, 2 * fine,
                2 * coarse, "", d.snowBase(), d.snowFull(), d.snowMorphology(), TerrainSettings.World.UNBOUNDED,
                d.memoryBudget(), d.importScale(), 0, d.importDetail(), false, d.erosionTalus(), false);
        return new DetailBands(new BandedHeights(s2, seed), beta, sigma);
    }

    /** The detail at world (x, z), metres: mean 0, standard deviation {@link #sigma()}. */
    double at(double x, double z) {
        return bands.heightAt(x, z);
    }

    /** The exponent measured from the model and continued: amplitude ~ 1/f^β. */
    double beta() {
        return beta;
    }

    /** Standard deviation of the synthesised detail, metres. */
    double sigma() {
        return sigma;
    }

    /** Octaves synthesised. */
    int octaves() {
        return bands.levels();
    }
}
