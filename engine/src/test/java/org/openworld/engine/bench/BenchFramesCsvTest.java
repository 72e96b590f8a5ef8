package org.openworld.engine.bench;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import static org.junit.jupiter.api.Assertions.assertEquals;

class BenchFramesCsvTest {

    @TempDir
    Path dir;

    @Test
    void headerIsTheUnionInFirstSeenOrderAndMissingCellsAreEmpty() throws IOException {
        Path csv = dir.resolve("frames.csv");
        FramesCsv.write(BenchFrames.threeFrames(), csv);

        assertEquals(List.of(
                "frame,sim_time_s,cpu_ms,frame_ms,cpu_ms.terrain,cpu_ms.water,gpu_ms.terrain,gpu_ms.water,"
                        + "triangles,draw_calls,terrain.visible,grass.blades",
                "0,0.0000,5.0000,5.0000,2.0000,,3.0000,,1000,10,64,",
                "1,0.0167,4.0000,6.0000,1.5000,0.2500,4.0000,2.0000,1200,12,60,",
                "2,0.0333,6.0000,8.0000,2.5000,0.7500,5.0000,3.0000,1400,14,56,1.5000"),
                Files.readAllLines(csv));
    }

    @Test
    void decimalPointDoesNotDependOnTheLocale() throws IOException {
        Locale before = Locale.getDefault();
        Locale.setDefault(Locale.GERMANY);
        try {
            Path csv = dir.resolve("frames.csv");
            FramesCsv.write(BenchFrames.threeFrames(), csv);
            assertEquals("1,0.0167,4.0000,6.0000,1.5000,0.2500,4.0000,2.0000,1200,12,60,",
                    Files.readAllLines(csv).get(2));
        } finally {
            Locale.setDefault(before);
        }
    }

    @Test
    void namesWithCommasAreQuoted() throws IOException {
        Path csv = dir.resolve("frames.csv");
        FramesCsv.write(List.of(new FrameRecord(0, 0, 1, 1, BenchFrames.ordered(), BenchFrames.ordered(), 0, 0,
                BenchFrames.ordered("a,b", 1.0))), csv);
        assertEquals("frame,sim_time_s,cpu_ms,frame_ms,triangles,draw_calls,\"a,b\"", Files.readAllLines(csv).get(0));
    }
}
