package org.openworld.engine.shadow;

import static org.lwjgl.opengl.GL15C.GL_DYNAMIC_DRAW;
import static org.lwjgl.opengl.GL31C.GL_UNIFORM_BUFFER;

import java.nio.ByteBuffer;
import java.util.ArrayList;
import java.util.List;
import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Vector3d;
import org.joml.Vector3fc;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.Cullable;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Owned;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.PassOwner;
import org.openworld.engine.core.PassView;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.ViewCamera;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.SunShadow;
import org.openworld.engine.gl.DepthTextureArray;
import org.openworld.engine.gl.Framebuffer;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.origin.RenderOrigin;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;
import org.openworld.engine.shadow.ShadowSettings.Method;

/**
 * The sun's shadows (paper 3.2): owns the {@link Pass#SHADOW} pass, which it runs once per cascade with an
 * orthographic camera looking along the sunlight into that cascade's depth layer, and publishes the maps with the
 * block that says how to read them as the world's {@link SunShadow}, which every lit shader reads through
 * {@code shaders/common/shadow.glsl}.
 *
 * <p>Each frame, before the pass ({@link #passViews}): the view is cut into slices ({@link CascadeSplits}), each
 * slice gets its light box ({@link LightFit#stable}, or the paper's {@link LightFit#covering}), the box reaches
 * towards the sun as far as a caster can stand (the height span of everything culling knows of, over the sine of the
 * sun's elevation), and the block is rewritten. Only the maps whose box moved are redrawn ({@link CascadeRefresh},
 * {@code shadow.refresh}): the others keep their depths and the box they were drawn with. The casters (the terrain
 * and the trees, drawing depth only) are culled against each box by the culling system, like any pass camera.
 *
 * <p>No views, and so no shadows, while the sun is below the horizon: its light is then nil anyway.
 */
public final class ShadowSystem implements EngineSystem, PassOwner {
    /** The counter of the cascades drawn again this frame. */
    private static final Counter REDRAWN = Counter.of("shadow", "redrawn");

    /** The most cascades: the length of the block's matrix array ({@code ShadowSettings.cascades}' maximum). */
    static final int MAX_CASCADES = 4;
    /** Fraction of a cascade's side, at its border, over which the next cascade is blended in. */
    static final float BLEND_BAND = 0.1f;
    /** Fraction of the shadow distance, at its end, over which shadows fade out. */
    static final float FADE = 0.1f;
    /**
     * The lowest sun elevation the casters' reach is computed for, as a sine (1°): at a grazing sun a caster's
     * shadow is endless, and the box must stop somewhere.
     */
    static final double MIN_SUN_SINE = Math.sin(Math.toRadians(1));

