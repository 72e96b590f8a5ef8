package org.openworld.engine.minimap;

import static org.lwjgl.opengl.GL11C.*;

import java.nio.ByteBuffer;
import java.util.List;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.Layer;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * A top-down map of the ground around the camera, north up, in a corner of the picture, with a marker at the camera
 * pointing where it looks. See the package documentation for the technique; {@code docs/adding-a-system.md} builds
 * it step by step.
 *
 * <p>The map ({@link ReliefMap}) is sampled from the world's {@link HeightField} on the CPU and uploaded to one
 * texture, only when the camera has moved a quarter of the range from where it was built, or the range or the water
 * changed. Each frame the shader draws the square, moves the map under it to the camera's exact position and turns
 * the marker to its yaw.
 */
public final class MinimapSystem implements EngineSystem {

    private static final TextureUnits UNITS = new TextureUnits();
    /** The relief map. */
    private static final TextureUnits.Sampler RELIEF = UNITS.add("relief");
    /** Width of the border around the map, pixels: a thin dark line that parts it from the scene. */
    private static final float BORDER_PX = 2;
    /** The marker's length from the camera to its tip, as a share of the map's side (23 px on the default 324 px). */
    static final float MARKER_SHARE = 0.07f;

    private ShaderProgram program;
    private Uniform.Vec3 squareUniform;
    private Uniform.Vec3 cameraUniform;
    private Uniform.Vec2 headingUniform;
    private Uniform.Vec2 markerUniform;
    private Mesh quad;
    private Texture2D relief;
    /** The map in the texture; null until the minimap is first drawn. */
    private ReliefMap map;
    private int builds;

    @Override
    public SystemSpec spec() {
        // Layer.TRANSPARENT: drawn over the finished picture, after every other system that draws in OVERLAY
        return SystemSpec.named("minimap").reads(Settings.class, Camera.class, HeightField.class, WaterLevel.class)
                .layer(Layer.TRANSPARENT).draws(Pass.OVERLAY)
                .offByDefault(); // shots and figures unchanged unless asked for: --set system.minimap=on
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(MinimapSettings.SETTINGS);
    }

    @Override
    public void init(EngineContext context) {
        program = context.own("program", context.shaders().program("minimap/minimap.vert", "minimap/minimap.frag"));
        program.sampler(RELIEF);
        squareUniform = program.vec3("uSquare");
        cameraUniform = program.vec3("uCamera");
        headingUniform = program.vec2("uHeading");
        markerUniform = program.vec2("uMarker");
        // the square, corners (0, 0) to (1, 1), which the vertex shader places in the picture
        quad = context.own("quad", new Mesh(context.gl(), new float[] {0, 0, 1, 0, 1, 1, 0, 1},
                new int[] {0, 1, 2, 0, 2, 3}, new Mesh.Attribute(0, 2)));
        relief = context.own("relief", Texture2D.empty(context.gl(), ReliefMap.TEXELS, ReliefMap.TEXELS,
                Format.RGBA8, Sampling.LINEAR_CLAMP));
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        MinimapSettings s = context.world().resource(Settings.class).get(MinimapSettings.class);
        CameraPose pose = context.world().resource(Camera.class).pose();
        // 1. the map around the camera: built again only when the camera nears its edge or what it shows changed
        HeightField field = context.world().findResource(HeightField.class).orElse(HeightField.FLAT);
        double water = waterLevel(context.world());
        if (map == null || !map.covers(field, pose.x(), pose.z(), s.range(), water)) {
            map = ReliefMap.build(field, pose.x(), pose.z(), s.range(), water);
            ByteBuffer texels = MemoryUtil.memAlloc(map.rgba().length).put(map.rgba()).flip();
            try {
                relief.upload(0, 0, ReliefMap.TEXELS, texels);
            } finally {
                MemoryUtil.memFree(texels);
            }
            builds++;
        }
        // 2. where it goes: a square in a corner, its lower-left corner in GL's pixels (rows counted upwards)
        int height = context.target().height();
        MinimapSettings.Square square = s.square(context.target().width(), height);
        double yaw = Math.toRadians(pose.yaw());
        program.use();
        squareUniform.set(square.left(), height - square.top() - square.side(), square.side());
        // 3. the map moved to the camera's exact position, and the marker turned to where it looks
        cameraUniform.set((float) map.s(pose.x()), (float) map.t(pose.z()), (float) map.shownShare());
        headingUniform.set((float) Math.sin(yaw), (float) Math.cos(yaw));
        markerUniform.set(MARKER_SHARE * square.side(), BORDER_PX);
        relief.bind(RELIEF.unit());
        // 4. one square over the picture: no depth test, and the scene's depth left as it was
        glDisable(GL_DEPTH_TEST);
        glDepthMask(false);
        quad.draw(context.stats());
        glDepthMask(true);
    }

    /**
     * The height under which the map shows water: the world's {@link WaterLevel} (the water system writes it), or
     * {@code -∞} when the world has none, so no ground is drawn as water that the picture shows dry.
     */
    static double waterLevel(World world) {
        return world.findResource(WaterLevel.class).map(WaterLevel::height).orElse(Double.NEGATIVE_INFINITY);
    }

    /** How often the map was built: once when first drawn, then once per move of a quarter range (tests). */
    int builds() {
        return builds;
    }
}
