package org.openworld.engine.sky.clouds;

import static org.lwjgl.opengl.GL30C.*;

import java.nio.FloatBuffer;
import java.util.List;
import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Vector2d;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Layer;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.environment.CloudPanorama;
import org.openworld.engine.environment.CloudShadow;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.SharedBlock;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.Texture3D;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;
import org.openworld.engine.sky.CloudField;
import org.openworld.engine.sky.CloudSettings;
import org.openworld.engine.sky.SkySystem;

/**
 * Volumetric clouds ({@code clouds.mode=volumetric}; the package's front page has the method): the sky's cloud field
 * ray-marched as a volume over the picture, with its shadow on everything the sun lights. In the MAIN pass, after
 * every other system but the transparent ones (it reads the finished depth). In the update, before the passes, the
 * base field is drawn at this moment in 2D (clouds/bake.frag, read by every march), and the cloud shadow map is
 * redrawn when the clouds evolved for {@link #SHADOW_REFRESH} s or the sun moved. Per frame:
 * <ol>
 *   <li>the march ({@code clouds/march.frag}) on a quarter grid, one texel of every 2 × 2 per frame, every texel when
 *       there is no usable history ({@link #jumped});</li>
 *   <li>the resolve ({@code clouds/resolve.frag}) fills the grid from the march and the reprojected history;</li>
 *   <li>the composite ({@code clouds/composite.frag}) upsamples it over the picture, twice: over the sky's pixels
 *       and over the surfaces' (the depth test picks them), each from the grid texels marched against the same.</li>
 * </ol>
 * With {@code clouds.mode=layer} it draws nothing and its shadow block says "no clouds"; the sky draws the layer.
 * In the frame's first pass (the water's REFLECTION, else MAIN) a band of the clouds' panorama is marched
 * ({@link CloudPanoramaMarch}); the reflection draws it over its sky, the sky's environment map reads it.
 *
 * <p>Counter: {@code clouds.full} (1 when every grid texel was marched this frame).
 */
public final class CloudVolumeSystem implements EngineSystem {
    /** The counter: 1 on a frame that marched every texel of the grid (a cut or a shot's first frame), else 0. */
    private static final Counter FULL = Counter.of("clouds", "full");

    /** Texels of the cloud shadow map per side: one per field sample at the default 128² field (94 m). */
    static final int SHADOW_SIZE = 128;
    /** Simulation seconds after which the shadow map is redrawn for the field's evolution (the sky's own refresh). */
    static final double SHADOW_REFRESH = 0.5;
    /** Radians the sun may move before the shadow map is redrawn: 0.2°, a shadow 2 km below shifts 7 m. */
    static final double SHADOW_SUN_STEP = Math.toRadians(0.2);
    /**
     * A camera that moved this far (metres) or turned this much (the cosine between view directions) since the last
     * frame has cut, not moved: the history shows another place, and every texel is marched. 300 m/s at 30 frames a
     * second is 10 m a frame, far below.
     */
    static final double CUT_DISTANCE = 200;
    static final double CUT_COSINE = Math.cos(Math.toRadians(20));
    /** The march's slot in each 2 × 2 block of the grid, frame after frame: every texel once in four frames. */
    private static final int[][] SLOTS = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    /**
     * Spectral exponent of the base shape's field: power 1/f³, smoother than the sky's 1/f² so that a cloud's outline
     * does not follow the texels of the field; drawn with the same seed, so its phases, and the places of the large
     * clouds, are the layer's (which the reflections show). The sky's field, at {@code clouds.beta}, erodes it.
     */
    static final double BASE_BETA = 3;
    /** Radius of the Earth, metres, as the atmosphere has it ({@code shaders/clouds/volume.glsl}, EARTH_RADIUS). */
    private static final double EARTH_RADIUS = 6360e3;

