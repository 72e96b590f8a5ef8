package org.openworld.engine.antialias;

import org.openworld.engine.core.Owned;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.temporal.TemporalAntialias;

/**
 * The engine's anti-aliasing, whichever {@code antialias.method} names: {@link #viewer} begins a frame (the viewer's
 * camera as the method wants it, jittered for TAA; the camera, frame and settings kept for the pass), and
 * {@link #draw} makes the anti-aliased picture after the passes.
 */
public final class Antialiasing implements AutoCloseable {

    private final Owned owned = new Owned("antialias");
    private final Fxaa fxaa;
    private final TemporalAntialias temporal;
    private ViewCamera camera;
    private long frame;
    private AntialiasSettings settings = AntialiasSettings.DEFAULTS;

    public Antialiasing(GlContext gl, ShaderLibrary shaders) {
        try {
            fxaa = owned.own(new Fxaa(gl, shaders));
            temporal = owned.own(new TemporalAntialias(gl, shaders));
        } catch (RuntimeException e) {
            owned.close();
            throw e;
        }
    }

    /** The camera the viewer's passes draw engine frame {@code frame} with, into {@code scene}. */
    public ViewCamera viewer(ViewCamera camera, long frame, Framebuffer scene, AntialiasSettings settings) {
        this.camera = camera;
        this.frame = frame;
        this.settings = settings;
        return settings.method() == AntialiasSettings.Method.TAA
                ? temporal.jittered(camera, frame, settings.samples(), scene) : camera;
    }

    /** Draws {@code scene} anti-aliased into {@code target}, as the last {@link #viewer} call's settings say. */
    public void draw(Framebuffer scene, Framebuffer target, DrawStats stats) {
        if (settings.method() == AntialiasSettings.Method.TAA) {
            temporal.draw(scene, target, camera, frame, settings.blend(), stats);
        } else {
            fxaa.draw(scene, target, settings, stats);
        }
    }

    @Override
    public void close() {
        owned.close();
    }
}
