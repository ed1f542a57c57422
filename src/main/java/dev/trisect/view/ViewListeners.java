package dev.trisect.view;

import dev.trisect.base.internal.ErrorLine;
import dev.trisect.scene.Pick;
import dev.trisect.view.internal.FrameReport;
import java.awt.event.MouseEvent;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;

/**
 * Who hears from a {@link TrisectView}: its frame listeners, told of each frame on the render thread,
 * its update hooks, run on the render thread before each frame, and its pick listeners, told of each
 * click on an object on the event thread. Not API (package
 * private; the view's public methods add and remove the listeners). It lives in the API package
 * rather than in {@code view.internal} because it names the API's listener types, which the packages
 * below this one may not. Any thread: the lists are copy-on-write, so a listener may be added or
 * removed while others are told.
 */
final class ViewListeners {
    private final List<FrameListener> frames = new CopyOnWriteArrayList<>();
    private final List<PickListener> picks = new CopyOnWriteArrayList<>();
    private final List<UpdateListener> updates = new CopyOnWriteArrayList<>();
    /** Where a failing hook is reported (any thread). */
    private final Consumer<String> problems;

    ViewListeners(Consumer<String> problems) {
        this.problems = problems;
    }

    void addFrameListener(FrameListener listener) {
        frames.add(Objects.requireNonNull(listener, "listener"));
    }

    void removeFrameListener(FrameListener listener) {
        frames.remove(listener);
    }

    void addPickListener(PickListener listener) {
        picks.add(Objects.requireNonNull(listener, "listener"));
    }

    void removePickListener(PickListener listener) {
        picks.remove(listener);
    }

    void addUpdateListener(UpdateListener listener) {
        updates.add(Objects.requireNonNull(listener, "listener"));
    }

    void removeUpdateListener(UpdateListener listener) {
        updates.remove(listener);
    }

    /**
     * Render thread, before frame {@code frame}: runs every update hook (a failing one is reported and
     * the others still run); whether one asked for the next frame.
     */
    boolean update(double seconds, long frame) {
        boolean animates = false;
        for (UpdateListener u : updates) {
            try {
                animates |= u.update(seconds, frame);
            } catch (RuntimeException e) {
                problems.accept(ErrorLine.of("an update hook failed: " + e));
            }
        }
        return animates;
    }

    /** Whether anyone hears of picks: a click is picked only then. */
    boolean hearPicks() {
        return !picks.isEmpty();
    }

    /** Event thread: tells the pick listeners what {@code click} picked. */
    void picked(Pick pick, MouseEvent click) {
        for (PickListener l : picks) {
            l.picked(pick, click);
        }
    }

    /** Render thread: tells the frame listeners of a frame drawn (making its public record only if anyone hears). */
    void frameDone(FrameReport r) {
        if (frames.isEmpty()) {
            return;
        }
        FrameInfo info = new FrameInfo(r.frame(), r.width(), r.height(), r.camera(), r.settings(), r.stats(),
                r.frameMs(), r.fps(), r.warning());
        for (FrameListener l : frames) {
            l.frameDrawn(info);
        }
    }
}
