package org.openworld.engine.grass;

import static org.lwjgl.opengl.GL11C.GL_CULL_FACE;
import static org.lwjgl.opengl.GL11C.GL_DEPTH_TEST;
import static org.lwjgl.opengl.GL11C.GL_TRIANGLES;
import static org.lwjgl.opengl.GL11C.glDepthMask;
import static org.lwjgl.opengl.GL11C.glDisable;
import static org.lwjgl.opengl.GL11C.glEnable;
import static org.lwjgl.opengl.GL31C.glDrawArraysInstanced;

import java.nio.FloatBuffer;
import java.util.List;
import org.joml.FrustumIntersection;
import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.gl.VertexArray;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.terrain.material.GrassAlbedo;

/**
 * The grass's GL side: the field as a texture, one program, an empty vertex array (the blades are made from
 * {@code gl_VertexID} and {@code gl_InstanceID} in {@code shaders/grass/grass.vert}) and the instanced draws of the
 * frame's {@link GrassRuns}: {@code glDrawArraysInstanced} of {@link #VERTICES} vertices (the tuft's blades, three
 * triangles each) per cell.
 */
final class GrassDraw {

    /** Vertices of one tuft: {@link GrassField#BLADES} blades of three triangles (two for the lower half, the tip). */
    static final int VERTICES = GrassField.BLADES * 9;
    /**
     * Radians per metre east and south of a blade's swing phase: a gust's crest rolls across the meadow in waves
     * 4 to 6 m long.
     */
    static final double SWAY_WAVE_X = 1.1;
    static final double SWAY_WAVE_Z = 1.6;

    private static final TextureUnits UNITS = new TextureUnits();
    private static final TextureUnits.Sampler FIELD = UNITS.add("uField");

    private final EngineContext context;
    private final ShaderProgram program;
    private final VertexArray empty;
    private Texture2D field;
    private final Uniform.Vec3 fieldAt;
    private final Uniform.Int cellX;
    private final Uniform.Int cellZ;
    private final Uniform.Int wide;
    private final Uniform.Int seed;
    private final Uniform.Vec3 runAt;
    private final Uniform.Vec3 blade;
    private final Uniform.Vec2 wind;
    private final Uniform.Vec3 sway;
    private final Uniform.Float density;
    private final Uniform.Vec4 groundAlbedo;

    GrassDraw(EngineContext context) {
        this.context = context;
        program = context.own("program", context.shaders().program("grass/grass.vert", "grass/grass.frag"));
        program.sampler(FIELD);
        empty = context.own("tufts", new VertexArray(context.gl()));
        fieldAt = program.vec3("uFieldAt");
        cellX = program.int1("uCellX");
        cellZ = program.int1("uCellZ");
        wide = program.int1("uWide");
        seed = program.int1("uSeed");
        runAt = program.vec3("uRunAt");
        blade = program.vec3("uBlade");
        wind = program.vec2("uWind");
        sway = program.vec3("uSway");
        density = program.float1("uDensity");
        groundAlbedo = program.vec4("uGround");
    }

    /** The field's samples into the texture, a new texture when its size changed. */
    void upload(GrassField f) {
        int n = f.size();
        if (field == null) {
            field = context.own("field", Texture2D.empty(context.gl(), n, n, Format.RGBA32F, Sampling.LINEAR_CLAMP));
        } else if (field.width() != n) {
            field = context.owned().replace("field", field, Texture2D.empty(context.gl(), n, n, Format.RGBA32F,
                    Sampling.LINEAR_CLAMP));
        }
        FloatBuffer data = MemoryUtil.memAllocFloat(4 * n * n).put(f.texels()).flip();
        try {
            field.upload(0, 0, n, data);
        } finally {
            MemoryUtil.memFree(data);
        }
    }

    /**
     * Draws the tufts the camera sees within the distance of the viewer.
     *
     * @param groundWind m/s of the wind among the blades, x (east) and z (south)
     * @param ground     the ground's grass from afar, which the blades take on as they thin away
     * @return the tufts drawn
     */
    int draw(RenderContext rc, GrassField f, GrassSettings s, float[] groundWind, GrassAlbedo ground,
             int worldSeed) {
        // 1. the blocks in reach and in view: their boxes from the render origin against the camera's frustum
        RenderOrigin origin = rc.world().resource(RenderOrigin.class);
        Matrix4f viewProjection = new Matrix4f(rc.camera().projection()).mul(rc.camera().viewFrom(origin.x(),
                origin.z()));
        FrustumIntersection frustum = new FrustumIntersection(viewProjection);
        double cell = s.cell();
        double eyeX = rc.camera().exactPosition().x();
        double eyeZ = rc.camera().exactPosition().z();
        List<GrassRuns.Run> runs = GrassRuns.plan(eyeX, eyeZ, s.distance(), cell, s.height(), f,
                (x0, y0, z0, x1, y1, z1) -> frustum.testAab(origin.relativeX(x0), (float) y0, origin.relativeZ(z0),
                        origin.relativeX(x1), (float) y1, origin.relativeZ(z1)));

        if (runs.isEmpty()) {
            return 0;
        }
        // 2. what every run shares: the field from the render origin, the blades' size and fade, the wind, the ground
        program.use();
        field.bind(FIELD.unit());
        fieldAt.set(origin.relativeX(f.firstX() * GrassField.SPACING), origin.relativeZ(f.firstZ()
                * GrassField.SPACING), f.size());
        float end = (float) s.distance();
        blade.set((float) s.height(), (float) (1 - GrassField.FADE_SHARE) * end, end);
        wind.set(groundWind[0], groundWind[1]);
        density.set((float) s.density());
        groundAlbedo.set(ground.r(), ground.g(), ground.b(), ground.sheen());
        seed.set(worldSeed);
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
        glDisable(GL_CULL_FACE);
        empty.bind();
        // 3. one instanced draw per run: its first cell by index (the hash) and from the origin (the place), and
        //    the swing's phase there, reduced modulo a turn in double
        int tufts = 0;
        for (GrassRuns.Run run : runs) {
            double x = run.cellX() * cell;
            double z = run.cellZ() * cell;
            cellX.set((int) run.cellX());
            cellZ.set((int) run.cellZ());
            wide.set(run.wide());
            runAt.set(origin.relativeX(x), origin.relativeZ(z), (float) cell);
            sway.set((float) SWAY_WAVE_X, (float) SWAY_WAVE_Z, (float) RenderOrigin.reduce(SWAY_WAVE_X * x
                    + SWAY_WAVE_Z * z, 2 * Math.PI));
            glDrawArraysInstanced(GL_TRIANGLES, 0, VERTICES, run.instances());
            tufts += run.instances();
        }
        rc.stats().add(runs.size(), (long) tufts * VERTICES / 3);
        return tufts;
    }
}
