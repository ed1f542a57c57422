package dev.trisect.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The retention policy: when a buffer gives its storage back, and how much it keeps. */
class RetentionTest {
    @Test
    void storageFarAboveTheRecentNeedShrinksToTwiceItAfterTheWindow() {
        Retention r = new Retention(100);
        long capacity = 1_000_000;
        for (int i = 0; i < Retention.FRAMES - 1; i++) {
            assertEquals(-1, r.keep(1000, capacity), "not judged on fewer frames than the window");
        }
        assertEquals(2000, r.keep(1000, capacity));
    }

    @Test
    void oneLargeFrameInTheWindowKeepsTheStorage() {
        Retention r = new Retention(100);
        long capacity = 1_000_000;
        r.keep(capacity, capacity);
        for (int i = 0; i < Retention.FRAMES - 1; i++) {
            assertEquals(-1, r.keep(10, capacity), "frame " + i + " still remembers the large one");
        }
        assertEquals(100, r.keep(10, capacity), "the floor (above twice the need) once the large frame has left the window");
    }

    @Test
    void needsWithinTheFactorNeverReallocate() {
        Retention r = new Retention(0);
        for (int i = 0; i < 100; i++) {
            assertEquals(-1, r.keep(i % 2 == 0 ? 1000 : 1000 / Retention.FACTOR, 1000));
        }
    }

    @Test
    void storageAtTheFloorStays() {
        Retention r = new Retention(4096);
        for (int i = 0; i < 3 * Retention.FRAMES; i++) {
            assertEquals(-1, r.keep(0, 4096));
        }
        Retention none = new Retention(0);
        for (int i = 0; i < Retention.FRAMES - 1; i++) {
            none.keep(0, 64);
        }
        assertEquals(0, none.keep(0, 64), "with no floor, storage no frame needs goes entirely");
    }
}
