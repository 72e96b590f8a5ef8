package org.openworld.engine.erosion.hydraulic;

/**
 * The virtual-pipe erosion on the CPU: the reference the fragment-shader passes ({@link GpuPipeErosion}) are tested
 * against, and the step a machine without OpenGL (the {@code heightmap} command) runs. Each step is the shaders'
 * stages in their order (the thermal step is the transport pass's second half there: it reads the bed the transport
 * does not change), in float arithmetic with the shaders' operations in the shaders' order, every cell read from the
 * state before the stage (Jacobi), so the two differ only by the GPU's rounding. O(cells) a step, on one thread.
 */
public final class PipeErosion {

    /** Pipe directions: left (x − 1), right (x + 1), top (z − 1), bottom (z + 1). */
    private static final int[] DX = {-1, 1, 0, 0};
    private static final int[] DZ = {0, 0, -1, 1};
    /** The direction opposite each: the pipe of the neighbour that points back. */
    private static final int[] BACK = {1, 0, 3, 2};

    private final int n;
    private final PipeModel model;
    private final float[] b;
    private final float[] d;
    private final float[] s;
    private float[][] flux = new float[4][];
    /** The next flux, the inflow per pipe, the next b, d and s: scratch, swapped or copied in after each stage. */
    private float[][] next = new float[4][];
    private final float[][] inflow = new float[4][];
    private final float[] nb;
    private final float[] nd;
    private final float[] ns;
    private final float[] d1;
    private double sedimentOut;

    /**
     * @param heights {@code n × n} terrain heights, row-major (z rows of x), metres; copied
     */
    public PipeErosion(float[] heights, int n, PipeModel model) {
        if (heights.length != n * n) {
            throw new IllegalArgumentException(heights.length + " heights for " + n + "² cells");
        }
        this.n = n;
        this.model = model;
        b = heights.clone();
        d = new float[n * n];
        s = new float[n * n];
        d1 = new float[n * n];
        nb = new float[n * n];
        nd = new float[n * n];
        ns = new float[n * n];
        for (int k = 0; k < 4; k++) {
            flux[k] = new float[n * n];
            next[k] = new float[n * n];
            inflow[k] = new float[n * n];
        }
    }

    /** {@code steps} steps from dry ground: the CPU's {@link PipeState.Runner}. */
    public static PipeState simulate(float[] heights, int n, PipeModel model, int steps) {
        PipeErosion run = new PipeErosion(heights, n, model);
        run.run(steps);
        return run.state();
    }

    /** Runs {@code steps} steps. */
    public void run(int steps) {
        for (int i = 0; i < steps; i++) {
            step();
        }
    }

    /** One step: the flux, the water and erosion, the transport and evaporation, the thermal slide. */
    public void step() {
        fluxPass();
        waterPass();
        transportPass();
        thermalPass();
    }

    /** The heights, water and suspended sediment now (copies). */
    public PipeState state() {
        return new PipeState(b.clone(), d.clone(), s.clone());
    }

    /** Sediment carried out through the apron's edge so far, metres summed over cells (0 on a periodic grid). */
    public double sedimentOut() {
        return sedimentOut;
    }

    /** Cell index of the neighbour of (x, z) in direction k, or −1 past an apron's edge. */
    private int neighbour(int x, int z, int k) {
        int nx = x + DX[k];
        int nz = z + DZ[k];
        if (model.border() == PipeModel.Border.PERIODIC) {
            return Math.floorMod(nz, n) * n + Math.floorMod(nx, n);
        }
        return nx < 0 || nz < 0 || nx >= n || nz >= n ? -1 : nz * n + nx;
    }

