package org.openworld.engine;

import static org.lwjgl.opengl.GL11C.GL_COLOR_BUFFER_BIT;
import static org.lwjgl.opengl.GL11C.GL_LINEAR;
import static org.lwjgl.opengl.GL30C.GL_DRAW_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.GL_READ_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;
import static org.lwjgl.opengl.GL30C.glBlitFramebuffer;

import org.openworld.engine.core.Owned;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Sampling;

/**
 * The engine's scene target at the render scale ({@code engine.render-scale}, docs/design.md, "Render scale"),
 * the anti-aliased copy of it ({@code antialias.method}, {@link org.openworld.engine.antialias}), and the full-size
 * picture made from them. Below scale 1 the viewer's passes draw into a target of scale × the
 * picture's width and height, so the fragment shaders run for scale² of the pixels (0.75: 56 %); at the end of the
 * frame one blit with linear filtering stretches it over the picture. The picture is what the window shows, what is
 * read back and what the panel and HUD draw over, so the picture keeps its size and the text stays sharp; the price
 * is a softer picture (an edge blurs over about 1 / scale pixels) and the blit itself, one read and one write per
 * picture pixel. At scale 2 (supersampling, the one scale above 1: {@link EngineSettings}) the passes draw four times
 * the pixels and the same blit halves each side: every picture pixel's centre falls between four samples, so the
 * linear filter returns their mean, a box filter over the pixel.
 * At scale 1 the two are one target: nothing is copied and the picture is what it was without a scale.
 * With anti-aliasing on, its pass writes the scene into a colour target of the scene's size, which is the picture at
 * scale 1 and what is stretched below it; off, that target is the scene target itself.
 */
final class ScaledScene {

    private final GlContext gl;
    /** The engine's: holds the scene target as {@code engine.scene} and, below scale 1, {@code engine.picture}. */
    private final Owned owned;
    private Framebuffer scene;
    /** The scene anti-aliased, at the scene's size; the scene target itself with anti-aliasing off. */
    private Framebuffer resolved;
    /** The full-size picture; {@link #resolved} at scale 1. */
    private Framebuffer picture;

    ScaledScene(GlContext gl, Owned owned, int width, int height, double scale, boolean antialiased) {
        this.gl = gl;
        this.owned = owned;
        fit(width, height, scale, antialiased);
    }

    /** A side of the scene target: the picture's side times the scale, at least one pixel. */
    static int scaled(int side, double scale) {
        return Math.max(1, (int) Math.round(side * scale));
    }

    /**
     * Re-makes the targets when the picture's size (a resized window), the scale (the panel) or the anti-aliasing's
     * switch has changed; 0×0 (minimised) is ignored.
     */
    void fit(int width, int height, double scale, boolean antialiased) {
        int w = scaled(width, scale);
        int h = scaled(height, scale);
        if (width <= 0 || height <= 0 || (picture != null && picture.width() == width && picture.height() == height
                && scene.width() == w && scene.height() == h && antialiased() == antialiased)) {
            return;
        }
        if (picture != resolved) {
            owned.drop(picture);
        }
        if (resolved != scene) {
            owned.drop(resolved);
        }
        owned.drop(scene);
        scene = owned.own("scene", Framebuffer.scene(gl, w, h));
        // colour alone: what draws over the picture (the panel) needs no depth
        resolved = antialiased ? owned.own("antialiased", colour(w, h)) : scene;
        picture = w == width && h == height ? resolved : owned.own("picture", colour(width, height));
    }

    private Framebuffer colour(int width, int height) {
        return new Framebuffer(gl, width, height, Format.RGBA8, null, Sampling.NEAREST_CLAMP);
    }

    /** Where the viewer's passes draw. */
    Framebuffer scene() {
        return scene;
    }

    /** The full-size picture: shown, read back, drawn over. */
    Framebuffer picture() {
        return picture;
    }

    /** Where the anti-aliasing pass writes the scene: the picture at scale 1. */
    Framebuffer resolved() {
        return resolved;
    }

    /** Whether the scene is anti-aliased into a target of its own. */
    boolean antialiased() {
        return resolved != scene;
    }

    /** Whether the scene is drawn at another size than the picture, to be resized to it at the end of the frame. */
    boolean scaled() {
        return picture != resolved;
    }

    /** Stretches the (anti-aliased) scene over the picture, or at scale 2 halves it, filtering linearly. */
    void upscale() {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, resolved.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, picture.id());
        glBlitFramebuffer(0, 0, resolved.width(), resolved.height(), 0, 0, picture.width(), picture.height(),
                GL_COLOR_BUFFER_BIT, GL_LINEAR);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
}
