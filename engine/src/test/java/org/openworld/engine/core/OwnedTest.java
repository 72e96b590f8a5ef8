package org.openworld.engine.core;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.openworld.engine.gl.Labelled;

/** What an owner closes, in which order, how often, and what it reports when closes fail; no GL needed. */
class OwnedTest {

    final List<String> events = new ArrayList<>();

    /** Logs its close and label; throws from close when given a failure message. */
    final class Thing implements Labelled {
        final String name;
        final String failure;
        String label;

        Thing(String name, String failure) {
            this.name = name;
            this.failure = failure;
        }

        Thing(String name) {
            this(name, null);
        }

        @Override
        public void label(String label) {
            this.label = label;
        }

        @Override
        public void close() {
            events.add("close " + name);
            if (failure != null) {
                throw new IllegalStateException(failure);
            }
        }
    }

    @Test
    void closesNewestFirst() {
        Owned owned = new Owned("terrain");
        owned.own(new Thing("program"));
        owned.own(new Thing("heights"));
        owned.own(new Thing("patches"));

        owned.close();

        assertEquals(List.of("close patches", "close heights", "close program"), events);
        assertEquals(0, owned.size());
    }

    @Test
    void goesOnPastFailingClosesAndReportsEveryFailure() {
        Owned owned = new Owned("water");
        owned.own(new Thing("a"));
        owned.own(new Thing("b", "b broke"));
        owned.own(new Thing("c"));
        owned.own(new Thing("d", "d broke"));

        IllegalStateException e = assertThrows(IllegalStateException.class, owned::close);

        assertEquals(List.of("close d", "close c", "close b", "close a"), events);
        assertEquals("d broke", e.getMessage(), "the first failure, in closing order, is the exception");
        assertArrayEquals(new String[] {"b broke"},
                List.of(e.getSuppressed()).stream().map(Throwable::getMessage).toArray(String[]::new));
    }

    @Test
    void neverClosesTwice() {
        Owned owned = new Owned("sky");
        owned.own(new Thing("view"));
        owned.close();
        owned.close();

        assertEquals(List.of("close view"), events);
    }

    @Test
    void replaceClosesTheOldOnceAndOwnsTheFresh() {
        Owned owned = new Owned("water");
        Thing first = owned.own("reflection", new Thing("reflection 1"));
        Thing second = owned.replace("reflection", first, new Thing("reflection 2"));
        assertEquals(List.of("close reflection 1"), events, "the old target is closed at once");
        assertEquals(1, owned.size());

        owned.close();

        assertEquals(List.of("close reflection 1", "close reflection 2"), events, "and never again at the end");
        assertEquals("water.reflection", second.label);
    }

    @Test
    void replaceOfNothingOrOfSomethingOwnedElsewhereOnlyOwnsTheFresh() {
        Owned owned = new Owned("water");
        Thing elsewhere = new Thing("borrowed");
        owned.replace("ripples", null, new Thing("ripples 1"));
        owned.replace("ripples", elsewhere, new Thing("ripples 2"));

        assertEquals(List.of(), events);
        assertEquals(2, owned.size());
    }

    @Test
    void dropClosesOneThingNowAndNotAgain() {
        Owned owned = new Owned("shadow");
        Thing layer = owned.own("map0", new Thing("map0"));
        owned.own("maps", new Thing("maps"));

        owned.drop(layer);
        owned.close();

        assertEquals(List.of("close map0", "close maps"), events);
    }

    @Test
    void labelsEachObjectWithItsOwnerAndRole() {
        Thing heights = new Owned("terrain").own("heights", new Thing("heights"));
        Thing plain = new Owned().own("scratch", new Thing("scratch"));

        assertEquals("terrain.heights", heights.label);
        assertEquals("scratch", plain.label);
    }

    @Test
    void ownHandsTheObjectBackAndRefusesNull() {
        Owned owned = new Owned("particles");
        Thing state = new Thing("state");

        assertSame(state, owned.own(state));
        assertThrows(IllegalArgumentException.class, () -> owned.own(null));
    }

    @Test
    void aCheckedExceptionFromCloseIsReportedWithWhatFailed() {
        Owned owned = new Owned("engine");
        owned.own(() -> {
            throw new Exception("disk gone");
        });

        IllegalStateException e = assertThrows(IllegalStateException.class, owned::close);

        assertTrue(e.getMessage().endsWith("failed: disk gone"), e.getMessage());
    }
}
