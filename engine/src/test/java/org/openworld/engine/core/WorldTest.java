package org.openworld.engine.core;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class WorldTest {

    record Position(double x) {
    }

    record Label(String text) {
    }

    @Test
    void componentsAreStoredPerEntityAndClass() {
        World world = new World();
        int a = world.spawn();
        int b = world.spawn();
        assertNotEquals(a, b);
        world.add(a, new Position(1));
        world.add(b, new Position(2));
        world.add(b, new Label("b"));
        world.add(a, new Position(3)); // replaces

        assertEquals(new Position(3), world.get(a, Position.class).orElseThrow());
        assertTrue(world.get(a, Label.class).isEmpty());
        assertEquals(List.of(a, b), world.with(Position.class));
        assertEquals(List.of(b), world.with(Label.class));

        List<Double> xs = new ArrayList<>();
        world.each(Position.class, (entity, p) -> xs.add(p.x()));
        assertEquals(List.of(3.0, 2.0), xs);

        world.remove(b, Label.class);
        assertTrue(world.with(Label.class).isEmpty());
        world.despawn(a);
        assertEquals(List.of(b), world.with(Position.class));
    }

    @Test
    void resourcesByClassOrInterfaceWithAClearErrorWhenMissing() {
        World world = new World();
        assertTrue(world.findResource(HeightField.class).isEmpty());
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> world.resource(HeightField.class));
        assertTrue(e.getMessage().contains("HeightField"), e.getMessage());

        HeightField slope = (x, z) -> x * 0.5;
        world.setResource(HeightField.class, slope);
        assertEquals(5, world.resource(HeightField.class).heightAt(10, 0));
        world.setResource(new Label("sun"));
        assertEquals("sun", world.resource(Label.class).text());
    }
}
