package org.openworld.engine.water;

import static org.lwjgl.opengl.GL11C.*;
import static org.lwjgl.opengl.GL14C.glBlendFuncSeparate;
import static org.lwjgl.opengl.GL30C.*;
import static org.lwjgl.opengl.GL32C.GL_DEPTH_CLAMP;

import java.nio.FloatBuffer;
import java.util.List;
import org.joml.Matrix4f;
import org.joml.Vector4fc;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Owned;
import org.openworld.engine.core.Layer;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.PassOwner;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.SkyMaps;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.TextureArray;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;
import org.openworld.engine.water.WaterSettings.Method;

/**
 * The water (paper section 3.3): a plane at {@code water.level} to the horizon, drawn by the paper's stencil method
 * or, by default, by two pictures mixed by the Fresnel term. See the package documentation for both.
 *
 * <p>Frame by frame: as the owner of {@link Pass#REFLECTION} it gives the engine the mirrored camera and its
 * reflection target (nothing while the eye is under the water); the terrain and the sky draw into it. In
 * {@link Pass#MAIN}, after them, it copies the scene's colour and depth (what lies behind the water) and draws the
 * water over the whole screen, one ray–plane intersection per pixel. The paper's stencil method sets its stencil
 * rule in {@link #beginPass}, before the terrain and the sky draw in MAIN.
 *
 * <p>It publishes the plane's height as the world's {@link WaterLevel} ({@code SystemSpec.publishes}: at init, and
 * renewed in every update), so a change of {@code water.level} is seen by the systems after it in the same step (the
 * minimap) and by those before it (the trees) one step later. Switched off, the water is
 * not drawn but the level stays in the world as last written: the lake is still there for the map, as the terrain's
 * height field stays when the terrain is switched off.
 */
public final class WaterSystem implements EngineSystem, PassOwner {
    /** The counter that is 1 when the eye is under the water. */
    private static final Counter UNDERWATER = Counter.of("water", "underwater");

    /** Cosines per row of the Fresnel table: the steepest change, near total internal reflection, spans 3 texels. */
    private static final int FRESNEL_SIZE = 256;
    /** Ripple texture: texels a side, over a tile of {@link #RIPPLE_TILE} metres (wavelengths 0.5 to 32 m). */
    private static final int RIPPLE_SIZE = 128;
    private static final double RIPPLE_TILE = 32;
    /**
     * Frames of the ripple loop over {@link #RIPPLE_PERIOD} seconds: 1/8 s apart, so the shortest waves (0.5 m,
     * a period of 0.57 s) move less than a quarter of their length between the frames the shader blends.
     */
    private static final int RIPPLE_FRAMES = 64;
    private static final double RIPPLE_PERIOD = 8;
    /**
     * The share of the Cox–Munk slope variance the ripple texture resolves; the rest is in waves shorter than its
     * texels (capillary waves, millimetres to centimetres), which only spread the sun's glitter.
     */
    static final double RESOLVED_VARIANCE = 0.3;
    /** Slopes are packed into bytes over ± this many times their RMS: beyond 4σ lies 0.03% of a Gaussian. */
    private static final double SLOPE_RANGE = 4;

    private GlContext gl;
    /** What this system owns, for the targets and ripples re-made when the size or the wind changes. */
    private Owned owned;
    private Mesh fullScreen;
    private WaterPrograms programs;
    private Texture2D fresnelTable;
    private TextureArray ripples;
    private float rippleSlopeScale;
    private double rippleWind = Double.NaN;
    private double rippleDirection = Double.NaN;
    /** The world seed ({@code engine.seed}, fixed at start): the ripples' waves derive from it. */
    private int seed;
    private Framebuffer reflection;
    private Framebuffer behind;
    /**
     * The viewer's camera that the reflection target mirrors: written by {@link #passViews} when it gives the engine a
     * reflection view, read by {@link #beginPass} to scissor that pass and by {@link #render}, which uses the
     * reflection when this is the very camera MAIN draws with. The engine makes the viewer's camera anew each frame and hands the same object to the owners of a
     * pass and to MAIN's systems, so a frame whose reflection pass did not run (the eye under the water, or nothing
     * drawing in it) finds an older camera here and shows no reflection: nothing needs resetting after MAIN.
     */
    private ViewCamera mirroredViewer;
    private double simTime;

