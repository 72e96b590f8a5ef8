package org.openworld.engine.terrain;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.openworld.engine.terrain.heights.HeightImportException;
import org.openworld.engine.terrain.heights.StageTimes;
import org.openworld.engine.terrain.heights.TestTerrain;

/** Making the whole terrain data, with its stages timed. */
class TerrainDataTest {

    @TempDir
    Path dir;

    @Test
    void generatedTerrainRecordsItsStagesInOrder() {
        List<String> heard = new ArrayList<>();
        StageTimes times = new StageTimes(stage -> heard.add(stage.name()));
        TerrainData data = TerrainData.create(TestTerrain.settings("terrain.size=256"), 1, times);
        List<String> expected = List.of(TerrainData.SYNTHESIS, TerrainData.PYRAMID, TerrainData.SNOW_MAP);
        assertEquals(expected, times.stages().stream().map(StageTimes.Stage::name).toList());
        assertEquals(expected, heard, "the listener hears each stage as it ends");
        assertTrue(times.stages().stream().allMatch(s -> s.ms() >= 0));
        // doubles: the same sum of stage times, equal to round-off
        assertEquals(times.stages().stream().mapToDouble(StageTimes.Stage::ms).sum(), times.totalMs(), 1e-9);
        assertEquals(256, data.pyramid().base().size());
        assertEquals(9, data.pyramid().levelCount());
        assertEquals(256, data.snow().size());
        assertTrue(data.snow().periodic());
    }

    @Test
    void importedTerrainIsNotPeriodicAndNamesItsStageImport() throws Exception {
        Path file = dir.resolve("h.raw");
        ByteBuffer bytes = ByteBuffer.allocate(257 * 257 * 4).order(ByteOrder.LITTLE_ENDIAN);
        for (int i = 0; i < 257 * 257; i++) {
            bytes.putFloat(i % 257 + i / 257);
        }
        Files.write(file, bytes.array());
        StageTimes times = new StageTimes();
        TerrainData data = TerrainData.create(TestTerrain.settings("terrain.import-file=" + file), 1, times);
        assertEquals(TerrainData.IMPORT, times.stages().get(0).name());
        assertEquals(256, data.pyramid().base().size());
        assertFalse(data.pyramid().base().periodic());
        assertFalse(data.snow().periodic());
    }

    @Test
    void aBadImportFileIsAnImportError() {
        Path missing = dir.resolve("missing.png");
        assertThrows(HeightImportException.class,
                () -> TerrainData.create(TestTerrain.settings("terrain.import-file=" + missing), 1, new StageTimes()));
    }
}