    /** 1. Rain, then each pipe's flux accelerated by the drop of the water's surface, scaled to the water held. */
    private void fluxPass() {
        float dt = (float) model.dt();
        float rain = dt * (float) model.rain();
        float accel = dt * (float) model.spacing() * (float) PipeModel.GRAVITY;
        float area = (float) (model.spacing() * model.spacing());
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                int i = z * n + x;
                float water = d[i] + rain;
                float surface = b[i] + water;
                float total = 0;
                for (int k = 0; k < 4; k++) {
                    int j = neighbour(x, z, k);
                    float other = j < 0 ? b[i] : b[j] + (d[j] + rain);
                    float f = Math.max(0f, flux[k][i] + accel * (surface - other));
                    next[k][i] = f;
                    total += f;
                }
                float scale = total > 0 ? Math.min(1f, water * area / (total * dt)) : 1f;
                for (int k = 0; k < 4; k++) {
                    next[k][i] *= scale;
                }
                d1[i] = water;
            }
        }
        float[][] last = flux;
        flux = next;
        next = last;
    }

    /**
     * 2. The water moved by the fluxes, its velocity, and the bed eroded or built up towards the capacity. Notes
     * each cell's inflow per pipe (the neighbour's flux towards it), which the transport reads too.
     */
    private void waterPass() {
        float dt = (float) model.dt();
        float l = (float) model.spacing();
        float area = l * l;
        float[] h = new float[4];
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                int i = z * n + x;
                float in = 0;
                float out = 0;
                for (int k = 0; k < 4; k++) {
                    int j = neighbour(x, z, k);
                    inflow[k][i] = j < 0 ? 0f : flux[BACK[k]][j];
                    h[k] = j < 0 ? b[i] : b[j];
                    in += inflow[k][i];
                    out += flux[k][i];
                }
                float water = Math.max(0f, d1[i] + dt * (in - out) / area);
                float mean = 0.5f * (d1[i] + water);
                float u = velocity(inflow[0][i], flux[0][i], flux[1][i], inflow[1][i], mean, l);
                float v = velocity(inflow[2][i], flux[2][i], flux[3][i], inflow[3][i], mean, l);
                float gx = (h[1] - h[0]) / (2 * l);
                float gz = (h[3] - h[2]) / (2 * l);
                float tan2 = gx * gx + gz * gz;
                float sine = Math.max((float) model.minSine(), (float) Math.sqrt(tan2 / (1 + tan2)));
                float cap = (float) model.capacity() * sine * (float) Math.sqrt(u * u + v * v)
                        * Math.min(water, (float) model.depthCap());
                float bed = b[i];
                float load = s[i];
                if (cap > load) {
                    float e = (float) model.dissolve() * (cap - load);
                    bed -= e;
                    load += e;
                } else {
                    float e = (float) model.deposit() * (load - cap);
                    bed += e;
                    load -= e;
                }
                nb[i] = bed;
                nd[i] = water;
                ns[i] = load;
            }
        }
        System.arraycopy(nb, 0, b, 0, b.length);
        System.arraycopy(nd, 0, d, 0, d.length);
        System.arraycopy(ns, 0, s, 0, s.length);
    }

    /**
     * Velocity along one axis, m/s: the mean of the net flow through the cell's two faces, over the face's width l
     * and the mean depth; 0 on a dry cell.
     */
    static float velocity(float inLow, float outLow, float outHigh, float inHigh, float meanDepth, float l) {
        if (meanDepth <= (float) PipeModel.DRY) {
            return 0f;
        }
        return 0.5f * ((inLow - outLow) + (outHigh - inHigh)) / (l * meanDepth);
    }

    /** 3. The suspended sediment moved with the water, then evaporation. */
    private void transportPass() {
        float dt = (float) model.dt();
        float l = (float) model.spacing();
        float area = l * l;
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                int i = z * n + x;
                ns[i] = model.advection() == PipeModel.Advection.FLUX ? donorCell(x, z, dt, area)
                        : upstream(x, z, dt, l);
            }
        }
        float keep = 1f - (float) model.evaporate() * dt;
        for (int i = 0; i < s.length; i++) {
            s[i] = ns[i];
            d[i] *= keep;
        }
    }

    /** The load that stays, plus each neighbour's share sent through its pipe towards this cell. */
    private float donorCell(int x, int z, float dt, float area) {
        int i = z * n + x;
        float load = s[i];
        float stays = load;
        for (int k = 0; k < 4; k++) {
            float leaves = share(load, flux[k][i], d1[i], dt, area);
            stays -= leaves;
            int j = neighbour(x, z, k);
            if (j < 0) {
                sedimentOut += leaves;
            } else {
                stays += share(s[j], flux[BACK[k]][j], d1[j], dt, area);
            }
        }
        return stays;
    }

    /** The part of {@code load} a pipe carries: the share of the cell's water it carries this step. */
    static float share(float load, float f, float water, float dt, float area) {
        return water > 0 ? load * (f * dt / (water * area)) : 0f;
    }

    /** The paper's step: the load at x − v Δt, read bilinearly (clamped at an apron's edge). */
    private float upstream(int x, int z, float dt, float l) {
        int i = z * n + x;
        float mean = 0.5f * (d1[i] + d[i]);
        float u = velocity(inflow[0][i], flux[0][i], flux[1][i], inflow[1][i], mean, l);
        float v = velocity(inflow[2][i], flux[2][i], flux[3][i], inflow[3][i], mean, l);
        float px = x - u * dt / l;
        float pz = z - v * dt / l;
        int x0 = (int) Math.floor(px);
        int z0 = (int) Math.floor(pz);
        float fx = px - x0;
        float fz = pz - z0;
        float top = load(x0, z0) + (load(x0 + 1, z0) - load(x0, z0)) * fx;
        float bottom = load(x0, z0 + 1) + (load(x0 + 1, z0 + 1) - load(x0, z0 + 1)) * fx;
        return top + (bottom - top) * fz;
    }

    private float load(int x, int z) {
        if (model.border() == PipeModel.Border.PERIODIC) {
            return s[Math.floorMod(z, n) * n + Math.floorMod(x, n)];
        }
        return s[Math.max(0, Math.min(n - 1, z)) * n + Math.max(0, Math.min(n - 1, x))];
    }

    /** 4. Thermal erosion: an eighth of each side's excess drop over the talus slides down (no slide past an apron). */
    private void thermalPass() {
        float limit = (float) model.talus() * (float) model.spacing();
        float share = (float) PipeModel.THERMAL_SHARE;
        for (int z = 0; z < n; z++) {
            for (int x = 0; x < n; x++) {
                int i = z * n + x;
                float change = 0;
                for (int k = 0; k < 4; k++) {
                    int j = neighbour(x, z, k);
                    if (j >= 0) {
                        change += share * Math.max(0f, b[j] - b[i] - limit) - share * Math.max(0f, b[i] - b[j] - limit);
                    }
                }
                nb[i] = b[i] + change;
            }
        }
        System.arraycopy(nb, 0, b, 0, b.length);
    }
}