    @Override
    public SystemSpec spec() {
        // Layer.OVER_OPAQUE: after every opaque system of MAIN (the terrain, the sky, the trees, ...), whose picture it
        // copies to show what lies behind the water. The level is published, not written in the frame: the trees,
        // opaque and so before the water, read it too. prepares(REFLECTION): in the reflection pass it draws
        // nothing, only scissors the pass to the water's part of the screen (beginPass).
        return SystemSpec.named("water").reads(Settings.class, Camera.class, SkyMaps.class)
                .publishes(WaterLevel.class).layer(Layer.OVER_OPAQUE).prepares(Pass.REFLECTION).draws(Pass.MAIN);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(WaterSettings.SETTINGS);
    }

    @Override
    public Pass ownedPass() {
        return Pass.REFLECTION;
    }

    @Override
    public void init(EngineContext context) {
        gl = context.gl();
        owned = context.owned();
        fullScreen = context.own("fullScreen", Mesh.fullScreenTriangle(gl));
        programs = new WaterPrograms(context);
        fresnelTable = context.own("fresnelTable",
                Texture2D.empty(gl, FRESNEL_SIZE, 2, Format.R16F, Sampling.LINEAR_CLAMP));
        FloatBuffer table = MemoryUtil.memAllocFloat(2 * FRESNEL_SIZE).put(Fresnel.table(FRESNEL_SIZE)).flip();
        try {
            fresnelTable.upload(0, 0, 2, table);
        } finally {
            MemoryUtil.memFree(table);
        }
        seed = context.settings().get(EngineSettings.class).seed();
        updateRipples(context.settings().get(WaterSettings.class));
        context.world().setResource(new WaterLevel(context.settings().get(WaterSettings.class).level()));
    }

    @Override
    public void update(World world, double step) {
        simTime += step;
        world.setResource(new WaterLevel(world.resource(Settings.class).get(WaterSettings.class).level()));
    }

    @Override
    public List<PassView> passViews(World world, PassView viewer) {
        WaterSettings s = world.resource(Settings.class).get(WaterSettings.class);
        if (viewer.camera().position().y() < s.level() + MirrorCamera.MIN_HEIGHT
                || !onScreen(viewer.camera(), s).visible()) {
            return List.of();
        }
        int width = s.reflection().of(viewer.target().width());
        int height = s.reflection().of(viewer.target().height());
        reflection = fit("reflection", reflection, width, height, Format.DEPTH32F, Sampling.LINEAR_CLAMP);
        mirroredViewer = viewer.camera();
        // the paper's method draws the mirrored scene whole; the Fresnel method cuts it at the water
        return List.of(new PassView(MirrorCamera.of(viewer.camera(), (float) s.level(), s.method() == Method.FRESNEL),
                reflection));
    }

    /**
     * Step 1 of the paper's stencil method, for MAIN when the water will be drawn by it: the stencil cleared to 0xFF
     * and every fragment that passes the depth test, whoever draws it, writing 0 ("stencil clear value 0xFF, the
     * terrain writes 0"). Set here, before the terrain and the sky draw, so they need not know of it; with the
     * Fresnel method, under the water or with the water switched off, no stencil state is set at all. Cost: one
     * stencil-only clear of the scene target per frame (the engine's own clear leaves the stencil at 0).
     */
    @Override
    public void beginPass(Pass pass, RenderContext context) {
        WaterSettings s = context.world().resource(Settings.class).get(WaterSettings.class);
        if (pass == Pass.REFLECTION) {
            scissorToWater(s, context.target());
            return;
        }
        if (pass != Pass.MAIN || !drawsByStencil(s, context.camera())) {
            return;
        }
        glClearStencil(0xFF);
        glStencilMask(0xFF);
        glClear(GL_STENCIL_BUFFER_BIT);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    }

