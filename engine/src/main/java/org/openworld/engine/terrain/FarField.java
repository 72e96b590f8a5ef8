package org.openworld.engine.terrain;

import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.glDisable;

import org.joml.Vector3fc;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Uniform;

/**
 * The far field: a ring of ground from under the edge of the drawn patches out past the horizon, so that the world
 * ends where the planet's curvature hides it and not where the patches (the tile's copies, the unbounded world's
 * roots, 14 to 35 km away) stop. Without it an eye 2000 m up saw the last row of peaks end in a line, and the sky's
 * distant ground below it.
 *
 * <p><b>The horizon.</b> Level ground at the world's mean height, curved with the planet's radius R (the sky's ground
 * sphere, 6360 km), lies d² / 2R below an eye's tangent plane d metres away, so an eye h above it sees it up to the
 * horizon distance {@code sqrt(2 R h)}, at a depression {@code acos(R / (R + h))} below the horizontal: 159 km and
 * 1.44° for h = 2000 m, 357 km at 10 km. The ring reaches 1.25 times that, at least twice its inner radius, so its
 * outer edge always lies behind the bulge, whatever the altitude; a ray that goes below the horizon meets it.
 *
 * <p><b>The ring.</b> {@value #AZIMUTHS} azimuths by {@value #RINGS} rings a constant ratio apart (3.7 % of the
 * distance from one ring to the next at 2000 m, 1.5 times the gap between azimuths there): a camera-centred polar
 * grid puts its vertices evenly over the picture's width and depth. It starts 10 % inside the patches' square and
 * goes down under it at {@code farfield.vert}'s skirt slope, so the patches' ground hides it there and no crack opens
 * where the two meet. Its heights are the coarsest level's (the unbounded world's level 7, 256 m apart; the tile's
 * pyramid level of the same spacing, periodic), bilinear, and its colour the far program's
 * ({@code terrain.frag} with {@code TERRAIN_FARFIELD}), so it continues the patches' ground. The relief fades into
 * level ground at the mean height over the ring's outer half, and on the unbounded world also where its coarsest
 * window may end, since beyond it the layer wraps round to other ground: the window keeps the eye at
 * least a quarter of its side inside, so the relief fades out over the last 8 km before that square (32.8 km by
 * default), which makes the ring depend on the place alone, not on the flight that led there: the level ground
 * there takes the snow cover the rule gives the mean height. The curvature counts from the patches' inscribed
 * circle, so the flat patches and the ring meet at the same height there; towards the square's corners the ring
 * lies (d² − r²) / 2R lower than the patches' edge, 33 m at the corners of the unbounded world's square seen from its
 * centre, 73 m at the far corner from an eye half a root off it (the seam rises, it opens nothing).
 *
 * <p><b>Depth.</b> The camera's far plane ({@link Camera#FAR}, 40 km) keeps depth precise over the patches; the ring
 * reaches hundreds of kilometres. Each ring vertex beyond the farthest patch point, at distance d, is drawn along its
 * own line of sight at {@code x + (y − x)(1 − e^−(d − x)/(y − x))}, x that farthest point and y just before the
 * far plane: on screen nothing moves (a perspective projection sees only the direction), depth order is kept (the
 * map is monotonic), and only the ring's own depths are squeezed. Inner rings are drawn first, so where two squeezed
 * depths round to one the nearer wins the depth test.
 *
 * <p><b>Cost.</b> {@value #AZIMUTHS} · {@value #RINGS} · 2 triangles in one draw call, main pass only (the water's
 * reflection and the shadows do not see it), its vertices each four height fetches and the slope, the sky seen, the
 * sky's reflection and the air read as terrain.vert's far program reads them; 130 KiB of vertices and 384 KiB of
 * indices on the GPU, nothing per frame but four uniforms.
 *
 * <p><b>Limits.</b> A polar grid centred on the eye samples the relief at moving points, so in flight the far
 * relief's outline shifts a little; the ring is not in the water's reflection; past its inner rings its relief is the
 * coarsest level's, smoother than the patches' ground; the level ground has no relief finer than the tile's, or none
 * beyond a quarter of the unbounded world's window; in a fast flight a block that has just entered the window may
 * show the place it left for a frame or two, out there.
 */
final class FarField {

