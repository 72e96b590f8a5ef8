package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.openworld.engine.camera.CameraPose;
import org.openworld.engine.colour.Shimmer;
import org.openworld.engine.gl.Image;
import picocli.CommandLine;

/**
 * {@code openworld stability}'s shimmer on real renders of a small world, the README's pose stepped one metre south:
 * supersampled frames shimmer far less than single samples, and the default anti-aliasing (TAA) at least halves the
 * single sample's figure.
 */
@Tag("gl")
class StabilityTest {

    /** Small, so that each of the eight worlds builds in seconds; 4 × 4 references are 640 × 360. */
    private static final String SIZE = "160x90";
    private static final CameraPose FIRST = new CameraPose(0, 400, 900, 300, 2, CameraPose.DEFAULT_FOV);
    private static final CameraPose SECOND = new CameraPose(0, 400, 901, 300, 2, CameraPose.DEFAULT_FOV);
    /** Samples a side of the supersampled frames: four a pixel, a quarter of the references'. */
    private static final int SUPERSAMPLED = 2;

    private static Shimmer single;
    private static Shimmer supersampled;
    private static Shimmer temporal;

    private static RenderOptions options(String size, String... sets) {
        List<String> args = new ArrayList<>(List.of("--size", size, "--time", "17:30", "--set", "terrain.world=tile",
                "--set", "terrain.size=256", "--set", "shadow.resolution=512"));
        for (String set : sets) {
            args.add("--set");
            args.add(set);
        }
        return CommandLine.populateCommand(new RenderOptions(), args.toArray(String[]::new));
    }

    @BeforeAll
    static void measure() {
        RenderOptions off = options(SIZE, "antialias.method=off");
        RenderOptions reference = StabilityCommand.reference(off);
        Image firstReference = Shimmer.reduce(StabilityCommand.frame(reference, FIRST), StabilityCommand.REFERENCE_SCALE);
        Image secondReference = Shimmer.reduce(StabilityCommand.frame(reference, SECOND),
                StabilityCommand.REFERENCE_SCALE);
        single = Shimmer.of(StabilityCommand.frame(off, FIRST), StabilityCommand.frame(off, SECOND), firstReference,
                secondReference);
        RenderOptions large = options("320x180", "antialias.method=off",
                "lod.pixel-error=" + 6 * SUPERSAMPLED); // the default error in the frame's pixels, as the references
        supersampled = Shimmer.of(Shimmer.reduce(StabilityCommand.frame(large, FIRST), SUPERSAMPLED),
                Shimmer.reduce(StabilityCommand.frame(large, SECOND), SUPERSAMPLED), firstReference, secondReference);
        RenderOptions taa = options(SIZE, "antialias.method=taa");
        temporal = Shimmer.of(StabilityCommand.frame(taa, FIRST), StabilityCommand.frame(taa, SECOND),
                firstReference, secondReference);
    }

    @Test
    void supersampledFramesShimmerFarLessThanSingleSamples() {
        // the single sample's aliasing must be there to be measured: an edge or a texel that flips between the
        // frames in a few pixels of the 14 400 at least
        assertTrue(single.share() > 0.005, "single sample's shimmer " + single.share());
        // a mean of four samples has about half the error of one (1 / sqrt 4), so a pixel whose change exceeds the
        // reference's by more than 1 with four samples would exceed it by about 2 with one: fewer than half as many
        assertTrue(supersampled.share() < single.share() / 2,
                "4 samples " + supersampled.share() + " against 1 sample " + single.share());
    }

    @Test
    void temporalAntialiasingAtLeastHalvesTheShimmer() {
        // a settled frame is the mean of the jitter's 16 samples, the references' count, where four samples already
        // halve it (above); half is the bound the anti-aliasing is built for
        assertTrue(temporal.share() < single.share() / 2,
                "TAA " + temporal.share() + " against no anti-aliasing " + single.share());
    }
}