    /**
     * The reflection pass draws only where the water can be seen: the bounding rectangle of the screen below the
     * horizon ({@link PlaneOnScreen}), in the reflection target's pixels (it is aligned with the screen). Nothing
     * there is lost: a mirrored ray points below the horizon, so the water looks the reflection up below the horizon
     * line only; one texel more on each side keeps the bilinear look-ups at the horizon as they were. Set after the
     * engine cleared the whole target (alpha 0: nothing drawn), and lifted by the engine at the next pass.
     */
    private void scissorToWater(WaterSettings s, Framebuffer target) {
        Vector4fc ndc = onScreen(mirroredViewer, s).bounds();
        int x0 = Math.max(0, (int) Math.floor((ndc.x() + 1) / 2 * target.width()) - 1);
        int y0 = Math.max(0, (int) Math.floor((ndc.y() + 1) / 2 * target.height()) - 1);
        int x1 = Math.min(target.width(), (int) Math.ceil((ndc.z() + 1) / 2 * target.width()) + 1);
        int y1 = Math.min(target.height(), (int) Math.ceil((ndc.w() + 1) / 2 * target.height()) + 1);
        glScissor(x0, y0, x1 - x0, y1 - y0);
        glEnable(GL_SCISSOR_TEST);
    }

    private static PlaneOnScreen onScreen(ViewCamera camera, WaterSettings s) {
        // the plane y = level is the same seen from anywhere on x and z: measured from the eye's own x and z, the
        // float inverse keeps its precision however far out the eye is
        Matrix4f fromEye = new Matrix4f(camera.projection())
                .mul(camera.viewFrom(camera.exactPosition().x(), camera.exactPosition().z()));
        return PlaneOnScreen.of(fromEye, camera.position().y(), (float) s.level());
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        if (pass != Pass.MAIN) {
            return; // the reflection pass only takes the scissor (beginPass)
        }
        WaterSettings s = context.world().resource(Settings.class).get(WaterSettings.class);
        updateRipples(s);
        boolean underwater = underwater(s, context.camera());
        context.world().resource(Counters.class).put(UNDERWATER, underwater ? 1 : 0);
        // whether the reflection pass ran for this very camera this frame (see mirroredViewer): read, never reset
        boolean reflected = mirroredViewer == context.camera();
        if (drawsByStencil(s, context.camera())) {
            drawStencil(s, reflected, context);
        } else {
            copyBehind(context.target());
            drawFresnel(s, underwater, reflected, context);
        }
    }

    /** At the surface itself the eye counts as under it: from above, the plane would pass through the eye. */
    private static boolean underwater(WaterSettings s, ViewCamera camera) {
        return camera.position().y() <= s.level();
    }

    /** The paper's method when chosen and the eye is above the water; else (and always below it) the Fresnel one. */
    private static boolean drawsByStencil(WaterSettings s, ViewCamera camera) {
        return s.method() == Method.STENCIL && !underwater(s, camera);
    }

