package org.openworld.engine.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Frame order from declarations alone: data edges, after(), alphabetical ties, and the errors. */
class SystemOrderTest {

    /** Resource types the fake systems declare; only their classes matter. */
    static final class Terrain {
    }

    static final class Wind {
    }

    /** A system that only declares; the order never calls its lifecycle. */
    record Fake(SystemSpec spec) implements EngineSystem {
    }

    static Fake system(SystemSpec spec) {
        return new Fake(spec);
    }

    static List<String> names(SystemOrder order) {
        return order.systems().stream().map(s -> s.spec().name()).toList();
    }

    @Test
    void writerRunsBeforeReaderWhateverTheNames() {
        // Alphabetically the reader would go first; the data edge must win.
        Fake reader = system(SystemSpec.named("a-reader").reads(Terrain.class));
        Fake writer = system(SystemSpec.named("z-writer").writes(Terrain.class));

        assertEquals(List.of("z-writer", "a-reader"), names(SystemOrder.resolve(List.of(reader, writer))));
        assertEquals(List.of("z-writer", "a-reader"), names(SystemOrder.resolve(List.of(writer, reader))));
    }

    @Test
    void explicitAfterOrdersSystemsThatShareNoData() {
        Fake first = system(SystemSpec.named("zz-first"));
        Fake second = system(SystemSpec.named("aa-second").after("zz-first"));

        assertEquals(List.of("zz-first", "aa-second"), names(SystemOrder.resolve(List.of(second, first))));
    }

    @Test
    void freeSystemsGoAlphabeticallyNotInInsertionOrder() {
        List<Fake> systems = new ArrayList<>(List.of(
                system(SystemSpec.named("alpha")), system(SystemSpec.named("bravo")),
                system(SystemSpec.named("charlie")), system(SystemSpec.named("delta"))));
        Collections.reverse(systems);

        assertEquals(List.of("alpha", "bravo", "charlie", "delta"), names(SystemOrder.resolve(systems)));
    }

    @Test
    void alphabeticalOrderAppliesAmongTheReadyOnes() {
        // "b" must wait for "c"; "a" and "d" are free. Ready sets: {a, c, d} → a, c; then {b, d} → b, d.
        List<Fake> systems = List.of(
                system(SystemSpec.named("d")), system(SystemSpec.named("c")),
                system(SystemSpec.named("b").after("c")), system(SystemSpec.named("a")));

        assertEquals(List.of("a", "c", "b", "d"), names(SystemOrder.resolve(systems)));
    }

    @Test
    void aTransparentSystemFollowsEveryOpaqueOneThatDrawsInItsPassesAndNoOther() {
        // Alphabetically "flakes" would go before "sky" and "water"; it must follow every opaque drawer of MAIN.
        List<Fake> systems = List.of(
                system(SystemSpec.named("water").draws(Pass.MAIN)),
                system(SystemSpec.named("flakes").layer(Layer.TRANSPARENT).draws(Pass.MAIN)),
                system(SystemSpec.named("sky").draws(Pass.MAIN, Pass.REFLECTION)),
                system(SystemSpec.named("zz-shadow").draws(Pass.SHADOW)),
                system(SystemSpec.named("hud").draws(Pass.OVERLAY)));

        SystemOrder order = SystemOrder.resolve(systems);

        List<String> names = names(order);
        assertTrue(names.indexOf("flakes") > names.indexOf("water") && names.indexOf("flakes") > names.indexOf("sky"),
                names.toString());
        assertTrue(names.indexOf("flakes") < names.indexOf("zz-shadow"), "no edge from a system of another pass: "
                + names);
        assertTrue(order.describe().contains("flakes is transparent, blended over what water draws in main"),
                order.describe());
    }

