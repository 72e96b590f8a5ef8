package org.openworld.engine.sky;

import static org.lwjgl.opengl.GL11C.*;

import java.nio.FloatBuffer;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import org.joml.Matrix4fc;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector4f;
import org.lwjgl.system.MemoryUtil;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.Layer;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.Workers;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.CloudPanorama;
import org.openworld.engine.environment.Exposure;
import org.openworld.engine.environment.SkyIrradiance;
import org.openworld.engine.environment.SkyMaps;
import org.openworld.engine.environment.Sun;
import org.openworld.engine.environment.TimeOfDay;
import org.openworld.engine.environment.Wind;
import org.openworld.engine.gl.CubeMapTexture;
import org.openworld.engine.gl.DrawStats;
import org.openworld.engine.gl.Format;
import org.openworld.engine.gl.GlContext;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.Sampling;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.Texture2D;
import org.openworld.engine.gl.Texture3D;
import org.openworld.engine.gl.Uniform;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;

/**
 * The sky of paper sections 2.3 and 3.1: the atmosphere's scattering tables for the sun of the moment, the sky and
 * its clouds drawn behind everything, the environment map glossy surfaces reflect, and the light of the world (the
 * sun's colour at the eye, the sky's ambient light, the exposure).
 *
 * <p>Per update: the sun's direction from the clock ({@link SolarPosition}); when it or the eye's altitude moved
 * enough to matter ({@link SunTables#staleFor}) new tables, on a worker thread while the sun drifts with the day
 * cycle (the sky keeps the old ones until they are ready) and at once when it jumped (a new {@code --time}, a
 * scrub), so a picture never shows the tables of another hour. New tables are uploaded in the update, and the
 * {@link SkyPanorama} (the sky with its clouds in every direction) and the environment map are redrawn from them when
 * the tables or the cloud settings changed, the sun moved {@link #PANORAMA_SUN_STEP} or the clouds drifted for
 * {@link #PANORAMA_REFRESH} seconds: before any pass, so every system that reads the sky's maps draws with this
 * step's.
 *
 * <p>Per pass (the water's REFLECTION, without the sun's disc, which the water adds as glitter; and MAIN) the sky is
 * the {@link org.openworld.engine.core.Layer#BACKGROUND background}: drawn after every opaque system, on the
 * far plane with the depth test on and depth writes off, so a pixel some surface covers is rejected before it is
 * shaded, and each sky pixel is one panorama lookup plus the sun's disc.
 *
 * <p>Counters: {@code sky.tables-ms} (CPU time of tables that arrived this frame), {@code sky.panorama} (1 when the
 * panorama and the environment map were redrawn).
 */
public final class SkySystem implements EngineSystem {
    /** The counters: 1 when the panorama was drawn; CPU time of tables that arrived this frame, ms. */
    private static final Counter PANORAMA_DRAWN = Counter.of("sky", "panorama");
    private static final Counter TABLES_MS = Counter.of("sky", "tables-ms");

    /** Texels along a side of the environment map's faces: the sky's gradients are smooth, so few suffice. */
    public static final int ENVIRONMENT_SIZE = 64;
    /**
     * Simulation seconds after which drifting clouds are redrawn into the panorama: at the default wind (8 m/s on a
     * layer 2500 m up) the clouds overhead move 0.09° meanwhile, about a pixel of a 1280 × 720 picture.
     */
    static final double PANORAMA_REFRESH = 0.5;
    /**
     * Radians the sun may move before the panorama is redrawn: it is laid out in world azimuth, while the tables
     * follow the sun's elevation only. A third of the disc's radius.
     */
    static final double PANORAMA_SUN_STEP = Math.toRadians(0.1);
    /**
     * Tables this many steps of {@link SunTables#staleFor} away are rebuilt at once rather than in the background: the
     * sun jumped (a new time was set) instead of drifting with the day cycle.
     */
    static final int JUMP_STEPS = 4;

