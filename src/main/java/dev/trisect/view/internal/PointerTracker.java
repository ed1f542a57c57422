package dev.trisect.view.internal;

import dev.trisect.scene.Node;
import dev.trisect.scene.Pick;
import dev.trisect.scene.PointerEvent;
import dev.trisect.scene.SceneObject;
import java.awt.event.MouseEvent;
import java.util.ArrayList;
import java.util.List;

/**
 * The pointer over a view's objects: which object is under it (from the frame on screen's triangle
 * ids, {@link FrameIds}), entering and leaving nodes as it moves or as frames move things under a
 * still pointer, and the press, drag, release and click of a gesture on an object, each told to the
 * scene's nodes ({@link Node#firePointerEvent}). It also tells the render thread which node's hover
 * highlight to draw. Event thread only.
 */
final class PointerTracker {
    private final ViewController controller;
    private final ViewMouse mouse;
    /** The object under the pointer, and its groups, innermost first; empty when none. */
    private List<Node> over = List.of();
    private SceneObject pressed;
    private boolean pressConsumed;
    private boolean dragged;
    /** The last mouse event inside the view, to look again under a still pointer; null when outside. */
    private MouseEvent last;
    private long lookedAtFrame = -1;

    PointerTracker(ViewController controller, ViewMouse mouse) {
        this.controller = controller;
        this.mouse = mouse;
    }

    /** What the frame on screen shows at view point (x, y), or null (nothing, or the frame kept no ids). */
    Pick pickAt(int x, int y) {
        FrameSlot f = controller.front();
        if (f == null || !FrameIds.has(f)) {
            return null;
        }
        return FrameIds.pick(f, mouse.frameX(f, x), mouse.frameY(f, y));
    }

    void moved(MouseEvent e) {
        last = e;
        hover(e, pickAt(e.getX(), e.getY()));
    }

    void pressed(MouseEvent e) {
        last = e;
        dragged = false;
        Pick p = pickAt(e.getX(), e.getY());
        pressed = p == null ? null : p.object();
        pressConsumed = pressed != null && fire(PointerEvent.Kind.PRESSED, pressed, p, e);
    }

    void dragged(MouseEvent e) {
        last = e;
        dragged = true;
        Pick p = pickAt(e.getX(), e.getY());
        hover(e, p);
        if (pressed != null) {
            fire(PointerEvent.Kind.DRAGGED, pressed, p, e);
        }
    }

    void released(MouseEvent e) {
        last = e;
        Pick p = pickAt(e.getX(), e.getY());
        SceneObject o = pressed;
        pressed = null;
        pressConsumed = false;
        if (o != null) {
            fire(PointerEvent.Kind.RELEASED, o, p, e);
            if (!dragged && p != null && p.object() == o) {
                fire(PointerEvent.Kind.CLICKED, o, p, e);
            }
        }
    }

    /** The pointer left the view: it is over nothing. */
    void left(MouseEvent e) {
        last = null;
        if (pressed == null) {
            hover(e, null);
        }
    }

    /** Whether the gesture under way began with a press a listener consumed (the camera leaves it alone). */
    boolean gestureConsumed() {
        return pressConsumed;
    }

    /** A new frame is on screen: things may have moved under a still pointer. */
    void frameShown() {
        FrameSlot f = controller.front();
        if (last == null || f == null || f.serial == lookedAtFrame) {
            return;
        }
        lookedAtFrame = f.serial;
        hover(last, pickAt(last.getX(), last.getY()));
    }

    /** The pointer is over {@code p}'s object (or none): tell the nodes it left and the ones it came onto. */
    private void hover(MouseEvent e, Pick p) {
        List<Node> now = chain(p == null ? null : p.object());
        highlight(now);
        if (now.equals(over)) {
            return;
        }
        List<Node> before = over;
        over = now;
        SceneObject left = before.isEmpty() ? null : (SceneObject) before.get(0);
        for (Node n : before) {
            if (!now.contains(n)) {
                n.firePointerEvent(new PointerEvent(PointerEvent.Kind.EXITED, left, n, p, e));
            }
        }
        for (int i = now.size() - 1; i >= 0; i--) {
            Node n = now.get(i);
            if (!before.contains(n)) {
                n.firePointerEvent(new PointerEvent(PointerEvent.Kind.ENTERED, p.object(), n, p, e));
            }
        }
    }

    /** Tells the render thread whose hover highlight to draw: the nearest node of {@code now} holding one. */
    private void highlight(List<Node> now) {
        Node owner = null;
        for (Node n : now) {
            if (n.hoverHighlight() != null) {
                owner = n;
                break;
            }
        }
        controller.state().hovered(owner);
    }

    private static List<Node> chain(SceneObject o) {
        List<Node> c = new ArrayList<>();
        for (Node n = o; n != null; n = n.parent()) {
            c.add(n);
        }
        return c;
    }

    private static boolean fire(PointerEvent.Kind kind, SceneObject o, Pick p, MouseEvent e) {
        PointerEvent ev = new PointerEvent(kind, o, o, p, e);
        o.firePointerEvent(ev);
        return ev.isConsumed();
    }
}
