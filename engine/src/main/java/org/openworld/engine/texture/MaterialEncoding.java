package org.openworld.engine.texture;

/**
 * Packs a {@link MaterialFields} into the two RGBA8 textures the terrain shader samples, rows from y = 0, texel
 * (x, y) at {@code 4 (y n + x)}.
 *
 * <p><b>Albedo</b> ({@link #albedo}): sRGB-encoded colour, alpha 255; upload as {@code GL_SRGB8_ALPHA8} so sampling
 * returns linear values. The encoding {@code e = 12.92 c} for c ≤ 0.0031308, else {@code 1.055 c^(1/2.4) − 0.055}, is
 * looked up in a table of {@value #SRGB_TABLE} + 1 steps rather than computed per texel: 8 bits of sRGB spend most of
 * their codes on dark values, where the curve is steep, and 4096 steps keep even those exact to 1/255.
 *
 * <p><b>Detail</b> ({@link #detail}): r, g = the tangent-space normal's x (along +u) and y (along +v), each encoded
 * {@code n · 0.5 + 0.5}; b = relief height 0..1 (material blending uses it); a = gloss 0..1. The normal comes from
 * the wrapped central differences of the relief h (texels), {@code n = normalize(−∂h/∂x, −∂h/∂y, 1)} with
 * {@code ∂h/∂x ≈ (h(x+1) − h(x−1)) / 2}; the wrap keeps the tile's edges as seamless as its interior. The relief is
 * stored as its mean ± 2.5 standard deviations over 0..1, so every material's height spreads alike for the blending
 * in the shader; beyond that it clips (1.2 % of a Gaussian's values).
 *
 * <p><b>Cost.</b> One pass per texture over the n² texels, a table look-up per colour channel, a square root per
 * normal: a few milliseconds at 512².
 *
 * <p><b>Limits.</b> 8 bits per channel: the normal's steps are 1/127.5 in each component (about 0.45° near flat),
 * fine for detail seen at a few texels per pixel, visible as banding only on very smooth, very close surfaces.
 */
public final class MaterialEncoding {

    /** Entries of the linear-to-sRGB table: 4096 steps keep dark values (where sRGB is steep) exact to 1/255. */
    private static final int SRGB_TABLE = 4096;

    private final int n;
    private final int mask;
    private final byte[] srgb = new byte[SRGB_TABLE + 1];

    /** Encodes tiles of {@code n}² texels, {@code n} a power of two. */
    public MaterialEncoding(int n) {
        this.n = n;
        this.mask = n - 1;
        for (int i = 0; i <= SRGB_TABLE; i++) {
            double c = (double) i / SRGB_TABLE;
            double e = c <= 0.0031308 ? 12.92 * c : 1.055 * Math.pow(c, 1 / 2.4) - 0.055;
            srgb[i] = (byte) Math.round(e * 255);
        }
    }

    /** RGBA8 albedo: the fields' colour sRGB-encoded, alpha 255. */
    public byte[] albedo(MaterialFields f) {
        byte[] out = new byte[n * n * 4];
        for (int i = 0; i < n * n; i++) {
            out[4 * i] = toSrgb(f.red()[i]);
            out[4 * i + 1] = toSrgb(f.green()[i]);
            out[4 * i + 2] = toSrgb(f.blue()[i]);
            out[4 * i + 3] = (byte) 255;
        }
        return out;
    }

    /**
     * RGBA8 detail: the normal from the wrapped central differences of the relief; the relief itself stored as
     * mean ± 2.5 standard deviations over 0..1; gloss (see the class comment).
     */
    public byte[] detail(MaterialFields f) {
        float[] h = f.height();
        double[] relief = new double[h.length];
        for (int i = 0; i < h.length; i++) {
            relief[i] = h[i];
        }
        double[] moments = PeriodicNoise.meanAndDeviation(relief);
        double mean = moments[0];
        double spread = 5 * moments[1];
        byte[] out = new byte[n * n * 4];
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int i = y * n + x;
                double dx = (h[index(x + 1, y)] - h[index(x - 1, y)]) * 0.5;
                double dy = (h[index(x, y + 1)] - h[index(x, y - 1)]) * 0.5;
                double len = Math.sqrt(dx * dx + dy * dy + 1);
                out[4 * i] = unorm(-dx / len * 0.5 + 0.5);
                out[4 * i + 1] = unorm(-dy / len * 0.5 + 0.5);
                out[4 * i + 2] = unorm(0.5 + (h[i] - mean) / spread);
                out[4 * i + 3] = unorm(f.gloss()[i]);
            }
        }
        return out;
    }

    /** The sRGB byte of a linear value, clamped to 0..1, from the table's nearest step. */
    byte toSrgb(float linear) {
        return srgb[(int) (Math.min(Math.max(linear, 0f), 1f) * SRGB_TABLE + 0.5f)];
    }

    /** The texel at (x, y) of the periodic tile: indices wrap. */
    private int index(int x, int y) {
        return (y & mask) * n + (x & mask);
    }

    private static byte unorm(double v) {
        return (byte) Math.round(Math.min(Math.max(v, 0), 1) * 255);
    }
}
