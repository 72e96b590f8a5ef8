package org.openworld.engine.sky.clouds;

import org.openworld.engine.core.Owned;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Labelled;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.Texture2D;

/**
 * The clouds' render targets for one picture size, on the quarter grid (a quarter of the width and of the height,
 * {@link #GRID_DIVISOR}): this frame's march and two histories that the resolve writes in turn (one read while the
 * other is written). Each is two textures: the light (RGBA16F, rgb light and a transmittance) and the distances
 * (RGBA32F: metres up to the 10⁷ that stands for the sky, beyond a half float). At 1280 × 720: 320 × 180 texels,
 * 1.4 MB in all.
 */
final class CloudTargets implements Labelled {

    /** The grid's texel is this many pixels on a side: 1/16 of the pixels are marched, 1/64 per frame. */
    static final int GRID_DIVISOR = 4;

    private final Owned owned = new Owned();
    final int width;
    final int height;
    final int gridWidth;
    final int gridHeight;
    final Texture2D freshLight;
    final Texture2D freshDepth;
    final Framebuffer fresh;
    final Texture2D[] historyLight = new Texture2D[2];
    final Texture2D[] historyDepth = new Texture2D[2];
    final Framebuffer[] history = new Framebuffer[2];

    CloudTargets(GlContext gl, int width, int height) {
        this.width = width;
        this.height = height;
        gridWidth = (width + GRID_DIVISOR - 1) / GRID_DIVISOR;
        gridHeight = (height + GRID_DIVISOR - 1) / GRID_DIVISOR;
        try {
            freshLight = owned.own(grid(gl, Format.RGBA16F, Sampling.NEAREST_CLAMP));
            freshDepth = owned.own(grid(gl, Format.RGBA32F, Sampling.NEAREST_CLAMP));
            fresh = owned.own(Framebuffer.onTextures(gl, freshLight, freshDepth));
            for (int i = 0; i < 2; i++) {
                historyLight[i] = owned.own(grid(gl, Format.RGBA16F, Sampling.LINEAR_CLAMP));
                historyDepth[i] = owned.own(grid(gl, Format.RGBA32F, Sampling.NEAREST_CLAMP));
                history[i] = owned.own(Framebuffer.onTextures(gl, historyLight[i], historyDepth[i]));
            }
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    private Texture2D grid(GlContext gl, Format format, Sampling sampling) {
        return Texture2D.empty(gl, gridWidth, gridHeight, format, sampling);
    }

    boolean fits(int w, int h) {
        return width == w && height == h;
    }

    @Override
    public void label(String name) {
        fresh.label(name + ".fresh");
        freshLight.label(name + ".freshLight");
        freshDepth.label(name + ".freshDepth");
        for (int i = 0; i < 2; i++) {
            history[i].label(name + ".history" + i);
            historyLight[i].label(name + ".historyLight" + i);
            historyDepth[i].label(name + ".historyDepth" + i);
        }
    }

    @Override
    public void close() {
        owned.close();
    }
}