    private GlContext gl;
    /** What this system owns, for the maps re-made when their size or number changes. */
    private Owned owned;
    private DepthTextureArray maps;
    private final List<Framebuffer> layers = new ArrayList<>();
    private GpuBuffer block;
    private final ByteBuffer blockData = MemoryUtil.memCalloc(SunShadow.BLOCK_SIZE);
    private List<LightBox> boxes = List.of();
    private final CascadeRefresh refresh = new CascadeRefresh();
    /** The {@link Settings#changes} count the maps were drawn under; −1 before the first frame. */
    private long drawnUnder = -1;
    private ShadowProbe probe;

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("shadow").reads(Settings.class, Camera.class, Sun.class, Cullable.class)
                .writes(SunShadow.class).draws(Pass.OVERLAY);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(ShadowSettings.SETTINGS);
    }

    @Override
    public Pass ownedPass() {
        return Pass.SHADOW;
    }

    @Override
    public void init(EngineContext context) {
        gl = context.gl();
        owned = context.owned();
        block = context.own("block", new GpuBuffer(gl, GL_UNIFORM_BUFFER));
        block.allocate(SunShadow.BLOCK_SIZE, GL_DYNAMIC_DRAW);
        probe = new ShadowProbe(context);
        fitMaps(context.settings().get(ShadowSettings.class), context.world());
    }

    /** (Re)makes the depth layers when their size, number or depth format changed: once, not every frame. */
    private void fitMaps(ShadowSettings s, World world) {
        if (maps != null && maps.size() == s.resolution() && maps.layers() == s.maps()
                && maps.format() == s.depth().format) {
            return;
        }
        layers.forEach(owned::drop);
        layers.clear();
        maps = owned.replace("maps", maps, DepthTextureArray.of(gl, s.resolution(), s.maps(), s.depth().format));
        for (int i = 0; i < s.maps(); i++) {
            layers.add(owned.own("map" + i, Framebuffer.onLayer(gl, maps, i)));
        }
        world.setResource(new SunShadow(maps, block));
    }

    /**
     * Fits each map's box and returns the views of the maps to redraw ({@link CascadeRefresh}); the others keep their
     * depths and their boxes, and the block describes the boxes the maps hold.
     */
    @Override
    public List<PassView> passViews(World world, PassView viewer) {
        Settings settings = world.resource(Settings.class);
        ShadowSettings s = settings.get(ShadowSettings.class);
        fitMaps(s, world);
        if (settings.changes() != drawnUnder) {
            refresh.forget(s.maps());                       // the casters, the maps or their layout may have changed
            drawnUnder = settings.changes();
        }
        refresh.nextFrame();
        ViewCamera eye = viewer.camera();
        Vector3fc toSun = world.findResource(Sun.class).orElse(Sun.NOON).direction();
        if (toSun.y() <= 0) {
            refresh.forget(s.maps());
            boxes = List.of();
            writeBlock(s, eye, world.resource(RenderOrigin.class)); // no cascades: everything lit
            return List.of();
        }
        double reach = CasterHeights.of(world).span() / Math.max(toSun.y(), MIN_SUN_SINE);
        double[] splits = s.method() == Method.PAPER ? new double[] {eye.near(), s.distance()}
                : CascadeSplits.distances(eye.near(), s.distance(), s.cascades(), s.splitBlend());
        List<LightBox> held = new ArrayList<>();
        List<PassView> views = new ArrayList<>();
        for (int i = 0; i + 1 < splits.length; i++) {
            Vector3fc sun = refresh.sunFor(i, toSun, s.refreshAngle(), s.refresh());
            LightBox box = s.method() == Method.PAPER
                    ? LightFit.covering(eye.view(), eye.projection(), splits[i], splits[i + 1], sun, reach,
                            s.resolution())
                    : LightFit.stable(eye.view(), eye.projection(), splits[i], splits[i + 1], sun, reach,
                            s.resolution());
            Vector3d[] corners = LightFit.sliceCorners(eye.view(), eye.projection(), splits[i], splits[i + 1]);
            if (refresh.redraw(i, box, sun, corners, s.refresh())) {
                views.add(new PassView(new ViewCamera(box.view(), box.projection(), box.sunwardCentre(), 0,
                        box.depthRange()), layers.get(i), splits.length > 2 ? i : -1));
            }
            held.add(refresh.box(i));
        }
        boxes = List.copyOf(held);
        writeBlock(s, eye, world.resource(RenderOrigin.class));
        world.resource(Counters.class).put(REDRAWN, views.size());
        return views;
    }

    /**
     * The std140 {@code ShadowBlock} of {@code shaders/common/shadow.glsl}, member by member. The paper's method has
     * the margin alone (no slope or normal bias) and no fade: its map simply ends at the shadow distance. The
     * matrices and the viewer take positions from the render origin, as the frame block does: {@code L · T(origin)},
     * multiplied in double.
     */
    private void writeBlock(ShadowSettings s, ViewCamera eye, RenderOrigin origin) {
        int n = boxes.size();
        boolean paper = s.method() == Method.PAPER;
        for (int i = 0; i < MAX_CASCADES; i++) {                    // lightViewProjection[4]
            Matrix4f fromOrigin = i < n ? new Matrix4f(new Matrix4d(boxes.get(i).viewProjection())
                    .translate(origin.x(), 0, origin.z())) : new Matrix4f();
            fromOrigin.get(i * 64, blockData);
        }
        Vector3fc viewer = eye.positionFrom(origin.x(), origin.z());
        int o = MAX_CASCADES * 64;
        for (int i = 0; i < MAX_CASCADES; i++) {
            blockData.putFloat(o + 4 * i, i < n ? boxes.get(i).texelSize() : 0);          // cascadeTexel
            blockData.putFloat(o + 16 + 4 * i, i < n ? boxes.get(i).depthRange() : 1);    // cascadeDepth
        }
        o += 32;
        o = vec4(o, n, s.kernel(), (float) s.margin(), BLEND_BAND);                    // shadowParams
        float far = (float) s.distance();
        o = vec4(o, paper ? 0 : (float) s.normalOffset(), paper ? 0 : (float) s.slopeBias(),
                far * (1 - FADE), paper ? 0 : far);                                     // biasParams
        // the sun's disc: metres of soft edge per metre between caster and ground (0: the filter's width only)
        float penumbra = paper || !s.penumbra() ? 0 : (float) (2 * Math.tan(Math.toRadians(Sun.ANGULAR_RADIUS_DEG)));
        vec4(o, viewer.x(), viewer.y(), viewer.z(), penumbra);                           // viewerPos
        block.update(blockData);
    }

    private int vec4(int offset, float x, float y, float z, float w) {
        blockData.putFloat(offset, x).putFloat(offset + 4, y).putFloat(offset + 8, z).putFloat(offset + 12, w);
        return offset + 16;
    }

    /**
     * The light boxes the maps hold this frame, one per map (for tests and tools): this frame's fit for a map redrawn,
     * the one it was drawn with for a map kept; empty while the sun is down.
     */
    public List<LightBox> boxes() {
        return boxes;
    }

    /** With {@code shadow.measure} on: the flicker and acne of the finished picture, into the counters. */
    @Override
    public void render(Pass pass, RenderContext context) {
        if (context.world().resource(Settings.class).get(ShadowSettings.class).measure()) {
            probe.measure(context);
        }
    }

    /** Frees the block's staging memory; the GL objects were handed to {@code context.own}, the engine closes them. */
    @Override
    public void close() {
        MemoryUtil.memFree(blockData);
    }
}