    /** The ground sphere's radius, metres: the sky's (the atmosphere's bottom), so horizon and air agree. */
    static final double PLANET_RADIUS = 6_360_000;
    /** Vertices around the ring: 1.4° apart, 15 pixels at 960 pixels across a 60° by 91° view. */
    static final int AZIMUTHS = 256;
    /** Rings from the inner edge to the outer. */
    static final int RINGS = 64;
    /** Where the ring starts: this share of the way from the eye to the nearest edge of the patches' square. */
    static final double INNER_SHARE = 0.9;
    /** The ring reaches this many horizon distances. */
    static final double HORIZON_MARGIN = 1.25;
    /**
     * How many steps of a 24-bit depth buffer the squeezed depths end short of the far plane's 1. Near the far plane
     * a step of depth is about z² 2^−24 / n of distance: 180 m at 39 km for the camera's 0.5 m near plane. A ring
     * squeezed to within a step of the far plane rounds to depth 1 and fails the depth test against the cleared
     * buffer: a hole in the picture. Four steps short the ring ends 750 m before the far plane.
     */
    static final int DEPTH_STEPS_SHORT = 4;
    /** The squeezed depths start no later than this share of where they end, so they keep some room. */
    static final double DEPTH_START_MAX = 0.9;

    /** Where the far heights come from: the level, its spacing and sample 0's position (metres), the mean height. */
    record Source(int level, double spacing, double origin, double meanHeight) {
    }

    private final Mesh mesh;
    private final Source source;
    private final Uniform.Vec3 ring;
    private final Uniform.Vec3 square;
    private final Uniform.Vec2 depthRoom;

    /** @param program the far field's program ({@link TerrainShading#farField}), its maps' samplers set */
    FarField(EngineContext context, ShaderProgram program, Source source) {
        this.source = source;
        mesh = context.own("far-field", new Mesh(context.gl(), grid(), triangles(), new Mesh.Attribute(0, 2)));
        program.use();
        program.float1("uMeanHeight").set((float) source.meanHeight());
        program.float1("uPlanetRadius").set((float) PLANET_RADIUS);
        program.float1("uSampleSpacing").set((float) source.spacing());
        program.float1("uOrigin").set((float) source.origin());
        program.int1("uFarLevel").set(source.level());
        ring = program.vec3("uRing");
        square = program.vec3("uSquare");
        depthRoom = program.vec2("uDepthRoom");
    }

    /**
     * The distance, metres, at which the squeezed depths end: {@value #DEPTH_STEPS_SHORT} steps of a 24-bit depth short
     * of the camera's far plane. Depth is (1 − n/z) f / (f − n), so a depth k steps short of 1 lies at
     * 1/z ≈ 1/f + k 2^−24 / n.
     */
    static double depthEnd() {
        return 1 / (1 / Camera.FAR + DEPTH_STEPS_SHORT * Math.scalb(1.0, -24) / Camera.NEAR);
    }

    /** The ring's vertices: (azimuth, ring) in 0..1, the azimuth's last column repeating its first. */
    private static float[] grid() {
        float[] v = new float[2 * (AZIMUTHS + 1) * (RINGS + 1)];
        int c = 0;
        for (int j = 0; j <= RINGS; j++) {
            for (int i = 0; i <= AZIMUTHS; i++) {
                v[c++] = i / (float) AZIMUTHS;
                v[c++] = j / (float) RINGS;
            }
        }
        return v;
    }

    /** Two triangles per cell, the inner rings first (the depth test keeps the first of two equal depths). */
    private static int[] triangles() {
        int[] t = new int[6 * AZIMUTHS * RINGS];
        int c = 0;
        int row = AZIMUTHS + 1;
        for (int j = 0; j < RINGS; j++) {
            for (int i = 0; i < AZIMUTHS; i++) {
                int a = j * row + i;
                t[c++] = a;
                t[c++] = a + row;
                t[c++] = a + 1;
                t[c++] = a + 1;
                t[c++] = a + row;
                t[c++] = a + row + 1;
            }
        }
        return t;
    }

    /**
     * Draws the ring with its program in use (its materials bound), around {@code eye}, for patches drawn on the
     * square of {@code halfSide} metres around (centreX, centreZ) whose heights lie within lowest .. highest.
     */
    void draw(Vector3fc eye, double centreX, double centreZ, double halfSide, double lowest, double highest,
              DrawStats stats) {
        double dx = Math.abs(eye.x() - centreX);
        double dz = Math.abs(eye.z() - centreZ);
        double inscribed = Math.max(halfSide - Math.max(dx, dz), 1);
        double inner = INNER_SHARE * inscribed;
        double horizon = Math.sqrt(2 * PLANET_RADIUS * Math.max(eye.y() - source.meanHeight(), 0));
        ring.set((float) inner, (float) Math.max(2 * inner, HORIZON_MARGIN * horizon), (float) inscribed);
        square.set((float) centreX, (float) centreZ, (float) halfSide);
        double corner = Math.hypot(dx + halfSide, dz + halfSide);
        double height = Math.max(Math.abs(eye.y() - lowest), Math.abs(eye.y() - highest));
        double end = depthEnd();
        double farthest = Math.min(Math.hypot(corner, height), DEPTH_START_MAX * end);
        depthRoom.set((float) farthest, (float) end);
        glDisable(GL_CULL_FACE);
        mesh.draw(stats);
    }
}