    @Test
    void theBackgroundDrawsAfterTheOpaqueSystemsOfEachPassAndBeforeWhatIsDrawnOverThem() {
        // Alphabetically "sky" would draw first of the drawers and "terrain" after it. The sky writes the sun that
        // "boulders" (opaque, in MAIN) reads: its update runs first, yet it still draws behind the boulders.
        List<Fake> systems = List.of(
                system(SystemSpec.named("terrain").draws(Pass.MAIN, Pass.REFLECTION)),
                system(SystemSpec.named("rocks").draws(Pass.REFLECTION)),
                system(SystemSpec.named("boulders").reads(String.class).draws(Pass.MAIN)),
                system(SystemSpec.named("sky").writes(String.class).layer(Layer.BACKGROUND)
                        .draws(Pass.MAIN, Pass.REFLECTION)),
                system(SystemSpec.named("shadow").reads(String.class).draws(Pass.OVERLAY)),
                system(SystemSpec.named("water").layer(Layer.OVER_OPAQUE).draws(Pass.MAIN)),
                system(SystemSpec.named("flakes").layer(Layer.TRANSPARENT).draws(Pass.MAIN)),
                system(SystemSpec.named("a-hud").draws(Pass.OVERLAY)));

        SystemOrder order = SystemOrder.resolve(systems);

        List<String> names = names(order);
        assertTrue(names.indexOf("sky") < names.indexOf("boulders"), "the reader's update after the sky's: " + names);
        assertEquals(List.of("boulders", "terrain", "sky", "water", "flakes"), drawing(order, Pass.MAIN));
        assertEquals(List.of("rocks", "terrain", "sky"), drawing(order, Pass.REFLECTION));
        assertEquals(List.of("a-hud", "shadow"), drawing(order, Pass.OVERLAY));
        assertTrue(order.describe().contains("Drawing in main: boulders, terrain, sky, water, flakes"),
                order.describe());
    }

    private static List<String> drawing(SystemOrder order, Pass pass) {
        return order.drawOrder(pass).stream().map(s -> s.spec().name()).toList();
    }

    @Test
    void aSystemOverTheOpaquePictureFollowsEveryOpaqueOneOfItsPassesAndPrecedesTheTransparentOnes() {
        // Alphabetically "trees" and "zz-rocks" would be split around "water": both are opaque and must go before it.
        List<Fake> systems = List.of(
                system(SystemSpec.named("water").layer(Layer.OVER_OPAQUE).draws(Pass.MAIN)),
                system(SystemSpec.named("zz-rocks").draws(Pass.MAIN, Pass.SHADOW)),
                system(SystemSpec.named("trees").draws(Pass.MAIN, Pass.SHADOW, Pass.REFLECTION)),
                system(SystemSpec.named("flakes").layer(Layer.TRANSPARENT).draws(Pass.MAIN)),
                system(SystemSpec.named("zz-shadow").draws(Pass.SHADOW)));

        SystemOrder order = SystemOrder.resolve(systems);

        List<String> names = names(order);
        assertTrue(names.indexOf("trees") < names.indexOf("water") && names.indexOf("zz-rocks") < names.indexOf("water"),
                names.toString());
        assertTrue(names.indexOf("flakes") > names.indexOf("water"), names.toString());
        assertTrue(names.indexOf("water") < names.indexOf("zz-shadow"), "no edge from a system of another pass: "
                + names);
        assertTrue(order.describe().contains("water is drawn over the opaque picture, which it reads: over what "
                + "zz-rocks draws in main"), order.describe());
    }

    @Test
    void cycleThroughAfterNamesItsSystemsAndReasons() {
        List<Fake> systems = List.of(
                system(SystemSpec.named("water").after("sky")),
                system(SystemSpec.named("sky").after("water")));

        SystemOrderException e = assertThrows(SystemOrderException.class, () -> SystemOrder.resolve(systems));

        assertTrue(e.getMessage().contains("cycle"), e.getMessage());
        assertTrue(e.getMessage().contains("water declares after(sky)"), e.getMessage());
        assertTrue(e.getMessage().contains("sky declares after(water)"), e.getMessage());
    }

    @Test
    void cycleMixingDataAndAfterNamesBothReasons() {
        // terrain writes what grass reads (terrain → grass), and terrain declares after(grass): a cycle.
        List<Fake> systems = List.of(
                system(SystemSpec.named("terrain").writes(Terrain.class).after("grass")),
                system(SystemSpec.named("grass").reads(Terrain.class)));

        SystemOrderException e = assertThrows(SystemOrderException.class, () -> SystemOrder.resolve(systems));

        assertTrue(e.getMessage().contains("grass reads Terrain, which terrain writes"), e.getMessage());
        assertTrue(e.getMessage().contains("terrain declares after(grass)"), e.getMessage());
    }

    @Test
    void cycleIsFoundWhenASystemDownstreamOfItIsListedFirst() {
        // "hud" only follows the cycle; listed first, it must not hide the cycle behind another error.
        List<Fake> systems = List.of(
                system(SystemSpec.named("hud").after("sky")),
                system(SystemSpec.named("sky").after("water")),
                system(SystemSpec.named("water").after("sky")));

        SystemOrderException e = assertThrows(SystemOrderException.class, () -> SystemOrder.resolve(systems));

        assertTrue(e.getMessage().contains("sky declares after(water)"), e.getMessage());
        assertTrue(e.getMessage().contains("water declares after(sky)"), e.getMessage());
        assertTrue(!e.getMessage().contains("hud"), "hud is not part of the cycle: " + e.getMessage());
    }