    private final ExecutorService worker = Workers.single("sky-tables");
    private CompletableFuture<SunTables> building;
    private SunTables tables;
    private SunTables uploaded;
    private double simTime;
    /** Whether a simulation step has run: init's update, of 0 s, sees the camera before anyone placed it. */
    private boolean stepped;
    /** The simulation time, tables and settings the panorama was last drawn for. */
    private double panoramaTime;
    private SunTables panoramaTables;
    private final Vector3f panoramaSun = new Vector3f();
    private CloudSettings panoramaClouds;
    private double panoramaAlbedo = Double.NaN;
    /**
     * Ground light (display units) below which the panorama is stored relative to it: above, with the sun higher than
     * about 3° below the horizon, the sky is within a half float's normal range as it is, and stored unscaled, so no
     * daylight picture changes.
     */
    static final double PANORAMA_SCALED_BELOW = 1e-3;
    /** What the panorama's radiance is multiplied by: 1 / the ground's light when it was drawn (SkyPanorama#draw). */
    private float panoramaScale = 1;
    /** The sky's light for any normal, and the tables, ground albedo and sun it was projected for. */
    private SkyIrradiance irradiance;
    private SunTables irradianceTables;
    private double irradianceAlbedo = Double.NaN;
    private final Vector3f irradianceSun = new Vector3f();
    private double irradianceMoonAge = Double.NaN;
    /** The night's light of this step, for the discs and the stars the passes draw. */
    private NightLight night;
    private StarField stars;
    private StarField.NightUniforms nightUniforms;
    /** The panorama's draws, made in the update, outside any frame's counts. */
    private final DrawStats updateDraws = new DrawStats();

