package org.openworld.engine.gl;

import static org.lwjgl.opengl.GL32C.*;

import java.nio.FloatBuffer;
import java.util.function.Function;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.lwjgl.system.MemoryUtil;

/**
 * A cube map ({@code GL_TEXTURE_CUBE_MAP}): six square faces sampled by direction, {@code texture(samplerCube, dir)},
 * for what surrounds the scene (the sky that glossy surfaces reflect). Made with {@link #fromDirections} from a
 * function of direction; stored as half floats ({@code GL_RGB16F}) so radiance above 1 survives.
 *
 * <p>Seamless filtering ({@code GL_TEXTURE_CUBE_MAP_SEAMLESS}, core since 3.2) is switched on in {@link #bind}: without
 * it, linear filtering stops at each face's border and the cube's edges show as lines in a blurry reflection. It is
 * global GL state that no other texture is affected by, so enabling it at every bind is harmless and keeps the
 * requirement next to its reason.
 */
public final class CubeMapTexture implements AutoCloseable {

    private final GlContext gl;
    private final int size;
    private int id;

    private CubeMapTexture(GlContext gl, int size) {
        this.gl = gl;
        this.size = size;
        this.id = glGenTextures();
        gl.objects().created(GlObjects.Kind.TEXTURE);
    }

    /**
     * Fills each face texel with the function's value at the direction through the texel's centre, builds the
     * mipmaps (coarser levels for blurrier reflections) and samples trilinearly.
     *
     * @param size     texels along a face's side
     * @param radiance linear RGB for a unit direction in world space
     */
    public static CubeMapTexture fromDirections(GlContext gl, int size, Function<Vector3fc, Vector3fc> radiance) {
        if (size <= 0) {
            throw new IllegalArgumentException("cube map face size must be positive, got " + size);
        }
        CubeMapTexture t = new CubeMapTexture(gl, size);
        glBindTexture(GL_TEXTURE_CUBE_MAP, t.id);
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
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
        return t;
    }

    /**
     * The unit direction through the centre of texel (x, y) of face f (+X, −X, +Y, −Y, +Z, −Z), from the table
     * of the OpenGL specification (section 8.13, "Cube Map Texture Selection"): with s, t the texel centre in
     * −1..1, face +X holds (1, −t, −s), −X (−1, −t, s), +Y (s, 1, t), −Y (s, −1, −t), +Z (s, −t, 1), −Z (−s, −t, −1).
     */
    private static Vector3f direction(int f, int x, int y, int size, Vector3f out) {
        float s = 2 * (x + 0.5f) / size - 1;
        float t = 2 * (y + 0.5f) / size - 1;
        switch (f) {
            case 0 -> out.set(1, -t, -s);
            case 1 -> out.set(-1, -t, s);
            case 2 -> out.set(s, 1, t);
            case 3 -> out.set(s, -1, -t);
            case 4 -> out.set(s, -t, 1);
            default -> out.set(-s, -t, -1);
        }
        return out.normalize();
    }

    /** Binds to texture unit {@code unit} and makes cube filtering seamless across the faces' edges. */
    public void bind(int unit) {
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_CUBE_MAP, id);
    }

    public int id() {
        return id;
    }

    public int size() {
        return size;
    }

    @Override
    public void close() {
        if (id != 0) {
            glDeleteTextures(id);
            gl.objects().deleted(GlObjects.Kind.TEXTURE);
            id = 0;
        }
    }
}
