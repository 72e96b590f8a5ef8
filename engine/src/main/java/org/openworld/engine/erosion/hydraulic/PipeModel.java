package org.openworld.engine.erosion.hydraulic;

/**
 * The constants of the virtual-pipe erosion (Mei, Decaudin and Hu 2007), the same for the CPU reference
 * ({@link PipeErosion}) and the fragment-shader passes ({@link GpuPipeErosion}); the package comment has the
 * equations they enter.
 *
 * @param spacing    metres between samples: the pipes' length l; a pipe's cross-section is l², so
 *                   {@code f += Δt · l · g · Δh}
 * @param dt         time step, s; with the outflow scaled so no cell loses more water than it holds, water moves at
 *                   most one cell a step, whatever Δt (the scheme's CFL limit is built in)
 * @param rain       water added to every cell, m/s
 * @param capacity   K_c, s/m: sediment a stream can carry, {@code C = K_c · sin α · |v| · min(d, depthCap)} metres
 *                   of material: the paper's {@code K_c sin α |v|} times the depth, so the load grows with the
 *                   discharge per metre of width {@code |v| d} and a film of rain carries no more than a film's worth
 * @param depthCap   m: the depth beyond which a stream carries no more (a river's bed load does not grow with the
 *                   water piled above it, and without friction deep water would cut without end)
 * @param dissolve   K_s: share of the missing load {@code C − s} taken from the bed in one step, 0..1
 * @param deposit    K_d: share of the excess load {@code s − C} laid down in one step, 0..1
 * @param evaporate  K_e, 1/s: water lost as {@code d ← d (1 − K_e Δt)}
 * @param minSine    the least sin α counted, so water on a flat floor still carries what it holds while it flows
 * @param talus      the steepest slope thermal erosion leaves, as a gradient, m/m
 * @param border     what lies past the grid's edge
 * @param advection  how the suspended sediment moves with the water
 */
public record PipeModel(double spacing, double dt, double rain, double capacity, double depthCap, double dissolve,
                        double deposit, double evaporate, double minSine, double talus, Border border,
                        Advection advection) {

    /** Gravity, m/s². */
    public static final double GRAVITY = 9.81;
    /** Share of each side's excess drop over the talus that slides in one step (the tile's thermal step's eighth). */
    public static final double THERMAL_SHARE = 0.125;
    /** Water depth, m, below which a cell counts as dry and its water has no velocity. */
    public static final double DRY = 1e-4;

    /** What lies past the edge of the grid. */
    public enum Border {
        /** The grid wraps: a periodic tile. Nothing leaves. */
        PERIODIC,
        /**
         * The grid is a block with an apron: past the edge lies dry ground of the edge cell's height, so water and
         * the sediment it carries flow out (and are counted), nothing flows in, and no material slides across.
         * Only the block inside the apron is kept.
         */
        APRON
    }

    /** How the suspended sediment moves with the water. */
    public enum Advection {
        /**
         * The paper's: each cell takes the load found upstream, {@code s(x − v Δt)}, read bilinearly. Simple and
         * stable, but not conservative: the load read is not the load that left.
         */
        SEMI_LAGRANGIAN,
        /**
         * Donor cell along the pipes: each pipe carries the share of its cell's load that it carries of its water,
         * {@code s · f Δt / (d₁ l²)}. Every amount leaves one cell and enters another, so the mass is kept.
         */
        FLUX
    }

    /**
     * The tile's model at {@code spacing} metres: rain of 1 mm a step for {@code TileHydraulics.ITERATIONS} steps of
     * 0.1 s (a thin sheet that gathers into the channels), a carrying capacity and rates that move metres of
     * sediment in that time on slopes of tens of degrees, the given talus.
     */
    public static PipeModel tile(double spacing, double talusDegrees, Border border) {
        return new PipeModel(spacing, 0.1, 0.01, 0.1, 0.1, 0.3, 0.3, 0.5, 0.05,
                Math.tan(Math.toRadians(talusDegrees)), border, Advection.FLUX);
    }

    /** The same model with another border. */
    public PipeModel with(Border other) {
        return new PipeModel(spacing, dt, rain, capacity, depthCap, dissolve, deposit, evaporate, minSine, talus, other,
                advection);
    }

    /** The same model with another advection. */
    public PipeModel with(Advection other) {
        return new PipeModel(spacing, dt, rain, capacity, depthCap, dissolve, deposit, evaporate, minSine, talus, border,
                other);
    }
}