    /** What lies behind the water, the scene so far: colour and depth, copied as they are. */
    private void copyBehind(Framebuffer scene) {
        behind = fit("behind", behind, scene.width(), scene.height(), Format.DEPTH24_STENCIL8,
                Sampling.NEAREST_CLAMP);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, scene.id());
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, behind.id());
        glBlitFramebuffer(0, 0, scene.width(), scene.height(), 0, 0, scene.width(), scene.height(),
                GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
        scene.bind();
    }

    private void drawFresnel(WaterSettings s, boolean underwater, boolean reflected, RenderContext context) {
        WaterOptics optics = WaterOptics.of(s.clarity());
        RenderOrigin origin = context.world().resource(RenderOrigin.class);
        WaterPrograms.Ripple ripple = new WaterPrograms.Ripple((float) (1 / RIPPLE_TILE), RIPPLE_FRAMES,
                (float) (simTime / RIPPLE_PERIOD % 1.0), rippleSlopeScale,
                WaterPrograms.Ripple.originTiles(origin.x(), origin.z(), RIPPLE_TILE));
        behind.color().bind(WaterPrograms.REFRACTION.unit());
        behind.depth().bind(WaterPrograms.DEPTH.unit());
        fresnelTable.bind(WaterPrograms.FRESNEL.unit());
        ripples.bind(WaterPrograms.RIPPLES.unit());
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
        if (underwater) {
            // every pixel is under water: the shader writes the surface's depth, or the scene's where that is nearer
            programs.useBelow((float) s.level(), optics, ripple, context.shares(SunShadow.class));
            glDepthFunc(GL_ALWAYS);
            fullScreen.draw(context.stats());
            glDepthFunc(GL_LESS);
            return;
        }
        if (reflection != null) {
            reflection.color().bind(WaterPrograms.REFLECTION.unit());
        }
        double slopeVariance = s.rmsSlope() * s.rmsSlope();
        programs.useAbove(onScreen(context.camera(), s), (float) s.level(), optics, ripple, reflected,
                (float) (slopeVariance * (1 - RESOLVED_VARIANCE)), (float) (slopeVariance * RESOLVED_VARIANCE),
                context.shares(SunShadow.class));
        drawPlane(context);
    }

    /**
     * The plane as geometry with its own depth, cut at the horizon ({@link PlaneOnScreen}, set in the program):
     * depth-tested before its fragment shader runs, so only the water that is seen is shaded. Beyond the far plane
     * the depth is clamped to it (depth clamp instead of clipping), where the sky lies, so the test passes on equal
     * depths: the water reaches the horizon.
     */
    private void drawPlane(RenderContext context) {
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_DEPTH_CLAMP);
        glEnable(GL_CLIP_DISTANCE0);
        fullScreen.draw(context.stats());
        glDisable(GL_CLIP_DISTANCE0);
        glDisable(GL_DEPTH_CLAMP);
        glDepthFunc(GL_LESS);
    }

    /**
     * The paper's four steps; {@link #beginPass} did step 1 (stencil cleared to 0xFF, the terrain and sky wrote 0)
     * and the reflection pass step 3 (the mirrored scene, front faces culled by the flipped winding, stencil off).
     */
    private void drawStencil(WaterSettings s, boolean reflected, RenderContext context) {
        // 2. the water plane: depth tested, alpha only, 0xFF into the stencil where it passes
        glEnable(GL_DEPTH_TEST);
        glDepthMask(true);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0xFF, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glColorMask(false, false, false, true);
        programs.useStencil(2, (float) s.alpha(), onScreen(context.camera(), s));
        drawPlane(context);
        glColorMask(true, true, true, true);
        // 4. the mirrored scene over the whole screen, kept where the stencil says water, blended by its alpha
        if (reflected) {
            reflection.color().bind(WaterPrograms.REFLECTION.unit());
            glDisable(GL_DEPTH_TEST);
            glDepthMask(false);
            glStencilFunc(GL_EQUAL, 0xFF, 0xFF);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            glEnable(GL_BLEND);
            glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_ZERO, GL_ONE);
            programs.useStencil(4, (float) s.alpha(), null);
            fullScreen.draw(context.stats());
            glDisable(GL_BLEND);
            glDepthMask(true);
            glEnable(GL_DEPTH_TEST);
        }
        // the stencil has served: what is drawn after the water neither tests nor marks it
        glDisable(GL_STENCIL_TEST);
    }

    /** (Re)synthesises the ripples when the wind changes (at start-up, or from the settings panel). */
    private void updateRipples(WaterSettings s) {
        if (s.wind() == rippleWind && s.windDirection() == rippleDirection) {
            return;
        }
        double resolvedRms = s.rmsSlope() * Math.sqrt(RESOLVED_VARIANCE);
        RippleField field = RippleField.synthesize(RIPPLE_SIZE, RIPPLE_FRAMES, RIPPLE_TILE, RIPPLE_PERIOD, s.wind(),
                s.windDirection(), resolvedRms, seed);
        rippleSlopeScale = (float) (SLOPE_RANGE * resolvedRms);
        ripples = owned.replace("ripples", ripples, TextureArray.repeatingMipmapped(gl, RIPPLE_SIZE, RIPPLE_SIZE,
                Format.RGBA8, field.texels(rippleSlopeScale)));
        rippleWind = s.wind();
        rippleDirection = s.windDirection();
    }

    /** A colour + depth target of this size: {@code current} if it fits, else a new one in its place. */
    private Framebuffer fit(String role, Framebuffer current, int width, int height, Format depth,
                            Sampling sampling) {
        if (current != null && current.width() == width && current.height() == height) {
            return current;
        }
        return owned.replace(role, current, new Framebuffer(gl, width, height, Format.RGBA8, depth, sampling));
    }

    /** The reflection pass's target, null before the first reflection (tools and tests read it back). */
    public Framebuffer reflectionTarget() {
        return reflection;
    }
}
