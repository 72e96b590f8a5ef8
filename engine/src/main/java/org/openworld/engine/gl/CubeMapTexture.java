package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL32C.*;

import java.nio.FloatBuffer;
import java.util.function.Function;
import java.util.function.IntConsumer;
import org.joml.Matrix3f;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.lwjgl.opengl.GL30C;
import org.lwjgl.system.MemoryUtil;

/**
 * A cube map ({@code GL_TEXTURE_CUBE_MAP}): six square faces sampled by direction, {@code texture(samplerCube, dir)},
 * for what surrounds the scene (the sky that glossy surfaces reflect). Made with {@link #fromDirections} from a
 * function of direction, or drawn into face by face with {@link #render}; stored as half floats
 * ({@code GL_RGB16F}) so radiance above 1 survives, with a full mip chain for blurrier reflections.
 *
 * <p>Seamless filtering ({@code GL_TEXTURE_CUBE_MAP_SEAMLESS}, core since 3.2) is switched on in {@link #bind}: without
 * it, linear filtering stops at each face's border and the cube's edges show as lines in a blurry reflection. It is
 * global GL state that no other texture is affected by, so enabling it at every bind is harmless and keeps the
 * requirement next to its reason.
 */
public final class CubeMapTexture extends GlTexture {

    private int framebuffer;

    /** Trilinear, clamped at the faces' edges (seamless filtering joins them, see {@link #bind}). */
    private CubeMapTexture(GlContext gl, int size) {
        super(gl, GL_TEXTURE_CUBE_MAP, size, size, 1, Format.RGB16F, Sampling.TRILINEAR_CLAMP);
    }

    /**
     * Fills each face texel with the function's value at the direction through the texel's centre, builds the
     * mipmaps (coarser levels for blurrier reflections) and samples trilinearly.
     *
     * @param size     texels along a face's side
     * @param radiance linear RGB for a unit direction in world space
     */
    public static CubeMapTexture fromDirections(GlContext gl, int size, Function<Vector3fc, Vector3fc> radiance) {
        CubeMapTexture t = new CubeMapTexture(gl, size);
        FloatBuffer face = MemoryUtil.memAllocFloat(3 * size * size);
        try {
            Vector3f dir = new Vector3f();
            for (int f = 0; f < 6; f++) {
                face.clear();
                for (int y = 0; y < size; y++) {
                    for (int x = 0; x < size; x++) {
                        Vector3fc c = radiance.apply(direction(f, x, y, size, dir));
                        face.put(c.x()).put(c.y()).put(c.z());
                    }
                }
                face.flip();
                glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
                glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGB16F, size, size, 0, GL_RGB, GL_FLOAT, face);
            }
        } finally {
            MemoryUtil.memFree(face);
        }
        glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
        t.stored(fullChain(size, size));
        return t;
    }

    /**
     * Storage to draw into with {@link #render}: six empty {@code size}² faces and their mip levels.
     *
     * @param size texels along a face's side, a power of two
     */
    public static CubeMapTexture renderTarget(GlContext gl, int size) {
        if (size <= 0 || Integer.bitCount(size) != 1) {
            throw new IllegalArgumentException("cube map face size must be a power of two, got " + size);
        }
        CubeMapTexture t = new CubeMapTexture(gl, size);
        for (int f = 0; f < 6; f++) {
            for (int level = 0, s = size; s >= 1; level++, s /= 2) {
                glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, level, GL_RGB16F, s, s, 0, GL_RGB, GL_FLOAT,
                        (FloatBuffer) null);
            }
        }
        t.stored(fullChain(size, size));
        t.framebuffer = gl.objects().create(GlObjects.Kind.FRAMEBUFFER, GL30C::glGenFramebuffers);
        return t;
    }

    /**
     * Draws the six faces of a {@link #renderTarget}: for each face, binds it as the colour target with the viewport
     * on it and calls {@code drawFace} with the face's index (0 .. 5 as +X, −X, +Y, −Y, +Z, −Z; see
     * {@link #faceAxes}); then rebuilds the mip levels and restores the framebuffer and viewport that were bound.
     */
    public void render(IntConsumer drawFace) {
        if (framebuffer == 0) {
            throw new IllegalStateException("cube map made from directions, not a render target");
        }
        int previous = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
        int[] viewport = new int[4];
        glGetIntegerv(GL_VIEWPORT, viewport);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glViewport(0, 0, size(), size());
        for (int f = 0; f < 6; f++) {
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, id(), 0);
            drawFace.accept(f);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, previous);
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        bindForUpdate();
        glGenerateMipmap(GL_TEXTURE_CUBE_MAP);
    }

    /**
     * The axes of face f (+X, −X, +Y, −Y, +Z, −Z) as the columns of a matrix: the direction through the point
     * (s, t) of the face, s and t in −1..1 along its texel columns and rows, is {@code normalize(axes · (s, t, 1))}.
     * From the table of the OpenGL specification (section 8.13, "Cube Map Texture Selection"): face +X holds
     * (1, −t, −s), −X (−1, −t, s), +Y (s, 1, t), −Y (s, −1, −t), +Z (s, −t, 1), −Z (−s, −t, −1).
     */
    public static Matrix3f faceAxes(int f) {
        return switch (f) {
            case 0 -> new Matrix3f(0, 0, -1, 0, -1, 0, 1, 0, 0);
            case 1 -> new Matrix3f(0, 0, 1, 0, -1, 0, -1, 0, 0);
            case 2 -> new Matrix3f(1, 0, 0, 0, 0, 1, 0, 1, 0);
            case 3 -> new Matrix3f(1, 0, 0, 0, 0, -1, 0, -1, 0);
            case 4 -> new Matrix3f(1, 0, 0, 0, -1, 0, 0, 0, 1);
            case 5 -> new Matrix3f(-1, 0, 0, 0, -1, 0, 0, 0, -1);
            default -> throw new IllegalArgumentException("cube face " + f + ": expected 0..5");
        };
    }

    /** The unit direction through the centre of texel (x, y) of face f (see {@link #faceAxes}). */
    private static Vector3f direction(int f, int x, int y, int size, Vector3f out) {
        float s = 2 * (x + 0.5f) / size - 1;
        float t = 2 * (y + 0.5f) / size - 1;
        return faceAxes(f).transform(out.set(s, t, 1)).normalize();
    }

    /** Binds to texture unit {@code unit} and makes cube filtering seamless across the faces' edges. */
    public void bind(int unit) {
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        super.bind(unit);
    }

    /** Texels along a face's side. */
    public int size() {
        return width();
    }

    /** Names the cube map, and its render target's framebuffer as {@code name.target}. */
    @Override
    public void label(String name) {
        super.label(name);
        gl.debug().label(GL_FRAMEBUFFER, framebuffer, name + ".target");
    }

    @Override
    public void close() {
        framebuffer = gl.objects().delete(GlObjects.Kind.FRAMEBUFFER, framebuffer, GL30C::glDeleteFramebuffers);
        super.close();
    }
}
