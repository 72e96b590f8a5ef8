package org.openworld.engine.culling;

import static org.lwjgl.opengl.GL11C.*;

import org.joml.Matrix4d;
import org.joml.Matrix4fc;
import org.joml.Vector3d;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;

/**
 * Draws the twelve edges of a frustum, seen from the current camera: the debug view of {@link CullingSettings#freeze}.
 * Core-profile OpenGL draws lines one pixel wide at most, so each edge is a ribbon of two triangles that
 * {@code shaders/culling/outline.vert} turns towards the screen; the static mesh holds only which corners each edge
 * joins, and the corners come as uniforms.
 */
final class FrustumOutline {

    /** Width of the drawn edges, pixels: visible at a glance without hiding what lies behind. */
    private static final float WIDTH_PX = 3;
    private static final int CORNERS = 8;
    /** An edge's four ribbon vertices in drawing order: (which end, which side). */
    private static final float[][] RIBBON = {{0, -1}, {0, 1}, {1, 1}, {1, -1}};

    private final ShaderProgram program;
    private final Mesh ribbons;
    private final Uniform.Vec3[] wsCorners = new Uniform.Vec3[CORNERS];
    private final Uniform.Float halfWidthPx;
    private final Matrix4d inverse = new Matrix4d();
    private final Vector3d corner = new Vector3d();
    /** The corners, world space in double (x, y, z each), kept while the outline is frozen. */
    private final double[] corners = new double[3 * CORNERS];

    FrustumOutline(EngineContext context) {
        program = context.own("outline", context.shaders().program("culling/outline.vert", "culling/outline.frag"));
        for (int i = 0; i < CORNERS; i++) {
            wsCorners[i] = program.vec3("wsCorners[" + i + "]");
        }
        halfWidthPx = program.float1("halfWidthPx");
        ribbons = context.own("outline.ribbons", edgeRibbons(context));
    }

    /**
     * Corner {@code i} of the clip cube is at x = ±1, y = ±1, z = ±1 by bits 0, 1 and 2 of {@code i}; an edge joins
     * two corners that differ in one bit. Each edge is four vertices (corner indices a, b; which end; which side).
     */
    private static Mesh edgeRibbons(EngineContext context) {
        float[] vertices = new float[12 * 4 * 4];
        int[] triangles = new int[12 * 6];
        int edge = 0;
        for (int a = 0; a < CORNERS; a++) {
            for (int bit = 1; bit < CORNERS; bit <<= 1) {
                int b = a | bit;
                if (b == a) {
                    continue;
                }
                for (int v = 0; v < 4; v++) {
                    int at = (edge * 4 + v) * 4;
                    vertices[at] = a;
                    vertices[at + 1] = b;
                    vertices[at + 2] = RIBBON[v][0];
                    vertices[at + 3] = RIBBON[v][1];
                }
                int base = edge * 4;
                System.arraycopy(new int[] {base, base + 1, base + 2, base, base + 2, base + 3}, 0, triangles,
                        edge * 6, 6);
                edge++;
            }
        }
        return new Mesh(context.gl(), vertices, triangles, new Mesh.Attribute(0, 2), new Mesh.Attribute(1, 2));
    }

    /**
     * Sets the frustum to outline: the corners are the clip cube's, taken back to world space through the inverse
     * of its view-projection, in double precision so the far corners of a deep perspective frustum stay exact. The
     * view-projection takes positions from (originX, 0, originZ), as the GPU's do; the corners are kept in the world's.
     */
    void setFrustum(Matrix4fc viewProjection, double originX, double originZ) {
        inverse.set(viewProjection).invert();
        for (int i = 0; i < CORNERS; i++) {
            inverse.transformProject((i & 1) == 0 ? -1 : 1, (i & 2) == 0 ? -1 : 1, (i & 4) == 0 ? -1 : 1, corner);
            corners[3 * i] = corner.x + originX;
            corners[3 * i + 1] = corner.y;
            corners[3 * i + 2] = corner.z + originZ;
        }
    }

    /**
     * Draws the edges, depth-tested against the scene, with the camera in the frame block, the corners from the
     * frame's render origin (originX, 0, originZ).
     */
    void draw(DrawStats stats, double originX, double originZ) {
        glEnable(GL_DEPTH_TEST);
        glDepthMask(false);
        glDisable(GL_CULL_FACE);
        program.use();
        for (int i = 0; i < CORNERS; i++) {
            wsCorners[i].set((float) (corners[3 * i] - originX), (float) corners[3 * i + 1],
                    (float) (corners[3 * i + 2] - originZ));
        }
        halfWidthPx.set(WIDTH_PX / 2);
        ribbons.draw(stats);
        glDepthMask(true);
    }
}
