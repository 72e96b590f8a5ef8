package org.openworld.engine.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class CountersTest {

    private static final Counter PATCHES = Counter.of("terrain", "patches");

    @Test
    void aCounterPerPassIsNamedWithItsPass() {
        assertEquals("terrain.patches", PATCHES.name());
        assertEquals("terrain.main.patches", PATCHES.in(Pass.MAIN).name());
        assertEquals("terrain.shadow.patches", PATCHES.in(Pass.SHADOW).name());
    }

    @Test
    void passesAreCountedApartAndAddedUpWithinOne() {
        Counters counters = new Counters();
        counters.add(PATCHES.in(Pass.SHADOW), 3);
        counters.add(PATCHES.in(Pass.MAIN), 5);
        counters.add(PATCHES.in(Pass.MAIN), 2);
        assertEquals(7.0, counters.get(PATCHES.in(Pass.MAIN)));
        assertNull(counters.get(PATCHES), "the frame's count is not the passes' sum");
        Map<String, Double> named = counters.snapshot();
        assertEquals(List.of("terrain.shadow.patches", "terrain.main.patches"), List.copyOf(named.keySet()));
        counters.clear();
        assertEquals(Map.of(), counters.snapshot());
    }

    @Test
    void aNameThatWouldNotMakeAColumnIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> Counter.of("terrain", "select ms"));
        assertThrows(IllegalArgumentException.class, () -> Counter.of("Terrain", "patches"));
    }
}
