package dev.trisect.view;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import dev.trisect.view.internal.RenderLoop;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** A view's problems reach its message listeners starting as every other problem's message does. */
class ViewMessagesTest {
    @Test
    void aFailingHookAndAFailedFrameAreSaidTheCommandLinesWay() {
        List<String> said = new ArrayList<>();
        ViewListeners listeners = new ViewListeners(said::add);
        listeners.addUpdateListener((seconds, frame) -> {
            throw new IllegalStateException("boom");
        });
        listeners.update(0.01, 1);
        assertEquals(1, said.size());
        // It said "an update hook failed: ..." and a frame "rendering failed: ...", the command line "trisect: ...".
        assertTrue(said.get(0).startsWith("trisect: an update hook failed: "), said.get(0));
        assertTrue(RenderLoop.failure("draw the frame", new OutOfMemoryError()).startsWith(
                "trisect: cannot draw the frame: out of memory (lower the render scale"));
    }
}
