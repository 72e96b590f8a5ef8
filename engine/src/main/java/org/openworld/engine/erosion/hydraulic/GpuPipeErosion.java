package org.openworld.engine.erosion.hydraulic;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.FloatBuffer;
import java.util.Map;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.OffscreenState;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderLibrary;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.TextureUnits;

/**
 * The virtual-pipe erosion as fragment-shader ping-pong passes (OpenGL 3.3, no compute shaders): the state (b, d, s,
 * d₁) and the four pipes' flux each live in two RGBA32F textures of the grid's size, and a step draws one
 * full-screen triangle per pass, {@code shaders/erosion/flux.frag}, {@code water.frag} and {@code transport.frag}
 * (which also runs the thermal step: it reads the bed the transport leaves alone), each reading the last texture
 * written and writing the other. The heights are uploaded
 * once and the state read back once, at the end.
 *
 * <p>Cost: 3 passes a step, each a handful of texel fetches per cell (the transport's 13 the most); GPU memory
 * 4 × 16 bytes a cell (16 MiB at 512²). On llvmpipe, 512² cells took 64 to 150 ms a pass of wall time with the
 * two-core machine's load at 23 (the tile's 450 passes: 29 to 66 s); a hardware GPU has not been measured. Binds
 * its two texture units and leaves the program in use changed; the framebuffer, viewport and tests are given back.
 */
public final class GpuPipeErosion implements PipeState.Runner {

    private static final TextureUnits UNITS = new TextureUnits();
    private static final TextureUnits.Sampler STATE = UNITS.add("uState");
    private static final TextureUnits.Sampler FLUX = UNITS.add("uFlux");

    private final GlContext gl;
    private final ShaderLibrary shaders;

    public GpuPipeErosion(GlContext gl, ShaderLibrary shaders) {
        this.gl = gl;
        this.shaders = shaders;
    }

    @Override
    public PipeState run(float[] heights, int n, PipeModel model, int steps) {
        Map<String, Float> values = Map.of("uDt", (float) model.dt(), "uRain", (float) model.rain(),
                "uSpacing", (float) model.spacing(), "uCapacity", (float) model.capacity(),
                "uDepthCap", (float) model.depthCap(), "uDissolve", (float) model.dissolve(),
                "uDeposit", (float) model.deposit(),
                "uEvaporate", (float) model.evaporate(), "uMinSine", (float) model.minSine(),
                "uTalus", (float) model.talus());
        int periodic = model.border() == PipeModel.Border.PERIODIC ? 1 : 0;
        try (ShaderProgram flux = program("erosion/flux.frag", n, periodic, values, "uDt", "uRain", "uSpacing");
             ShaderProgram water = program("erosion/water.frag", n, periodic, values, "uDt", "uRain", "uSpacing",
                     "uCapacity", "uDepthCap", "uDissolve", "uDeposit", "uMinSine");
             ShaderProgram transport = program("erosion/transport.frag", n, periodic, values, "uDt", "uSpacing",
                     "uEvaporate", "uTalus");
             Mesh triangle = Mesh.fullScreenTriangle(gl);
             OffscreenState offscreen = OffscreenState.enter();
             Texture2D state0 = texture(n);
             Texture2D state1 = texture(n);
             Texture2D flux0 = texture(n);
             Texture2D flux1 = texture(n);
             Framebuffer toState0 = Framebuffer.onTextures(gl, state0);
             Framebuffer toState1 = Framebuffer.onTextures(gl, state1);
             Framebuffer toFlux0 = Framebuffer.onTextures(gl, flux0);
             Framebuffer toFlux1 = Framebuffer.onTextures(gl, flux1)) {
            transport.use();
            transport.int1("uAdvection").set(model.advection() == PipeModel.Advection.FLUX ? 1 : 0);
            upload(state0, n, heights);
            upload(flux0, n, new float[n * n]);
            Texture2D[] state = {state0, state1};
            Framebuffer[] toState = {toState0, toState1};
            Texture2D[] fluxes = {flux0, flux1};
            Framebuffer[] toFlux = {toFlux0, toFlux1};
            DrawStats stats = new DrawStats();
            int s = 0;
            int f = 0;
            for (int step = 0; step < steps; step++) {
                // 1. flux from the state and the last flux; 2, 3. each pass reads the last state, writes the other
                draw(flux, state[s], fluxes[f], toFlux[1 - f], triangle, stats);
                f = 1 - f;
                for (ShaderProgram pass : new ShaderProgram[] {water, transport}) {
                    draw(pass, state[s], fluxes[f], toState[1 - s], triangle, stats);
                    s = 1 - s;
                }
            }
            return read(toState[s], n);
        }
    }

    /**
     * One pass's program, its samplers on their units and its constants set: the grid's size and border, and the
     * model's values it reads, by name (the compiler drops a uniform a pass does not use, and setting one is an error).
     */
    private ShaderProgram program(String fragment, int n, int periodic, Map<String, Float> values, String... used) {
        ShaderProgram p = shaders.program("terrain/material/bake.vert", fragment);
        p.use();
        p.sampler(STATE);
        p.sampler(FLUX);
        p.int1("uSize").set(n);
        p.int1("uPeriodic").set(periodic);
        for (String name : used) {
            p.float1(name).set(values.get(name));
        }
        return p;
    }

    private void draw(ShaderProgram pass, Texture2D state, Texture2D flux, Framebuffer target, Mesh triangle,
                      DrawStats stats) {
        pass.use();
        target.bind();
        state.bind(STATE.unit());
        flux.bind(FLUX.unit());
        triangle.draw(stats);
    }

    private Texture2D texture(int n) {
        return Texture2D.empty(gl, n, n, Format.RGBA32F, Sampling.NEAREST_CLAMP);
    }

    /** Level 0 of {@code target} = (heights, 0, 0, 0), or all zeros where {@code heights} is. */
    private static void upload(Texture2D target, int n, float[] heights) {
        FloatBuffer texels = MemoryUtil.memAllocFloat(4 * n * n);
        try {
            for (float h : heights) {
                texels.put(h).put(0).put(0).put(0);
            }
            target.upload(0, 0, n, texels.flip());
        } finally {
            MemoryUtil.memFree(texels);
        }
    }

    private static PipeState read(Framebuffer source, int n) {
        FloatBuffer texels = MemoryUtil.memAllocFloat(4 * n * n);
        try {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, source.id());
            glReadBuffer(GL_COLOR_ATTACHMENT0);
            glReadPixels(0, 0, n, n, GL_RGBA, GL_FLOAT, texels);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
            float[] b = new float[n * n];
            float[] d = new float[n * n];
            float[] s = new float[n * n];
            for (int i = 0; i < b.length; i++) {
                b[i] = texels.get(4 * i);
                d[i] = texels.get(4 * i + 1);
                s[i] = texels.get(4 * i + 2);
            }
            return new PipeState(b, d, s);
        } finally {
            MemoryUtil.memFree(texels);
        }
    }
}