    private ShaderProgram program;
    private Uniform.Int cubeFace;
    private Uniform.Mat3 faceAxes;
    private Uniform.Float sunDisc;
    private Uniform.Float cloudLayer;
    private Uniform.Float cloudVolume;
    private Mesh fullScreen;
    private SkyPanorama panorama;
    private Texture2D skyView;
    private Texture3D air;
    private Texture3D clouds;
    private CloudField cloudField;
    /** The density threshold for {@link #thresholdCover}: a sort of the whole field, so computed once per cover. */
    private float threshold;
    private double thresholdCover = Double.NaN;
    private CubeMapTexture environment;

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("sky").reads(TimeOfDay.class, Settings.class, Camera.class)
                .writes(Sun.class, Exposure.class, SkyMaps.class, Wind.class).updatesOnGpu().layer(Layer.BACKGROUND)
                .draws(Pass.REFLECTION, Pass.MAIN);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(SkySettings.SETTINGS, AtmosphereSettings.SETTINGS, CloudSettings.SETTINGS);
    }

    /** The tables' layout, which {@code shaders/sky/atmosphere.glsl} reads them by. */
    @Override
    public Map<String, Number> shaderConstants() {
        return Map.of("SKY_VIEW_WIDTH", SkyView.WIDTH, "SKY_VIEW_HEIGHT", SkyView.HEIGHT,
                "AERIAL_WIDTH", AerialPerspective.WIDTH, "AERIAL_HEIGHT", AerialPerspective.HEIGHT,
                "AERIAL_DEPTH", AerialPerspective.DEPTH, "AERIAL_MAX_DISTANCE", AerialPerspective.MAX_DISTANCE);
    }

    @Override
    public void init(EngineContext context) {
        GlContext gl = context.gl();
        Settings settings = context.settings();
        CloudSettings c = settings.get(CloudSettings.class);
        int seed = settings.get(EngineSettings.class).seed();
        cloudField = CloudField.generate(c.resolution(), c.frames(), c.beta(), seed);
        program = context.own("program", context.shaders().program("sky/sky.vert", "sky/sky.frag"));
        program.sampler(SkyPanorama.SKY_PANORAMA);
        program.sampler(SkyPanorama.CLOUD_PANORAMA);
        program.sampler(SkyPanorama.CLOUD_VOLUME);
        cubeFace = program.int1("uCubeFace");
        faceAxes = program.mat3("uFaceAxes");
        sunDisc = program.float1("uSunDisc");
        cloudLayer = program.float1("uCloudLayer");
        cloudVolume = program.float1("uCloudVolume");
        nightUniforms = new StarField.NightUniforms(program);
        stars = new StarField(context, StarCatalogue.generate(seed));
        panorama = new SkyPanorama(context);
        fullScreen = context.own("fullScreen", Mesh.fullScreenTriangle(gl));
        // full floats: the twilight's and the night's radiance (10^-7 and less, display units) lies below a half
        // float's normal range (6·10^-5), where it keeps a few bits or none; read only when the panorama is drawn
        skyView = context.own("view", Texture2D.empty(gl, SkyView.WIDTH, SkyView.HEIGHT, Format.RGB32F,
                Sampling.LINEAR_CLAMP));
        air = context.own("aerialPerspective", Texture3D.of(gl, AerialPerspective.WIDTH, AerialPerspective.HEIGHT,
                AerialPerspective.DEPTH, Format.RGBA16F, Sampling.LINEAR_CLAMP, null));
        clouds = context.own("clouds", upload(gl, cloudField));
        environment = context.own("environment", CubeMapTexture.renderTarget(gl, ENVIRONMENT_SIZE));
        context.world().setResource(new SkyMaps(air, environment));
        update(context.world(), 0);
    }

    /** The field as a 3D texture (s, t one tile, r one period; R16F, wrapping), as the sky and the clouds read it. */
    public static Texture3D upload(GlContext gl, CloudField field) {
        FloatBuffer data = MemoryUtil.memAllocFloat(field.values().length).put(field.values()).flip();
        try {
            return Texture3D.of(gl, field.resolution(), field.resolution(), field.frames(), Format.R16F,
                    Sampling.LINEAR_REPEAT, data);
        } finally {
            MemoryUtil.memFree(data);
        }
    }

    @Override
    public void update(World world, double step) {
        simTime += step;
        Settings settings = world.resource(Settings.class);
        SkySettings s = settings.get(SkySettings.class);
        AtmosphereSettings atmosphere = settings.get(AtmosphereSettings.class);
        double hours = world.resource(TimeOfDay.class).hours();
        Vector3f toSun = SolarPosition.direction(hours, s.latitude(), s.declination());
        double elevation = Math.asin(toSun.y);
        double altitude = Math.max(0, world.resource(Camera.class).pose().y());
        Counters counters = world.resource(Counters.class);

        if (building != null && building.isDone()) {
            accept(building.join(), counters);
            building = null;
        }
        if (tables == null || tables.staleFor(atmosphere, elevation, altitude)) {
            // at once, not in the background, when there are none yet, when the sun or the eye jumped, and until
            // the first step: the tables of init are for wherever the camera was before the director placed it
            if (tables == null || !stepped || jumped(atmosphere, elevation, altitude)) {
                accept(build(tables, atmosphere, elevation, altitude), counters);
            } else if (building == null) {
                SunTables current = tables;
                building = CompletableFuture.supplyAsync(() -> build(current, atmosphere, elevation, altitude), worker);
            }
        }
        stepped |= step > 0;
        SkyLight light = tables.light();
        night = NightLight.of(tables.atmosphere(), s, hours, altitude);
        double albedo = atmosphere.groundAlbedo();
        if (irradianceTables != tables || irradianceAlbedo != albedo || irradianceMoonAge != s.moonAge()
                || toSun.angle(irradianceSun) >= PANORAMA_SUN_STEP) {
            irradiance = SkyLight.irradiance(tables.view(), light, toSun, albedo, night);
            irradianceTables = tables;
            irradianceAlbedo = albedo;
            irradianceMoonAge = s.moonAge();
            irradianceSun.set(toSun);
        }
        Vector3d ambient = light.ambient().add(night.onLevelGround());
        world.setResource(new Sun(toSun, vector(light.sun()), vector(ambient), irradiance));
        world.setResource(exposure(s, light.sun().mul(Math.max(toSun.y, 0)).add(ambient)));
        world.setResource(new Wind(settings.get(CloudSettings.class).windVelocity(new Vector3f())));
        refresh(settings, world.resource(Sun.class), volume(world), counters);
    }

    /**
     * The volumetric clouds' panorama, where a clouds system marches them ({@code clouds.mode=volumetric} and the
     * system present): the sky then draws no layer, and its environment map takes the volume's clouds.
     */
    private static CloudPanorama volume(World world) {
        boolean volumetric = world.resource(Settings.class).get(CloudSettings.class).mode()
                == CloudSettings.Mode.VOLUMETRIC;
        return volumetric ? world.findResource(CloudPanorama.class).orElse(null) : null;
    }

    /**
     * Uploads tables that arrived and redraws the panorama and the environment map when the tables, the cloud
     * settings or the ground changed, the sun moved {@link #PANORAMA_SUN_STEP}, or the clouds drifted for
     * {@link #PANORAMA_REFRESH} seconds.
     */
    private void refresh(Settings settings, Sun sun, CloudPanorama volume, Counters counters) {
        if (uploaded != tables) {
            uploadTables(tables);
            uploaded = tables;
        }
        CloudSettings c = settings.get(CloudSettings.class);
        double albedo = settings.get(AtmosphereSettings.class).groundAlbedo();
        if (panoramaTables == tables && c.equals(panoramaClouds) && albedo == panoramaAlbedo
                && sun.direction().angle(panoramaSun) < PANORAMA_SUN_STEP && simTime - panoramaTime < PANORAMA_REFRESH) {
            return;
        }
        if (c.cover() != thresholdCover) {
            threshold = CloudField.coverageThreshold(cloudField, c.cover());
            thresholdCover = c.cover();
        }
        skyView.bind(SkyPanorama.VIEW.unit());
        clouds.bind(SkyPanorama.CLOUDS.unit());
        air.bind(SkyPanorama.AIR.unit());
        Vector3f ground = new Vector3f(sun.color()).mul(Math.max(sun.direction().y(), 0)).add(sun.ambient());
        double light = Math.max(Adaptation.luminance(new Vector3d(ground)), Adaptation.MIN_LIGHT);
        panoramaScale = light < PANORAMA_SCALED_BELOW ? (float) (1 / light) : 1;
        panorama.draw(sun, tables.altitude(), albedo, panoramaScale, c.cloudParams(threshold, tables.altitude(), new Vector4f()),
                c.cloudMotion(simTime, new Vector4f()), fullScreen, updateDraws);
        // the environment map: the panorama into the six faces, linear and without the sun's disc (neither target
        // has a depth buffer, so the depth test passes whatever its state)
        program.use();
        panorama.sky().bind(SkyPanorama.SKY_PANORAMA.unit());
        panorama.clouds().bind(SkyPanorama.CLOUD_PANORAMA.unit());
        cubeFace.set(1);
        cloudLayer.set(volume == null ? 1 : 0);
        cloudVolume.set(volume == null ? 0 : 1);
        if (volume != null) {
            volume.texture().bind(SkyPanorama.CLOUD_VOLUME.unit());
        }
        nightUniforms.set(night, panoramaScale);
        environment.render(face -> {
            faceAxes.set(CubeMapTexture.faceAxes(face));
            fullScreen.draw(updateDraws);
        });
        panoramaTime = simTime;
        panoramaTables = tables;
        panoramaSun.set(sun.direction());
        panoramaClouds = c;
        panoramaAlbedo = albedo;
        counters.put(PANORAMA_DRAWN, 1);
    }

    /** New tables for a sun and an eye, reusing those of {@code current} (may be null) that the air shares. */
    private static SunTables build(SunTables current, AtmosphereSettings atmosphere, double elevation,
                                   double altitude) {
        AtmosphereTables own = current != null && current.atmosphere().settings().equals(atmosphere)
                ? current.atmosphere() : AtmosphereTables.build(atmosphere);
        return SunTables.build(own, elevation, altitude);
    }

    /** Whether the sun or the eye moved {@link #JUMP_STEPS} times what makes tables stale, or the air changed. */
    private boolean jumped(AtmosphereSettings atmosphere, double elevation, double altitude) {
        double e = tables.sunElevation() + (elevation - tables.sunElevation()) / JUMP_STEPS;
        double a = tables.altitude() + (altitude - tables.altitude()) / JUMP_STEPS;
        return tables.staleFor(atmosphere, e, a);
    }

    private void accept(SunTables fresh, Counters counters) {
        tables = fresh;
        counters.put(TABLES_MS, fresh.buildMillis());
    }

    /**
     * The exposure for the light on level ground {@code ground} (display units) by {@link Adaptation}'s law and its
     * Purkinje shift; with {@code sky.auto-exposure} off, noon's (1: the light of a high sun is about 1) and no shift.
     * Times the user's compensation either way.
     */
    static Exposure exposure(SkySettings s, Vector3d ground) {
        if (!s.autoExposure()) {
            return new Exposure((float) Adaptation.exposure(1, s.exposure()));
        }
        double e = Adaptation.luminance(ground);
        return new Exposure((float) Adaptation.exposure(e, s.exposure()), (float) Adaptation.scotopicShare(e));
    }

    private static Vector3f vector(Vector3d v) {
        return new Vector3f((float) v.x, (float) v.y, (float) v.z);
    }

    /** The sky behind everything opaque: the far plane, depth-tested, one panorama lookup and the sun's disc. */
    @Override
    public void render(Pass pass, RenderContext context) {
        program.use();
        panorama.sky().bind(SkyPanorama.SKY_PANORAMA.unit());
        panorama.clouds().bind(SkyPanorama.CLOUD_PANORAMA.unit());
        cubeFace.set(0);
        sunDisc.set(pass == Pass.MAIN ? 1 : 0);
        // the volumetric clouds, where a system marches them, draw themselves over the picture and the reflection
        cloudLayer.set(volume(context.world()) == null ? 1 : 0);
        cloudVolume.set(0);
        nightUniforms.set(night, panoramaScale);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(false);
        fullScreen.draw(context.stats());
        Matrix4fc projection = context.camera().projection();
        double pixel = 4.0 / (projection.m00() * projection.m11() * context.target().width() * context.target().height());
        if (stars.visible(context.world().resource(Exposure.class).scale(), pixel)) {
            SkySettings s = context.world().resource(Settings.class).get(SkySettings.class);
            double hours = context.world().resource(TimeOfDay.class).hours();
            stars.draw(MoonPosition.equatorialToLocal(hours, s.latitude(), s.declination()), night, panoramaScale,
                    context.stats());
        }
        glDepthMask(true);
        glDepthFunc(GL_LESS);
    }

    private void uploadTables(SunTables t) {
        FloatBuffer view = MemoryUtil.memAllocFloat(t.view().rgb().length).put(t.view().rgb()).flip();
        FloatBuffer table = MemoryUtil.memAllocFloat(t.air().rgba().length).put(t.air().rgba()).flip();
        try {
            skyView.upload(0, 0, SkyView.HEIGHT, view);
            air.upload(table);
        } finally {
            MemoryUtil.memFree(view);
            MemoryUtil.memFree(table);
        }
    }

    /** Stops the table worker; the GL objects were handed to {@code context.own} and the engine closes them. */
    @Override
    public void close() {
        worker.shutdownNow();
    }
}
