package org.openworld.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * {@code openworld info --frame}, the demo's frame order with the reason for each edge, against the snapshot
 * {@code src/test/resources/snapshots/info-frame.txt}: a system added, removed or reordered, or a declaration that
 * changes a reason, fails here with a line diff. The frame order needs no OpenGL, so neither does this test.
 *
 * <p>When the change is meant (a new system, a rewritten one), update the snapshot deliberately and commit it with
 * the change: {@code ./mvnw -B -o -pl engine,demo test -Dtest=InfoFrameSnapshotTest
 * -Dsurefire.failIfNoSpecifiedTests=false -Dsnapshot.update=true} (see {@link Snapshot}).
 */
class InfoFrameSnapshotTest {

    @RegisterExtension
    final ConsoleCapture console = new ConsoleCapture();

    @Test
    void frameOrderMatchesTheSnapshot() throws Exception {
        assertEquals(0, Main.execute("info", "--frame"), console.stderr());
        Snapshot.assertMatches("info-frame.txt", console.stdout());
    }

    @Test
    void aChangedLineShowsAsRemovedAndAddedWithItsContext() {
        String diff = Snapshot.diff(List.of("a", "b", "c", "d", "e", "f", "g"),
                List.of("a", "b", "c", "D", "e", "f", "g", "h"));
        assertEquals("  b\n  c\n- d\n+ D\n  e\n  f\n  g\n+ h\n", diff, diff);
        assertTrue(Snapshot.diff(List.of("x"), List.of("x")).isEmpty(), "no change, no lines");
    }
}