    private GlContext gl;
    private EngineContext context;
    private CloudPrograms programs;
    private Mesh fullScreen;
    private Texture3D field;
    /** The base field at this moment, one tile in 2D (clouds/bake.frag), drawn in each update; what every pass reads. */
    private Texture2D fieldNow;
    private Framebuffer fieldNowTarget;
    private Texture3D detail;
    private CloudField cloudField;
    private Texture2D optics;
    private double opticsType = Double.NaN;
    private float threshold;
    private double thresholdCover = Double.NaN;
    private CloudShadow shadow;
    private Framebuffer shadowTarget;
    private double shadowTime = Double.NEGATIVE_INFINITY;
    private final Vector3f shadowSun = new Vector3f();
    private CloudSettings shadowSettings;
    private CloudTargets targets;
    private CloudPanoramaMarch panorama;
    /** The frame whose panorama band was marched (in its first pass: the reflection's, or MAIN's without one). */
    private long panoramaFrame = -1;
    private int written;          // the history the last resolve wrote
    private long frame;
    private boolean haveHistory;
    private CloudSettings historySettings;
    /** The last frame's view (world, double) and projection: its world-to-clip from this frame's origin. */
    private final Matrix4d previousView = new Matrix4d();
    private final Matrix4f previousProjection = new Matrix4f();
    private final Vector3f previousEye = new Vector3f();
    private final Vector3f previousForward = new Vector3f();
    private double simTime;
    /** The shadow map's draws, made in the update, outside any frame's counts (as the sky's panorama). */
    private final DrawStats updateDraws = new DrawStats();

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("clouds").reads(Settings.class, Sun.class, Camera.class)
                .publishes(CloudShadow.class, CloudPanorama.class).updatesOnGpu().layer(Layer.TRANSPARENT)
                .draws(Pass.REFLECTION, Pass.MAIN);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of();
    }

    @Override
    public void init(EngineContext context) {
        this.context = context;
        gl = context.gl();
        Settings settings = context.settings();
        CloudSettings c = settings.get(CloudSettings.class);
        int seed = settings.get(EngineSettings.class).seed();
        cloudField = CloudField.generate(c.resolution(), c.frames(), BASE_BETA, seed);
        field = context.own("field", SkySystem.upload(gl, cloudField));
        fieldNow = context.own("fieldNow", Texture2D.empty(gl, c.resolution(), c.resolution(), Format.R32F,
                Sampling.LINEAR_REPEAT));
        fieldNowTarget = context.own("fieldNowTarget", Framebuffer.onTextures(gl, fieldNow));
        detail = context.own("detail", SkySystem.upload(gl, CloudField.generate(c.resolution(), c.frames(), c.beta(),
                seed)));
        optics = context.own("optics", Texture2D.empty(gl, CloudOptics.SIZE, 1, Format.RGBA16F,
                Sampling.LINEAR_CLAMP));
        programs = new CloudPrograms(context);
        fullScreen = context.own("fullScreen", Mesh.fullScreenTriangle(gl));
        Texture2D map = context.own("shadowMap", Texture2D.empty(gl, SHADOW_SIZE, SHADOW_SIZE, Format.RG16F,
                Sampling.LINEAR_REPEAT));
        shadowTarget = context.own("shadowTarget", Framebuffer.onTextures(gl, map));
        shadow = new CloudShadow(map, context.own("shadowBlock", SharedBlock.CLOUD_SHADOW.standIn(gl)));
        context.world().setResource(shadow);
        panorama = new CloudPanoramaMarch(context);
        context.world().setResource(panorama.resource());
    }

    @Override
    public void update(World world, double step) {
        simTime += step;
        CloudSettings c = world.resource(Settings.class).get(CloudSettings.class);
        RenderOrigin origin = world.resource(RenderOrigin.class);
        // from the world's origin: the render origin may step before this frame's passes, which add their own
        Vector2d wind = c.windOffset(simTime, new Vector2d());
        boolean volumetric = c.mode() == CloudSettings.Mode.VOLUMETRIC;
        shadow.write((float) c.base(), (float) c.tileSize(), (float) wind.x, (float) wind.y, volumetric ? 1 : 0);
        if (!volumetric) {
            return;
        }
        prepareTables(c);
        int previous = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING);
        int[] viewport = new int[4];
        glGetIntegerv(GL_VIEWPORT, viewport);
        // the base field at this moment, for every pass of the frame and the shadow map
        Vector4f motion = motion(c, origin);
        field.bind(CloudPrograms.FIELD_VOLUME.unit());
        fieldNowTarget.bind();
        programs.useBake(c.resolution(), motion.z + motion.w);
        fullScreen.draw(updateDraws);
        // the shadow map, before the passes that read it, when the clouds evolved or the sun moved
        Sun sun = world.resource(Sun.class);
        if (simTime - shadowTime >= SHADOW_REFRESH || sun.direction().angle(shadowSun) >= SHADOW_SUN_STEP
                || !c.equals(shadowSettings)) {
            fieldNow.bind(CloudPrograms.FIELD.unit());
            optics.bind(CloudPrograms.OPTICS.unit());
            shadowTarget.bind();
            CameraPose pose = world.resource(Camera.class).pose();
            programs.useShadow(layer(c), motion, SHADOW_SIZE, origin.relative(pose.x(), pose.y(), pose.z()),
                    sun.direction());
            fullScreen.draw(updateDraws);
            shadowTime = simTime;
            shadowSun.set(sun.direction());
            shadowSettings = c;
        }
        glBindFramebuffer(GL_FRAMEBUFFER, previous);
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    }

    /** The {@code uLayer} uniform: the base's and the top's radii, the tile, the cover's density threshold. */
    private Vector4f layer(CloudSettings c) {
        return new Vector4f((float) (EARTH_RADIUS + c.base()), (float) (EARTH_RADIUS + c.base() + c.thickness()),
                (float) c.tileSize(), threshold);
    }

    /**
     * The {@code uMotion} uniform: the wind's offset and the time phase ({@link CloudSettings#cloudMotion}), and half a
     * frame of the field's time axis (its texel centres). The offset is taken from the render origin, as the GPU's
     * positions are: the clouds stay where they are in the world when the origin moves.
     */
    private Vector4f motion(CloudSettings c, RenderOrigin origin) {
        Vector2d shift = originInTile(origin, c);
        Vector4f m = c.cloudMotion(simTime, new Vector4f()).setComponent(3, 0.5f / c.frames());
        return m.set((float) (m.x - shift.x), (float) (m.y - shift.y), m.z, m.w);
    }

    /** The render origin modulo the field's tile (the field and its detail repeat over a tile), metres. */
    private static Vector2d originInTile(RenderOrigin origin, CloudSettings c) {
        return new Vector2d(RenderOrigin.reduce(origin.x(), c.tileSize()), RenderOrigin.reduce(origin.z(),
                c.tileSize()));
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        CloudSettings c = context.world().resource(Settings.class).get(CloudSettings.class);
        if (c.mode() != CloudSettings.Mode.VOLUMETRIC) {
            haveHistory = false;
            return;
        }
        Framebuffer scene = context.target();
        int previousFramebuffer = glGetInteger(GL_DRAW_FRAMEBUFFER_BINDING); // before making targets, which binds them
        Vector4f layer = layer(c);
        RenderOrigin origin = context.world().resource(RenderOrigin.class);
        Vector4f motion = motion(c, origin);
        if (pass == Pass.MAIN && (targets == null || !targets.fits(scene.width(), scene.height()))) {
            targets = this.context.owned().replace("targets", targets, new CloudTargets(gl, scene.width(),
                    scene.height()));
            haveHistory = false;
        }
        // bound after the targets are made: making a texture binds it to the active unit
        fieldNow.bind(CloudPrograms.FIELD.unit());
        detail.bind(CloudPrograms.DETAIL.unit());
        optics.bind(CloudPrograms.OPTICS.unit());
        // 0. the panorama's band, in the frame's first pass: the reflection draws it, the environment map reads it
        if (panoramaFrame != frame) {
            CameraPose viewer = context.world().resource(Camera.class).pose();
            panorama.march(layer, motion, c, new Vector3f((float) viewer.x(), (float) viewer.y(), (float) viewer.z()),
                    viewer.y(), c.base(), c.base() + c.thickness(), fullScreen, context.stats());
            panoramaFrame = frame;
        }
        if (pass == Pass.REFLECTION) {
            panorama.drawReflection(fullScreen, context.stats());
            return;
        }
        glDisable(GL_DEPTH_TEST);
        glDepthMask(false);
        scene.depth().bind(CloudPrograms.SCENE_DEPTH.unit()); // read while another target is drawn into

        // 1. the march: the frame's slot of every 2 x 2 block, or every texel without a usable history
        boolean every = !haveHistory || !c.equals(historySettings) || jumped(context);
        int[] slot = SLOTS[(int) (frame % SLOTS.length)];
        targets.fresh.bind();
        int gw = targets.gridWidth;
        int gh = targets.gridHeight;
        glViewport(0, 0, every ? gw : (gw + 1) / 2, every ? gh : (gh + 1) / 2);
        programs.useMarch(layer, motion, gw, gh, slot, every);
        fullScreen.draw(context.stats());

        // 2. the resolve into the other history
        int read = written;
        written = 1 - written;
        targets.history[written].bind();
        targets.freshLight.bind(CloudPrograms.FRESH_LIGHT.unit());
        targets.freshDepth.bind(CloudPrograms.FRESH_DEPTH.unit());
        targets.historyLight[read].bind(CloudPrograms.HISTORY.unit());
        // the last frame's world-to-clip from this frame's origin, as the resolve's points are
        Matrix4f previous = new Matrix4f(previousProjection).mul(new Matrix4f(new Matrix4d(previousView)
                .translate(origin.x(), 0, origin.z())));
        programs.useResolve(previous, gw, gh, slot, every);
        fullScreen.draw(context.stats());

        // 3. the composite over the picture: the sky's pixels, then the surfaces', chosen by the depth test
        glBindFramebuffer(GL_FRAMEBUFFER, previousFramebuffer);
        glViewport(0, 0, scene.width(), scene.height());
        targets.historyLight[written].bind(CloudPrograms.LIGHT.unit());
        targets.historyDepth[written].bind(CloudPrograms.DEPTH.unit());
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        programs.useComposite(gw, gh, true);
        glDepthFunc(GL_LEQUAL);
        fullScreen.draw(context.stats());
        programs.useComposite(gw, gh, false);
        glDepthFunc(GL_GREATER);
        fullScreen.draw(context.stats());
        glDepthFunc(GL_LESS);
        glDisable(GL_BLEND);
        glDepthMask(true);

        context.world().resource(Counters.class).put(FULL, every ? 1 : 0);
        remember(context);
        haveHistory = true;
        historySettings = c;
        frame++;
    }

    /** The optics table for the cloud type and the density threshold for the cover, when they changed. */
    private void prepareTables(CloudSettings c) {
        if (c.type() != opticsType) {
            float[] table = CloudOptics.table(c.type());
            FloatBuffer data = MemoryUtil.memAllocFloat(table.length).put(table).flip();
            try {
                optics.upload(0, 0, 1, data);
            } finally {
                MemoryUtil.memFree(data);
            }
            opticsType = c.type();
        }
        if (c.cover() != thresholdCover) {
            threshold = CloudField.coverageThreshold(cloudField, c.cover());
            thresholdCover = c.cover();
        }
    }

    /** Whether the camera cut since the last frame: moved {@link #CUT_DISTANCE} or turned past {@link #CUT_COSINE}. */
    private boolean jumped(RenderContext context) {
        Vector3f forward = forward(context, new Vector3f());
        return context.camera().position().distance(previousEye) > CUT_DISTANCE
                || forward.dot(previousForward) < CUT_COSINE;
    }

    private void remember(RenderContext context) {
        previousView.set(context.camera().exactView());
        previousProjection.set(context.camera().projection());
        previousEye.set(context.camera().position());
        forward(context, previousForward);
    }

    /** The view direction, world space: the view matrix's third row, negated. */
    private static Vector3f forward(RenderContext context, Vector3f dest) {
        return context.camera().view().positiveZ(dest).negate();
    }

    /** The GL objects were handed to {@code context.own} (the targets to its {@code replace}); nothing else to free. */
    @Override
    public void close() {
    }
}
