package dev.trisect.view.internal;

import dev.trisect.base.internal.ChangeSignal;
import dev.trisect.pipeline.FrameRenderer;
import dev.trisect.render.Framebuffer;
import dev.trisect.scene.Pick;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

/**
 * Picking a pixel of the frame on screen: what object, triangle, 3D point and texel it shows. A frame
 * that recorded its UV output (the texel coordinates and triangle of every pixel: while the developer
 * tools measure, or the inspector is on) answers at once; one that did not is drawn once more with it
 * by the render thread, before its next frame — the cost of one frame per click rather than of the UV
 * output on every frame (about a quarter more time per frame). Drawing is deterministic, so the redraw
 * shows the same pixels.
 *
 * <p>{@link #request} from the event thread; {@link #serve} on the render thread. The slot asked
 * about is the one on screen: the render thread never writes it while it shows, and reads it here
 * between its own frames, when it hands nothing to the screen.
 */
public final class Picks {
    /** A pick asked for: pixel (x, y) of {@code slot}'s frame; {@code answer} hears the pick or null. */
    private record Request(FrameSlot slot, int x, int y, Consumer<Pick> answer) {
    }

    /** The latest click waiting; a newer one replaces it (a user clicking faster than frames are drawn). */
    private final AtomicReference<Request> pending = new AtomicReference<>();
    /** Where frames are drawn again with their UV output. Render thread only. */
    private Framebuffer again;

    /**
     * Event thread: picks pixel (x, y) of {@code slot}'s frame. Answers at once when the frame has its
     * UV output; otherwise {@code answer} is called later on the render thread. The answer is null
     * where the pixel shows the background.
     */
    public void request(FrameSlot slot, int x, int y, Consumer<Pick> answer) {
        if (slot.frame.uv() != null) {
            answer.accept(at(slot, slot.frame.uv(), x, y));
        } else {
            pending.set(new Request(slot, x, y, answer));
            // An idle loop serves it now.
            ChangeSignal.signal();
        }
    }

    /** Render thread, between frames: answers a waiting pick by drawing its frame again with UV output. */
    void serve(FrameRenderer renderer) {
        Request r = pending.getAndSet(null);
        if (r == null) {
            return;
        }
        FrameSlot s = r.slot();
        if (again == null || again.width() != s.width() || again.height() != s.height()) {
            again = new Framebuffer(s.width(), s.height());
            again.recordUv(true);
        }
        renderer.render(s.draws, s.drawnRender.withBorders(false), again);
        r.answer().accept(at(s, again.uv(), r.x(), r.y()));
    }

    /** The pick at frame pixel (x, y) of {@code slot}, from UV output {@code uv} of that frame; null for the background. */
    private static Pick at(FrameSlot slot, double[] uv, int x, int y) {
        int i = 3 * (y * slot.width() + x);
        int id = (int) uv[i + 2] - 1;
        return id < 0 ? null : slot.drawn.pick(id, uv[i], uv[i + 1], x, y);
    }
}
