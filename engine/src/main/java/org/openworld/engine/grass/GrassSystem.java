package org.openworld.engine.grass;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import org.joml.Vector3f;
import org.openworld.engine.EngineSettings;
import org.openworld.engine.camera.Camera;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.core.Counter;
import org.openworld.engine.core.Counters;
import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.EngineSystem;
import org.openworld.engine.core.HeightField;
import org.openworld.engine.core.Pass;
import org.openworld.engine.core.RenderContext;
import org.openworld.engine.core.SystemSpec;
import org.openworld.engine.core.Workers;
import org.openworld.engine.core.World;
import org.openworld.engine.environment.SnowLine;
import org.openworld.engine.environment.WaterLevel;
import org.openworld.engine.environment.Wind;
import org.openworld.engine.settings.Settings;
import org.openworld.engine.settings.SettingsGroup;
import org.openworld.engine.terrain.material.GrassAlbedo;
import org.openworld.engine.vegetation.PlacementField;

/**
 * Grass near the eye: tufts of blades made on the GPU from their cell of the world's grid, where the land grows
 * grass. See the package documentation for the technique.
 *
 * <p>Frame by frame: {@link #update} has the {@link GrassField} around the viewer made again when the viewer has moved
 * {@link GrassField#REBUILD_SHARE} of the distance from its middle, on a worker thread, and uploads it when it is
 * ready; only the first (and one after the world or the settings changed) is made at once. {@link #render} plans the
 * blocks in view ({@link GrassRuns}) and has {@link GrassDraw} draw them.
 */
public final class GrassSystem implements EngineSystem {
    /** The counters: making the field's CPU time (ms, when it was made), the tufts drawn. */
    private static final Counter FIELD_MS = Counter.of("grass", "field-ms");
    private static final Counter DRAWN = Counter.of("grass", "drawn");

    /**
     * The wind among the blades as a share of the cloud layer's: half a metre up, the ground slows the air to a fifth
     * of what blows a kilometre up (a logarithmic profile over a meadow's roughness).
     */
    static final float GROUND_WIND = 0.2f;
    /** Metres above the water where grass begins: the wet rim of a lake is mud and reeds. */
    static final double SHORE = 0.3;
    /**
     * The ground's grass where the world has no terrain textures to take it from: the mean of the blades' roots'
     * albedos ({@code grass.frag}), without a sheen, so the blades thin into their own roots' colour.
     */
    static final GrassAlbedo ROOTS = new GrassAlbedo(0.0575f, 0.12f, 0.021f, 0);

    private final ExecutorService worker = Workers.single("grass-field");
    private GrassDraw draw;
    private GrassField field;
    /** Everything the field depends on but the viewer's place: a change makes it again at once. */
    private Land land;
    private CompletableFuture<Made> making;

    /** The land the field is made from. */
    private record Land(HeightField heights, PlacementField placement, GrassField.Rules rules, double distance) {
    }

    @Override
    public SystemSpec spec() {
        return SystemSpec.named("grass")
                .reads(Settings.class, Camera.class, HeightField.class, WaterLevel.class, SnowLine.class,
                        PlacementField.class, Wind.class, GrassAlbedo.class)
                .draws(Pass.MAIN);
    }

    @Override
    public List<SettingsGroup<?>> settings() {
        return List.of(GrassSettings.SETTINGS);
    }

    @Override
    public void init(EngineContext context) {
        draw = new GrassDraw(context);
    }

    @Override
    public void update(World world, double step) {
        GrassSettings s = world.resource(Settings.class).get(GrassSettings.class);
        CameraPose pose = world.resource(Camera.class).pose();
        Land now = new Land(world.findResource(HeightField.class).orElse(HeightField.FLAT),
                world.findResource(PlacementField.class).orElse(null), rules(world, s), s.distance());
        if (!now.equals(land)) {
            // a new world or new settings: made at once, whatever was under way is dropped
            if (making != null) {
                making.cancel(false);
                making = null;
            }
            land = now;
            take(world, timed(now, pose.x(), pose.z()));
        } else if (making != null && making.isDone()) {
            take(world, making.join());
            making = null;
        } else if (making == null && Math.hypot(pose.x() - field.middleX(), pose.z() - field.middleZ())
                > GrassField.REBUILD_SHARE * s.distance()) {
            double x = pose.x();
            double z = pose.z();
            making = CompletableFuture.supplyAsync(() -> timed(now, x, z), worker);
        }
    }

    /** A field and the milliseconds of CPU it took (on whichever thread made it). */
    private record Made(GrassField field, double ms) {
    }

    private static Made timed(Land l, double x, double z) {
        long t0 = System.nanoTime();
        GrassField f = GrassField.around(x, z, l.distance(), l.heights(), l.placement(), l.rules());
        return new Made(f, (System.nanoTime() - t0) / 1e6);
    }

    private void take(World world, Made made) {
        world.resource(Counters.class).put(FIELD_MS, made.ms());
        field = made.field();
        draw.upload(field);
    }

    /** The rules from the world: above the water (if any) by {@link #SHORE}, under the snow line (if any). */
    static GrassField.Rules rules(World world, GrassSettings s) {
        double lowest = world.findResource(WaterLevel.class).map(w -> w.height() + SHORE)
                .orElse(Double.NEGATIVE_INFINITY);
        return new GrassField.Rules(lowest, world.findResource(SnowLine.class).orElse(null), s.maxGradient());
    }

    @Override
    public void render(Pass pass, RenderContext context) {
        if (field == null) {
            return;
        }
        World world = context.world();
        GrassSettings s = world.resource(Settings.class).get(GrassSettings.class);
        Vector3f wind = new Vector3f(world.findResource(Wind.class).orElse(Wind.CALM).velocity()).mul(GROUND_WIND);
        // the ground's look as the terrain draws it (its sheen only while its gloss maps are on)
        GrassAlbedo ground = world.findResource(GrassAlbedo.class).orElse(ROOTS);
        int drawn = draw.draw(context, field, s, new float[] {wind.x, wind.z}, ground,
                world.resource(Settings.class).get(EngineSettings.class).seed());
        world.resource(Counters.class).add(DRAWN.in(pass), drawn);
    }

    @Override
    public void close() {
        worker.shutdownNow();
    }

    /** The field drawn now (tests). */
    GrassField field() {
        return field;
    }

    /** Waits for a field under way and takes it (tests: the next frame shows it). */
    void settle(World world) {
        if (making != null) {
            take(world, making.join());
            making = null;
        }
    }
}
