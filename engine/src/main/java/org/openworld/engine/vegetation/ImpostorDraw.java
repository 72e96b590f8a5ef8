package org.openworld.engine.vegetation;

import org.openworld.engine.core.EngineContext;
import org.openworld.engine.core.Pass;
import org.openworld.engine.gl.GpuBuffer;
import org.openworld.engine.gl.Mesh;
import org.openworld.engine.gl.ShaderProgram;
import org.openworld.engine.gl.TextureUnits;
import org.openworld.engine.gl.Uniform;

/**
 * The impostors' GL side: the {@link ImpostorAtlas}, one card (two triangles) drawn instanced over the plants'
 * records, and its two programs ({@code shaders/vegetation/impostor.vert} with the lit {@code impostor.frag}, or the
 * depth-only {@code impostor-depth.frag} in the sun's shadow pass, whose cards face the sun), which blend the three
 * frames nearest the eye's direction and sway as the meshes do. The caller picks the
 * tiles and the distances ({@link TreeDraw}); this class sets the programs up for a pass and a kind.
 */
final class ImpostorDraw {

    private static final TextureUnits UNITS = new TextureUnits();
    private static final TextureUnits.Sampler ATLAS = UNITS.add("uAtlas");

    private final ImpostorAtlas atlas;
    private final Mesh card;
    private final Uniforms lit;
    private final Uniforms depth;

    /** The uniforms both programs have. */
    private record Uniforms(ShaderProgram program, Uniform.Vec2 fade, Uniform.Vec2 band, Uniform.Vec2 placed,
                            Uniform.Vec2 sphere, Uniform.Int kind, Uniform.Int towardsSun, Uniform.Float frames,
                            Uniform.Int sampler, Uniform.Vec2 wind, Uniform.Vec3 sway) {

        static Uniforms of(ShaderProgram p) {
            return new Uniforms(p, p.vec2("uFade"), p.vec2("uImpostor"), p.vec2("uPlaced"), p.vec2("uSphere"),
                    p.int1("uKind"), p.int1("uTowardsSun"), p.float1("uFrames"), p.int1(ATLAS.name()),
                    p.vec2("uWind"), p.vec3("uSway"));
        }
    }

    /** Bakes the atlas (the plants wearing {@code maps}) and makes the card over the plants' {@code records} ({@link TreePlacement#FLOATS} floats each). */
    ImpostorDraw(EngineContext context, GpuBuffer records, int footLocation, int turnLocation, PlantMaps maps) {
        atlas = context.own("impostors", new ImpostorAtlas(context, maps));
        lit = Uniforms.of(context.own("impostor", context.shaders().program("vegetation/impostor.vert",
                "vegetation/impostor.frag")));
        depth = Uniforms.of(context.own("impostorDepth", context.shaders().program("vegetation/impostor.vert",
                "vegetation/impostor-depth.frag")));
        card = context.own("card", new Mesh(context.gl(), new float[] {-1, -1, 1, -1, 1, 1, -1, 1},
                new int[] {0, 1, 2, 0, 2, 3}, new Mesh.Attribute(0, 2)));
        card.instances(records, TreePlacement.FLOATS, new Mesh.Attribute(footLocation, 4),
                new Mesh.Attribute(turnLocation, 2));
    }

    ImpostorAtlas atlas() {
        return atlas;
    }

    /**
     * Sets the pass's program up: the depth-only one, its cards towards the sun, in {@link Pass#SHADOW}, the lit one
     * otherwise.
     *
     * @param fade   metres from the viewer where plants start to shrink and where they are gone
     * @param band   metres from the viewer over which the impostors take over (equal: a hard switch)
     * @param placed the layout's centre from the render origin, metres
     * @param wind   m/s of the wind among the plants, x (east) and z (south)
     * @param sway   the swing's phase per metre east and south and at the layout's centre, radians (as the meshes')
     */
    void begin(Pass pass, float[] fade, float[] band, float[] placed, float[] wind, float[] sway) {
        Uniforms u = pass == Pass.SHADOW ? depth : lit;
        u.program().use();
        u.fade().set(fade[0], fade[1]);
        u.band().set(band[0], band[1]);
        u.placed().set(placed[0], placed[1]);
        u.towardsSun().set(pass == Pass.SHADOW ? 1 : 0);
        u.frames().set(ImpostorAtlas.FRAMES);
        u.wind().set(wind[0], wind[1]);
        u.sway().set(sway[0], sway[1], sway[2]);
        u.sampler().set(ATLAS.unit());
        atlas.texture().bind(ATLAS.unit());
    }

    /** The card, set up for one kind in the pass {@link #begin} set up. */
    Mesh card(Pass pass, TreeKind kind) {
        Uniforms u = pass == Pass.SHADOW ? depth : lit;
        float[] sphere = atlas.sphere(kind);
        u.sphere().set(sphere[0], sphere[1]);
        u.kind().set(kind.ordinal());
        return card;
    }
}
