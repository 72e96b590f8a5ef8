package org.openworld.engine.particles;

import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL15C.GL_ARRAY_BUFFER;
import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_COPY;
import static org.lwjgl.opengl.GL15C.glBufferSubData;
import static org.lwjgl.opengl.GL15C.glGetBufferSubData;
import static org.lwjgl.opengl.GL20C.glEnableVertexAttribArray;
import static org.lwjgl.opengl.GL20C.glVertexAttribPointer;
import static org.lwjgl.opengl.GL30C.*;

import java.nio.FloatBuffer;
import java.util.List;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.Owned;
import org.openworld.engine.core.Layer;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.Wind;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.gl.VertexArray;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * Snowfall (paper section 4, figure 14): flakes updated on the GPU by transform feedback and drawn as instanced
 * billboards. See the package documentation for the technique.
 *
 * <p>Two buffers hold the flakes' state ({@link SnowMotion#FLOATS} floats each) and take turns: each update step
 * reads one and writes the other. They are built, and the flakes spread through the air, when it first snows, and
 * again only when {@code particles.count} changes. The ground under the cube is a {@link GroundPatch}, sampled again
 * when the eye nears its edge. The flakes are drawn last in {@link Pass#MAIN}, blended over everything else: one
 * square {@link Mesh}, instanced over the current state buffer ({@link Mesh#instances}, the position of each record).
 */
public final class ParticleSystem implements EngineSystem {
    /** The counter of the flakes alive. */
    private static final Counter COUNT = Counter.of("particles", "count");

    /** Samples a side of the ground patch: 0.47 m apart under the default 30 m cube (the patch spans two cubes). */
    private static final int GROUND_SAMPLES = 128;
    /** The smallest radius a flake is drawn with, pixels: smaller ones would flicker between pixels. */
    private static final float MIN_RADIUS_PIXELS = 1;
    /** A flake's albedo: fresh snow reflects 80–90% of visible light. */
    private static final float ALBEDO = 0.85f;
    private static final TextureUnits UNITS = new TextureUnits();
    /** The ground patch in the update program. */
    private static final TextureUnits.Sampler GROUND = UNITS.add("ground");
    /**
     * An eye that moved more than this share of the cube's side between two steps jumped: 1/4 of the default 30 m
     * in 1/60 s is 450 m/s, beyond any flight.
     */
    private static final double CUT = 0.25;
    private static final int POSITION = 0;
    private static final int VELOCITY = 1;
    /** The square's corner, 0..1 on each axis, in the draw program (whose location 1 is free: no velocity there). */
    private static final int CORNER = 1;

    private GlContext gl;
    /** What this system owns, for the state buffers re-made when the flake count changes. */
    private Owned owned;
    private ShaderProgram updateProgram;
    private ShaderProgram drawProgram;
    private UpdateUniforms updateUniforms;
    private Uniform.Vec4 flakeUniform;
    /** The two state buffers and, for each, a vertex array to update from. */
    private final GpuBuffer[] states = new GpuBuffer[2];
    private final VertexArray[] updateFrom = new VertexArray[2];
    /** One flake's square, drawn once per flake of the current state buffer. */
    private Mesh square;
    private int current;
    private int count;
    private int builds;
    private long steps;
    private GroundPatch ground;
    /** The world's heights, and the same from the render origin the flakes are simulated from (see prepare). */
    private HeightField worldGround;
    private HeightField groundFromOrigin;
    private double originX = Double.NaN;
    private double originZ = Double.NaN;
    /** The eye at the last step or frame, to tell a jump from a flight. */
    private final Vector3f lastEye = new Vector3f(Float.NaN);
    /** The side of the cube the flakes were last spread through, metres. */
    private double side;
    private Texture2D groundTexture;

    private record UpdateUniforms(Uniform.Vec4 forces, Uniform.Vec3 wind, Uniform.Vec4 volume, Uniform.Int stepKey,
                                  Uniform.Vec4 ground) {
    }

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("particles").reads(Settings.class, Camera.class, HeightField.class, Wind.class)
                .updatesOnGpu().layer(Layer.TRANSPARENT).draws(Pass.MAIN)
                .offByDefault(); // a fair day by default: --set system.particles=on makes it snow (figure 14)
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(ParticleSettings.SETTINGS);
    }

    @Override
    public void init(EngineContext context) {
        gl = context.gl();
        owned = context.owned();
        updateProgram = context.own("update", context.shaders().feedbackProgram("particles/update.vert",
                "outPosition", "outVelocity"));
        updateProgram.sampler(GROUND);
        updateUniforms = new UpdateUniforms(updateProgram.vec4("uForces"), updateProgram.vec3("uWind"),
                updateProgram.vec4("uVolume"), updateProgram.int1("uStepKey"), updateProgram.vec4("uGround"));
        drawProgram = context.own("draw", context.shaders().program("particles/flake.vert", "particles/flake.frag"));
        flakeUniform = drawProgram.vec4("uFlake");
        square = context.own("square", new Mesh(gl, new float[] {0, 0, 1, 0, 0, 1, 1, 1}, new int[] {0, 1, 2, 2, 1, 3},
                new Mesh.Attribute(CORNER, 2)));
        groundTexture = context.own("ground", Texture2D.empty(gl, GROUND_SAMPLES, GROUND_SAMPLES, Format.R32F,
                Sampling.NEAREST_CLAMP));
    }

    @Override
    public void update(World world, double step) {
        ParticleSettings s = world.resource(Settings.class).get(ParticleSettings.class);
        prepare(world, s);
        Vector3f wind = windAtGround(world, s);
        float dt = (float) step;
        updateProgram.use();
        updateUniforms.forces().set((float) s.gravity(), (float) s.drag(), (float) (s.brownian() * Math.sqrt(step)),
                dt);
        updateUniforms.wind().set(wind.x, wind.y, wind.z);
        updateUniforms.volume().set(lastEye.x, lastEye.y, lastEye.z, (float) s.volume());
        updateUniforms.stepKey().set(SnowMotion.stepKey(world.resource(Settings.class).get(EngineSettings.class).seed(),
                steps));
        updateUniforms.ground().set(ground.originX(), ground.originZ(), 1f / ground.spacing(), ground.samples());
        groundTexture.bind(GROUND.unit());

        updateFrom[current].bind();
        states[1 - current].bindForFeedback(0);
        glEnable(GL_RASTERIZER_DISCARD);
        glBeginTransformFeedback(GL_POINTS);
        glDrawArrays(GL_POINTS, 0, count);
        glEndTransformFeedback();
        glDisable(GL_RASTERIZER_DISCARD);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
        current = 1 - current;
        steps++;
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        World world = context.world();
        ParticleSettings s = world.resource(Settings.class).get(ParticleSettings.class);
        prepare(world, s);
        drawProgram.use();
        flakeUniform.set((float) (0.5 * s.size()), MIN_RADIUS_PIXELS, (float) s.volume(), ALBEDO);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(false);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        square.instances(states[current], SnowMotion.FLOATS, new Mesh.Attribute(POSITION, 3));
        square.drawInstances(0, count, context.stats());
        glDisable(GL_BLEND);
        glDepthMask(true);
        world.resource(Counters.class).put(COUNT, count);
    }

    /**
     * Makes the ground patch cover the cube, and the buffers hold {@code particles.count} flakes: built when it first
     * snows and when the count changes, spread afresh around the eye also when the cube's size changes and when the
     * eye jumped (a cut in a path, a shot's pose), since the air it left has another ground and the flakes carry its
     * shape.
     */
    private void prepare(World world, ParticleSettings s) {
        // the flakes live in the GPU's coordinates, from the render origin: when it moves a step, the eye seems to
        // jump by it, and the flakes are spread afresh around it (alike, as falling snow is)
        CameraPose pose = world.resource(Camera.class).pose();
        RenderOrigin origin = world.resource(RenderOrigin.class);
        HeightField worldHeights = world.findResource(HeightField.class).orElse(HeightField.FLAT);
        if (worldHeights != worldGround || origin.x() != originX || origin.z() != originZ) {
            double ox = origin.x();
            double oz = origin.z();
            worldGround = worldHeights;
            groundFromOrigin = (x, z) -> worldHeights.heightAt(x + ox, z + oz);
            originX = ox;
            originZ = oz;
        }
        HeightField field = groundFromOrigin;
        Vector3f eye = origin.relative(pose.x(), pose.y(), pose.z());
        if (ground == null || !ground.covers(field, eye.x, eye.z, 0.5 * s.volume())) {
            ground = GroundPatch.sample(field, eye.x, eye.z, 2 * s.volume(), GROUND_SAMPLES);
            FloatBuffer heights = MemoryUtil.memAllocFloat(ground.heights().length).put(ground.heights()).flip();
            try {
                groundTexture.upload(0, 0, GROUND_SAMPLES, heights);
            } finally {
                MemoryUtil.memFree(heights);
            }
        }
        boolean jumped = lastEye.distance(eye) > CUT * s.volume();
        lastEye.set(eye);
        if (count == s.count() && !jumped && side == s.volume()) {
            return;
        }
        side = s.volume();
        SnowMotion.Volume volume = new SnowMotion.Volume(eye, (float) s.volume());
        Vector3f steady = windAtGround(world, s).sub(0, (float) SnowMotion.terminalVelocity(s.gravity(), s.drag()), 0);
        int seed = world.resource(Settings.class).get(EngineSettings.class).seed();
        float[] state = SnowMotion.seed(s.count(), volume, ground, steady, seed);
        if (count != s.count()) {
            build(state);
        } else {
            FloatBuffer data = MemoryUtil.memAllocFloat(state.length).put(state).flip();
            try {
                states[current].bind();
                glBufferSubData(GL_ARRAY_BUFFER, 0, data);
            } finally {
                MemoryUtil.memFree(data);
            }
        }
    }

    /** The wind where the snow falls: the clouds' wind ({@link Wind}) times {@code particles.wind-share}. */
    private static Vector3f windAtGround(World world, ParticleSettings s) {
        return new Vector3f(world.findResource(Wind.class).orElse(Wind.CALM).velocity()).mul((float) s.windShare());
    }

    /** New state buffers holding {@code state}, in place of the old ones, which are closed as they are replaced. */
    private void build(float[] state) {
        count = state.length / SnowMotion.FLOATS;
        FloatBuffer data = MemoryUtil.memAllocFloat(state.length).put(state).flip();
        try {
            for (int i = 0; i < 2; i++) {
                states[i] = owned.replace("state" + i, states[i], new GpuBuffer(gl, GL_ARRAY_BUFFER));
                states[i].upload(data, GL_DYNAMIC_COPY);
                updateFrom[i] = owned.replace("update" + i, updateFrom[i], layout(states[i]));
            }
        } finally {
            MemoryUtil.memFree(data);
        }
        current = 0;
        builds++;
    }

    /** A vertex array reading the flakes from {@code buffer} one a vertex, for the update step. */
    private VertexArray layout(GpuBuffer buffer) {
        VertexArray vao = new VertexArray(gl);
        vao.bind();
        buffer.bind();
        int stride = SnowMotion.FLOATS * Float.BYTES;
        glEnableVertexAttribArray(POSITION);
        glVertexAttribPointer(POSITION, 3, GL_FLOAT, false, stride, 0);
        glEnableVertexAttribArray(VELOCITY);
        glVertexAttribPointer(VELOCITY, 3, GL_FLOAT, false, stride, 3L * Float.BYTES);
        glBindVertexArray(0);
        return vao;
    }

    /** The flakes' current state, read back from the GPU ({@link SnowMotion#FLOATS} floats each; tests and tools). */
    public float[] readState() {
        float[] state = new float[count * SnowMotion.FLOATS];
        if (count > 0) {
            states[current].bind();
            glGetBufferSubData(GL_ARRAY_BUFFER, 0, state);
        }
        return state;
    }

    /** How often the state buffers were built: once when it first snowed, then once per change of the count. */
    int builds() {
        return builds;
    }

    /** The ground patch under the cube, null before it first snowed. */
    GroundPatch ground() {
        return ground;
    }
}
