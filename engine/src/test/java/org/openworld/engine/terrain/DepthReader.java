package org.openworld.engine.terrain;

import static org.lwjgl.opengl.GL30C.GL_DEPTH_COMPONENT;
import static org.lwjgl.opengl.GL30C.GL_FLOAT;
import static org.lwjgl.opengl.GL30C.GL_READ_FRAMEBUFFER;
import static org.lwjgl.opengl.GL30C.glBindFramebuffer;
import static org.lwjgl.opengl.GL30C.glReadPixels;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.gl.Framebuffer;

/** Reads the scene's depth in the overlay pass and keeps what turns it back into world points (terrain GL tests). */
public final class DepthReader implements EngineSystem {
    private final Matrix4f toWorld = new Matrix4f();
    /** The eye of the pass read. */
    public final Vector3f eye = new Vector3f();
    private float[] depth = new float[0];
    private int width;
    private int height;

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("depth-reader").draws(Pass.OVERLAY);
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        Framebuffer scene = context.target();
        width = scene.width();
        height = scene.height();
        depth = new float[width * height];
        glBindFramebuffer(GL_READ_FRAMEBUFFER, scene.id());
        glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
        context.camera().viewProjection().invert(toWorld);
        eye.set(context.camera().position());
    }

    /** The world point drawn at image pixel (x, y from the top), or null where nothing was drawn. */
    public Vector3f point(int x, int y) {
        float d = depth[(height - 1 - y) * width + x];
        if (d >= 1) {
            return null;
        }
        Vector4f clip = new Vector4f(2 * (x + 0.5f) / width - 1, 1 - 2 * (y + 0.5f) / height, 2 * d - 1, 1);
        toWorld.transform(clip);
        return new Vector3f(clip.x / clip.w, clip.y / clip.w, clip.z / clip.w);
    }
}