    @Test
    void twoUnorderedWritersOfOneTypeAreAnError() {
        List<Fake> systems = List.of(
                system(SystemSpec.named("wind").writes(Wind.class)),
                system(SystemSpec.named("storm").writes(Wind.class)));

        SystemOrderException e = assertThrows(SystemOrderException.class, () -> SystemOrder.resolve(systems));

        assertTrue(e.getMessage().contains("'wind'"), e.getMessage());
        assertTrue(e.getMessage().contains("'storm'"), e.getMessage());
        assertTrue(e.getMessage().contains("Wind"), e.getMessage());
    }

    @Test
    void twoWritersOrderedByAfterResolve() {
        Fake reader = system(SystemSpec.named("grass").reads(Wind.class));
        Fake storm = system(SystemSpec.named("storm").writes(Wind.class).after("wind"));
        Fake wind = system(SystemSpec.named("wind").writes(Wind.class));

        assertEquals(List.of("wind", "storm", "grass"), names(SystemOrder.resolve(List.of(reader, storm, wind))));
    }

    @Test
    void writersOrderedThroughAChainOfAftersResolve() {
        Fake wind = system(SystemSpec.named("wind").writes(Wind.class));
        Fake clouds = system(SystemSpec.named("clouds").after("wind"));
        Fake storm = system(SystemSpec.named("storm").writes(Wind.class).after("clouds"));

        assertEquals(List.of("wind", "clouds", "storm"), names(SystemOrder.resolve(List.of(storm, clouds, wind))));
    }

    @Test
    void afterAnUnknownSystemIsAnError() {
        List<Fake> systems = List.of(system(SystemSpec.named("water").after("skye")), system(SystemSpec.named("sky")));

        SystemOrderException e = assertThrows(SystemOrderException.class, () -> SystemOrder.resolve(systems));

        assertTrue(e.getMessage().contains("'water'"), e.getMessage());
        assertTrue(e.getMessage().contains("'skye'"), e.getMessage());
    }

    @Test
    void duplicateNamesAreAnError() {
        List<Fake> systems = List.of(system(SystemSpec.named("sky")), system(SystemSpec.named("sky")));

        SystemOrderException e = assertThrows(SystemOrderException.class, () -> SystemOrder.resolve(systems));

        assertTrue(e.getMessage().contains("'sky'"), e.getMessage());
    }

    @Test
    void describeListsEverySystemInOrderWithItsReasons() {
        SystemOrder order = SystemOrder.resolve(List.of(
                system(SystemSpec.named("grass").reads(Terrain.class).draws(Pass.MAIN)),
                system(SystemSpec.named("terrain").writes(Terrain.class).draws(Pass.SHADOW, Pass.MAIN)),
                system(SystemSpec.named("hud").after("grass").draws(Pass.OVERLAY))));

        String text = order.describe();

        int terrain = text.indexOf("terrain");
        int grass = text.indexOf("grass");
        int hud = text.indexOf("hud");
        assertTrue(terrain >= 0 && grass > terrain && hud > grass, text);
        assertTrue(text.contains("shadow,main"), text);
        assertTrue(text.contains("grass reads Terrain, which terrain writes"), text);
        assertTrue(text.contains("hud declares after(grass)"), text);
    }

    @Test
    void describeListsReadsAndWritesInTheOrderDeclaredOnEveryRun() {
        // A set's own order would change from one JVM to the next, and so would openworld info's text.
        SystemOrder order = SystemOrder.resolve(List.of(system(SystemSpec.named("many")
                .reads(String.class, Integer.class, Long.class, Double.class, Float.class, Short.class, Byte.class)
                .writes(Terrain.class, Wind.class, Character.class, Boolean.class))));

        assertTrue(order.describe().contains(
                "writes Terrain,Wind,Character,Boolean; reads String,Integer,Long,Double,Float,Short,Byte"),
                order.describe());
    }

    @Test
    void systemNamesMustBeKebabCase() {
        assertThrows(IllegalArgumentException.class, () -> SystemSpec.named("Sky"));
        assertThrows(IllegalArgumentException.class, () -> SystemSpec.named("sky system"));
    }
}
