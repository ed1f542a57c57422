package dev.trisect.base;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.base.internal.ErrorLine;
import org.junit.jupiter.api.Test;

/** Every problem's message starts "trisect: ", as the command line's do. */
class ErrorLineTest {
    @Test
    void aFailureSaysWhatCouldNotBeDoneAndWhy() {
        assertEquals("trisect: cannot draw the frame: m.obj: line 3: bad face",
                ErrorLine.cannot("draw the frame", new InputException("m.obj: line 3: bad face"), "hint"));
        assertEquals("trisect: cannot pick: out of memory (give Java more)",
                ErrorLine.cannot("pick", new OutOfMemoryError(), "give Java more"));
        assertTrue(ErrorLine.cannot("pick", new IllegalStateException("x"), "h")
                .startsWith("trisect: cannot pick: internal error: java.lang.IllegalStateException"));
        assertEquals("trisect: an update hook failed", ErrorLine.of("an update hook failed"));
    }
}
